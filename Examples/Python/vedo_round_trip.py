#!/usr/bin/env python3
"""Laplacian editing inside vedo: a vedo mesh in, a vedo mesh out.

    vedo_round_trip.py [MESH] [--offscreen SCREENSHOT.png]

Loads MESH (default: ../shared/data/stanford-bunny.obj) with vedo, hands its polydata to
vtkLaplacianDeformationFilter, lifts and turns the region around the highest point with
SetHandleTranslation and SetHandleRotation, and wraps the result back into a vedo.Mesh. It
checks what it did: the handle moved by the requested amount, nothing outside the region
moved. With --offscreen it renders the rest and edited meshes side by side to a PNG.

Needs PYTHONPATH=build/vtk/lib/python3/dist-packages (see the README) and python3-vedo.
"""
import argparse
import math
import os
import sys

import vedo

import laplacianediting

HERE = os.path.dirname(os.path.abspath(__file__))
DEFAULT_MESH = os.path.join(HERE, "..", "..", "..", "shared", "data", "stanford-bunny.obj")


def main(argv):
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("mesh", nargs="?", default=DEFAULT_MESH, help="a mesh vedo can load")
    parser.add_argument("--offscreen", metavar="PNG", help="render the result to a PNG file")
    args = parser.parse_args(argv)

    mesh = vedo.Mesh(args.mesh)
    points = mesh.points()
    top = int(points[:, 1].argmax())
    diagonal = mesh.diagonal_size()

    deform = laplacianediting.vtkLaplacianDeformationFilter()
    deform.SetInputData(mesh.polydata())  # vedo's VTK polydata, as it is
    deform.SetRadiusUnitsToDiagonalFraction()
    deform.SetHandleRadius(0.03)
    deform.SetROIRadius(0.15)
    deform.SetHandleCenter(*points[top])
    deform.SetRotationModeToAsRigidAsPossible()
    lift = 0.05 * diagonal
    deform.SetHandleRotation(0, 0, 20)  # degrees about x, y, z, around HandleCenter
    deform.SetHandleTranslation(0, lift, 0)
    deform.Update()
    edited = vedo.Mesh(deform.GetOutput()).c("gold")  # back into vedo, EditRole and all

    after = edited.points()
    moved = [i for i in range(len(points)) if any(after[i] != points[i])]
    roles = deform.GetOutput().GetPointData().GetArray("EditRole")
    still = all(roles.GetValue(i) != 0 for i in moved)  # 0: fixed, outside the region
    # The centre vertex is in the handle: turned about itself, then lifted.
    handle_move = math.dist(points[top], after[top])
    print(f"{len(moved)} of {len(points)} points moved, all in the region: {still}; "
          f"the handle centre moved by {handle_move:.5g} (asked {lift:.5g})")
    if args.offscreen:
        vedo.settings.default_backend = "vtk"
        plotter = vedo.Plotter(N=2, offscreen=True, size=(900, 450))
        plotter.at(0).show(mesh.c("grey"), "rest")
        plotter.at(1).show(edited, "edited")
        plotter.screenshot(args.offscreen)
        plotter.close()
        print(f"wrote {args.offscreen}")
    checks = {"only points in the region moved": still,
              "the handle moved as asked": abs(handle_move - lift) < 1e-3 * diagonal,
              "the region is more than the handle": deform.GetNumberOfROIVertices() > 10}
    failed = [check for check, ok in checks.items() if not ok]
    print("FAILED: " + "; ".join(failed) if failed else "round trip checked")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
