#include "GeodesicDistance.h"

#include <functional>
#include <limits>
#include <queue>
#include <utility>

namespace LaplacianEditing
{
std::vector<double> ComputeGeodesicDistances(
  const SurfaceMesh& mesh, const std::vector<int>& sources, double maxDistance)
{
  const double infinity = std::numeric_limits<double>::infinity();
  std::vector<double> distance(mesh.GetNumberOfVertices(), infinity);
  using Entry = std::pair<double, int>;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> queue;
  for (int source : sources)
  {
    distance[source] = 0.0;
    queue.emplace(0.0, source);
  }
  const auto& positions = mesh.GetPositions();
  while (!queue.empty())
  {
    const auto [d, v] = queue.top();
    queue.pop();
    if (d > distance[v])
    {
      continue;
    }
    for (const int* w = mesh.NeighborsBegin(v); w != mesh.NeighborsEnd(v); ++w)
    {
      const double candidate = d + (positions[*w] - positions[v]).norm();
      if (candidate <= maxDistance && candidate < distance[*w])
      {
        distance[*w] = candidate;
        queue.emplace(candidate, *w);
      }
    }
  }
  return distance;
}
}
