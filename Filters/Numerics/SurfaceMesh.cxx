#include "SurfaceMesh.h"

#include "CoincidentPoints.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <numeric>
#include <utility>

namespace LaplacianEditing
{
namespace
{
// Spreads the low 21 bits of `bits` three apart.
std::uint64_t SpreadBits(std::uint64_t bits)
{
  bits &= 0x1fffff;
  bits = (bits | bits << 32) & 0x1f00000000ffffull;
  bits = (bits | bits << 16) & 0x1f0000ff0000ffull;
  bits = (bits | bits << 8) & 0x100f00f00f00f00full;
  bits = (bits | bits << 4) & 0x10c30c30c30c30c3ull;
  return (bits | bits << 2) & 0x1249249249249249ull;
}

// Renumbers the vertices in the lexicographic order of their points' coordinates as the input
// has them (`inputPoints`), each vertex keyed by its point `representative`. Why this order:
// it is the one a translation, a uniform scale and the choice of a part all keep, so that a
// region reached from a selection or gathered from ranks, or a model far from the origin,
// numbers its vertices as the whole surface at unit scale does, and every later tie-break
// (samples, equal distances on regular grids, colourings) falls the same way. (A Z-order
// keeps neighbours nearer in memory, but no Z-order is kept by all three.)
void NumberInInputOrder(const std::vector<Vector3>& inputPoints,
  const std::vector<int>& representative, std::vector<int>& vertexOfPoint,
  std::vector<Vector3>& positions)
{
  std::vector<int> order(positions.size());
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](int a, int b) {
    const Vector3& p = inputPoints[representative[a]];
    const Vector3& q = inputPoints[representative[b]];
    return std::lexicographical_compare(p.data(), p.data() + 3, q.data(), q.data() + 3);
  });
  std::vector<int> renumbered(positions.size());
  std::vector<Vector3> sorted(positions.size());
  for (std::size_t i = 0; i < order.size(); ++i)
  {
    renumbered[order[i]] = static_cast<int>(i);
    sorted[i] = positions[order[i]];
  }
  positions.swap(sorted);
  for (int& vertex : vertexOfPoint)
  {
    vertex = vertex < 0 ? vertex : renumbered[vertex];
  }
}

