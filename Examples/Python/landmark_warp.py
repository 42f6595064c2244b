#!/usr/bin/env python3
"""A landmark warp with numpy and vedo: landmark pairs in, a warped vedo mesh out.

    landmark_warp.py [MESH] [--landmarks N] [--angle DEGREES] [--csv PAIRS.csv]
                     [--offscreen SCREENSHOT.png]

Loads MESH (default: ../shared/data/stanford-bunny.obj) with vedo and takes N random vertices
(default 200) as source landmarks. Their targets turn the top 40% of the mesh (by height)
ANGLE degrees (default 30) about the z axis through its hinge, the rest staying: numpy arrays,
handed to vtkLaplacianLandmarkWarp as vtkPoints. The warped polydata goes back into a vedo
mesh. It checks what it did: every landmark on its target, the bottom in place. With --csv it
writes the pairs as a CSV table (x, y, z, tx, ty, tz), the form ParaView reads
(Documentation/landmark-warps.md); with --offscreen it renders the rest and warped meshes
side by side to a PNG.

Needs PYTHONPATH=build/vtk/lib/python3/dist-packages (see the README) and python3-vedo.
"""
import argparse
import os
import sys

import numpy as np
import vedo
from vtkmodules.util.numpy_support import numpy_to_vtk
from vtkmodules.vtkCommonCore import vtkPoints

import laplacianediting

HERE = os.path.dirname(os.path.abspath(__file__))
DEFAULT_MESH = os.path.join(HERE, "..", "..", "..", "shared", "data", "stanford-bunny.obj")


def as_vtk_points(array):
    points = vtkPoints()
    points.SetData(numpy_to_vtk(np.ascontiguousarray(array, dtype=float), deep=True))
    return points


def hinge(points, bounds, degrees):
    """The top 40% of the bounds turned about z through the hinge, blended over 5% of the
    diagonal; the rest stays."""
    low, high = bounds[2], bounds[3]
    cut = low + 0.6 * (high - low)
    band = 0.05 * np.linalg.norm(np.subtract(bounds[1::2], bounds[0::2]))
    pivot = np.array([(bounds[0] + bounds[1]) / 2, cut, (bounds[4] + bounds[5]) / 2])
    c, s = np.cos(np.radians(degrees)), np.sin(np.radians(degrees))
    d = points - pivot
    turned = pivot + np.column_stack([c * d[:, 0] - s * d[:, 1], s * d[:, 0] + c * d[:, 1], d[:, 2]])
    t = np.clip((points[:, 1] - (cut - band)) / (2 * band), 0, 1)
    weight = (t * t * (3 - 2 * t))[:, None]
    return points + weight * (turned - points), points[:, 1] < cut - band


def main(argv):
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("mesh", nargs="?", default=DEFAULT_MESH, help="a mesh vedo can load")
    parser.add_argument("--landmarks", type=int, default=200, help="how many landmark pairs")
    parser.add_argument("--angle", type=float, default=30.0, help="the hinge's turn, degrees")
    parser.add_argument("--csv", metavar="CSV", help="write the landmark pairs to a CSV table")
    parser.add_argument("--offscreen", metavar="PNG", help="render the result to a PNG file")
    args = parser.parse_args(argv)

    mesh = vedo.Mesh(args.mesh)
    points = np.asarray(mesh.points(), dtype=float)
    diagonal = mesh.diagonal_size()
    used = np.unique(np.concatenate([np.asarray(face) for face in mesh.faces()]))
    sources = points[np.random.default_rng(1).choice(used, args.landmarks, replace=False)]
    targets, _ = hinge(sources, mesh.bounds(), args.angle)

    warp = laplacianediting.vtkLaplacianLandmarkWarp()
    warp.SetInputData(mesh.polydata())  # vedo's VTK polydata, as it is
    warp.SetSourceLandmarks(as_vtk_points(sources))
    warp.SetTargetLandmarks(as_vtk_points(targets))
    warp.Update()
    warped = vedo.Mesh(warp.GetOutput()).c("gold")

    after = np.asarray(warped.points(), dtype=float)
    _, stays = hinge(points, mesh.bounds(), args.angle)
    drifts = np.linalg.norm(after - points, axis=1)[np.intersect1d(np.nonzero(stays)[0], used)]
    drift, typical = drifts.max(), np.median(drifts)
    print(f"{args.landmarks} landmarks in {warp.GetSetupTime() + warp.GetSolveTime():.2f} s, "
          f"{warp.GetNumberOfARAPIterations()} ARAP iterations; the farthest landmark ended "
          f"{warp.GetMaximumLandmarkDistance() / diagonal:.2g} of the diagonal from its target, "
          f"the bottom moved at most {drift / diagonal:.2g} (its median {typical / diagonal:.2g})")
    if args.csv:
        np.savetxt(args.csv, np.hstack([sources, targets]), fmt="%.9g", delimiter=",",
                   header="x,y,z,tx,ty,tz", comments="")
        print(f"wrote {args.csv}")
    if args.offscreen:
        vedo.settings.default_backend = "vtk"
        plotter = vedo.Plotter(N=2, offscreen=True, size=(900, 450))
        plotter.at(0).show(mesh.c("grey"), vedo.Points(sources, r=6, c="red"), "rest")
        plotter.at(1).show(warped, vedo.Points(targets, r=6, c="red"), "warped")
        plotter.screenshot(args.offscreen)
        plotter.close()
        print(f"wrote {args.offscreen}")
    # The mesh's points are floats: a landmark ends on its target up to their rounding.
    checks = {"every landmark on its target": warp.GetMaximumLandmarkDistance() < 1e-6 * diagonal,
              "the bottom stayed": typical < 0.005 * diagonal,
              "every point still there": warped.npoints == mesh.npoints}
    failed = [check for check, ok in checks.items() if not ok]
    print("FAILED: " + "; ".join(failed) if failed else "warp checked")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
