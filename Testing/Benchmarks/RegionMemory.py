"""Memory of an edit against the size of the input, in one process.

    RegionMemory.py [THETA PHI]    (default 2000 1002: a sphere of 2M points, 4M triangles)

Edits a region of about 4k vertices and prints the process growth at setup and after ten
handle moves, as a fraction of the dataset's own memory. Needs PYTHONPATH as in the README.
"""
import sys
import laplacianediting
from vtkmodules.vtkFiltersSources import vtkSphereSource


def rss_mb():
    with open("/proc/self/status") as status:
        for line in status:
            if line.startswith("VmRSS:"):
                return int(line.split()[1]) / 1024.0


sphere = vtkSphereSource()
theta, phi = (int(a) for a in sys.argv[1:3]) if len(sys.argv) > 2 else (2000, 1002)
sphere.SetThetaResolution(theta)
sphere.SetPhiResolution(phi)
sphere.Update()
mesh = sphere.GetOutput()
dataset_mb = mesh.GetActualMemorySize() / 1024.0
base = rss_mb()
deform = laplacianediting.vtkLaplacianDeformationFilter()
deform.SetInputData(mesh)
deform.SetRadiusUnitsToDiagonalFraction()
deform.SetHandleCenter(0.5, 0, 0)
deform.SetHandleRadius(0.01)
deform.SetROIRadius(0.034)
deform.Update()
setup = rss_mb() - base
for k in range(1, 11):
    deform.SetHandleTranslation(0.002 * k, 0, 0)
    deform.Update()
moves = rss_mb() - base
print(f"points {mesh.GetNumberOfPoints()} cells {mesh.GetNumberOfCells()} dataset {dataset_mb:.0f} MB; "
      f"ROI {deform.GetNumberOfROIVertices()}; growth at setup {setup:.0f} MB ({setup / dataset_mb:.2f} of the dataset), "
      f"after ten moves {moves:.0f} MB ({moves / dataset_mb:.2f}); factorizations {deform.GetNumberOfFactorizations()}; "
      f"surface graph {deform.GetNumberOfSurfaceVertices()} vertices")
