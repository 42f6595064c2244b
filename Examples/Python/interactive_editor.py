#!/usr/bin/env python3
"""Interactive Laplacian mesh editing from Python.

    interactive_editor.py [--mode none|explicit|implicit|arap] [--up x|y|z]
                          [--offscreen SCREENSHOT.png] [MESH]

Opens MESH (OBJ, PLY, STL, OFF, VTP, VTK) or the embedded bumpy plane with the handle widget.
The first view puts the up axis (default y) up and the mesh's longer horizontal extent across
the screen; the first handle sits on the point that stands out most, with radii of 0.03 and
0.15 of the diagonal. Mouse: a left drag orbits the camera; a click on the surface places the
handle (an edit in progress is committed first); drag the sphere to move the handle (Ctrl:
along one axis), the ring to turn it; Shift + drag the sphere resizes the region, Shift + drag
the ring the handle. Keys: m rotation mode, r reset, c commit the edit, u undo the commit,
s save edited.vtp, q quit. With --offscreen it plays a scripted drag and saves a screenshot.
A file it cannot read: one line on stderr, exit code 1.

Needs PYTHONPATH=build/vtk/lib/python3/dist-packages (see the README).
"""
import argparse
import ctypes
import math
import os
import sys

import vtkmodules.vtkInteractionStyle  # noqa: F401  (interactor styles)
import vtkmodules.vtkRenderingFreeType  # noqa: F401  (text)
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401  (rendering backend)
from vtkmodules.vtkCommonCore import vtkObject, vtkPoints
from vtkmodules.vtkCommonDataModel import vtkCellArray, vtkPolyData
from vtkmodules.vtkInteractionStyle import vtkInteractorStyleTrackballCamera
from vtkmodules.vtkIOGeometry import vtkOBJReader, vtkSTLReader
from vtkmodules.vtkIOImage import vtkPNGWriter
from vtkmodules.vtkIOLegacy import vtkPolyDataReader
from vtkmodules.vtkIOPLY import vtkPLYReader
from vtkmodules.vtkIOXML import vtkXMLPolyDataReader, vtkXMLPolyDataWriter
from vtkmodules.vtkRenderingCore import (vtkActor, vtkInteractorEventRecorder, vtkPolyDataMapper,
                                         vtkRenderer, vtkRenderWindow, vtkRenderWindowInteractor,
                                         vtkTextActor, vtkWindowToImageFilter)

import laplacianediting
from bumpy_plane import bumpy_plane

HELP = ("mouse: drag = orbit | click surface = place handle (commits the edit) | drag sphere = move\n"
        "       (Ctrl: one axis) | drag ring = turn | Shift+drag sphere = region | Shift+drag ring = handle\n"
        "keys:  m rotation mode | r reset | c commit edit | u undo commit | s save edited.vtp | q quit")
MODES = ["none", "explicit", "implicit", "arap"]
READERS = {"obj": vtkOBJReader, "ply": vtkPLYReader, "stl": vtkSTLReader, "vtp": vtkXMLPolyDataReader,
           "vtk": vtkPolyDataReader}


def read_off(path):
    """An OFF file (OFF, COFF, NOFF...: positions first on each vertex line, then polygons),
    which VTK has no reader for."""
    with open(path) as off:
        lines = [line.split("#", 1)[0].split() for line in off]
    lines = [words for words in lines if words]
    if not lines or not lines[0][0].endswith("OFF"):
        raise ValueError("not an OFF file")
    counts = lines[0][1:] if len(lines[0]) > 1 else lines[1]
    first = 1 if len(lines[0]) > 1 else 2
    n_points, n_faces = int(counts[0]), int(counts[1])
    points = vtkPoints()
    for words in lines[first:first + n_points]:
        points.InsertNextPoint(*map(float, words[:3]))
    polys = vtkCellArray()
    for words in lines[first + n_points:first + n_points + n_faces]:
        size = int(words[0])
        ids = [int(v) for v in words[1:1 + size]]
        if len(ids) != size or not all(0 <= i < n_points for i in ids):
            raise ValueError("a face refers to vertices the file does not have")
        polys.InsertNextCell(size, ids)
    if points.GetNumberOfPoints() != n_points or polys.GetNumberOfCells() != n_faces:
        raise ValueError("the file ends early")
    mesh = vtkPolyData()
    mesh.SetPoints(points)
    mesh.SetPolys(polys)
    return mesh


