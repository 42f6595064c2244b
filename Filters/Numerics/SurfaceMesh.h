// SurfaceMesh: the connectivity the editor walks, free of VTK types.
//
// Input points that share a position (texture seams split by vtkOBJReader, STL triangle soups,
// duplicated piece boundaries under MPI) become one surface vertex, so that a region of interest
// grows across seams instead of silently editing one seam-bounded patch.
#ifndef LaplacianEditing_SurfaceMesh_h
#define LaplacianEditing_SurfaceMesh_h

#include "Types.h"

#include <array>
#include <cstdint>
#include <vector>

namespace LaplacianEditing
{
class SurfaceMesh
{
public:
  /// Builds the mesh from polygons given as VTK-style offsets/connectivity into `points`.
  /// Polygons with more than three corners are split into a triangle fan. Triangles that
  /// collapse after merging (two corners on one vertex) are dropped. Triangles are then
  /// oriented consistently across manifold edges, each connected patch following the
  /// orientation of most of its input triangles, so that area-weighted normals do not cancel
  /// on meshes whose faces are wound inconsistently.
  /// With `mergeCoincidentPoints`, points within CoincidentPoints::RelativeTolerance of each
  /// other in every coordinate are one vertex (positions are expected in units of the mesh's
  /// size, as the VTK adapter gives them); without, each input point is its own vertex.
  /// Merged vertices are numbered in the lexicographic order of `inputPoints` (the points in
  /// the input's own coordinates, one per point; `points` when null), so that any part of one
  /// input, moved or scaled, numbers its vertices in the same order, whatever frame each part
  /// was scaled into.
  static SurfaceMesh FromPolygons(const std::vector<Vector3>& points,
    const std::vector<std::int64_t>& offsets, const std::vector<std::int64_t>& connectivity,
    bool mergeCoincidentPoints, const std::vector<Vector3>* inputPoints = nullptr);

  int GetNumberOfVertices() const { return static_cast<int>(this->Positions.size()); }
  int GetNumberOfTriangles() const { return static_cast<int>(this->Triangles.size()); }
  const std::vector<Vector3>& GetPositions() const { return this->Positions; }
  const std::vector<std::array<int, 3>>& GetTriangles() const { return this->Triangles; }

  /// Surface vertex of each input point.
  const std::vector<int>& GetVertexOfPoint() const { return this->VertexOfPoint; }

  /// One-ring of a vertex, sorted, without the vertex itself.
  const int* NeighborsBegin(int v) const { return this->Neighbors.data() + this->NeighborOffsets[v]; }
  const int* NeighborsEnd(int v) const { return this->Neighbors.data() + this->NeighborOffsets[v + 1]; }
  int GetValence(int v) const { return this->NeighborOffsets[v + 1] - this->NeighborOffsets[v]; }

  /// Triangles incident to a vertex.
  const int* TrianglesBegin(int v) const { return this->VertexTriangles.data() + this->TriangleOffsets[v]; }
  const int* TrianglesEnd(int v) const { return this->VertexTriangles.data() + this->TriangleOffsets[v + 1]; }

  /// Connected component of each vertex; -1 for a vertex no triangle references.
  const std::vector<int>& GetComponents() const { return this->Components; }
  int GetNumberOfComponents() const { return this->NumberOfComponents; }

  /// Vertex nearest to a point, among vertices some triangle references; -1 if there are none.
  int FindNearestVertex(const Vector3& point) const;

private:
  void BuildIncidences();
  void BuildAdjacency();
  void LabelComponents();
  void OrientTriangles();

  std::vector<Vector3> Positions;
  std::vector<std::array<int, 3>> Triangles;
  std::vector<int> VertexOfPoint;
  std::vector<int> NeighborOffsets;
  std::vector<int> Neighbors;
  std::vector<int> TriangleOffsets;
  std::vector<int> VertexTriangles;
  std::vector<int> Components;
  int NumberOfComponents = 0;
};

}

#endif
