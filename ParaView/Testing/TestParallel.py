"""pvbatch, serial or under mpiexec, or pvpython connected to a pvserver: edit a real mesh split
into pieces across the ranks and write every output point, its normal and its EditRole to a
file. With LAPLACIAN_PARALLEL_SELECTION=1 the handle is a ParaView selection (a threshold on
the x coordinate, the same points on every rank) instead of HandleCenter and HandleRadius.
With LAPLACIAN_PARALLEL_SOLVER=MUMPS or =limit, runs with several ranks factor across them.
MESH "sphere" edits ParaView's sphere source on its seam instead of a file.

    [mpiexec -np 2] pvbatch TestParallel.py PLUGIN POINTS.txt MESH
    pvpython TestParallel.py PLUGIN POINTS.txt MESH SERVER_PORT
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from paraview import servermanager  # noqa: E402
from paraview.simple import Connect, LoadPlugin  # noqa: E402

if len(sys.argv) > 4:
    Connect("localhost", int(sys.argv[4]))
    LoadPlugin(sys.argv[1], remote=True)  # the server runs the filter
LoadPlugin(sys.argv[1], remote=False)
from paraview.simple import (ExtractSurface, GenerateSurfaceNormals, OpenDataFile,  # noqa: E402
                             RedistributeDataSet, Sphere)
import paraview.simple as simple  # noqa: E402

if sys.argv[3] == "sphere":
    # ParaView's sphere source: each rank generates a slice, and the slices repeat their seam
    # points a few ulps apart (sin(2 pi) is -2.4e-16, not 0). The handle sits on that seam.
    mesh = Sphere(ThetaResolution=64, PhiResolution=48, Radius=0.5)
else:
    # The mesh is read on the first rank and redistributed: each rank gets a piece, and the
    # pieces repeat their shared boundary points, as ParaView's parallel pipelines do.
    mesh = ExtractSurface(Input=RedistributeDataSet(Input=OpenDataFile(sys.argv[3])))
# Point normals (one per point, no splitting), which the edit must refresh on every rank.
mesh = GenerateSurfaceNormals(Input=mesh, Splitting=0, Consistency=0)
bounds = servermanager.Fetch(mesh).GetBounds()
size = max(bounds[1] - bounds[0], bounds[3] - bounds[2], bounds[5] - bounds[4])
deform = simple.LaplacianDeformation(Input=mesh)
deform.HandleCenter = [bounds[1], 0.5 * (bounds[2] + bounds[3]), 0.5 * (bounds[4] + bounds[5])]
deform.HandleRadius = 0.05 * size
if os.environ.get("LAPLACIAN_PARALLEL_SELECTION") == "1":
    # Each rank labels the selection on its own piece; the labels travel with the pieces.
    deform.Input = simple.Calculator(Input=mesh, ResultArrayName="X", Function="coordsX")
    deform.Selection = simple.ThresholdSelectionSource(
        FieldType="POINT", ArrayName="X", Thresholds=[bounds[1] - 0.05 * size, bounds[1]])
deform.ROIRadius = 0.45 * size
ranks = servermanager.ActiveConnection.GetNumberOfDataPartitions()
# LAPLACIAN_PARALLEL_SOLVER: with several ranks, "MUMPS" factors across them, and "limit" does
# too because CHOLMOD's factor would exceed a 1 kB MaximumFactorMemory.
across = ranks > 1 and os.environ.get("LAPLACIAN_PARALLEL_SOLVER", "")
if across == "MUMPS":
    deform.Solver = "MUMPS"
elif across == "limit":
    deform.MaximumFactorMemory = 0.001
rest = servermanager.Fetch(mesh)


def check_and_write(edited, path):
    """Writes every output point, its normal and its EditRole; checks the selection's handle."""
    normals = edited.GetPointData().GetNormals()
    roles = edited.GetPointData().GetArray("EditRole")
    if normals is None or roles is None:
        sys.exit("FAILED: the output has no point normals or no EditRole")
    if os.environ.get("LAPLACIAN_PARALLEL_SELECTION") == "1":
        # The handle is exactly the selection: the rest x of every output point is in the input.
        selected = sorted(rest.GetPoint(i) for i in range(rest.GetNumberOfPoints())
                          if rest.GetPoint(i)[0] >= bounds[1] - 0.05 * size)
        handles = sorted(rest.GetPoint(i) for i in range(edited.GetNumberOfPoints())
                         if roles.GetTuple1(i) == 3)  # ROLE_HANDLE
        if not selected or selected != handles:
            sys.exit(f"FAILED: {len(handles)} handle points for {len(selected)} selected ones")
    with open(path, "w") as points:
        for i in range(edited.GetNumberOfPoints()):
            values = edited.GetPoint(i) + normals.GetTuple3(i) + (roles.GetTuple1(i),)
            points.write("%.17g %.17g %.17g %.9g %.9g %.9g %d\n" % values)


# Every rotation mode, each with two handle moves: the second must reuse the gathered part and
# the factor. The None mode and the implicit one without the rigid correction are affine in the
# handle maps: their moves send the maps alone, and each rank places its own points.
base, extension = os.path.splitext(sys.argv[2])
modes = {"none": ("None", 1), "explicit": ("Explicit", 1), "implicit": ("Implicit", 1),
         "implicit-linear": ("Implicit", 0), "arap": ("As rigid as possible", 1)}
for short, (mode, preserve_scale) in modes.items():
    deform.RotationMode = mode
    deform.PreserveDetailScale = preserve_scale
    deform.HandleTranslation = [0.1 * size, 0.05 * size, 0.0]
    deform.UpdatePipeline()
    deform.UpdatePropertyInformation()
    factorizations = deform.GetProperty("NumberOfFactorizations").GetData()
    deform.HandleTranslation = [0.15 * size, 0.05 * size, 0.02 * size]
    deform.UpdatePipeline()
    deform.UpdatePropertyInformation()
    if deform.GetProperty("NumberOfFactorizations").GetData() != factorizations:
        sys.exit(f"FAILED: {mode}: the second handle move refactored")
    if bool(across) != bool(deform.GetProperty("FactoredAcrossProcesses").GetData()):
        sys.exit(f"FAILED: {mode}: the factor is {'not ' if across else ''}across the ranks")
    edited = servermanager.Fetch(deform)  # all pieces, appended on the first rank
    check_and_write(edited, f"{base}-{short}{extension}")
    gathered = deform.GetProperty("NumberOfGatheredPoints").GetData()
    print(f"{mode}: {edited.GetNumberOfPoints()} points from {ranks} rank(s), "
          f"{gathered} gathered for the edit", flush=True)
