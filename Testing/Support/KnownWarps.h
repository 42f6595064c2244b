// Landmark warps with a known answer, shared by the landmark warp's benchmark, tests and
// pictures: a motion of space applied to the whole surface gives the true shape, and landmarks
// sampled on the surface, moved by the same motion, are what a warp is given.
//  - articulated: Armadillo.ply's two arms (beyond |x| = 38) swung 40 degrees about the
//    vertical through their shoulders ((+-38, 70, 0)), each blended in over a band of 2.5% of
//    the diagonal;
//  - hinge: stanford-bunny.obj's top 40% (by height) turned 50 degrees about the z axis
//    through its hinge, blended over a band of 5% of the diagonal;
//  - bend: bumps.obj, the sheet (in x and z, bumps up in y) rolled up about the z axis, its
//    first 30% (by x) staying, the rest bending at a constant rate, 90 degrees in all.
// The part that should stay is where the motion is the identity.
#ifndef KnownWarps_h
#define KnownWarps_h

#include "MeshReader.h"

#include "vtkIdList.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"

#include <array>
#include <cmath>
#include <functional>
#include <random>
#include <string>
#include <vector>

namespace KnownWarps
{
using Motion = std::function<void(const double* p, double* q)>;

struct Warp
{
  std::string Name;
  vtkSmartPointer<vtkPolyData> Mesh; // double-precision points
  Motion Map;
  std::function<bool(const double* p)> Stays;
};

// `count` random points on the surface: inside random triangles, at random weights.
inline vtkSmartPointer<vtkPoints> SurfacePoints(vtkPolyData* mesh, vtkIdType count, unsigned seed = 3)
{
  std::mt19937 random(seed);
  std::uniform_int_distribution<vtkIdType> cell(0, mesh->GetNumberOfCells() - 1);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  auto points = vtkSmartPointer<vtkPoints>::New();
  points->SetDataTypeToDouble();
  vtkNew<vtkIdList> corners;
  while (points->GetNumberOfPoints() < count)
  {
    mesh->GetCellPoints(cell(random), corners);
    if (corners->GetNumberOfIds() != 3)
    {
      continue;
    }
    double a = unit(random), b = unit(random), p[3][3], x[3];
    if (a + b > 1.0)
    {
      a = 1.0 - a;
      b = 1.0 - b;
    }
    for (int c = 0; c < 3; ++c)
    {
      mesh->GetPoint(corners->GetId(c), p[c]);
    }
    for (int k = 0; k < 3; ++k)
    {
      x[k] = a * p[0][k] + b * p[1][k] + (1.0 - a - b) * p[2][k];
    }
    points->InsertNextPoint(x);
  }
  return points;
}

// The points moved by `map`.
inline vtkSmartPointer<vtkPoints> Moved(vtkPoints* points, const Motion& map)
{
  auto moved = vtkSmartPointer<vtkPoints>::New();
  moved->SetDataTypeToDouble();
  moved->SetNumberOfPoints(points->GetNumberOfPoints());
  for (vtkIdType i = 0; i < points->GetNumberOfPoints(); ++i)
  {
    double p[3], q[3];
    points->GetPoint(i, p);
    map(p, q);
    moved->SetPoint(i, q);
  }
  return moved;
}

// A mesh with double-precision points: warps are checked finer than float points can hold.
inline vtkSmartPointer<vtkPolyData> LoadDouble(const std::string& path)
{
  std::string error;
  auto mesh = MeshReader::Read(path, error);
  if (!mesh)
  {
    return nullptr;
  }
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->DeepCopy(mesh->GetPoints());
  mesh->SetPoints(points);
  return mesh;
}

inline double Smoothstep(double t)
{
  t = std::min(1.0, std::max(0.0, t));
  return t * t * (3.0 - 2.0 * t);
}

// p turned by `angle` radians about the axis (0 x, 1 y, 2 z) through `pivot`.
inline void Turn(const double* p, const double* pivot, int axis, double angle, double* q)
{
  const int a = (axis + 1) % 3, b = (axis + 2) % 3;
  const double u = p[a] - pivot[a], v = p[b] - pivot[b];
  q[axis] = p[axis];
  q[a] = pivot[a] + std::cos(angle) * u - std::sin(angle) * v;
  q[b] = pivot[b] + std::sin(angle) * u + std::cos(angle) * v;
}

inline const double Degree = 3.14159265358979323846 / 180.0;

inline Warp Articulated(const std::string& dataDir)
{
  Warp warp{ "articulated", LoadDouble(dataDir + "/Armadillo.ply"), nullptr, nullptr };
  const double band = 0.025 * warp.Mesh->GetLength(), shoulder = 38.0;
  warp.Map = [band, shoulder](const double* p, double* q) {
    for (int k = 0; k < 3; ++k)
    {
      q[k] = p[k];
    }
    for (double side : { -1.0, 1.0 })
    {
      const double pivot[3] = { side * shoulder, 70.0, 0.0 }, out = side * p[0] - shoulder;
      double turned[3];
      Turn(p, pivot, 1, -side * 40.0 * Degree, turned);
      const double w = Smoothstep((out + band) / (2.0 * band));
      for (int k = 0; k < 3; ++k)
      {
        q[k] += w * (turned[k] - p[k]);
      }
    }
  };
  warp.Stays = [band, shoulder](const double* p) { return std::abs(p[0]) - shoulder < -band; };
  return warp;
}

inline Warp Hinge(const std::string& dataDir)
{
  Warp warp{ "hinge", LoadDouble(dataDir + "/stanford-bunny.obj"), nullptr, nullptr };
  double bounds[6];
  warp.Mesh->GetBounds(bounds);
  const double band = 0.05 * warp.Mesh->GetLength(), cut = bounds[2] + 0.6 * (bounds[3] - bounds[2]);
  const std::array<double, 3> pivot = { 0.5 * (bounds[0] + bounds[1]), cut,
    0.5 * (bounds[4] + bounds[5]) };
  warp.Map = [band, cut, pivot](const double* p, double* q) {
    double turned[3];
    Turn(p, pivot.data(), 2, 50.0 * Degree, turned);
    const double w = Smoothstep((p[1] - (cut - band)) / (2.0 * band));
    for (int k = 0; k < 3; ++k)
    {
      q[k] = p[k] + w * (turned[k] - p[k]);
    }
  };
  warp.Stays = [band, cut](const double* p) { return p[1] < cut - band; };
  return warp;
}

inline Warp Bend(const std::string& dataDir)
{
  Warp warp{ "bend", LoadDouble(dataDir + "/bumps.obj"), nullptr, nullptr };
  double bounds[6];
  warp.Mesh->GetBounds(bounds);
  const double start = bounds[0] + 0.3 * (bounds[1] - bounds[0]);
  const double rate = 90.0 * Degree / (bounds[1] - start);
  // The sheet spans x and z, its bumps rise in y; the bent part rolls up onto a circle of
  // radius 1 / rate above the sheet's base plane.
  const double radius = 1.0 / rate, base = bounds[2];
  warp.Map = [start, rate, radius, base](const double* p, double* q) {
    q[2] = p[2];
    if (p[0] <= start)
    {
      q[0] = p[0];
      q[1] = p[1];
      return;
    }
    const double angle = rate * (p[0] - start), r = radius - (p[1] - base);
    q[0] = start + r * std::sin(angle);
    q[1] = base + radius - r * std::cos(angle);
  };
  warp.Stays = [start](const double* p) { return p[0] <= start; };
  return warp;
}

/// Spot's hind part turned 30 degrees about the vertical axis through its middle, in a wide
/// smooth band: a closed surface and a warp whose displacement field stays invertible, for the
/// image warps (an image is resampled through the warp's inverse).
inline Warp TurnedHead(const std::string& dataDir)
{
  Warp warp{ "turned head", LoadDouble(dataDir + "/spot.obj"), nullptr, nullptr };
  double bounds[6];
  warp.Mesh->GetBounds(bounds);
  const double band = 0.15 * warp.Mesh->GetLength();
  const double neck = bounds[0] + 0.4 * (bounds[1] - bounds[0]);
  const std::array<double, 3> pivot = { neck, 0.5 * (bounds[2] + bounds[3]),
    0.5 * (bounds[4] + bounds[5]) };
  warp.Map = [band, neck, pivot](const double* p, double* q) {
    double turned[3];
    Turn(p, pivot.data(), 1, 30.0 * Degree, turned);
    const double w = Smoothstep(((neck + band) - p[0]) / (2.0 * band));
    for (int k = 0; k < 3; ++k)
    {
      q[k] = p[k] + w * (turned[k] - p[k]);
    }
  };
  warp.Stays = [band, neck](const double* p) { return p[0] > neck + band; };
  return warp;
}

/// The benchmark's warps.
inline std::vector<Warp> All(const std::string& dataDir)
{
  return { Articulated(dataDir), Hinge(dataDir), Bend(dataDir) };
}
} // namespace KnownWarps

#endif
