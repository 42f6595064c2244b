#include "LandmarkBinder.h"

#include "SurfaceMesh.h"
#include "SurfaceAdapter.h"

#include "vtkCellArray.h"
#include "vtkDoubleArray.h"
#include "vtkIdTypeArray.h"
#include "vtkNew.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkStaticCellLocator.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace le = LaplacianEditing;

namespace LaplacianEditing
{
namespace Pipeline
{

namespace
{
// Barycentric weights of `p` (in the triangle's plane) on corners a, b, c; the nearest corner
// alone where the triangle has no area.
std::array<double, 3> Barycentric(
  const le::Vector3& p, const le::Vector3& a, const le::Vector3& b, const le::Vector3& c)
{
  const le::Vector3 ab = b - a, ac = c - a, ap = p - a;
  const double d00 = ab.dot(ab), d01 = ab.dot(ac), d11 = ac.dot(ac);
  const double d20 = ap.dot(ab), d21 = ap.dot(ac);
  const double denominator = d00 * d11 - d01 * d01;
  if (!(denominator > 1e-14 * d00 * d11))
  {
    const double distances[3] = { (p - a).squaredNorm(), (p - b).squaredNorm(), (p - c).squaredNorm() };
    const int nearest = static_cast<int>(std::min_element(distances, distances + 3) - distances);
    std::array<double, 3> weights = { { 0.0, 0.0, 0.0 } };
    weights[nearest] = 1.0;
    return weights;
  }
  const double v = (d11 * d20 - d01 * d21) / denominator;
  const double w = (d00 * d21 - d01 * d20) / denominator;
  return { { 1.0 - v - w, v, w } };
}

// The surface's triangles in the core's frame, for a locator.
vtkNew<vtkPolyData> TrianglesOf(const le::SurfaceMesh& mesh)
{
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(mesh.GetNumberOfVertices());
  for (int v = 0; v < mesh.GetNumberOfVertices(); ++v)
  {
    points->SetPoint(v, mesh.GetPositions()[v].data());
  }
  vtkNew<vtkIdTypeArray> connectivity;
  connectivity->SetNumberOfValues(3 * static_cast<vtkIdType>(mesh.GetNumberOfTriangles()));
  for (int t = 0; t < mesh.GetNumberOfTriangles(); ++t)
  {
    for (int c = 0; c < 3; ++c)
    {
      connectivity->SetValue(3 * t + c, mesh.GetTriangles()[t][c]);
    }
  }
  vtkNew<vtkCellArray> triangles;
  triangles->SetData(3, connectivity);
  vtkNew<vtkPolyData> surface;
  surface->SetPoints(points);
  surface->SetPolys(triangles);
  return surface;
}

bool IsFinite(const double p[3])
{
  return std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2]);
}
}

