"""Frames per second of a handle drag in the ParaView GUI, as DragFrameRate measures it in VTK:
the project's handle widget is dragged by mouse events sent to the render view's interactor,
2 pixels up per frame, with Auto Apply on, and released. Each frame renders the view, as the
panel has it rendered: where the drag is previewed (the filter solves in the process that
renders), the preview draws the move and the pipeline updates once, on release; otherwise each
frame first applies the handle's values, as Auto Apply does. Run in the GUI's own Python:

    LAPLACIAN_BENCH="MESH ROI_FRACTION [FRAMES] [MODE] [DRAGS]" paraview \\
      --plugin-search-paths=build/paraview/lib/paraview-5.11/plugins/LaplacianEditing \\
      --plugins=LaplacianEditing --script=ParaView/Testing/DragFrameRate.py

MESH is a file ParaView reads, sphere:THETAxPHI for ParaView's Sphere source at those
resolutions (sphere:2000x1002 has 2M points and carries point normals), or scan:LEVELS:PATH for
the benchmark's scan (Testing/Support/MeshReader.h's Scan: the surface Loop-subdivided LEVELS
times, with fine bumps along its normals; scan:3:../shared/data/Armadillo.ply has 2.4M points),
or volume:PATH for a volume mesh (VolumeEditBenchmark's cache holds tetgen's: --cache DIR; volume:bar
is TestGUIVolume.py's bar of 1,600 tetrahedra), edited
by Laplacian Volume Deformation (as rigid as possible unless MODE says None) and shown as its
outline with a Clip through its centre shown as a surface, as issue 48 measures it. The handle sits on point
0 (on a sphere, the point nearest (0.5, 0, 0), on the equator) with a radius of 3% of the
bounding-box diagonal, or a third of the ROI radius if that is less; the ROI radius is
ROI_FRACTION of the diagonal; FRAMES defaults to 60; MODE is the rotation mode name (None,
Explicit, Implicit or ARAP; default None); DRAGS (default 1) drags in a row, the figures of the
last of which are reported as well ("later_drag": a region's still part is built by its first).
The view is 800 x 600. Before the drag, ten still renders of the same scene are timed (their
median is still_ms). Prints one JSON line to LAPLACIAN_BENCH_OUTPUT (default: standard output):
the first frame's milliseconds (a preview builds the still part of the surface there) and the
median of the others (frame_ms), of which updating the pipeline (filter_ms, without a preview),
frame_ms over still_ms, whether the drag was previewed and the median of the preview's solve and
write among the frames (preview_ms), and the release's milliseconds (its update and render), in
steps (the release event, the pipeline update, the render) and as a CLOCK_MONOTONIC window to
cut a profile with:
`perf record -k mono -g -o FILE -- paraview ...`, then `perf report --time START,END`.
Where the release's settle stops at the panel's time limit (a large region), the line waits
for the settle that the panel continues between the events, and adds: its updates, iterations
and seconds from the release (to its last update, and to the render of the settled shape), the
longest and the median turn of the event loop among them (the longest the window waits), and
the energy reached. The earlier drags of DRAGS are
grabbed again before their settles end, as a user who grabs again would."""
import json
import math
import os
import sys
import time


def scan(spec):
    """MeshReader.h's Scan, on ParaView's VTK: the surface of PATH Loop-subdivided LEVELS times,
    each point moved along its normal by 5e-4 of the diagonal times sin(kx) sin(ky) sin(kz),
    k = 2 pi / (6e-3 of the diagonal)."""
    import numpy as np
    from vtkmodules.util.numpy_support import numpy_to_vtk, vtk_to_numpy
    from vtkmodules.vtkCommonDataModel import vtkPolyData
    from vtkmodules.vtkFiltersCore import vtkPolyDataNormals
    from vtkmodules.vtkFiltersModeling import vtkLoopSubdivisionFilter
    from vtkmodules.vtkIOGeometry import vtkOBJReader, vtkSTLReader
    from vtkmodules.vtkIOPLY import vtkPLYReader
    levels, path = spec[len("scan:"):].split(":", 1)
    reader = {"ply": vtkPLYReader, "obj": vtkOBJReader, "stl": vtkSTLReader}[path.rsplit(".", 1)[-1].lower()]()
    reader.SetFileName(path)
    reader.Update()
    surface = vtkPolyData()
    surface.SetPoints(reader.GetOutput().GetPoints())
    surface.SetPolys(reader.GetOutput().GetPolys())
    subdivide = vtkLoopSubdivisionFilter()
    subdivide.SetInputData(surface)
    subdivide.SetNumberOfSubdivisions(int(levels))
    normals = vtkPolyDataNormals()
    normals.SetInputConnection(subdivide.GetOutputPort())
    normals.SplittingOff()
    normals.ComputeCellNormalsOff()
    normals.Update()
    mesh = normals.GetOutput()
    diagonal = mesh.GetLength()
    height, k = 5e-4 * diagonal, 2.0 * np.pi / (6e-3 * diagonal)
    points = vtk_to_numpy(mesh.GetPoints().GetData()).astype(float)
    along = vtk_to_numpy(mesh.GetPointData().GetNormals()).astype(float)
    bumps = height * np.prod(np.sin(k * points), axis=1)
    moved = points + bumps[:, None] * along
    mesh.GetPoints().SetData(numpy_to_vtk(moved.astype(vtk_to_numpy(mesh.GetPoints().GetData()).dtype), deep=True))
    mesh.GetPointData().Initialize()
    return mesh


