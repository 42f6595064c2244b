// VolumeMesh: the numerical core's view of a vtkUnstructuredGrid of linear 3D cells.
//
// Each cell becomes corner tetrahedra (InjectiveDeformation): a tetrahedron is its own; a
// hexahedron, voxel or wedge has one at each corner, formed by the corner and its three edge
// neighbours; a pyramid one at each base corner. A cell is valid where all its corner
// tetrahedra have the orientation that the mesh's cells of its type have (so a mesh written with
// the opposite convention, as some generators do, is taken as it is), and the corner
// tetrahedra are stored positively oriented.
//
// The boundary surface (the faces that one cell has) is a vtkPolyData of triangles (quadrilateral
// faces split) on all the grid's points, with the grid's point data: its point ids are the
// grid's, so the surface editor's regions, handles and selections name grid points. Its faces
// face outwards.
//
// The zone of an edit: the grid points within a distance, along the mesh's edges, of the boundary
// points the edit moves. Its interior points are free, its other boundary points fixed; the
// corner tetrahedra that touch a point of the zone make the core's problem. Building costs one
// pass over the grid per content change; a zone costs what its cells cost.
#ifndef LaplacianEditing_Pipeline_VolumeMesh_h
#define LaplacianEditing_Pipeline_VolumeMesh_h

#include "InjectiveDeformation.h"
#include "vtkLaplacianEditingFiltersModule.h" // for export macro

#include "vtkSmartPointer.h"
#include "vtkType.h"

#include <algorithm>
#include <limits>
#include <string>
#include <vector>

class vtkDataArray;
class vtkPoints;
class vtkPolyData;
class vtkUnstructuredGrid;

namespace LaplacianEditing
{
namespace Pipeline
{
class VTKLAPLACIANEDITINGFILTERS_EXPORT VolumeMesh
{
public:
  /// The cells whose quality has more than corners.
  enum class CellKind : unsigned char
  {
    Tetrahedron,
    Hexahedron,
    Voxel,
    Other
  };

  /// Builds from `grid` at its points, unless built from the same content (ContentTime);
  /// `rebuilt` says whether it built. Errors: an empty grid, no 3D cell, non-linear or
  /// unsupported cells, cells flat or inverted at rest, a face of more than two cells, a
  /// boundary edge not on exactly two boundary faces.
  std::string Update(vtkUnstructuredGrid* grid, bool& rebuilt);

  /// The boundary surface (see the class description); null before a build.
  vtkPolyData* GetBoundary() const { return this->Boundary; }

  /// Puts a copy of the grid's point array `labels` among the boundary's point data, in place of
  /// the grid's, with the interior points' labels 0: a selection labels grid points, and the
  /// surface editor selects on the boundary. Copied again only when `labels` changes.
  void SetBoundaryLabels(vtkDataArray* labels);

  struct Zone
  {
    std::vector<vtkIdType> Points; // grid id of each zone point
    std::vector<PointKind> Kinds;
    Tetrahedra Tets;               // in zone point indices
    std::vector<vtkIdType> Cells;  // the grid cells whose corner tetrahedra these are
    /// Per cell: its row of Tets if it is a tetrahedron (its quality is that row's), else -1.
    std::vector<int> CellTets;
    /// Whether the zone holds every point the seeds connect to: it cannot grow.
    bool Complete = false;
  };

  /// The zone of the boundary points `targeted` (they become Targeted): the grid points within
  /// `reach` of them along the mesh's edges, with the points at `positions`.
  void SelectZone(const std::vector<vtkIdType>& targeted, double reach, vtkPoints* positions,
    Zone& zone) const;

