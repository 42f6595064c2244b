// Approximate geodesic distance: shortest paths along mesh edges weighted by their length.
// The paper uses it for the anchor weights and the normal smoothing support (Sections 7, 8).
#ifndef LaplacianEditing_GeodesicDistance_h
#define LaplacianEditing_GeodesicDistance_h

#include "SurfaceMesh.h"

#include <vector>

namespace LaplacianEditing
{
/// Dijkstra distances over edge lengths from a set of source vertices (the paper's
/// approximation of geodesic distance, Section 8). Vertices farther than `maxDistance`, or not
/// reached, get +infinity.
std::vector<double> ComputeGeodesicDistances(
  const SurfaceMesh& mesh, const std::vector<int>& sources, double maxDistance);
}

#endif
