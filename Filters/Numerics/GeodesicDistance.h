// Geodesic distance on the surface, for the region, the anchor weights and the normal smoothing
// support (Sections 6, 7). Two methods:
//  - FastMarching (default): Kimmel and Sethian's fast marching on triangulated domains (PNAS
//    1998). A vertex is reached across a triangle from its two settled corners by a planar
//    front when the front's direction enters the triangle; otherwise along an edge. Discs come
//    out round: on a regular grid, the extent of a disc varies by a few percent with direction.
//  - EdgePaths: shortest paths along edges (Dijkstra), the paper's approximation. Discs are
//    polygons: on a regular grid their extent varies by 30% with direction.
#ifndef LaplacianEditing_GeodesicDistance_h
#define LaplacianEditing_GeodesicDistance_h

#include "SurfaceMesh.h"

#include <algorithm>
#include <array>
#include <functional>
#include <limits>
#include <utility>
#include <vector>

namespace LaplacianEditing
{
enum class DistanceMethod
{
  FastMarching,
  EdgePaths
};

/// The distance at `target` of the planar front that reaches corner a at `da` and corner b at
/// `db`, or +infinity when the front does not come to `target` through the triangle.
double FrontArrival(const Vector3& target, const Vector3& a, double da, const Vector3& b, double db);

/// Bounded Dijkstra searches on one mesh. The work arrays are kept between searches and reset
/// only where a search went, so many small searches cost what they visit, not O(n) each.
class GeodesicSearch
{
public:
  explicit GeodesicSearch(const SurfaceMesh& mesh, DistanceMethod method = DistanceMethod::FastMarching)
    : Mesh(mesh)
    , Method(method)
    , Distance(mesh.GetNumberOfVertices(), std::numeric_limits<double>::infinity())
    , Settled(mesh.GetNumberOfVertices(), 0)
    , HeapSlot(mesh.GetNumberOfVertices(), -1)
  {
  }

  /// Calls visit(vertex, distance) once for every vertex within `radius` of the nearest
  /// source, in increasing distance. Paths only pass through vertices for which
  /// mayEnter(vertex) holds (and the sources).
  template <typename Visitor, typename Filter = bool (*)(int)>
  void Visit(const std::vector<int>& sources, double radius, Visitor&& visit,
    Filter mayEnter = [](int) { return true; })
  {
    const auto& positions = this->Mesh.GetPositions();
    for (int source : sources)
    {
      this->Reach(source, 0.0);
    }
    if (this->Method == DistanceMethod::FastMarching)
    {
      // Near a source the front is a circle, not a plane: its two rings start at their straight
      // distance, exact where the surface is flat at that scale.
      for (int source : sources)
      {
        for (const int* w = this->Mesh.NeighborsBegin(source); w != this->Mesh.NeighborsEnd(source); ++w)
        {
          for (const int* x = this->Mesh.NeighborsBegin(*w); x != this->Mesh.NeighborsEnd(*w); ++x)
          {
            for (const int seed : { *w, *x })
            {
              const double d = (positions[seed] - positions[source]).norm();
              if (d <= radius && d < this->Distance[seed] && mayEnter(seed))
              {
                this->Reach(seed, d);
              }
            }
          }
        }
      }
    }
    while (!this->Heap.empty())
    {
      const int v = this->PopNearest();
      const double d = this->Distance[v];
      this->Settled[v] = 1;
      visit(v, d);
      // Each unsettled neighbour's best arrival: along its edge, or across a triangle at v
      // whose other corner is settled (fast marching). One queue entry per improvement.
      const int* triangles = this->Mesh.TrianglesBegin(v);
      const int triangleCount = static_cast<int>(this->Mesh.TrianglesEnd(v) - triangles);
      std::array<std::pair<int, double>, 32> across;
      int acrossCount = 0;
      for (int k = 0; this->Method == DistanceMethod::FastMarching && k < triangleCount; ++k)
      {
        const auto& tri = this->Mesh.GetTriangles()[triangles[k]];
        const int corner = tri[0] == v ? 0 : (tri[1] == v ? 1 : 2);
        const int a = tri[(corner + 1) % 3];
        const int b = tri[(corner + 2) % 3];
        for (const auto& [target, other] : { std::pair<int, int>{ a, b }, { b, a } })
        {
          if (this->Settled[other] && !this->Settled[target] && acrossCount < 32)
          {
            across[acrossCount++] = { target,
              FrontArrival(positions[target], positions[v], d, positions[other], this->Distance[other]) };
          }
        }
      }
      for (const int* w = this->Mesh.NeighborsBegin(v); w != this->Mesh.NeighborsEnd(v); ++w)
      {
        if (this->Settled[*w])
        {
          continue;
        }
        double candidate = d + (positions[*w] - positions[v]).norm();
        for (int k = 0; k < acrossCount; ++k)
        {
          candidate = across[k].first == *w ? std::min(candidate, across[k].second) : candidate;
        }
        if (candidate <= radius && candidate < this->Distance[*w] && mayEnter(*w))
        {
          this->Reach(*w, candidate);
        }
      }
    }
    for (int v : this->Touched)
    {
      this->Distance[v] = std::numeric_limits<double>::infinity();
      this->Settled[v] = 0;
    }
    this->Touched.clear();
  }

private:
  // The frontier is an indexed binary heap on Distance: each vertex is in it at most once, and
  // a shorter distance moves it up (fewer heap operations than re-pushing).
  void Reach(int v, double d)
  {
    if (this->Distance[v] == std::numeric_limits<double>::infinity())
    {
      this->Touched.push_back(v);
    }
    this->Distance[v] = d;
    if (this->HeapSlot[v] < 0)
    {
      this->HeapSlot[v] = static_cast<int>(this->Heap.size());
      this->Heap.push_back(v);
    }
    this->SiftUp(this->HeapSlot[v]);
  }