// Welds points within CoincidentPoints::RelativeTolerance of each other in every coordinate.
// Returns each point's vertex and fills `positions`, each vertex's position (the least of its
// points), numbered by NumberInInputOrder.
//
// Why this way: sorted on Z-order cells of the bounds at least 4 tolerances wide, twins share a
// cell, or lie within a tolerance of a cell's border on both sides of it; so a point is
// compared with the run of its cell, and only points near a border go through a
// CoincidentPoints table (a table of every point cost a second on a 2.4M-point scan).
std::vector<int> WeldAlongZOrder(const std::vector<Vector3>& points,
  const std::vector<Vector3>& inputPoints, std::vector<Vector3>& positions)
{
  const double tolerance = CoincidentPoints::RelativeTolerance;
  const int numberOfPoints = static_cast<int>(points.size());
  Vector3 low = Vector3::Constant(std::numeric_limits<double>::infinity());
  Vector3 high = -low;
  for (const Vector3& p : points)
  {
    low = low.cwiseMin(p);
    high = high.cwiseMax(p);
  }
  const double cells = static_cast<double>((1 << 21) - 1);
  const Vector3 cellSize =
    (high - low).unaryExpr([&](double extent) { return std::max(extent / cells, 4.0 * tolerance); });
  struct Keyed
  {
    std::uint64_t Key;
    int Point;
  };
  std::vector<Keyed> order(numberOfPoints);
  std::vector<char> nearBorder(numberOfPoints, 0);
  for (int point = 0; point < numberOfPoints; ++point)
  {
    std::uint64_t key = 0;
    for (int a = 0; a < 3; ++a)
    {
      const double offset = (points[point][a] - low[a]) / cellSize[a];
      const double cell = std::max(0.0, std::min(cells, std::floor(offset)));
      const double fromBorder = std::min(offset - cell, cell + 1.0 - offset) * cellSize[a];
      nearBorder[point] |= fromBorder <= 2.0 * tolerance;
      key |= SpreadBits(static_cast<std::uint64_t>(cell)) << a;
    }
    order[point] = { key, point };
  }
  std::sort(order.begin(), order.end(), [&points](const Keyed& a, const Keyed& b) {
    if (a.Key != b.Key)
    {
      return a.Key < b.Key;
    }
    const Vector3& p = points[a.Point];
    const Vector3& q = points[b.Point];
    return std::lexicographical_compare(p.data(), p.data() + 3, q.data(), q.data() + 3) ||
      (p == q && a.Point < b.Point);
  });
  std::vector<int> vertexOfPoint(numberOfPoints, -1);
  std::vector<int> representative;
  positions.clear();
  positions.reserve(points.size());
  representative.reserve(points.size());
  // Points near a border, and those of crowded cells (a far outlier makes every cell large),
  // go through the table.
  constexpr std::size_t Crowded = 32;
  CoincidentPoints table(tolerance, low);
  std::size_t run = 0; // the first of the current cell's points in `order`
  for (std::size_t i = 0; i < order.size(); ++i)
  {
    const int point = order[i].Point;
    const Vector3& p = points[point];
    run = order[i].Key == order[run].Key ? run : i;
    if (i - run == Crowded)
    {
      for (std::size_t j = run; j < i; ++j)
      {
        const int earlier = order[j].Point;
        if (!nearBorder[earlier])
        {
          nearBorder[earlier] = 1;
          table.Add(points[earlier], vertexOfPoint[earlier]);
        }
      }
    }
    nearBorder[point] |= i - run >= Crowded;
    int vertex = nearBorder[point] ? table.Find(p) : -1;
    for (std::size_t j = run; j < i && i - run < Crowded; ++j)
    {
      const int twin = vertexOfPoint[order[j].Point];
      if ((points[order[j].Point] - p).cwiseAbs().maxCoeff() <= tolerance && (vertex < 0 || twin < vertex))
      {
        vertex = twin;
      }
    }
    if (vertex < 0)
    {
      vertex = static_cast<int>(positions.size());
      positions.push_back(p);
      representative.push_back(point);
    }
    else if (std::lexicographical_compare(p.data(), p.data() + 3, positions[vertex].data(),
               positions[vertex].data() + 3))
    {
      positions[vertex] = p; // the least of the twins, whatever the order met them in
      representative[vertex] = point;
    }
    vertexOfPoint[point] = vertex;
    if (nearBorder[point])
    {
      table.Add(p, vertex);
    }
  }
  NumberInInputOrder(inputPoints, representative, vertexOfPoint, positions);
  return vertexOfPoint;
}
}

SurfaceMesh SurfaceMesh::FromPolygons(const std::vector<Vector3>& points,
  const std::vector<std::int64_t>& offsets, const std::vector<std::int64_t>& connectivity,
  bool mergeCoincidentPoints, const std::vector<Vector3>* inputPoints)
{
  SurfaceMesh mesh;
  const int numberOfPoints = static_cast<int>(points.size());
  if (mergeCoincidentPoints)
  {
    mesh.VertexOfPoint =
      WeldAlongZOrder(points, inputPoints ? *inputPoints : points, mesh.Positions);
  }
  else
  {
    mesh.Positions = points;
    mesh.VertexOfPoint.resize(numberOfPoints);
    std::iota(mesh.VertexOfPoint.begin(), mesh.VertexOfPoint.end(), 0);
  }

  // Sizes reserved ahead: at millions of triangles, the copies of growing arrays and the page
  // faults of their fresh memory cost more than filling them.
  std::size_t fans = 0;
  for (std::size_t cell = 0; cell + 1 < offsets.size(); ++cell)
  {
    fans += static_cast<std::size_t>(std::max<std::int64_t>(offsets[cell + 1] - offsets[cell] - 2, 0));
  }
  mesh.Triangles.reserve(fans);
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
  mesh.BuildIncidences();
  mesh.OrientTriangles();
  mesh.BuildAdjacency();
  mesh.LabelComponents();
  return mesh;
}

