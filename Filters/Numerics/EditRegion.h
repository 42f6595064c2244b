// The classification of the paper's Fig. 2: the region of interest (ROI) holds the handle
// vertices, the free vertices, and the stationary anchors padding its outer layer; everything
// else is fixed and stays untouched.
#ifndef LaplacianEditing_EditRegion_h
#define LaplacianEditing_EditRegion_h

#include "GeodesicDistance.h"
#include "SurfaceMesh.h"

#include <string>
#include <vector>

namespace LaplacianEditing
{
/// Values of the filter's EditRole point array.
enum class VertexRole : unsigned char
{
  Fixed = 0,
  Anchor = 1,
  Free = 2,
  Handle = 3
};

struct EditRegion
{
  /// ROI surface vertices.
  std::vector<int> Vertices;
  /// Per ROI vertex.
  std::vector<VertexRole> Roles;
  /// Per ROI vertex: the handle group of a handle vertex, -1 otherwise.
  std::vector<int> HandleGroups;
  /// Per ROI vertex: where it lies between the handles (0) and the fixed part (1),
  /// h / (h + b) with h its distance from the handles and b its distance to the nearest fixed
  /// vertex (h over the largest h where the ROI has no fixed border). Anchors are the outer
  /// padding of it, weighted in proportion to it (Section 6).
  std::vector<double> RelativeDistances;
  int NumberOfHandleGroups = 0;
  /// The largest distance of an ROI vertex from the handles.
  double Radius = 0.0;
  /// Geodesic selection: whether the ROI borders the fixed part (false: the disc swallowed its
  /// whole connected component).
  bool BordersFixedPart = true;

  int GetNumberOfVertices() const { return static_cast<int>(this->Vertices.size()); }
};

/// Handle: vertices within `handleRadius` of `centerVertex`. ROI: vertices within `roiRadius`
/// of it. Anchors: ROI vertices whose relative distance exceeds 1 - anchorPadding, a band along
/// the border with the fixed part. Returns an error message, empty on success.
std::string SelectGeodesicRegion(const SurfaceMesh& mesh, int centerVertex, double handleRadius,
  double roiRadius, double anchorPadding, EditRegion& region,
  DistanceMethod method = DistanceMethod::FastMarching);

/// Per surface vertex labels: 0 fixed, 1 ROI, 2 + g handle group g (the .sel convention).
/// With `roiRadius` > 0, vertices labelled 0 within it of the handles join the ROI too (handles
/// chosen by a selection, the ROI around them). Anchors as above: the padding lines the border
/// with the fixed part, wherever the handles are. Returns an error message, empty on success.
std::string SelectLabeledRegion(const SurfaceMesh& mesh, std::vector<int> labels,
  double anchorPadding, EditRegion& region, DistanceMethod method = DistanceMethod::FastMarching,
  double roiRadius = 0.0);

/// Every vertex of the connected components that hold a seed vertex, all free: the region of a
/// landmark warp, which its point constraints alone hold (PointConstraints.h). Radius is the
/// diagonal of the region's bounding box. Returns an error message, empty on success.
std::string SelectComponents(const SurfaceMesh& mesh, const std::vector<int>& seeds, EditRegion& region);
}

#endif
