// NormalRefresher: recomputes the output's point and cell normals where an edit moved the surface.
//
// Per region, Index finds the points whose normals the edit can change (the ROI and its ring),
// the triangles around them, and the polygons with a corner in the ROI (a pass over the input's
// polygons). The Write methods then
// recompute only those tuples (OutputArray keeps the rest), so all other normals
// stay bit-identical and a handle move costs time in proportion to the region. The index refers to vertices only by
// number, so Restrict can cut out the part that one piece of a distributed surface needs.
#ifndef LaplacianEditing_Pipeline_NormalRefresher_h
#define LaplacianEditing_Pipeline_NormalRefresher_h

#include "Types.h"
#include "vtkLaplacianEditingFiltersModule.h" // for export macro

#include "vtkType.h"

#include <functional>
#include <vector>

class vtkDataArray;
class vtkPolyData;

namespace LaplacianEditing
{
namespace Pipeline
{
class SurfaceAdapter;

class VTKLAPLACIANEDITINGFILTERS_EXPORT NormalRefresher
{
public:
  /// After the surface's IndexRegion; `input` is the polydata it was built from. Vertices are
  /// the surface's.
  void Index(vtkPolyData* input, const SurfaceAdapter& surface);

  /// The output point ids and cell ids whose normals the edit can change.
  const std::vector<vtkIdType>& GetPointIds() const { return this->Points; }
  const std::vector<vtkIdType>& GetCellIds() const { return this->Cells; }

  /// Writes the point normals (at GetPointIds) and the polygon normals (at GetCellIds) of the
  /// edited surface into `normals`, with vertex v at rest[v], or at solution's row
  /// rowOfVertex[v] where that is not -1 (the moved region), in the core's coordinates
  /// (normals do not depend on the frame's translation and scale). With `compact`, the i-th
  /// id's normal goes to tuple i instead (an array of the region alone).
  void WritePointNormals(vtkDataArray* normals, const std::vector<LaplacianEditing::Vector3>& rest,
    const std::vector<int>& rowOfVertex, const LaplacianEditing::Positions& solution,
    bool compact = false) const;
  void WriteCellNormals(vtkDataArray* normals, const std::vector<LaplacianEditing::Vector3>& rest,
    const std::vector<int>& rowOfVertex, const LaplacianEditing::Positions& solution,
    bool compact = false) const;

  /// The part of the index on the points and polygons that `pointId` and `cellId` map to
  /// another data set's ids (-1: not in the part), with its vertices renumbered in order of
  /// first use; `vertices` receives each new vertex's number here.
  NormalRefresher Restrict(const std::function<vtkIdType(vtkIdType)>& pointId,
    const std::function<vtkIdType(vtkIdType)>& cellId, std::vector<int>& vertices) const;

  /// Calls `visit` on each of the index's arrays, always in the same order (to send it).
  template <typename Visitor>
  void VisitArrays(Visitor&& visit)
  {
    VisitArraysOf(*this, visit);
  }
  template <typename Visitor>
  void VisitArrays(Visitor&& visit) const
  {
    VisitArraysOf(*this, visit);
  }

private:
  // The points whose normals can change (input ids) and, as offsets into PointTriangles, the
  // triangles around each (slots of TriangleVertices, three vertices each); the polygons to
  // refresh with their vertices (offsets into CellVertices).
  std::vector<vtkIdType> Points;
  std::vector<int> PointTriangleOffsets;
  std::vector<int> PointTriangles;
  std::vector<int> TriangleVertices;
  std::vector<vtkIdType> Cells;
  std::vector<int> CellVertexOffsets;
  std::vector<int> CellVertices;

  template <typename Self, typename Visitor>
  static void VisitArraysOf(Self& self, Visitor& visit)
  {
    visit(self.Points);
    visit(self.PointTriangleOffsets);
    visit(self.PointTriangles);
    visit(self.TriangleVertices);
    visit(self.Cells);
    visit(self.CellVertexOffsets);
    visit(self.CellVertices);
  }
};

}
}

#endif