void SurfaceMesh::BuildIncidences()
{
  // A counting sort of the corners by vertex: each row lists its triangles in order.
  const int n = this->GetNumberOfVertices();
  this->TriangleOffsets.assign(n + 1, 0);
  for (const auto& triangle : this->Triangles)
  {
    for (int corner : triangle)
    {
      ++this->TriangleOffsets[corner + 1];
    }
  }
  std::partial_sum(
    this->TriangleOffsets.begin(), this->TriangleOffsets.end(), this->TriangleOffsets.begin());
  std::vector<int> next(this->TriangleOffsets.begin(), this->TriangleOffsets.end() - 1);
  this->VertexTriangles.resize(3 * this->Triangles.size());
  for (std::size_t t = 0; t < this->Triangles.size(); ++t)
  {
    for (int corner : this->Triangles[t])
    {
      this->VertexTriangles[next[corner]++] = static_cast<int>(t);
    }
  }
}

void SurfaceMesh::BuildAdjacency()
{
  // Each vertex's one-ring: the other corners of its triangles, sorted, without repeats.
  const int n = this->GetNumberOfVertices();
  this->NeighborOffsets.assign(n + 1, 0);
  this->Neighbors.clear();
  this->Neighbors.reserve(this->VertexTriangles.size() + this->VertexTriangles.size() / 8);
  std::vector<int> ring;
  for (int v = 0; v < n; ++v)
  {
    ring.clear();
    for (const int* t = this->TrianglesBegin(v); t != this->TrianglesEnd(v); ++t)
    {
      for (int corner : this->Triangles[*t])
      {
        if (corner != v)
        {
          ring.push_back(corner);
        }
      }
    }
    std::sort(ring.begin(), ring.end());
    this->Neighbors.insert(this->Neighbors.end(), ring.begin(), std::unique(ring.begin(), ring.end()));
    this->NeighborOffsets[v + 1] = static_cast<int>(this->Neighbors.size());
  }
}

void SurfaceMesh::OrientTriangles()
{
  // Flipping makes the triangles across each manifold edge run it oppositely: each patch
  // reachable across such edges is walked from a seed. The triangle across edge k of t (from
  // corner k to k + 1) is the other triangle at both its ends, where there is exactly one.
  const int count = this->GetNumberOfTriangles();
  std::vector<int> across(3 * static_cast<std::size_t>(count), -1);
  std::vector<char> sameDirection(across.size(), 0);
  for (int t = 0; t < count; ++t)
  {
    for (int k = 0; k < 3; ++k)
    {
      const int a = this->Triangles[t][k];
      const int b = this->Triangles[t][(k + 1) % 3];
      int others = 0;
      for (const int* u = this->TrianglesBegin(a); u != this->TrianglesEnd(a); ++u)
      {
        const auto& tri = this->Triangles[*u];
        const int j = tri[0] == b ? 0 : tri[1] == b ? 1 : tri[2] == b ? 2 : -1;
        if (*u != t && j >= 0 && ++others == 1)
        {
          across[3 * t + k] = *u;
          sameDirection[3 * t + k] = tri[(j + 2) % 3] == a; // u also runs the edge from a to b
        }
      }
      if (others != 1)
      {
        across[3 * t + k] = -1; // a boundary or a non-manifold edge
      }
    }
  }
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
      for (int k = 0; k < 3; ++k)
      {
        const int neighbor = across[3 * t + k];
        if (neighbor >= 0 && flip[neighbor] < 0)
        {
          flip[neighbor] = flip[t] ^ static_cast<int>(sameDirection[3 * t + k]);
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
