// The classification of the paper's Fig. 2: the region of interest (ROI) holds the handle
// vertices, the free vertices, and the stationary anchors padding its outer layer; everything
// else is fixed and stays untouched.
#ifndef LaplacianEditing_EditRegion_h
#define LaplacianEditing_EditRegion_h

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
  /// Per ROI vertex: geodesic distance from the handle divided by the ROI radius, in [0, 1].
  /// Anchors are weighted in proportion to it (Section 6).
  std::vector<double> RelativeDistances;
  int NumberOfHandleGroups = 0;
  /// The distance that RelativeDistances are relative to: the ROI radius, or in a labelled
  /// selection the largest distance of an ROI vertex from the handles.
  double Radius = 0.0;

  int GetNumberOfVertices() const { return static_cast<int>(this->Vertices.size()); }
};

/// Handle: vertices within `handleRadius` (edge-path distance) of `centerVertex`.
/// ROI: vertices within `roiRadius` of it. Anchors: ROI vertices farther than
/// (1 - anchorPadding) * roiRadius, or, when the ROI covers the whole component, farther than
/// (1 - anchorPadding) times the largest distance reached. Returns an error message, empty on
/// success.
std::string SelectGeodesicRegion(const SurfaceMesh& mesh, int centerVertex, double handleRadius,
  double roiRadius, double anchorPadding, EditRegion& region);

/// Per surface vertex labels: 0 fixed, 1 ROI, 2 + g handle group g (the .sel convention).
/// Anchors: ROI vertices in the outer `anchorPadding` fraction of the largest distance from the
/// handles. Returns an error message, empty on success.
std::string SelectLabeledRegion(const SurfaceMesh& mesh, const std::vector<int>& labels,
  double anchorPadding, EditRegion& region);
}

#endif