def read_mesh(path):
    """The mesh at `path`, or SystemExit with one line saying why not. VTK's own complaints about
    a bad file (several lines, from the reader, its parser and its executive) are kept quiet."""
    try:
        with open(path, "rb"):
            pass
    except OSError as error:
        raise SystemExit(f"error: cannot open {path}: {error.strerror}")
    extension = os.path.splitext(os.path.basename(path))[1][1:].lower()
    if extension not in READERS and extension != "off":
        problem = f"unknown mesh format '.{extension}'" if extension else f"no file extension on {path}"
        raise SystemExit(f"error: {problem} (use OBJ, PLY, STL, OFF, VTP or VTK)")
    warnings = vtkObject.GetGlobalWarningDisplay()
    vtkObject.GlobalWarningDisplayOff()
    try:
        if extension == "off":
            mesh = read_off(path)
        else:
            reader = READERS[extension]()
            reader.SetFileName(path)
            reader.Update()
            mesh = reader.GetOutput()
    except (ValueError, IndexError) as error:
        raise SystemExit(f"error: cannot read {path} as a .off file: {error}")
    finally:
        vtkObject.SetGlobalWarningDisplay(warnings)
    if mesh.GetNumberOfPoints() == 0:
        raise SystemExit(f"error: cannot read {path} as a .{extension} file")
    if mesh.GetNumberOfPolys() == 0:
        raise SystemExit(f"error: {path} holds no polygons")
    return mesh


def frame_mesh(renderer, mesh, up):
    """Up axis up, looking along the horizontal axis of smaller extent: returns that axis."""
    bounds = mesh.GetBounds()
    a, b = (up + 1) % 3, (up + 2) % 3
    view = a if bounds[2 * a + 1] - bounds[2 * a] < bounds[2 * b + 1] - bounds[2 * b] else b
    camera = renderer.GetActiveCamera()
    camera.SetFocalPoint(0, 0, 0)
    camera.SetPosition(*[1.0 if k == view else 0.0 for k in range(3)])
    camera.SetViewUp(*[1.0 if k == up else 0.0 for k in range(3)])
    renderer.ResetCamera(bounds)
    return view


def protruding_point(mesh, view):
    """On the camera's side of the centre, the point farthest from it across the screen."""
    center = mesh.GetCenter()
    best, best_distance = 0, -1.0
    for i in range(mesh.GetNumberOfPoints()):
        p = mesh.GetPoint(i)
        across = sum((p[k] - center[k]) ** 2 for k in range(3) if k != view)
        if p[view] >= center[view] and across > best_distance:
            best, best_distance = i, across
    return best


def attach_display(window):
    """Opens the X display and gives it to `window`, before the interactor can use a display it
    never checks (VTK 9.1's dies with a segmentation fault where there is none). Returns an
    error message, or None."""
    if not window.IsA("vtkXOpenGLRenderWindow"):
        return None  # another platform's window
    x11 = ctypes.cdll.LoadLibrary("libX11.so.6")
    x11.XOpenDisplay.restype = ctypes.c_void_p
    x11.XOpenDisplay.argtypes = [ctypes.c_char_p]
    display = x11.XOpenDisplay(None)
    if not display:
        name = os.environ.get("DISPLAY")
        where = f"'{name}': no X server answers there" if name else "(DISPLAY is unset)"
        return (f"Cannot open the X display {where}. The editor needs a window: run it on a "
                "desktop, through ssh -X, or with --offscreen under xvfb-run -a.")
    window.SetDisplayId(f"_{display:016x}_p_void")  # VTK's form of a void pointer
    return None


def make_filter(mesh, mode):
    deform = laplacianediting.vtkLaplacianDeformationFilter()
    if mesh is not None:
        deform.SetInputData(mesh)
        deform.SetRadiusUnitsToDiagonalFraction()
        deform.SetHandleRadius(0.03)
        deform.SetROIRadius(0.15)
    else:
        deform.SetInputData(bumpy_plane())
        deform.SetHandleCenter(0.8, 0.5, 0.0)
        deform.SetHandleRadius(0.08)
        deform.SetROIRadius(0.6)
    deform.SetRotationMode(MODES.index(mode))
    return deform


def open_window(renderer, title, size, offscreen):
    """A window showing `renderer`, with its interactor (the trackball camera), on a checked X
    display: SystemExit saying why where there is none."""
    window = vtkRenderWindow()
    error = attach_display(window)
    if error:
        raise SystemExit(error)
    window.SetSize(*size)
    window.SetWindowName(title)
    window.AddRenderer(renderer)
    window.SetOffScreenRendering(bool(offscreen))
    interactor = vtkRenderWindowInteractor()
    interactor.SetRenderWindow(window)
    interactor.SetInteractorStyle(vtkInteractorStyleTrackballCamera())
    return window, interactor


def press_and_drag(interactor, x, y, pixels, steps=10):
    """Press at display point (x, y), drag `pixels` up in `steps` moves, release: what a user
    does, through the event recorder."""
    x, y = int(x), int(y)
    lines = [f"MouseMoveEvent {x} {y} 0 0 0 0 i", f"LeftButtonPressEvent {x} {y} 0 0 0 0 i"]
    lines += [f"MouseMoveEvent {x} {y + pixels * step // steps} 0 0 0 0 i" for step in range(1, steps + 1)]
    lines.append(f"LeftButtonReleaseEvent {x} {y + pixels} 0 0 0 0 i")
    recorder = vtkInteractorEventRecorder()
    recorder.SetInteractor(interactor)
    recorder.ReadFromInputStringOn()
    recorder.SetInputString("\n".join(lines) + "\n")
    recorder.Play()


