/**
 * @class   vtkLaplacianNormalRefresher
 * @brief   recomputes the output's point and cell normals where an edit moved the surface
 *          (not wrapped)
 *
 * Per region, Index finds the points whose normals the edit can change (the ROI and its ring)
 * and the polygons with a corner in the ROI. Refresh then copies the input's normals and
 * recomputes only those tuples, so all other normals stay bit-identical and a handle move costs
 * time in proportion to the region.
 */
#ifndef vtkLaplacianNormalRefresher_h
#define vtkLaplacianNormalRefresher_h

#include "SurfaceMesh.h"

#include "vtkType.h"

#include <vector>

class vtkLaplacianSurfaceAdapter;
class vtkPolyData;

class vtkLaplacianNormalRefresher
{
public:
  /// After the surface's IndexRegion; `input` is the polydata it was built from.
  void Index(vtkPolyData* input, const vtkLaplacianSurfaceAdapter& surface);

  /// Refreshes the output's normals (where it has any) for the ROI moved to `solution`, in the
  /// core's coordinates (normals do not depend on the frame's translation and scale).
  void Refresh(vtkPolyData* output, const LaplacianEditing::SurfaceMesh& mesh,
    const std::vector<int>& rowOfVertex, const LaplacianEditing::Positions& solution) const;

private:
  // The points whose normals can change (input ids, and their surface vertices), the triangles around them (and each mesh triangle's
  // slot among them, -1 if none), and the polygons to refresh with their surface vertices
  // (offsets into CellVertices).
  std::vector<vtkIdType> Points;
  std::vector<int> PointVertices;
  std::vector<int> Triangles;
  std::vector<int> TriangleSlot;
  std::vector<vtkIdType> Cells;
  std::vector<int> CellVertexOffsets;
  std::vector<int> CellVertices;
};

#endif
