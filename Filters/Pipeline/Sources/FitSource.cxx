#include "FitSource.h"

#include "SurfaceAdapter.h"
#include "SurfaceMesh.h"

#include <algorithm>

namespace LaplacianEditing
{
namespace Pipeline
{
void FitSource::SetMatches(
  std::vector<vtkIdType> points, std::vector<std::array<double, 3>> targets, bool newPoints)
{
  this->MatchedPoints = std::move(points);
  this->MatchTargets = std::move(targets);
  if (newPoints)
  {
    ++this->Version;
  }
}

std::string FitSource::ChooseRegion(
  vtkPolyData* /*rest*/, const SurfaceAdapter& surface, RegionChoice& region)
{
  bool rebound = false;
  if (this->LandmarkSources)
  {
    const std::string error =
      this->Binder.Update(this->LandmarkSources, surface, this->MaximumBindingDistance, rebound);
    if (!error.empty())
    {
      return error;
    }
  }
  const SurfaceMesh& mesh = *surface.GetMesh();
  if (!this->Points || rebound || this->BuiltFor != this->Version)
  {
    std::vector<int> vertexOfPoint;
    for (std::size_t k = 0; k < surface.GetInputPoints().size(); ++k)
    {
      const vtkIdType id = surface.GetInputPoints()[k];
      vertexOfPoint.resize(std::max<std::size_t>(vertexOfPoint.size(), id + 1), -1);
      vertexOfPoint[id] = mesh.GetVertexOfPoint()[k];
    }
    auto points = std::make_shared<std::vector<SurfacePoint>>();
    this->MatchedVertices.clear();
    for (const vtkIdType id : this->MatchedPoints)
    {
      const int vertex = id < static_cast<vtkIdType>(vertexOfPoint.size()) ? vertexOfPoint[id] : -1;
      this->MatchedVertices.push_back(vertex);
      if (vertex >= 0)
      {
        SurfacePoint point;
        point.Vertices = { { vertex, vertex, vertex } };
        points->push_back(point);
      }
    }
    if (this->LandmarkSources)
    {
      for (SurfacePoint landmark : *this->Binder.GetPoints())
      {
        landmark.Pull = this->MatchedPoints.empty() ? 1.0 : this->LandmarkPull;
        points->push_back(landmark);
      }
    }
    this->Points = points;
    this->BuiltFor = this->Version;
    ++this->PointsVersion;
  }
  // Every component: a corner of each triangle seeds its own.
  region.Request.Selection = RegionRequest::Kind::Components;
  std::vector<int>& seeds = region.Request.Seeds;
  seeds.clear();
  for (const auto& triangle : mesh.GetTriangles())
  {
    seeds.push_back(triangle[0]);
  }
  std::sort(seeds.begin(), seeds.end());
  seeds.erase(std::unique(seeds.begin(), seeds.end()), seeds.end());
  region.Points = this->Points;
  region.PointsVersion = this->PointsVersion;
  region.PointWeight = this->Weight;
  region.FollowUnreferenced = this->FollowUnreferenced;
  return {};
}

std::string FitSource::ChooseMotions(
  const SurfaceAdapter& surface, const EditRegion& /*region*/, EditMotions& motions)
{
  motions.HasPoints = true;
  motions.Points.Exact = this->MatchedPoints.empty();
  Positions& targets = motions.Points.Targets;
  targets.resize(static_cast<Eigen::Index>(this->Points->size()), 3);
  Eigen::Index row = 0;
  for (std::size_t k = 0; k < this->MatchedPoints.size(); ++k)
  {
    if (this->MatchedVertices[k] >= 0)
    {
      targets.row(row++) = surface.Normalize(this->MatchTargets[k].data()).transpose();
    }
  }
  if (!this->LandmarkSources)
  {
    return {};
  }
  PointTargets landmarks;
  const std::string error = this->Binder.Targets(this->LandmarkTargets, surface, landmarks);
  if (error.empty())
  {
    targets.bottomRows(landmarks.Targets.rows()) = landmarks.Targets;
  }
  return error;
}
}
}