def load(mesh_path):
    """The surface, as triangles."""
    import paraview.simple as simple
    if mesh_path.startswith("scan:"):
        source = simple.PVTrivialProducer()
        source.GetClientSideObject().SetOutput(scan(mesh_path))
        return source
    if mesh_path.startswith("sphere:"):
        theta, phi = (int(n) for n in mesh_path[len("sphere:"):].split("x"))
        return simple.Sphere(ThetaResolution=theta, PhiResolution=phi)
    if mesh_path == "volume:bar":
        return simple.Tetrahedralize(Input=simple.Wavelet(WholeExtent=[0, 20, 0, 4, 0, 4]))
    if mesh_path.startswith("volume:"):
        return simple.OpenDataFile(mesh_path[len("volume:"):])
    surface = simple.ExtractSurface(Input=simple.OpenDataFile(mesh_path))
    return simple.Triangulate(Input=surface)


def edit(triangles, mesh_path, fraction, mode):
    """The deformation filter on the handle's vertex, shown in an 800 x 600 view."""
    import paraview.simple as simple
    triangles.UpdatePipeline()
    data = triangles.GetClientSideObject().GetOutputDataObject(0)  # a trivial producer has no GetOutput
    diagonal = data.GetLength()
    volume = mesh_path.startswith("volume:")
    deform = (simple.LaplacianVolumeDeformation if volume else simple.LaplacianDeformation)(
        Input=triangles)
    handle = 0
    if mesh_path.startswith("sphere:"):
        from vtkmodules.util.numpy_support import vtk_to_numpy
        xyz = vtk_to_numpy(data.GetPoints().GetData())
        handle = int(((xyz - [0.5, 0.0, 0.0]) ** 2).sum(axis=1).argmin())
    deform.HandleCenter = list(data.GetPoint(handle))
    deform.HandleRadius = min(0.03, fraction / 3.0) * diagonal
    deform.ROIRadius = fraction * diagonal
    if not volume or mode == "None":
        deform.RotationMode = mode
    simple.GetLayout().SetSize(800, 600)
    view = simple.GetActiveViewOrCreate("RenderView")
    shown = simple.Show(deform, view)  # the panel shows the handle of a source that is shown
    if volume:
        shown.SetRepresentationType("Outline")
        # Registered without becoming the active source: the panel keeps the volume's handle.
        from paraview import servermanager
        clip = servermanager.filters.Clip(Input=deform)
        servermanager.ProxyManager().RegisterProxy("sources", "Clip1", clip)
        clip.ClipType.Origin = list(data.GetCenter())
        clip.ClipType.Normal = [0.0, 1.0, 0.0]
        simple.Show(clip, view)
    simple.ResetCamera(view)
    simple.Render(view)
    return deform, view


def drag(deform, view, frames):
    """Drags the handle up by 2 pixels a frame; returns each frame's seconds, those of the
    pipeline updates among them, of the release, and whether the preview drew the drag."""
    import ViewEvents as gui
    widget = gui.handle_widgets(view)[0]
    at = gui.ViewEvents(view).display(
        [c + t for c, t in zip(deform.HandleCenter, deform.HandleTranslation)])
    previewed = [True]
    previews = []

    def apply_move():
        widget.UpdatePropertyInformation()
        previewed[0] = previewed[0] and widget.GetProperty("PreviewShownInfo").GetElement(0) == 1
        if previewed[0]:
            previews.append(widget.GetProperty("PreviewTimeInfo").GetElement(0))
            return 0.0
        deform.HandleTranslation = gui.unchecked(deform, "HandleTranslation")  # Auto Apply
        before = time.perf_counter()
        deform.UpdatePipeline()
        return time.perf_counter() - before

    def apply_release():  # Auto Apply, settled
        deform.HandleTranslation = gui.unchecked(deform, "HandleTranslation")

    times, update, release = gui.timed_drag(view, at, frames, apply_move, apply_release,
                                            deform.UpdatePipeline)
    return times, update, release, previewed[0], previews