def save_screenshot(window, path):
    grab = vtkWindowToImageFilter()
    grab.SetInput(window)
    png = vtkPNGWriter()
    png.SetInputConnection(grab.GetOutputPort())
    png.SetFileName(path)
    png.Write()


def scripted_drag(renderer, interactor, widget, pixels=140):
    """Press on the handle, drag it up, release."""
    center = [0.0, 0.0, 0.0]
    widget.GetDeformationHandleRepresentation().GetCurrentCenter(center)
    renderer.SetWorldPoint(*center, 1.0)
    renderer.WorldToDisplay()
    x, y, _ = renderer.GetDisplayPoint()
    press_and_drag(interactor, x, y, pixels)
    moved = [0.0, 0.0, 0.0]
    widget.GetDeformationHandleRepresentation().GetCurrentCenter(moved)
    return math.dist(center, moved)


def main(argv):
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("mesh", nargs="?",
                        help="OBJ, PLY, STL, OFF, VTP or VTK file (default: the embedded bumpy plane)")
    parser.add_argument("--mode", choices=MODES, default="explicit", help="rotation mode")
    parser.add_argument("--up", choices="xyz", default="y", help="the mesh's up axis (default y)")
    parser.add_argument("--offscreen", metavar="PNG", help="play a scripted drag and save a screenshot")
    args = parser.parse_args(argv)

    mesh = read_mesh(args.mesh) if args.mesh else None
    deform = make_filter(mesh, args.mode)
    mapper = vtkPolyDataMapper()  # default settings: EditRole carries its own colours
    mapper.SetInputConnection(deform.GetOutputPort())
    surface = vtkActor()
    surface.SetMapper(mapper)
    surface.GetProperty().SetInterpolationToFlat()

    renderer = vtkRenderer()
    renderer.SetBackground(1, 1, 1)
    renderer.AddActor(surface)
    status, help_text = vtkTextActor(), vtkTextActor()
    help_text.SetInput(HELP)
    help_text.SetDisplayPosition(10, 10)
    for text in (status, help_text):
        text.GetTextProperty().SetColor(0.1, 0.1, 0.1)
        text.GetTextProperty().SetFontSize(13)
        renderer.AddActor2D(text)
    status.GetTextProperty().SetVerticalJustificationToTop()
    status.GetPositionCoordinate().SetCoordinateSystemToNormalizedDisplay()
    status.SetPosition(0.01, 0.97)

    window, interactor = open_window(renderer, "Laplacian mesh editing", (900, 700), args.offscreen)
    if mesh is not None:
        view = frame_mesh(renderer, mesh, "xyz".index(args.up))
        deform.SetHandleCenter(mesh.GetPoint(protruding_point(mesh, view)))
    deform.Update()
    if mesh is None:
        renderer.GetActiveCamera().SetPosition(0, -1, 1)
        renderer.ResetCamera()

    widget = laplacianediting.vtkDeformationHandleWidget()
    widget.SetInteractor(interactor)
    widget.SetDeformationFilter(deform)
    widget.SetSurfaceProp(surface)
    widget.On()

    def show_status(*_):
        """After a key, a click or a resize (the region changed)."""
        deform.Update()
        status.SetInput(f"rotation mode: {MODES[deform.GetRotationMode()]}   "
                        f"ROI vertices: {deform.GetNumberOfROIVertices()}")
        interactor.Render()

    def on_key(caller, _event):
        key = caller.GetKeySym()
        if key == "m":
            deform.SetRotationMode((deform.GetRotationMode() + 1) % len(MODES))
        elif key == "r":
            widget.ResetHandle()
        elif key == "c":
            widget.CommitEdit()
        elif key == "u":
            widget.UndoCommit()
        elif key == "s":
            writer = vtkXMLPolyDataWriter()
            writer.SetInputConnection(deform.GetOutputPort())
            writer.SetFileName("edited.vtp")
            writer.Write()
            print("saved edited.vtp")
        else:
            return
        show_status()

    interactor.AddObserver("KeyPressEvent", on_key)
    widget.AddObserver("EndInteractionEvent", show_status)
    interactor.Initialize()
    show_status()
    if not args.offscreen:
        interactor.Start()
        return 0

    distance = scripted_drag(renderer, interactor, widget)  # the release refreshes the status
    save_screenshot(window, args.offscreen)
    print(f"handle moved by {distance:.4f}; {deform.GetNumberOfFactorizations()} factorization(s); "
          f"wrote {args.offscreen}")
    return 0 if distance > 0 else 1


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
