// Small meshes and maps the VTK-free unit tests build their cases from.
#ifndef NumericsTestMeshes_h
#define NumericsTestMeshes_h

#include "SurfaceMesh.h"
#include "Types.h"

#include <cstdint>
#include <functional>
#include <vector>

namespace LaplacianEditing
{
namespace Testing
{
// A triangulated grid over [0, width] x [0, 1] with `nx` x `ny` quads, lifted by `height`.
inline SurfaceMesh MakeGrid(int nx, int ny, double width = 1.0,
  const std::function<double(double, double)>& height = nullptr, double xOffset = 0.0)
{
  std::vector<Vector3> points;
  for (int j = 0; j <= ny; ++j)
  {
    for (int i = 0; i <= nx; ++i)
    {
      const double x = width * i / nx;
      const double y = static_cast<double>(j) / ny;
      points.emplace_back(x + xOffset, y, height ? height(x, y) : 0.0);
    }
  }
  std::vector<std::int64_t> offsets(1, 0);
  std::vector<std::int64_t> connectivity;
  for (int j = 0; j < ny; ++j)
  {
    for (int i = 0; i < nx; ++i)
    {
      const std::int64_t a = j * (nx + 1) + i;
      connectivity.insert(connectivity.end(), { a, a + 1, a + nx + 2, a + nx + 1 });
      offsets.push_back(static_cast<std::int64_t>(connectivity.size()));
    }
  }
  return SurfaceMesh::FromPolygons(points, offsets, connectivity, true);
}

inline AffineMap Translation(const Vector3& t)
{
  AffineMap map = AffineMap::Identity();
  map.col(3) = t;
  return map;
}
}
}

#endif