  /// The scaled Jacobian of cell `cell` with its points at `position(id)`: Verdict's for a
  /// tetrahedron (1 regular) and a hexahedron (its corners' and its centre's, 1 for a cube), the
  /// smallest corner's otherwise; negative where inverted, NaN for a cell that is not 3D.
  template <typename Position>
  double Quality(vtkIdType cell, const Position& position) const
  {
    const int begin = this->CellCorners[cell], end = begin + this->TrueCorners[cell];
    auto corner = [&](int c, int k) -> Vector3 { return position(this->Corners(c, k)); };
    if (begin == end)
    {
      return std::numeric_limits<double>::quiet_NaN();
    }
    if (this->Kinds[cell] == CellKind::Tetrahedron)
    {
      return InjectiveDeformation::TetrahedronScaledJacobian(
        corner(begin, 0), corner(begin, 1), corner(begin, 2), corner(begin, 3));
    }
    double smallest = std::numeric_limits<double>::infinity();
    for (int c = begin; c < end; ++c)
    {
      smallest = std::min(smallest,
        InjectiveDeformation::CornerScaledJacobian(
          corner(c, 0), corner(c, 1), corner(c, 2), corner(c, 3)));
    }
    if (this->Kinds[cell] != CellKind::Other)
    {
      // Verdict's ninth sample of a hexahedron: its principal axes, at the centre. The corner
      // tetrahedra start at the cell's points 0 to 7, oriented as the cell's type is.
      Vector3 p[8];
      for (int k = 0; k < 8; ++k)
      {
        p[k] = corner(begin + k, 0);
      }
      const bool voxel = this->Kinds[cell] == CellKind::Voxel;
      const Vector3 axes[3] = {
        voxel ? (p[1] - p[0] + p[3] - p[2] + p[5] - p[4] + p[7] - p[6]) : (p[1] - p[0] + p[2] - p[3] + p[5] - p[4] + p[6] - p[7]),
        voxel ? (p[2] - p[0] + p[3] - p[1] + p[6] - p[4] + p[7] - p[5]) : (p[3] - p[0] + p[2] - p[1] + p[7] - p[4] + p[6] - p[5]),
        p[4] - p[0] + p[5] - p[1] + p[6] - p[2] + p[7] - p[3]
      };
      const double lengths = axes[0].norm() * axes[1].norm() * axes[2].norm();
      const double centre = lengths > 0.0 ? axes[0].dot(axes[1].cross(axes[2])) / lengths : 0.0;
      smallest = std::min(smallest, this->Mirrored[cell] ? -centre : centre);
    }
    return smallest;
  }

  /// Whether `test(id)` holds for a point of cell `cell`. Safe from many threads, unlike the
  /// grid's cell access (which may copy into shared storage).
  template <typename Test>
  bool AnyPoint(vtkIdType cell, const Test& test) const
  {
    // Every point of a cell is a point of one of its corner tetrahedra.
    const int begin = this->CellCorners[cell], end = begin + this->TrueCorners[cell];
    for (int c = begin; c < end; ++c)
    {
      for (int k = 0; k < 4; ++k)
      {
        if (test(this->Corners(c, k)))
        {
          return true;
        }
      }
    }
    return false;
  }

  /// The grid of the last build.
  vtkUnstructuredGrid* GetGrid() const { return this->Grid; }

private:
  // What every volume editor requires of its input: points, at least one 3D cell, linear cells
  // only. Returns an error message, empty on success.
  static std::string CheckGrid(vtkUnstructuredGrid* grid);
  std::string Build(vtkUnstructuredGrid* grid);
  std::string BuildCorners();
  std::string BuildBoundary();

  vtkSmartPointer<vtkUnstructuredGrid> Grid;
  vtkMTimeType BuiltTime = 0;
  Tetrahedra Corners; // grid point ids, positive at rest
  std::vector<vtkIdType> CornerCell;
  std::vector<int> CellCorners;                      // offsets: a cell's corners are consecutive
  std::vector<CellKind> Kinds;
  std::vector<unsigned char> TrueCorners; // per cell: its corners (inscribed ones follow)
  std::vector<char> Mirrored;             // per cell: its type's cells are written mirrored
  std::vector<int> PointCornerOffsets, PointCorners; // the corners around each point
  std::vector<char> OnBoundary;
  vtkSmartPointer<vtkPolyData> Boundary;
  vtkSmartPointer<vtkDataArray> Labels;
  const vtkDataArray* LabelsSource = nullptr; // compared, never dereferenced
  vtkMTimeType LabelsTime = 0;
};
}
}

#endif
