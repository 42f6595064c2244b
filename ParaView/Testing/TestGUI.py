"""ParaView GUI smoke test, run as `paraview --plugins=LaplacianEditing --script=TestGUI.py`
with LAPLACIAN_GUI_OUTPUT, LAPLACIAN_GUI_BASELINE and LAPLACIAN_TESTING_DIR (this folder: the
GUI's script has no __file__) set: in the GUI's own Python, apply
Laplacian Deformation to a sphere, move the handle through its properties, save a screenshot of
the GUI's render view, compare it with the baseline, and quit with the result."""
import os
import sys
import traceback

output, baseline = os.environ["LAPLACIAN_GUI_OUTPUT"], os.environ["LAPLACIAN_GUI_BASELINE"]
try:
    sys.path.insert(0, os.environ["LAPLACIAN_TESTING_DIR"])
    from paraview.simple import GetActiveViewOrCreate, Render, SaveScreenshot
    import LaplacianDeformationScene as scene

    deform = scene.edit()
    view = scene.show(deform, GetActiveViewOrCreate("RenderView"))
    for step in range(1, 4):
        deform.HandleTranslation = [0.0, 0.05 * step, 0.1 * step]
        Render(view)
    SaveScreenshot(output, view, ImageResolution=[600, 500])
    # A GUI rendering may differ a little from pvpython's: a looser threshold than VTK's 0.05.
    failures = scene.compare_with_baseline(output, baseline, 1.0)
except Exception:  # any error must end the run, not open a modal dialog that never closes
    failures = [traceback.format_exc()]
with open(output + ".result", "w") as result:
    result.write("\n".join(failures) if failures else "passed")
os._exit(1 if failures else 0)