def main(out):
    args = os.environ["LAPLACIAN_BENCH"].split()
    mesh_path, fraction = args[0], float(args[1])
    frames = int(args[2]) if len(args) > 2 else 60
    mode = args[3] if len(args) > 3 else "None"
    mode = {"ARAP": "As rigid as possible"}.get(mode, mode)
    drags = int(args[4]) if len(args) > 4 else 1
    deform, view = edit(load(mesh_path), mesh_path, fraction, mode)
    import ViewEvents as gui
    still = gui.still_render_seconds(view)

    def info(name):
        """An information property's value; None where the filter has none (a volume's)."""
        deform.UpdatePropertyInformation()
        prop = deform.GetProperty(name)
        return prop.SMProperty.GetElement(0) if prop else None

    volume = mesh_path.startswith("volume:")
    # What a volume's figures count: its zone's points, the interior's iterations.
    region = "NumberOfZonePoints" if volume else "NumberOfROIVertices"
    steps = "NumberOfVolumeIterations" if volume else "NumberOfARAPIterations"
    factorizations = info("NumberOfFactorizations")
    each = []
    for _ in range(drags):
        times, update, release, previewed, previews = drag(deform, view, frames)
        each.append(gui.figures(times, update, release, frames, still))
        if previewed:  # the preview's solve and write, in the frames after the first
            later = sorted(previews[1:] or previews)
            each[-1]["preview_ms"] = round(1000.0 * later[len(later) // 2], 2)
    result = {"mesh": os.path.basename(mesh_path), "mode": mode,
              "roi_vertices": info(region), "frames": frames,
              "previewed": previewed, "fps": round(frames / sum(times), 2),
              "still_ms": round(1000.0 * still, 2)}
    result.update(each[0])
    if drags > 1:
        result["later_drag"] = each[-1]
    result["moved"] = math.dist(deform.HandleTranslation, [0.0, 0.0, 0.0])
    if factorizations is not None:
        result["refactorizations"] = info("NumberOfFactorizations") - factorizations
    if not info("Settling"):
        print(json.dumps(result), file=out, flush=True)
        return False
    # The release's settle stopped at the panel's time limit: the panel goes on between the
    # events, once this script has returned to the event loop. Each of its updates ends a turn
    # of the loop (the last update's render, then this one's solve and write).
    release_start, turns = result["release_window"]
    turns = [turns]
    iterations = [info(steps)]
    renders = [0]
    window = view.GetRenderWindow()
    window.AddObserver("EndEvent", lambda *_: renders.__setitem__(0, renders[0] + 1))

    def settled(filter, event):
        try:
            measure_turn(filter)
        except Exception:  # the event loop would go on without the benchmark
            import traceback
            print(traceback.format_exc(), file=out, flush=True)
            os._exit(1)

    def measure_turn(filter):
        turns.append(time.monotonic())
        iterations.append(info(steps))
        if info("Settling"):
            return
        waits = [b - a for a, b in zip(turns, turns[1:])]
        result.update({"settle_updates": len(iterations),
                       "settle_iterations": sum(iterations),
                       "settle_s": round(turns[-1] - release_start, 2),
                       "settle_longest_turn_ms": round(1000.0 * max(waits), 1),
                       "settle_median_turn_ms": round(1000.0 * sorted(waits)[len(waits) // 2], 1),
                       "settle_renders": renders[0],
                       "settled_energy": info("ARAPEnergy")})
        window.AddObserver("EndEvent", drawn)

    def drawn(window, event):  # the settled shape's render
        result["settle_drawn_s"] = round(time.monotonic() - release_start, 2)
        print(json.dumps(result), file=out, flush=True)
        os._exit(0)
    deform.GetClientSideObject().AddObserver("EndEvent", settled)
    return True


# Run from the repository's root, or with LAPLACIAN_TESTING_DIR (the GUI's script has no __file__).
sys.path.insert(0, os.environ.get("LAPLACIAN_TESTING_DIR", os.path.join("ParaView", "Testing")))
import ViewEvents  # noqa: E402
ViewEvents.run_benchmark(main)
