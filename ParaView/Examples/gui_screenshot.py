"""The README's picture of the ParaView GUI in the middle of an edit: the bunny's ear bent in the
as-rigid-as-possible mode, the handle widget in the render view, the Handle panel beside it.

Run by scripts/gui-screenshot, which starts `paraview --script` on this file under Xvfb with
LAPLACIAN_DATA (the shared meshes) and LAPLACIAN_SCREEN (the X screen dump to write) set. The
script sets up the scene and returns, so that the GUI paints; a helper process dumps the screen
with xwd a few seconds later and closes ParaView. An error (a failed import among them), or an
edit without a region, ends ParaView at once, with no dump."""
import os
import subprocess
import traceback

try:
    from paraview.simple import (GetActiveViewOrCreate, LaplacianDeformation, OpenDataFile,
                                 Render, ResetCamera, SetActiveSource, Show)
    from paraview import servermanager

    view = GetActiveViewOrCreate("RenderView")
    view.OrientationAxesVisibility = 0
    bunny = OpenDataFile(os.path.join(os.environ["LAPLACIAN_DATA"], "stanford-bunny.obj"))
    mesh = servermanager.Fetch(bunny)
    bounds = mesh.GetBounds()
    diagonal = sum((bounds[2 * i + 1] - bounds[2 * i]) ** 2 for i in range(3)) ** 0.5
    # The ear tip: the highest vertex (y is up in this file).
    tip = max((mesh.GetPoint(i) for i in range(mesh.GetNumberOfPoints())), key=lambda p: p[1])

    deform = LaplacianDeformation(Input=bunny)
    deform.HandleCenter = list(tip)
    deform.HandleRadius = 0.03 * diagonal
    deform.ROIRadius = 0.15 * diagonal
    deform.RotationMode = "As rigid as possible"
    deform.HandleTranslation = [0.06 * diagonal, -0.02 * diagonal, 0.02 * diagonal]
    deform.HandleRotation = [0.0, 0.0, -35.0]
    display = Show(deform, view)
    display.ColorArrayName = ["POINTS", "EditRole"]
    lut = display.LookupTable
    lut.InterpretValuesAsCategories = 1
    lut.Annotations = ["0", "fixed", "1", "anchor", "2", "free", "3", "handle"]
    lut.IndexedColors = [0.75, 0.75, 0.75, 0.85, 0.20, 0.15, 0.35, 0.75, 0.35, 0.95, 0.85, 0.10]
    display.SetScalarBarVisibility(view, True)
    SetActiveSource(deform)
    view.CameraPosition = [0.0, 0.0, 1.0]
    view.CameraFocalPoint = [0.0, 0.0, 0.0]
    view.CameraViewUp = [0.0, 1.0, 0.0]
    ResetCamera(view)
    view.GetActiveCamera().Dolly(1.3)
    Render(view)
    deform.UpdatePropertyInformation()
    if deform.GetProperty("NumberOfROIVertices").GetData() <= 0:
        raise RuntimeError("the edit failed: no region")
except Exception:  # end the run: an error must not leave the GUI waiting
    traceback.print_exc()
    os._exit(1)
subprocess.Popen(["sh", "-c", f"sleep 8; xwd -root -silent -out '{os.environ['LAPLACIAN_SCREEN']}'; "
                  f"kill {os.getpid()}"])
