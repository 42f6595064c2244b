#include "GeodesicDistance.h"

namespace LaplacianEditing
{
std::vector<double> ComputeGeodesicDistances(
  const SurfaceMesh& mesh, const std::vector<int>& sources, double maxDistance)
{
  std::vector<double> distance(mesh.GetNumberOfVertices(), std::numeric_limits<double>::infinity());
  GeodesicSearch(mesh).Visit(sources, maxDistance, [&](int v, double d) { distance[v] = d; });
  return distance;
}
}
