#!/usr/bin/env python3
"""Drag landmarks in the view: the warp follows each target as it moves.

    landmark_drag.py [MESH] [--landmarks FILE | --count N] [--offscreen SCREENSHOT.png]

Opens MESH (default: ../shared/data/stanford-bunny.obj; OBJ, PLY, STL, OFF, VTP, VTK) with
landmarks at their rest places: the points of FILE (3D Slicer's .mrk.json or .fcsv, read by
vtkLaplacianMarkupsReader), or N random vertices (default 40). Each target landmark is a seed
of VTK's vtkSeedWidget: drag one, and vtkLaplacianLandmarkWarp re-solves with Dragging on (its
factorization reused, a few iterations a frame); the release settles the shape. Keys: s saves
the targets to targets.mrk.json and the warped surface to warped.vtp, q quits. With --offscreen
it drags the highest landmark up, checks that the warp followed on one factorization, and saves
a screenshot.

Needs PYTHONPATH=build/vtk/lib/python3/dist-packages (see the README).
"""
import argparse
import math
import os
import random
import sys

import vtkmodules.vtkInteractionStyle  # noqa: F401  (interactor styles)
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401  (rendering backend)
from vtkmodules.vtkCommonCore import vtkPoints
from vtkmodules.vtkCommonDataModel import vtkPolyData
from vtkmodules.vtkInteractionWidgets import (vtkPointHandleRepresentation3D, vtkSeedRepresentation,
                                              vtkSeedWidget)
from vtkmodules.vtkIOXML import vtkXMLPolyDataWriter
from vtkmodules.vtkRenderingCore import vtkActor, vtkPolyDataMapper, vtkRenderer

import laplacianediting
from interactive_editor import frame_mesh, open_window, press_and_drag, read_mesh, save_screenshot

HERE = os.path.dirname(os.path.abspath(__file__))
DEFAULT_MESH = os.path.join(HERE, "..", "..", "..", "shared", "data", "stanford-bunny.obj")


def rest_landmarks(mesh, path, count):
    """The landmarks' rest places and their labels: the points of a markups file (its Label
    array), or `count` vertices that a polygon uses, drawn at random (the same draw every run;
    no labels)."""
    if path:
        reader = laplacianediting.vtkLaplacianMarkupsReader()
        reader.SetFileName(path)
        reader.Update()
        if reader.GetErrorCode() or reader.GetOutput().GetNumberOfPoints() == 0:
            raise SystemExit(f"error: no landmarks read from {path}")
        read = reader.GetOutput()
        return [read.GetPoint(i) for i in range(read.GetNumberOfPoints())], read.GetPointData().GetAbstractArray("Label")
    used = set()
    polys = mesh.GetPolys()
    for i in range(polys.GetNumberOfCells()):
        cell = mesh.GetCell(i)
        used.update(cell.GetPointId(k) for k in range(cell.GetNumberOfPoints()))
    picked = random.Random(1).sample(sorted(used), min(count, len(used)))
    return [mesh.GetPoint(i) for i in picked], None


def add_seeds(widget, places):
    """One seed a landmark, placed programmatically; the widget then only moves them."""
    handles = []
    for place in places:
        seed = widget.CreateNewHandle()
        seed.GetHandleRepresentation().SetWorldPosition(place)
        seed.SetEnabled(1)
        handles.append(seed)
    widget.CompleteInteraction()
    return handles


def scripted_drag(renderer, interactor, place, pixels=80):
    """Press on a landmark, drag it up, release."""
    renderer.SetWorldPoint(*place, 1.0)
    renderer.WorldToDisplay()
    x, y, _ = renderer.GetDisplayPoint()
    press_and_drag(interactor, x, y, pixels, steps=8)