  int PopNearest()
  {
    const int nearest = this->Heap.front();
    this->HeapSlot[nearest] = -1;
    const int last = this->Heap.back();
    this->Heap.pop_back();
    if (!this->Heap.empty())
    {
      this->Heap[0] = last;
      this->HeapSlot[last] = 0;
      this->SiftDown(0);
    }
    return nearest;
  }

  void Place(int slot, int v)
  {
    this->Heap[slot] = v;
    this->HeapSlot[v] = slot;
  }

  void SiftUp(int slot)
  {
    const int v = this->Heap[slot];
    while (slot > 0 && this->Distance[this->Heap[(slot - 1) / 2]] > this->Distance[v])
    {
      this->Place(slot, this->Heap[(slot - 1) / 2]);
      slot = (slot - 1) / 2;
    }
    this->Place(slot, v);
  }

  void SiftDown(int slot)
  {
    const int v = this->Heap[slot];
    const int size = static_cast<int>(this->Heap.size());
    for (int child = 2 * slot + 1; child < size; child = 2 * slot + 1)
    {
      child += child + 1 < size && this->Distance[this->Heap[child + 1]] < this->Distance[this->Heap[child]];
      if (this->Distance[this->Heap[child]] >= this->Distance[v])
      {
        break;
      }
      this->Place(slot, this->Heap[child]);
      slot = child;
    }
    this->Place(slot, v);
  }

  const SurfaceMesh& Mesh;
  DistanceMethod Method;
  std::vector<double> Distance;
  std::vector<char> Settled;
  std::vector<int> Touched;
  std::vector<int> Heap;
  std::vector<int> HeapSlot;
};

/// Distances from a set of source vertices; vertices farther than `maxDistance`, or not
/// reached, get +infinity.
std::vector<double> ComputeGeodesicDistances(const SurfaceMesh& mesh,
  const std::vector<int>& sources, double maxDistance,
  DistanceMethod method = DistanceMethod::FastMarching);
}

#endif