std::string LandmarkBinder::Update(vtkPoints* sources,
  const SurfaceAdapter& surface, double maximumDistance, bool& rebound)
{
  rebound = false;
  const le::SurfaceMesh& mesh = *surface.GetMesh();
  if (this->Points && this->BoundMesh == surface.GetMesh() && this->BoundSources == sources &&
    this->BoundTime == sources->GetMTime() && this->BoundDistance == maximumDistance)
  {
    return {};
  }
  this->Points.reset();
  const vtkIdType count = sources->GetNumberOfPoints();
  vtkNew<vtkPolyData> triangles = TrianglesOf(mesh);
  vtkNew<vtkStaticCellLocator> locator;
  locator->SetDataSet(triangles);
  locator->BuildLocator();
  auto points = std::make_shared<std::vector<le::SurfacePoint>>(count);
  this->Offsets.resize(count, 3);
  this->Distances.resize(count);
  for (vtkIdType i = 0; i < count; ++i)
  {
    double source[3], closest[3], squared = 0.0;
    sources->GetPoint(i, source);
    if (!IsFinite(source))
    {
      std::ostringstream message;
      message << "Source landmark " << i << " has a NaN or infinite coordinate.";
      return message.str();
    }
    const le::Vector3 normalized = surface.Normalize(source);
    vtkIdType cell = -1;
    int subId = 0;
    locator->FindClosestPoint(normalized.data(), closest, cell, subId, squared);
    const double distance = std::sqrt(squared) / surface.GetScale();
    if (cell < 0 || distance > maximumDistance)
    {
      std::ostringstream message;
      message << "Source landmark " << i << " lies on no component of the surface: it is "
              << distance << " from the nearest surface point, more than MaximumBindingDistance ("
              << maximumDistance << " in mesh units).";
      return message.str();
    }
    const auto& corners = mesh.GetTriangles()[cell];
    const le::Vector3 projection(closest[0], closest[1], closest[2]);
    (*points)[i].Vertices = corners;
    (*points)[i].Weights = Barycentric(projection, mesh.GetPositions()[corners[0]],
      mesh.GetPositions()[corners[1]], mesh.GetPositions()[corners[2]]);
    this->Offsets.row(i) = (normalized - projection).transpose();
    this->Distances[i] = distance;
  }
  // An input point of each corner vertex (a merged vertex has several), to read the output.
  std::vector<vtkIdType> pointOfVertex(mesh.GetNumberOfVertices(), -1);
  for (std::size_t k = 0; k < surface.GetInputPoints().size(); ++k)
  {
    pointOfVertex[mesh.GetVertexOfPoint()[k]] = surface.GetInputPoints()[k];
  }
  this->CornerPoints.resize(3 * count);
  for (vtkIdType i = 0; i < count; ++i)
  {
    for (int c = 0; c < 3; ++c)
    {
      this->CornerPoints[3 * i + c] = pointOfVertex[(*points)[i].Vertices[c]];
    }
  }
  this->Points = points;
  ++this->Version;
  this->BoundMesh = surface.GetMesh();
  this->BoundSources = sources;
  this->BoundTime = sources->GetMTime();
  this->BoundDistance = maximumDistance;
  rebound = true;
  return {};
}

std::vector<int> LandmarkBinder::GetSeeds() const
{
  std::vector<int> seeds;
  for (const le::SurfacePoint& point : *this->Points)
  {
    seeds.push_back(point.Vertices[0]);
  }
  std::sort(seeds.begin(), seeds.end());
  seeds.erase(std::unique(seeds.begin(), seeds.end()), seeds.end());
  return seeds;
}

std::string LandmarkBinder::Targets(
  vtkPoints* targets, const SurfaceAdapter& surface, le::PointTargets& points) const
{
  const vtkIdType count = targets->GetNumberOfPoints();
  points.Targets.resize(count, 3);
  for (vtkIdType i = 0; i < count; ++i)
  {
    double target[3];
    targets->GetPoint(i, target);
    if (!IsFinite(target))
    {
      std::ostringstream message;
      message << "Target landmark " << i << " has a NaN or infinite coordinate.";
      return message.str();
    }
    points.Targets.row(i) = surface.Normalize(target).transpose() - this->Offsets.row(i);
  }
  return {};
}

void LandmarkBinder::Misses(vtkPoints* output,
  const SurfaceAdapter& surface, vtkPoints* targets, vtkDoubleArray* misses) const
{
  const vtkIdType count = static_cast<vtkIdType>(this->Points->size());
  misses->SetNumberOfComponents(1);
  misses->SetNumberOfTuples(count);
  for (vtkIdType i = 0; i < count; ++i)
  {
    const le::SurfacePoint& point = (*this->Points)[i];
    le::Vector3 end = this->Offsets.row(i).transpose() / surface.GetScale();
    for (int c = 0; c < 3; ++c)
    {
      double corner[3];
      output->GetPoint(this->CornerPoints[3 * i + c], corner);
      end += point.Weights[c] * le::Vector3(corner[0], corner[1], corner[2]);
    }
    double target[3];
    targets->GetPoint(i, target);
    misses->SetValue(i, (end - le::Vector3(target[0], target[1], target[2])).norm());
  }
}
}
}
