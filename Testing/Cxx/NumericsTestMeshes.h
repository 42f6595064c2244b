// Small meshes and maps the VTK-free unit tests build their cases from.
#ifndef NumericsTestMeshes_h
#define NumericsTestMeshes_h

#include "SurfaceMesh.h"
#include "Types.h"

#include <cmath>
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

// An open tube along z: `rings` circles of `sides` vertices, radius 0.2, length 1.
inline SurfaceMesh MakeTube(int sides, int rings)
{
  std::vector<Vector3> points;
  const double pi = std::acos(-1.0);
  for (int r = 0; r < rings; ++r)
  {
    for (int s = 0; s < sides; ++s)
    {
      const double angle = 2.0 * pi * s / sides;
      points.emplace_back(0.2 * std::cos(angle), 0.2 * std::sin(angle), static_cast<double>(r) / (rings - 1));
    }
  }
  std::vector<std::int64_t> offsets(1, 0), connectivity;
  for (int r = 0; r + 1 < rings; ++r)
  {
    for (int s = 0; s < sides; ++s)
    {
      const std::int64_t a = r * sides + s, b = r * sides + (s + 1) % sides;
      connectivity.insert(connectivity.end(), { a, b, b + sides, a + sides });
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
