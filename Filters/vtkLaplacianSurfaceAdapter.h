/**
 * @class   vtkLaplacianSurfaceAdapter
 * @brief   the numerical core's view of a vtkPolyData, and the way back (not wrapped)
 *
 * Builds the core's SurfaceMesh from the input's polygons, in coordinates centred on the
 * input's bounding box and scaled to a unit diagonal so that offset or tiny models keep their
 * precision; maps handle transforms into that frame; and, per region, indexes which input points
 * the edit moves so that writing a result touches only them.
 */
#ifndef vtkLaplacianSurfaceAdapter_h
#define vtkLaplacianSurfaceAdapter_h

#include "EditRegion.h"
#include "Types.h"

#include "vtkSignedCharArray.h" // for the EditRole array
#include "vtkSmartPointer.h"

#include <cstdint>
#include <memory>
#include <string>
#include <utility>
#include <vector>

class vtkDataArray;
class vtkLinearTransform;
class vtkPoints;
class vtkPolyData;

class vtkLaplacianSurfaceAdapter
{
public:
  /// Checks the coordinates and builds the surface graph. Returns an error message, empty on
  /// success.
  std::string Build(vtkPolyData* input, bool mergeCoincidentPoints);

  std::shared_ptr<const LaplacianEditing::SurfaceMesh> GetMesh() const { return this->Mesh; }

  /// The polygons of `input` as offsets and connectivity (SurfaceMesh::FromPolygons's input).
  static void GetPolygons(
    vtkPolyData* input, std::vector<std::int64_t>& offsets, std::vector<std::int64_t>& connectivity);

  /// Core units per input unit.
  double GetScale() const { return this->Scale; }
  LaplacianEditing::Vector3 Normalize(const double p[3]) const;
  LaplacianEditing::Vector3 Denormalize(const LaplacianEditing::Vector3& p) const;
  /// x' = M x + t in input coordinates becomes x'_n = M x_n + s (M c + t - c).
  LaplacianEditing::AffineMap NormalizedMap(vtkLinearTransform* transform) const;

  /// Per surface vertex, the largest label of its points in an integer point array.
  std::vector<int> VertexLabels(vtkDataArray* selection) const;

  /// Indexes the input points in the region (the points to write) and builds the EditRole array.
  void IndexRegion(const LaplacianEditing::EditRegion& region);
  const std::vector<int>& GetRowOfVertex() const { return this->RowOfVertex; }
  vtkSignedCharArray* GetRoles() const { return this->Roles; }
  /// An EditRole array of `count` fixed points, with its colours (see GenerateEditRoles).
  static vtkSmartPointer<vtkSignedCharArray> NewRoles(vtkIdType count);

  /// A copy of `points` with the region's points moved to `solution` (rows follow the region).
  vtkSmartPointer<vtkPoints> MovePoints(
    vtkPoints* points, const LaplacianEditing::Positions& solution) const;

private:
  std::shared_ptr<LaplacianEditing::SurfaceMesh> Mesh;
  LaplacianEditing::Vector3 Center = LaplacianEditing::Vector3::Zero();
  double Scale = 1.0;
  // Per region: the ROI row of each surface vertex (-1 outside), the input points in the ROI
  // with their row, and the EditRole array.
  std::vector<int> RowOfVertex;
  std::vector<std::pair<vtkIdType, int>> RoiPoints;
  vtkSmartPointer<vtkSignedCharArray> Roles;
};

#endif
