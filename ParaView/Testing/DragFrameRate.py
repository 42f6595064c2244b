"""Frames per second of a handle drag in the ParaView GUI, as DragFrameRate measures it in VTK:
the project's handle widget is dragged by mouse events sent to the render view's interactor,
2 pixels up per frame, with Auto Apply on: each frame applies the handle's values and renders,
as Auto Apply does (the widget leaves the view's rendering to it during the drag). Run in the GUI's own Python:

    LAPLACIAN_BENCH="MESH ROI_FRACTION [FRAMES] [MODE]" paraview \\
      --plugin-search-paths=build/paraview/lib/paraview-5.11/plugins/LaplacianEditing \\
      --plugins=LaplacianEditing --script=ParaView/Testing/DragFrameRate.py

The handle sits on point 0 with a radius of 3% of the bounding-box diagonal; the ROI radius is
ROI_FRACTION of the diagonal; FRAMES defaults to 60; MODE is the rotation mode name (None,
Explicit, Implicit or ARAP; default None). The view is 800 x 600. Prints one JSON
line to LAPLACIAN_BENCH_OUTPUT (default: standard output), with the milliseconds a frame spends
updating the pipeline to the filter's output and the rest (the widget, ParaView's
representation and the rendering)."""
import json
import math
import os
import sys
import time
import traceback

args = os.environ["LAPLACIAN_BENCH"].split()
mesh_path, fraction = args[0], float(args[1])
frames = int(args[2]) if len(args) > 2 else 60
mode = args[3] if len(args) > 3 else "None"
mode = {"ARAP": "As rigid as possible"}.get(mode, mode)
out = open(os.environ["LAPLACIAN_BENCH_OUTPUT"], "w") if "LAPLACIAN_BENCH_OUTPUT" in os.environ else sys.stdout
status = 1
try:
    import paraview.simple as simple

    reader = simple.OpenDataFile(mesh_path)
    surface = simple.ExtractSurface(Input=reader)
    triangles = simple.Triangulate(Input=surface)
    triangles.UpdatePipeline()
    data = triangles.GetClientSideObject().GetOutput()
    diagonal = data.GetLength()
    deform = simple.LaplacianDeformation(Input=triangles)
    deform.HandleCenter = list(data.GetPoint(0))
    deform.HandleRadius = 0.03 * diagonal
    deform.ROIRadius = fraction * diagonal
    deform.RotationMode = mode
    simple.GetLayout().SetSize(800, 600)
    view = simple.GetActiveViewOrCreate("RenderView")
    simple.Show(deform, view)
    simple.ResetCamera(view)
    simple.Render(view)

    def info(name):
        deform.UpdatePropertyInformation()
        return deform.GetProperty(name).SMProperty.GetElement(0)

    translation = deform.GetProperty("HandleTranslation").SMProperty

    def unchecked(prop):
        return [prop.GetUncheckedElement(i) for i in range(prop.GetNumberOfElements())]

    renderer, interactor = view.GetRenderer(), view.GetInteractor()
    renderer.SetWorldPoint(*deform.HandleCenter, 1.0)
    renderer.WorldToDisplay()
    x, y = (int(round(c)) for c in renderer.GetDisplayPoint()[:2])

    def send(name, y_now):
        interactor.SetEventInformation(x, y_now, 0, 0)
        interactor.InvokeEvent(name)

    simple.GetSettingsProxy("GeneralSettings").AutoApply = 1
    send("MouseMoveEvent", y)
    send("LeftButtonPressEvent", y)
    factorizations = info("NumberOfFactorizations")
    start = time.perf_counter()
    update = 0.0  # of which the pipeline update up to the filter's output
    for frame in range(1, frames + 1):
        send("MouseMoveEvent", y + 2 * frame)
        deform.HandleTranslation = unchecked(translation)
        before = time.perf_counter()
        deform.UpdatePipeline()
        update += time.perf_counter() - before
        simple.Render(view)
    seconds = time.perf_counter() - start
    send("LeftButtonReleaseEvent", y + 2 * frames)
    deform.UpdatePropertyInformation()
    roi = sum(1 for i in range(deform.GetClientSideObject().GetOutput().GetNumberOfPoints())
              if deform.GetClientSideObject().GetOutput().GetPointData().GetArray("EditRole").GetValue(i) > 0)
    print(json.dumps({"mesh": os.path.basename(mesh_path), "mode": mode, "roi_points": roi,
                      "frames": frames, "fps": round(frames / seconds, 2),
                      "filter_ms": round(1000.0 * update / frames, 2),
                      "render_ms": round(1000.0 * (seconds - update) / frames, 2),
                      "moved": math.dist(unchecked(translation), [0.0, 0.0, 0.0]),
                      "refactorizations": info("NumberOfFactorizations") - factorizations}),
          file=out, flush=True)
    status = 0
except Exception:
    print(traceback.format_exc(), file=out, flush=True)
os._exit(status)
