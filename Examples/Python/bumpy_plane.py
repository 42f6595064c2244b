"""The test shape of the paper's Fig. 6 (top), as a vtkPolyData: a triangulated unit square in
the xy plane with a regular grid of smooth bumps (compactly supported cosine caps). The examples
and the Python tests edit it when no mesh is given (Testing/Support/BumpyPlane.h in C++)."""
import numpy as np
from vtkmodules.util.numpy_support import numpy_to_vtk, numpy_to_vtkIdTypeArray
from vtkmodules.vtkCommonCore import vtkPoints
from vtkmodules.vtkCommonDataModel import vtkCellArray, vtkPolyData


def bumpy_plane(resolution=80, bumps_per_side=5, bump_height=0.04, bump_radius=0.06):
    """`resolution` quads per side, each split into two triangles."""
    n = resolution
    x, y = np.meshgrid(np.arange(n + 1) / n, np.arange(n + 1) / n)
    z = np.zeros_like(x)
    for b in range(bumps_per_side * bumps_per_side):
        cx, cy = (b % bumps_per_side + 0.5) / bumps_per_side, (b // bumps_per_side + 0.5) / bumps_per_side
        r = np.hypot(x - cx, y - cy) / bump_radius
        z += np.where(r < 1.0, bump_height * 0.5 * (1.0 + np.cos(np.pi * r)), 0.0)
    points = vtkPoints()
    points.SetData(numpy_to_vtk(np.column_stack([x.ravel(), y.ravel(), z.ravel()]), deep=True))
    a = (np.arange(n)[None, :] + (n + 1) * np.arange(n)[:, None]).ravel()
    lower = np.column_stack([a, a + 1, a + n + 2])
    upper = np.column_stack([a, a + n + 2, a + n + 1])
    corners = np.stack([lower, upper], axis=1).reshape(-1, 3)
    triangles = vtkCellArray()
    triangles.SetData(3, numpy_to_vtkIdTypeArray(corners.ravel().astype(np.int64), deep=True))
    plane = vtkPolyData()
    plane.SetPoints(points)
    plane.SetPolys(triangles)
    return plane
