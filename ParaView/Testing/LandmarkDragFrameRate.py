"""A landmark drag in the ParaView GUI, as LandmarkWarpBenchmark's drag measures it in VTK: the
Landmark Drag panel's handle, on landmark 0's target, is dragged by mouse events sent to the
render view's interactor, 2 pixels a frame, with Auto Apply on, and released. Each frame applies
the moved target as Auto Apply does (the warp updating with Dragging on: its factorization
reused, a few ARAP iterations), and renders. Run in the GUI's own Python:

    LAPLACIAN_BENCH="MESH LANDMARKS [FRAMES]" paraview \\
      --plugin-search-paths=build/paraview/lib/paraview-5.11/plugins/LaplacianEditing \\
      --plugins=LaplacianEditing --script=ParaView/Testing/LandmarkDragFrameRate.py

MESH is a surface file ParaView reads; LANDMARKS random triangle centres (seed 0) are the
sources, at rest as targets; FRAMES defaults to 30. The view is 800 x 600. Prints one JSON line
to LAPLACIAN_BENCH_OUTPUT (default: standard output): the still render's milliseconds, the
first frame's and the median frame's (and the warp's update among them, filter_ms), each over
the still render, the release's (its settled update and render), and the factorizations the
drag added (0)."""
import json
import os
import sys
import time


def warp_with_landmarks(mesh_path, count):
    """The warp of the mesh by `count` landmarks at rest, shown in an 800 x 600 view."""
    import numpy as np
    import paraview.simple as simple
    from vtkmodules.util.numpy_support import numpy_to_vtk, vtk_to_numpy
    from vtkmodules.vtkCommonCore import vtkPoints
    from vtkmodules.vtkCommonDataModel import vtkPolyData
    surface = simple.Triangulate(Input=simple.ExtractSurface(Input=simple.OpenDataFile(mesh_path)))
    surface.UpdatePipeline()
    mesh = surface.GetClientSideObject().GetOutput()
    xyz = vtk_to_numpy(mesh.GetPoints().GetData()).astype(float)
    triangles = vtk_to_numpy(mesh.GetPolys().GetConnectivityArray()).reshape(-1, 3)
    picked = np.random.default_rng(0).choice(len(triangles), count, replace=False)
    sources = np.ascontiguousarray(xyz[triangles[picked]].mean(axis=1))
    landmarks = vtkPolyData()
    landmarks.SetPoints(vtkPoints())
    landmarks.GetPoints().SetData(numpy_to_vtk(sources, deep=True))
    targets = numpy_to_vtk(sources, deep=True)
    targets.SetName("Target")
    landmarks.GetPointData().AddArray(targets)
    producer = simple.PVTrivialProducer()
    producer.GetClientSideObject().SetOutput(landmarks)
    warp = simple.LaplacianLandmarkWarp(Input=surface, Landmarks=producer)
    warp.TargetArray = ["POINTS", "Target"]
    simple.GetLayout().SetSize(800, 600)
    view = simple.GetActiveViewOrCreate("RenderView")
    simple.Show(warp, view)
    simple.SetActiveSource(warp)
    simple.ResetCamera(view)
    simple.Render(view)
    return warp, view, sources[0]


def main(out):
    import ViewEvents as gui
    args = os.environ["LAPLACIAN_BENCH"].split()
    mesh_path, count = args[0], int(args[1])
    frames = int(args[2]) if len(args) > 2 else 30
    warp, view, target = warp_with_landmarks(mesh_path, count)
    still = gui.still_render_seconds(view)

    def info(name):
        warp.UpdatePropertyInformation()
        return warp.GetProperty(name).SMProperty.GetElement(0)

    factorizations = info("NumberOfFactorizations")

    def apply_move():
        warp.MovedTargets = gui.unchecked(warp, "MovedTargets")  # Auto Apply
        before = time.perf_counter()
        warp.UpdatePipeline()
        return time.perf_counter() - before

    # The release turned Dragging off: the update settles the shape.
    times, update, release = gui.timed_drag(view, gui.ViewEvents(view).display(target), frames,
                                            apply_move, lambda: None, warp.UpdatePipeline)
    result = {"mesh": os.path.basename(mesh_path), "landmarks": count, "frames": frames,
              "still_ms": round(1000.0 * still, 2)}
    result.update(gui.figures(times, update, release, frames, still))
    result["moved_targets"] = len(gui.unchecked(warp, "MovedTargets")) // 4
    result["refactorizations"] = info("NumberOfFactorizations") - factorizations
    print(json.dumps(result), file=out, flush=True)


# Run from the repository's root, or with LAPLACIAN_TESTING_DIR (the GUI's script has no __file__).
sys.path.insert(0, os.environ.get("LAPLACIAN_TESTING_DIR", os.path.join("ParaView", "Testing")))
import ViewEvents  # noqa: E402
ViewEvents.run_benchmark(main)
