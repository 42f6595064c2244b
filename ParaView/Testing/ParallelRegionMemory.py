"""Memory of an edit under MPI, per rank, against the size of the surface.

    mpiexec -np 2 pvbatch --symmetric ParallelRegionMemory.py PLUGIN [THETA PHI [ROI [MOVES [MODE [SOLVER]]]]]

Each rank generates its piece of a sphere (default 2000 x 1002: 2M points, 4M triangles), the
filter edits a region of 4,337 vertices around (0.5, 0, 0), on the seam of the pieces, and every
rank prints its growth and the time at setup and after MOVES (10) handle moves, its peak memory,
and how many of its points moved (ROI: the ROI radius as a fraction of the diagonal, 0.034 by
default); the first rank, which solves, also the points it gathered. It fails (exit 1) if that
rank gathered more than four times the region, or, for a region under 5% of the diagonal, more
than 5% of the surface. MOVES -1 only generates the pieces: the baseline of ParallelTraffic.py's
byte counts. MODE is the rotation mode: none (the default), explicit, implicit, implicit-linear
(without the rigid correction) or arap. SOLVER is CHOLMOD (the default: on the first rank) or
MUMPS (across the ranks); the first rank prints the factor's size and where it lives.
"""
import sys
import time

from paraview.simple import LoadPlugin, Sphere

LoadPlugin(sys.argv[1], remote=False)
import paraview.simple as simple  # noqa: E402
from vtkmodules.vtkParallelCore import vtkMultiProcessController  # noqa: E402


def rss_mb(field="VmRSS:"):
    with open("/proc/self/status") as status:
        for line in status:
            if line.startswith(field):
                return int(line.split()[1]) / 1024.0


theta, phi = (int(a) for a in sys.argv[2:4]) if len(sys.argv) > 3 else (2000, 1002)
roi = float(sys.argv[4]) if len(sys.argv) > 4 else 0.034
move_count = int(sys.argv[5]) if len(sys.argv) > 5 else 10
mode = sys.argv[6] if len(sys.argv) > 6 else "none"
solver = sys.argv[7] if len(sys.argv) > 7 else "CHOLMOD"
rotation_modes = {"none": ("None", 1), "explicit": ("Explicit", 1), "implicit": ("Implicit", 1),
                  "implicit-linear": ("Implicit", 0), "arap": ("As rigid as possible", 1)}
before_sphere = rss_mb()
sphere = Sphere(ThetaResolution=theta, PhiResolution=phi, Radius=0.5)
sphere.UpdatePipeline()
sphere_rss = rss_mb() - before_sphere  # what generating the piece took, for the ratios


def edit():
    piece = sphere.GetClientSideObject().GetOutputDataObject(0)
    base = rss_mb()
    deform = simple.LaplacianDeformation(Input=sphere)
    deform.HandleCenter = [0.5, 0.0, 0.0]
    deform.RotationMode, deform.PreserveDetailScale = rotation_modes[mode]
    deform.Solver = solver
    diagonal = 3 ** 0.5  # as RegionMemory.py's radii, fractions of the diagonal
    deform.HandleRadius = 0.01 * diagonal
    deform.ROIRadius = roi * diagonal
    start = time.perf_counter()
    deform.UpdatePipeline()
    setup_seconds = time.perf_counter() - start
    setup = rss_mb() - base
    start = time.perf_counter()
    for k in range(1, move_count + 1):
        deform.HandleTranslation = [0.002 * k, 0.0, 0.0]
        deform.UpdatePipeline()
    move_ms = (time.perf_counter() - start) * 1000.0 / max(move_count, 1)
    moves = rss_mb() - base
    deform.UpdatePropertyInformation()  # the first rank's figures
    rank = vtkMultiProcessController.GetGlobalController().GetLocalProcessId()
    figures = {name: deform.GetProperty(name).GetData() if deform.GetProperty(name) else "-"
               for name in ("NumberOfGatheredPoints", "NumberOfROIVertices", "NumberOfFactorizations",
                            "FactorMemory", "FactoredAcrossProcesses")}
    moved = deform.GetClientSideObject().GetOutputDataObject(0).GetPoints()
    before = piece.GetPoints()
    figures["moved here"] = sum(1 for i in range(moved.GetNumberOfPoints())
                                if moved.GetPoint(i) != before.GetPoint(i))
    dataset = piece.GetActualMemorySize() / 1024.0
    print(f"rank {rank}: piece {piece.GetNumberOfPoints()} points ({dataset:.0f} MB; "
          f"{sphere_rss:.0f} MB to generate); growth at setup {setup:.0f} MB, after "
          f"{move_count} moves {moves:.0f} MB ({moves / dataset:.2f} of the piece, "
          f"{moves / sphere_rss:.2f} of its generation); peak {rss_mb('VmHWM:'):.0f} MB; "
          f"setup {setup_seconds:.2f} s, "
          f"a move {move_ms:.1f} ms; the first "
          f"rank's edit: {figures}", flush=True)
    gathered, region = figures["NumberOfGatheredPoints"], figures["NumberOfROIVertices"]
    if rank == 0 and not (region > 0 and gathered <= 4 * region and
                          (roi > 0.05 or gathered <= 0.05 * theta * phi)):
        sys.exit(f"FAILED: the first rank gathered {gathered} points for a region of {region}")


if move_count >= 0:
    edit()
