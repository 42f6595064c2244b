#include "SurfaceMesh.h"

#include "CoincidentPoints.h"

#include <algorithm>
#include <tuple>
#include <limits>
#include <numeric>
#include <utility>

namespace LaplacianEditing
{
namespace
{
// Converts (item, key) pairs into compressed rows indexed by key.
void BuildCompressedRows(int numberOfRows, std::vector<std::pair<int, int>>& keyedItems,
  std::vector<int>& offsets, std::vector<int>& items)
{
  std::sort(keyedItems.begin(), keyedItems.end());
  keyedItems.erase(std::unique(keyedItems.begin(), keyedItems.end()), keyedItems.end());
  offsets.assign(numberOfRows + 1, 0);
  items.resize(keyedItems.size());
  for (std::size_t i = 0; i < keyedItems.size(); ++i)
  {
    ++offsets[keyedItems[i].first + 1];
    items[i] = keyedItems[i].second;
  }
  std::partial_sum(offsets.begin(), offsets.end(), offsets.begin());
}
}

SurfaceMesh SurfaceMesh::FromPolygons(const std::vector<Vector3>& points,
  const std::vector<std::int64_t>& offsets, const std::vector<std::int64_t>& connectivity,
  bool mergeCoincidentPoints)
{
  SurfaceMesh mesh;
  const int numberOfPoints = static_cast<int>(points.size());
  mesh.VertexOfPoint.resize(numberOfPoints);
  if (mergeCoincidentPoints)
  {
    std::vector<int> order(numberOfPoints);
    std::iota(order.begin(), order.end(), 0);
    auto lexicographic = [&points](int a, int b) {
      return std::lexicographical_compare(
        points[a].data(), points[a].data() + 3, points[b].data(), points[b].data() + 3);
    };
    std::sort(order.begin(), order.end(), lexicographic);
    CoincidentPoints merged(CoincidentPoints::RelativeTolerance, Vector3::Zero());
    for (int point : order)
    {
      int vertex = merged.Find(points[point]);
      if (vertex < 0)
      {
        vertex = static_cast<int>(mesh.Positions.size());
        mesh.Positions.push_back(points[point]);
        merged.Add(points[point], vertex);
      }
      mesh.VertexOfPoint[point] = vertex;
    }
  }
  else
  {
    mesh.Positions = points;
    std::iota(mesh.VertexOfPoint.begin(), mesh.VertexOfPoint.end(), 0);
  }

  for (std::size_t cell = 0; cell + 1 < offsets.size(); ++cell)
  {
    const std::int64_t begin = offsets[cell];
    const std::int64_t end = offsets[cell + 1];
    for (std::int64_t corner = begin + 1; corner + 1 < end; ++corner)
    {
      const std::array<int, 3> triangle = { mesh.VertexOfPoint[connectivity[begin]],
        mesh.VertexOfPoint[connectivity[corner]], mesh.VertexOfPoint[connectivity[corner + 1]] };
      if (triangle[0] != triangle[1] && triangle[1] != triangle[2] && triangle[0] != triangle[2])
      {
        mesh.Triangles.push_back(triangle);
      }
    }
  }
  mesh.OrientTriangles();
  mesh.BuildAdjacency();
  mesh.LabelComponents();
  return mesh;
}

void SurfaceMesh::BuildAdjacency()
{
  std::vector<std::pair<int, int>> edges;
  std::vector<std::pair<int, int>> incidences;
  edges.reserve(6 * this->Triangles.size());
  incidences.reserve(3 * this->Triangles.size());
  for (std::size_t t = 0; t < this->Triangles.size(); ++t)
  {
    const auto& tri = this->Triangles[t];
    for (int k = 0; k < 3; ++k)
    {
      edges.emplace_back(tri[k], tri[(k + 1) % 3]);
      edges.emplace_back(tri[(k + 1) % 3], tri[k]);
      incidences.emplace_back(tri[k], static_cast<int>(t));
    }
  }
  const int n = this->GetNumberOfVertices();
  BuildCompressedRows(n, edges, this->NeighborOffsets, this->Neighbors);
  BuildCompressedRows(n, incidences, this->TriangleOffsets, this->VertexTriangles);
}

namespace
{
// Per triangle, the triangles across its manifold edges, each with whether the two run the edge
// in the same direction (then one of them must flip).
std::vector<std::vector<std::pair<int, bool>>> ManifoldNeighbors(
  const std::vector<std::array<int, 3>>& triangles)
{
  // Directed edges (from, to, triangle), sorted so that the triangles of one undirected edge
  // are adjacent.
  struct Edge
  {
    int Low, High, Triangle;
    bool Forward; // the triangle runs the edge from Low to High
    bool operator<(const Edge& other) const
    {
      return std::tie(Low, High, Triangle) < std::tie(other.Low, other.High, other.Triangle);
    }
  };
  const int count = static_cast<int>(triangles.size());
  std::vector<Edge> edges;
  edges.reserve(3 * count);
  for (int t = 0; t < count; ++t)
  {
    for (int k = 0; k < 3; ++k)
    {
      const int a = triangles[t][k];
      const int b = triangles[t][(k + 1) % 3];
      edges.push_back({ std::min(a, b), std::max(a, b), t, a < b });
    }
  }
  std::sort(edges.begin(), edges.end());
  // Manifold edges only: pairs of triangles across each.
  std::vector<std::vector<std::pair<int, bool>>> across(count);
  for (std::size_t i = 0; i + 1 < edges.size(); ++i)
  {
    const Edge& e = edges[i];
    const Edge& f = edges[i + 1];
    const bool pair = e.Low == f.Low && e.High == f.High &&
      (i + 2 >= edges.size() || edges[i + 2].Low != e.Low || edges[i + 2].High != e.High) &&
      (i == 0 || edges[i - 1].Low != e.Low || edges[i - 1].High != e.High);
    if (pair)
    {
      across[e.Triangle].emplace_back(f.Triangle, e.Forward == f.Forward);
      across[f.Triangle].emplace_back(e.Triangle, e.Forward == f.Forward);
    }
  }
  return across;
}
}

void SurfaceMesh::OrientTriangles()
{
  // Flipping makes the triangles across each manifold edge run it oppositely: each patch
  // reachable across such edges is walked from a seed.
  const auto across = ManifoldNeighbors(this->Triangles);
  const int count = this->GetNumberOfTriangles();
  std::vector<int> flip(count, -1); // -1 unvisited, 0 keep, 1 flip
  std::vector<int> patch, stack;
  for (int seed = 0; seed < count; ++seed)
  {
    if (flip[seed] >= 0)
    {
      continue;
    }
    flip[seed] = 0;
    patch.assign(1, seed);
    stack.assign(1, seed);
    while (!stack.empty())
    {
      const int t = stack.back();
      stack.pop_back();
      for (const auto& [neighbor, sameDirection] : across[t])
      {
        if (flip[neighbor] < 0)
        {
          flip[neighbor] = flip[t] ^ static_cast<int>(sameDirection);
          patch.push_back(neighbor);
          stack.push_back(neighbor);
        }
      }
    }
    // Keep the orientation most of the patch's input triangles have.
    const auto flipped = std::count_if(patch.begin(), patch.end(), [&](int t) { return flip[t]; });
    const bool invert = 2 * flipped > static_cast<std::ptrdiff_t>(patch.size());
    for (int t : patch)
    {
      if (flip[t] != static_cast<int>(invert))
      {
        std::swap(this->Triangles[t][1], this->Triangles[t][2]);
      }
    }
  }
}

void SurfaceMesh::LabelComponents()
{
  const int n = this->GetNumberOfVertices();
  this->Components.assign(n, -1);
  this->NumberOfComponents = 0;
  std::vector<int> stack;
  for (int seed = 0; seed < n; ++seed)
  {
    if (this->Components[seed] >= 0 || this->GetValence(seed) == 0)
    {
      continue;
    }
    const int label = this->NumberOfComponents++;
    this->Components[seed] = label;
    stack.assign(1, seed);
    while (!stack.empty())
    {
      const int v = stack.back();
      stack.pop_back();
      for (const int* w = this->NeighborsBegin(v); w != this->NeighborsEnd(v); ++w)
      {
        if (this->Components[*w] < 0)
        {
          this->Components[*w] = label;
          stack.push_back(*w);
        }
      }
    }
  }
}

int SurfaceMesh::FindNearestVertex(const Vector3& point) const
{
  int nearest = -1;
  double nearestDistance = std::numeric_limits<double>::infinity();
  for (int v = 0; v < this->GetNumberOfVertices(); ++v)
  {
    const double distance = (this->Positions[v] - point).squaredNorm();
    if (this->GetValence(v) > 0 && distance < nearestDistance)
    {
      nearest = v;
      nearestDistance = distance;
    }
  }
  return nearest;
}

}
