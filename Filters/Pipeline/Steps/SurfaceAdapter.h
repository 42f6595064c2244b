// SurfaceAdapter: the numerical core's view of a vtkPolyData, and the way back.
//
// Builds the core's SurfaceMesh from the part of the input's polygons an edit can reach (those
// with a corner near the handle or the labelled points, and the ring of polygons around them),
// in coordinates centred on that part's bounding box and scaled to a unit diagonal so that
// offset or tiny models keep their precision; maps handle transforms into that frame; and, per
// region, indexes which input points the edit moves so that writing a result touches only them.
// Apart from passes over the input's points and polygons, its work and memory follow the part,
// not the input; it keeps no copy of the polygons it built the graph from.
#ifndef LaplacianEditing_Pipeline_SurfaceAdapter_h
#define LaplacianEditing_Pipeline_SurfaceAdapter_h

#include "EditRegion.h"
#include "EditTypes.h"
#include "Types.h"
#include "vtkLaplacianEditingFiltersModule.h" // for export macro

#include "vtkSmartPointer.h"

#include <array>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <utility>
#include <vector>

class vtkDataArray;
class vtkLinearTransform;
class vtkPoints;
class vtkPolyData;

namespace LaplacianEditing
{
namespace Pipeline
{
class VTKLAPLACIANEDITINGFILTERS_EXPORT SurfaceAdapter
{
public:
  /// What every editor requires of its input: points, polygons, no strips. Returns an error
  /// message, empty on success.
  static std::string CheckSurface(vtkPolyData* input);

  /// Checks the coordinates and builds the surface graph of the polygons with a corner in
  /// `reach` and the ring of polygons around them. Returns an error message, empty on success.
  std::string Build(vtkPolyData* input, bool mergeCoincidentPoints, const Reach& reach);

  /// Build, unless the graph held was built from the same content of `input` (GetContentTime),
  /// merge flag and reach; `rebuilt` says whether it built.
  std::string Update(vtkPolyData* input, bool mergeCoincidentPoints, const Reach& reach, bool& rebuilt);

  /// The polygons of `input` with a corner in `reach`, with their point and cell data and the
  /// input ids of their points and cells (vtkOriginalPointIds, vtkOriginalCellIds): the part of
  /// a piece that a parallel edit sends to the rank that solves.
  static vtkSmartPointer<vtkPolyData> ExtractReach(vtkPolyData* input, const Reach& reach);

  /// The polygon corner of `input` nearest `point`, -1 if there is none (one pass).
  static vtkIdType FindNearestCorner(vtkPolyData* input, const double point[3]);

  /// When the points, the cells or a point or cell array of `surface` last changed
  /// (ContentTime).
  static vtkMTimeType GetContentTime(vtkPolyData* surface);

  /// The input id of each point of the mesh (SurfaceMesh::GetVertexOfPoint's points).
  const std::vector<vtkIdType>& GetInputPoints() const { return this->InputPoints; }
  /// The mesh point of each input point, -1 for those the mesh does not hold.
  std::vector<int> GetPointOfInput(vtkIdType numberOfInputPoints) const;

  std::shared_ptr<const LaplacianEditing::SurfaceMesh> GetMesh() const { return this->Mesh; }

  /// Calls `visit` with the size and the point ids of each polygon of `input`, in order.
  static void VisitPolygons(vtkPolyData* input, const std::function<void(vtkIdType, const vtkIdType*)>& visit);

  /// The polygons of `input` as offsets and connectivity (SurfaceMesh::FromPolygons's input).
  static void GetPolygons(
    vtkPolyData* input, std::vector<std::int64_t>& offsets, std::vector<std::int64_t>& connectivity);

  /// Core units per input unit, and the input point at the core's origin.
  double GetScale() const { return this->Scale; }
  const LaplacianEditing::Vector3& GetCenter() const { return this->Center; }
  LaplacianEditing::Vector3 Normalize(const double p[3]) const;
  LaplacianEditing::Vector3 Denormalize(const LaplacianEditing::Vector3& p) const;
  /// x' = M x + t in input coordinates becomes x'_n = M x_n + s (M c + t - c).
  LaplacianEditing::AffineMap NormalizedMap(vtkLinearTransform* transform) const;

  /// Per surface vertex, the largest label of its points in an integer point array.
  std::vector<int> VertexLabels(vtkDataArray* selection) const;

  /// Indexes the input points in the region: the points an edit writes, with their rows and roles.
  void IndexRegion(const LaplacianEditing::EditRegion& region);
  const std::vector<int>& GetRowOfVertex() const { return this->RowOfVertex; }
  /// After IndexRegion: the points of `input` that no polygon uses move with the region's
  /// point nearest them at rest (RegionChoice::FollowUnreferenced).
  void AddFollowers(vtkPolyData* input);
  const MovedPoints& GetRegionPoints() const { return this->RegionPoints; }

  /// A solution of the indexed region as the output writer takes it, with the normals' index
  /// (null: none) and the region's version.
  OutputEdit GetEdit(const LaplacianEditing::Positions& solution,
    const NormalRefresher* normals, std::uint64_t regionVersion) const;

private:
  // Build's steps: the points in reach (1; an error for a non-finite coordinate), the ring of
  // points around them (2, with their coincident copies when merging), the polygons with a
  // marked corner and their points, and the core's frame (an error if the points coincide).
  static std::string MarkReach(vtkPolyData* input, const Reach& reach, std::vector<char>& mark);
  static void MarkRing(vtkPolyData* input, bool mergeCopies, std::vector<char>& mark);
  // The kept polygons in mesh point ids: FromPolygons's input, not kept after it (at 2.4M
  // points, 150 MB of an edit's peak memory).
  void KeepMarkedPolygons(vtkPolyData* input, const std::vector<char>& mark,
    std::vector<std::int64_t>& offsets, std::vector<std::int64_t>& connectivity);
  std::string ChooseFrame(vtkPolyData* input);

  std::shared_ptr<LaplacianEditing::SurfaceMesh> Mesh;
  // What the graph was built from (Update): content time, merge flag, reach.
  vtkMTimeType BuiltTime = 0;
  bool BuiltMerge = false;
  Reach BuiltReach;
  std::vector<vtkIdType> InputPoints;
  LaplacianEditing::Vector3 Center = LaplacianEditing::Vector3::Zero();
  double Scale = 1.0;
  // Per region: the ROI row of each surface vertex (-1 outside), the input points in the ROI.
  std::vector<int> RowOfVertex;
  MovedPoints RegionPoints;
};

}
}

#endif
