#!/usr/bin/env python3
"""Interactive Laplacian mesh editing from Python.

    interactive_editor.py [--mode none|explicit|implicit] [--offscreen SCREENSHOT.png] [MESH]

Opens MESH (OBJ, PLY, STL, VTP) or the embedded bumpy plane with the handle widget.
Mouse: click the surface to place the handle; drag the sphere to move it (Ctrl: along one
axis), the ring to turn it; Shift + drag the sphere resizes the region, Shift + drag the ring
the handle. Keys: m rotation mode, r reset, c commit the edit, u undo the commit,
s save edited.vtp, q quit. With --offscreen it plays a scripted drag and saves a screenshot.

Needs PYTHONPATH=build/vtk/lib/python3/dist-packages (see the README).
"""
import argparse
import math
import sys

import vtkmodules.vtkInteractionStyle  # noqa: F401  (interactor styles)
import vtkmodules.vtkRenderingFreeType  # noqa: F401  (text)
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401  (rendering backend)
from vtkmodules.vtkCommonCore import vtkLookupTable
from vtkmodules.vtkInteractionStyle import vtkInteractorStyleTrackballCamera
from vtkmodules.vtkIOGeometry import vtkOBJReader, vtkSTLReader
from vtkmodules.vtkIOImage import vtkPNGWriter
from vtkmodules.vtkIOPLY import vtkPLYReader
from vtkmodules.vtkIOXML import vtkXMLPolyDataReader, vtkXMLPolyDataWriter
from vtkmodules.vtkRenderingCore import (vtkActor, vtkInteractorEventRecorder, vtkPolyDataMapper,
                                         vtkRenderer, vtkRenderWindow, vtkRenderWindowInteractor,
                                         vtkTextActor, vtkWindowToImageFilter)

import laplacianediting

HELP = ("mouse: click surface = place handle | drag sphere = move (Ctrl: one axis) | drag ring = turn\n"
        "       Shift+drag sphere = region size | Shift+drag ring = handle size\n"
        "keys:  m rotation mode | r reset | c commit edit | u undo commit | s save edited.vtp | q quit")
MODES = ["none", "explicit", "implicit"]
READERS = {"obj": vtkOBJReader, "ply": vtkPLYReader, "stl": vtkSTLReader, "vtp": vtkXMLPolyDataReader}


def role_colors():
    """Fixed grey, anchors red, free green, handle yellow: the paper's Fig. 2."""
    table = vtkLookupTable()
    table.SetNumberOfTableValues(4)
    for role, rgb in enumerate([(0.75, 0.75, 0.75), (0.85, 0.2, 0.15), (0.35, 0.75, 0.35), (0.95, 0.85, 0.1)]):
        table.SetTableValue(role, *rgb, 1.0)
    table.SetTableRange(0, 3)
    table.Build()
    return table


def make_filter(mesh_path, mode):
    deform = laplacianediting.vtkLaplacianDeformationFilter()
    if mesh_path:
        reader = READERS[mesh_path.rsplit(".", 1)[-1].lower()]()
        reader.SetFileName(mesh_path)
        reader.Update()
        mesh = reader.GetOutput()
        deform.SetInputData(mesh)
        deform.SetHandleCenter(mesh.GetPoint(0))
        deform.SetHandleRadius(0.04 * mesh.GetLength())
        deform.SetROIRadius(0.25 * mesh.GetLength())
    else:
        plane = laplacianediting.vtkBumpyPlaneSource()
        deform.SetInputConnection(plane.GetOutputPort())
        deform.SetHandleCenter(0.8, 0.5, 0.0)
        deform.SetHandleRadius(0.08)
        deform.SetROIRadius(0.6)
    deform.SetRotationMode(MODES.index(mode))
    deform.Update()
    return deform


def scripted_drag(renderer, interactor, widget, pixels=140):
    """Press on the handle, drag it up, release: what a user does, through the event recorder."""
    center = [0.0, 0.0, 0.0]
    widget.GetDeformationHandleRepresentation().GetCurrentCenter(center)
    renderer.SetWorldPoint(*center, 1.0)
    renderer.WorldToDisplay()
    x, y, _ = renderer.GetDisplayPoint()
    lines = [f"MouseMoveEvent {int(x)} {int(y)} 0 0 0 0 i", f"LeftButtonPressEvent {int(x)} {int(y)} 0 0 0 0 i"]
    lines += [f"MouseMoveEvent {int(x)} {int(y + pixels * step / 10)} 0 0 0 0 i" for step in range(1, 11)]
    lines.append(f"LeftButtonReleaseEvent {int(x)} {int(y + pixels)} 0 0 0 0 i")
    recorder = vtkInteractorEventRecorder()
    recorder.SetInteractor(interactor)
    recorder.ReadFromInputStringOn()
    recorder.SetInputString("\n".join(lines) + "\n")
    recorder.Play()
    moved = [0.0, 0.0, 0.0]
    widget.GetDeformationHandleRepresentation().GetCurrentCenter(moved)
    return math.dist(center, moved)


def main(argv):
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("mesh", nargs="?", help="OBJ, PLY, STL or VTP file (default: the embedded bumpy plane)")
    parser.add_argument("--mode", choices=MODES, default="explicit", help="rotation mode")
    parser.add_argument("--offscreen", metavar="PNG", help="play a scripted drag and save a screenshot")
    args = parser.parse_args(argv)

    deform = make_filter(args.mesh, args.mode)
    mapper = vtkPolyDataMapper()
    mapper.SetInputConnection(deform.GetOutputPort())
    mapper.SetLookupTable(role_colors())
    mapper.SetColorModeToMapScalars()
    mapper.SetScalarModeToUsePointFieldData()
    mapper.SelectColorArray("EditRole")
    mapper.SetScalarRange(0, 3)
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

    window = vtkRenderWindow()
    window.SetSize(900, 700)
    window.SetWindowName("Laplacian mesh editing")
    window.AddRenderer(renderer)
    window.SetOffScreenRendering(bool(args.offscreen))
    interactor = vtkRenderWindowInteractor()
    interactor.SetRenderWindow(window)
    interactor.SetInteractorStyle(vtkInteractorStyleTrackballCamera())
    renderer.GetActiveCamera().SetPosition(0, -1, 1)
    renderer.ResetCamera()

    widget = laplacianediting.vtkDeformationHandleWidget()
    widget.SetInteractor(interactor)
    widget.SetDeformationFilter(deform)
    widget.SetSurfaceProp(surface)
    widget.On()

    def show_status():
        status.SetInput(f"rotation mode: {MODES[deform.GetRotationMode()]}   "
                        f"ROI vertices: {deform.GetNumberOfROIVertices()}")

    def on_key(caller, _event):
        key = caller.GetKeySym()
        if key == "m":
            deform.SetRotationMode((deform.GetRotationMode() + 1) % 3)
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
        deform.Update()
        show_status()
        caller.Render()

    interactor.AddObserver("KeyPressEvent", on_key)
    show_status()
    interactor.Initialize()
    window.Render()
    if not args.offscreen:
        interactor.Start()
        return 0

    distance = scripted_drag(renderer, interactor, widget)
    show_status()
    window.Render()
    grab = vtkWindowToImageFilter()
    grab.SetInput(window)
    png = vtkPNGWriter()
    png.SetInputConnection(grab.GetOutputPort())
    png.SetFileName(args.offscreen)
    png.Write()
    print(f"handle moved by {distance:.4f}; {deform.GetNumberOfFactorizations()} factorization(s); "
          f"wrote {args.offscreen}")
    return 0 if distance > 0 else 1


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
