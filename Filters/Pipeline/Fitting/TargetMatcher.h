// TargetMatcher: a template fit's closest points on its target. The target is a triangle surface
// (its triangles, with normals interpolated from their corners') or a point cloud (its points,
// with normals estimated from each point's neighbours, whose sign is unknown). A template
// point's match is the foot of its perpendicular on the target's tangent plane at the closest
// point: point-to-plane, which lets the template slide along the target where a point-to-point
// match would hold it back.
//
// A match is trusted only where it is likely the same place of the shape: near (within
// MaximumDistance), facing the same way (normals within an angle; for a cloud, either sign
// until OrientCloud),
// and, on a surface, not beyond the rim of a hole or of the target's border, where the closest
// point of a region the target lacks lands (on the rim's edge, off the perpendicular). A bound
// relative to the median distance, common in rigid ICP, sets aside for good the parts still far
// when most have arrived: it doubled the correspondence error of RegistrationBenchmark's bend.
#ifndef LaplacianEditing_Pipeline_TargetMatcher_h
#define LaplacianEditing_Pipeline_TargetMatcher_h

#include "vtkLaplacianEditingFiltersModule.h" // for export macro
#include "vtkNew.h"
#include "vtkSmartPointer.h"
#include "vtkType.h"

#include <array>
#include <string>
#include <vector>

class vtkDataArray;
class vtkGenericCell;
class vtkPointSet;
class vtkPolyData;
class vtkStaticCellLocator;
class vtkStaticPointLocator;

namespace LaplacianEditing
{
namespace Pipeline
{
class VTKLAPLACIANEDITINGFILTERS_EXPORT TargetMatcher
{
public:
  TargetMatcher();
  ~TargetMatcher();

  /// What a trusted match must be.
  struct Criteria
  {
    double MaximumDistance = 1e300;
    /// The cosine of the largest angle between the template's and the target's normals.
    double MinimumCosine = 0.5;
  };

  /// Each template point's match (the foot on the tangent plane) and the target's normal there,
  /// where it lands on the target (a surface's closest point; on a cloud, the foot, between its
  /// points), the distance to the closest point and whether the match is trusted.
  struct Matches
  {
    std::vector<std::array<double, 3>> Targets;
    std::vector<std::array<double, 3>> Normals;
    std::vector<std::array<double, 3>> Landings;
    std::vector<double> Distances;
    std::vector<char> Trusted;
  };

  /// The target: a point set whose triangles (if it has polygons) or points make the shape. Its
  /// points must be finite; polygons that are not triangles are an error. Returns an error
  /// message, empty on success.
  std::string SetTarget(vtkPointSet* target);
  bool IsSurface() const { return this->Surface != nullptr; }

  /// A cloud's normals turned to agree with the nearest point's of `shape` (a template already
  /// near the cloud), so that matches on the far side of thin parts face away; afterwards the
  /// cloud's normals count with their sign. Nothing for a surface.
  void OrientCloud(vtkPolyData* shape);

  /// The matches of `shape`'s points (a surface whose point normals are computed here), or of
  /// the points `subset` lists alone (the others are left untrusted).
  void Match(vtkPolyData* shape, const Criteria& criteria, Matches& matches,
    const std::vector<vtkIdType>* subset = nullptr) const;

  /// The distance from `point` to the target (its triangles, or its nearest point).
  double DistanceTo(const double point[3]) const;

private:
  // The closest target point to `point`, the target's normal there and whether `point` lies
  // beyond a rim, found with the surface's locator `locator`.
  void Closest(const double point[3], double closest[3], double normal[3], bool& rim,
    std::size_t locator = 0) const;
  // The barycentric weights of `p` on triangle `cellId`'s corners.
  void CornerWeights(vtkIdType cellId, const double p[3], double weights[3]) const;
  // Of the triangles around the vertex or edge that `closest` (on `cellId`, with `weights` on its
  // corners) lies on, the nearest to `point`, the lowest id among equals, with its closest point,
  // squared distance and weights. The locator returns any of equally near triangles (its bins'
  // cells come from a parallel sort), and a match must not depend on the threads' schedule.
  vtkIdType FirstOfEquallyNear(const double point[3], vtkIdType cellId, double closest[3],
    double& squared, double weights[3], vtkGenericCell* cell) const;

  vtkSmartPointer<vtkPolyData> Surface; // null for a cloud
  vtkSmartPointer<vtkPointSet> Cloud;
  // One locator per thread of Match: VTK 9.1's keeps a query's visited cells in the object.
  std::vector<vtkSmartPointer<vtkStaticCellLocator>> Cells;
  vtkNew<vtkStaticPointLocator> Points;
  vtkSmartPointer<vtkDataArray> Normals;     // per point (a cloud's estimated)
  vtkSmartPointer<vtkDataArray> FaceNormals; // per triangle of a surface
  std::vector<char> RimCells;
  std::vector<std::array<vtkIdType, 3>> Corners; // per triangle of a surface
  bool CloudOriented = false;
  double OnSurface = 0.0; // nearer the surface than this, a point is on it
};
}
}

#endif
