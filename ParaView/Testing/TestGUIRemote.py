"""ParaView GUI test against a one-process pvserver that renders (RunGUIRemote.py starts both):
the plugin loaded on both sides, the tests' scene edited on the server and drawn there (the
remote render threshold at 0). An Auto Apply drag of the handle is drawn by the server's
preview: the view mid-drag shows what it shows once applied, not the surface of before; the
applied result is pvbatch's for the same properties. Needs LAPLACIAN_GUI_OUTPUT,
LAPLACIAN_TESTING_DIR, LAPLACIAN_PLUGIN and LAPLACIAN_PVBATCH."""
import math
import os
import sys
import traceback

output = os.environ["LAPLACIAN_GUI_OUTPUT"]
sys.path.insert(0, os.environ["LAPLACIAN_TESTING_DIR"])
import ViewEvents as gui  # noqa: E402

checks = gui.Checks(output)
try:
    import paraview.simple as simple
    from paraview import servermanager
    simple.LoadPlugin(os.environ["LAPLACIAN_PLUGIN"], remote=True)
    import LaplacianDeformationScene as scene
    simple.GetSettingsProxy("RenderViewSettings").RemoteRenderThreshold = 0.0
    deform = scene.edit()
    view = scene.show(deform)
    events = gui.ViewEvents(view)
    at = events.display([c + t for c, t in zip(deform.HandleCenter, deform.HandleTranslation)])

    def shot(name):
        simple.SaveScreenshot(f"{output}.{name}.png", view, ImageResolution=[600, 500])
        return f"{output}.{name}.png"

    simple.GetSettingsProxy("GeneralSettings").AutoApply = 1
    before = shot("before")
    events.send("MouseMoveEvent", at)
    events.send("LeftButtonPressEvent", at)
    for k in range(1, 13):
        events.send("MouseMoveEvent", (at[0], at[1] + 40.0 * k / 12))
        simple.Render(view)
    preview = shot("preview")
    events.send("LeftButtonReleaseEvent", (at[0], at[1] + 40.0))
    deform.HandleTranslation = gui.unchecked(deform, "HandleTranslation")  # Auto Apply's apply
    deform.UpdatePipeline()
    simple.Render(view)
    applied = shot("applied")
    checks.check(view.GetClientSideObject().GetUseDistributedRenderingForRender(),
                 "the server renders the view")
    same = scene.compare_with_baseline(preview, applied, 1.0)
    differs = scene.compare_with_baseline(preview, before, 1.0)
    checks.check(not same and differs, f"mid-drag, the view shows the applied surface ({same}), "
                 f"not the surface of before ({'differs' if differs else 'the same'})")
    checks.check(math.dist(deform.HandleTranslation, [0.0, 0.0, 0.0]) > 0.05, "the drag moved the handle")
    edited = servermanager.Fetch(deform)
    scripted = gui.scripted_points(gui.applied_properties(deform))
    worst = max(math.dist(edited.GetPoint(i), p) for i, p in enumerate(scripted))
    checks.check(len(scripted) == edited.GetNumberOfPoints() and worst < 1e-9,
                 f"the applied drag's surface is pvbatch's for its properties (largest distance {worst:.1e})")
except Exception:  # any error must end the run, not open a modal dialog that never closes
    checks.fail(traceback.format_exc())
checks.finish()