def main(argv):
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("mesh", nargs="?", default=DEFAULT_MESH, help="OBJ, PLY, STL, OFF, VTP or VTK file")
    parser.add_argument("--landmarks", metavar="FILE", help="Slicer's .mrk.json or .fcsv landmarks")
    parser.add_argument("--count", type=int, default=40, help="random landmarks without a file")
    parser.add_argument("--offscreen", metavar="PNG", help="play a scripted drag and save a screenshot")
    args = parser.parse_args(argv)

    mesh = read_mesh(args.mesh)
    places, labels = rest_landmarks(mesh, args.landmarks, args.count)
    sources, targets = vtkPoints(), vtkPoints()
    for place in places:
        sources.InsertNextPoint(place)
        targets.InsertNextPoint(place)
    warp = laplacianediting.vtkLaplacianLandmarkWarp()
    warp.SetInputData(mesh)
    warp.SetSourceLandmarks(sources)
    warp.SetTargetLandmarks(targets)

    mapper = vtkPolyDataMapper()
    mapper.SetInputConnection(warp.GetOutputPort())
    surface = vtkActor()
    surface.SetMapper(mapper)
    renderer = vtkRenderer()
    renderer.SetBackground(1, 1, 1)
    renderer.AddActor(surface)
    window, interactor = open_window(renderer, "Landmark warp", (800, 700), args.offscreen)
    frame_mesh(renderer, mesh, 1)
    warp.Update()
    if warp.GetErrorCode():
        return 1  # the warp said why (landmarks off the surface, say)

    handle = vtkPointHandleRepresentation3D()
    handle.AllOff()  # a small cross, not lines across the view
    handle.SetHandleSize(16)
    handle.GetProperty().SetColor(0.85, 0.1, 0.1)
    handle.GetProperty().SetLineWidth(3)
    seeds_rep = vtkSeedRepresentation()
    seeds_rep.SetHandleRepresentation(handle)
    widget = vtkSeedWidget()
    widget.SetInteractor(interactor)
    widget.SetRepresentation(seeds_rep)
    widget.On()
    seeds = add_seeds(widget, places)

    frames = []  # the solves during drags

    def follow(seed, index):
        def moved(*_):
            frames.append(index)
            targets.SetPoint(index, seed.GetHandleRepresentation().GetWorldPosition())
            targets.Modified()
            warp.DraggingOn()  # the factorization reused, a few iterations a frame
            warp.Update()

        def released(*_):
            warp.DraggingOff()  # the next update settles the shape
            warp.Update()
            interactor.Render()
        seed.AddObserver("InteractionEvent", moved)
        seed.AddObserver("EndInteractionEvent", released)

    for index, seed in enumerate(seeds):
        follow(seed, index)

    def on_key(caller, _event):
        if caller.GetKeySym() != "s":
            return
        landmarks = vtkPolyData()
        landmarks.SetPoints(targets)
        if labels is not None:
            landmarks.GetPointData().AddArray(labels)  # Slicer's labels kept
        markups = laplacianediting.vtkLaplacianMarkupsWriter()
        markups.SetInputData(landmarks)
        markups.SetFileName("targets.mrk.json")
        markups.Write()
        surface_writer = vtkXMLPolyDataWriter()
        surface_writer.SetInputConnection(warp.GetOutputPort())
        surface_writer.SetFileName("warped.vtp")
        surface_writer.Write()
        print("saved targets.mrk.json and warped.vtp")

    interactor.AddObserver("KeyPressEvent", on_key)
    interactor.Initialize()
    window.Render()
    if not args.offscreen:
        interactor.Start()
        return 0

    highest = max(range(len(places)), key=lambda i: places[i][1])
    scripted_drag(renderer, interactor, places[highest])
    moved = math.dist(places[highest], targets.GetPoint(highest))
    size = mesh.GetLength()
    save_screenshot(window, args.offscreen)
    print(f"landmark {highest} dragged by {moved / size:.3f} of the diagonal in {len(frames)} frames; "
          f"{warp.GetNumberOfFactorizations()} factorization(s); the farthest landmark "
          f"{warp.GetMaximumLandmarkDistance() / size:.1e} of the diagonal from its target; "
          f"wrote {args.offscreen}")
    checks = {"the landmark moved": moved > 0.01 * size,
              "the warp followed the drag": frames.count(highest) >= 2,
              "every landmark on its target": warp.GetMaximumLandmarkDistance() < 1e-3 * size,
              "one factorization for the whole drag": warp.GetNumberOfFactorizations() == 1}
    failed = [check for check, ok in checks.items() if not ok]
    print("FAILED: " + "; ".join(failed) if failed else "drag checked")
    return 1 if failed else 0

if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
