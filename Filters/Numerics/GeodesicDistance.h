// Approximate geodesic distance: shortest paths along mesh edges weighted by their length.
// The paper uses it for the anchor weights and the normal smoothing support (Sections 7, 8).
#ifndef LaplacianEditing_GeodesicDistance_h
#define LaplacianEditing_GeodesicDistance_h

#include "SurfaceMesh.h"

#include <functional>
#include <limits>
#include <queue>
#include <utility>
#include <vector>

namespace LaplacianEditing
{
/// Bounded Dijkstra searches on one mesh. The work arrays are kept between searches and reset
/// only where a search went, so many small searches cost what they visit, not O(n) each.
class GeodesicSearch
{
public:
  explicit GeodesicSearch(const SurfaceMesh& mesh)
    : Mesh(mesh)
    , Distance(mesh.GetNumberOfVertices(), std::numeric_limits<double>::infinity())
  {
  }

  /// Calls visit(vertex, distance) once for every vertex within `radius` of the nearest
  /// source, in increasing distance.
  template <typename Visitor>
  void Visit(const std::vector<int>& sources, double radius, Visitor&& visit)
  {
    const auto& positions = this->Mesh.GetPositions();
    for (int source : sources)
    {
      this->Reach(source, 0.0);
    }
    while (!this->Queue.empty())
    {
      const auto [d, v] = this->Queue.top();
      this->Queue.pop();
      if (d > this->Distance[v])
      {
        continue;
      }
      visit(v, d);
      for (const int* w = this->Mesh.NeighborsBegin(v); w != this->Mesh.NeighborsEnd(v); ++w)
      {
        const double candidate = d + (positions[*w] - positions[v]).norm();
        if (candidate <= radius && candidate < this->Distance[*w])
        {
          this->Reach(*w, candidate);
        }
      }
    }
    for (int v : this->Touched)
    {
      this->Distance[v] = std::numeric_limits<double>::infinity();
    }
    this->Touched.clear();
  }

private:
  void Reach(int v, double d)
  {
    if (this->Distance[v] == std::numeric_limits<double>::infinity())
    {
      this->Touched.push_back(v);
    }
    this->Distance[v] = d;
    this->Queue.emplace(d, v);
  }

  using Entry = std::pair<double, int>;
  const SurfaceMesh& Mesh;
  std::vector<double> Distance;
  std::vector<int> Touched;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> Queue;
};

/// Distances from a set of source vertices; vertices farther than `maxDistance`, or not
/// reached, get +infinity.
std::vector<double> ComputeGeodesicDistances(
  const SurfaceMesh& mesh, const std::vector<int>& sources, double maxDistance);
}

#endif
