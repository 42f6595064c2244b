#include "SmoothNormals.h"

#include <functional>
#include <queue>
#include <utility>

namespace LaplacianEditing
{
void SmoothNormals::Build(const SurfaceMesh& mesh, const std::vector<int>& vertices, double radius)
{
  this->Radius = radius;
  const auto& positions = mesh.GetPositions();
  const int n = static_cast<int>(vertices.size());

  // Extended index: support vertices first (in order of discovery), then their one-ring.
  std::vector<int> extended(mesh.GetNumberOfVertices(), -1);
  std::vector<int> extendedVertices;
  auto extend = [&](int v) {
    if (extended[v] < 0)
    {
      extended[v] = static_cast<int>(extendedVertices.size());
      extendedVertices.push_back(v);
    }
    return extended[v];
  };

  // Bounded Dijkstra from each ROI vertex, reusing one distance array.
  std::vector<double> distance(mesh.GetNumberOfVertices(), radius);
  std::vector<int> touched;
  std::vector<Eigen::Triplet<double>> triplets;
  using Entry = std::pair<double, int>;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> queue;
  for (int row = 0; row < n; ++row)
  {
    const int source = vertices[row];
    distance[source] = 0.0;
    touched.assign(1, source);
    queue.emplace(0.0, source);
    while (!queue.empty())
    {
      const auto [d, v] = queue.top();
      queue.pop();
      if (d > distance[v])
      {
        continue;
      }
      const double t = d / radius;
      triplets.emplace_back(row, extend(v), 2.0 * t * t * t - 3.0 * t * t + 1.0);
      for (const int* w = mesh.NeighborsBegin(v); w != mesh.NeighborsEnd(v); ++w)
      {
        const double candidate = d + (positions[*w] - positions[v]).norm();
        if (candidate < distance[*w])
        {
          if (distance[*w] == radius)
          {
            touched.push_back(*w);
          }
          distance[*w] = candidate;
          queue.emplace(candidate, *w);
        }
      }
    }
    for (int v : touched)
    {
      distance[v] = radius;
    }
  }
  this->NumberOfSupportVertices = static_cast<int>(extendedVertices.size());
  this->Weights.resize(n, this->NumberOfSupportVertices);
  this->Weights.setFromTriplets(triplets.begin(), triplets.end());

  // Area normals of the support need the triangles around it, and their corners.
  std::vector<char> seen(mesh.GetNumberOfTriangles(), 0);
  this->Triangles.clear();
  for (int s = 0; s < this->NumberOfSupportVertices; ++s)
  {
    const int v = extendedVertices[s];
    for (const int* t = mesh.TrianglesBegin(v); t != mesh.TrianglesEnd(v); ++t)
    {
      if (!seen[*t])
      {
        seen[*t] = 1;
        const auto& tri = mesh.GetTriangles()[*t];
        this->Triangles.push_back({ extend(tri[0]), extend(tri[1]), extend(tri[2]) });
      }
    }
  }

  std::vector<int> roiRow(mesh.GetNumberOfVertices(), -1);
  for (int row = 0; row < n; ++row)
  {
    roiRow[vertices[row]] = row;
  }
  this->ExtendedRoiRow.resize(extendedVertices.size());
  this->ExtendedRest.resize(static_cast<Eigen::Index>(extendedVertices.size()), 3);
  for (std::size_t e = 0; e < extendedVertices.size(); ++e)
  {
    this->ExtendedRoiRow[e] = roiRow[extendedVertices[e]];
    this->ExtendedRest.row(e) = positions[extendedVertices[e]].transpose();
  }
}

Positions SmoothNormals::Compute(const Positions& roiPositions) const
{
  Positions current = this->ExtendedRest;
  for (Eigen::Index e = 0; e < current.rows(); ++e)
  {
    if (this->ExtendedRoiRow[e] >= 0)
    {
      current.row(e) = roiPositions.row(this->ExtendedRoiRow[e]);
    }
  }
  // Area-weighted vertex normals (twice the area, which the normalization cancels).
  Positions areaNormals = Positions::Zero(this->NumberOfSupportVertices, 3);
  for (const auto& tri : this->Triangles)
  {
    const Eigen::RowVector3d n =
      (current.row(tri[1]) - current.row(tri[0])).cross(current.row(tri[2]) - current.row(tri[0]));
    for (int corner : tri)
    {
      if (corner < this->NumberOfSupportVertices)
      {
        areaNormals.row(corner) += n;
      }
    }
  }
  Positions normals = this->Weights * areaNormals;
  normals.rowwise().normalize();
  return normals;
}
}
