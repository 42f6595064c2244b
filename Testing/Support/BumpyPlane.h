// The test shape of the paper's Fig. 6 (top): a triangulated unit square in the xy plane with a
// regular grid of bumpsPerSide x bumpsPerSide smooth bumps, each a compactly supported cosine cap
// of radius bumpRadius and height bumpHeight. A mesh that needs no data files, for the tests,
// the benchmarks and the C++ examples (Examples/Python/bumpy_plane.py makes the same in Python).
#ifndef LaplacianEditing_Testing_BumpyPlane_h
#define LaplacianEditing_Testing_BumpyPlane_h

#include "vtkCellArray.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"

#include <algorithm>
#include <cmath>

/// The shape's parameters, with the paper's defaults.
struct BumpyPlaneShape
{
  int Resolution = 80; // quads per side, each split into two triangles
  int BumpsPerSide = 5;
  double BumpHeight = 0.04;
  double BumpRadius = 0.06;

  /// Centre (x, y) of bump `b` of BumpsPerSide^2, row by row.
  void BumpCenter(int b, double center[2]) const
  {
    const int sides = std::max(this->BumpsPerSide, 1);
    center[0] = (b % sides + 0.5) / sides;
    center[1] = (b / sides + 0.5) / sides;
  }

  vtkSmartPointer<vtkPolyData> Make() const
  {
    const int n = this->Resolution;
    vtkNew<vtkPoints> points;
    points->SetDataTypeToDouble();
    points->SetNumberOfPoints((n + 1) * (n + 1));
    for (int j = 0; j <= n; ++j)
    {
      for (int i = 0; i <= n; ++i)
      {
        const double x = static_cast<double>(i) / n;
        const double y = static_cast<double>(j) / n;
        double z = 0.0;
        for (int b = 0; b < this->BumpsPerSide * this->BumpsPerSide; ++b)
        {
          double c[2];
          this->BumpCenter(b, c);
          const double r = std::hypot(x - c[0], y - c[1]) / this->BumpRadius;
          if (r < 1.0)
          {
            z += this->BumpHeight * 0.5 * (1.0 + std::cos(vtkMath::Pi() * r));
          }
        }
        points->SetPoint(j * (n + 1) + i, x, y, z);
      }
    }
    vtkNew<vtkCellArray> triangles;
    triangles->AllocateExact(2 * n * n, 6 * n * n);
    for (int j = 0; j < n; ++j)
    {
      for (int i = 0; i < n; ++i)
      {
        const vtkIdType a = j * (n + 1) + i;
        const vtkIdType lower[3] = { a, a + 1, a + n + 2 };
        const vtkIdType upper[3] = { a, a + n + 2, a + n + 1 };
        triangles->InsertNextCell(3, lower);
        triangles->InsertNextCell(3, upper);
      }
    }
    auto plane = vtkSmartPointer<vtkPolyData>::New();
    plane->SetPoints(points);
    plane->SetPolys(triangles);
    return plane;
  }
};

/// The default shape at `resolution` quads per side.
inline vtkSmartPointer<vtkPolyData> MakeBumpyPlane(int resolution = 80)
{
  BumpyPlaneShape shape;
  shape.Resolution = resolution;
  return shape.Make();
}

#endif
