/**
 * @class   vtkLaplacianPieceEdit
 * @brief   one piece's share of an edit solved on another rank (not wrapped)
 *
 * The rank that solves a distributed edit makes one per piece, once per region: which of the
 * piece's points the region moves, from which rows and with which EditRole; the rest positions
 * of the vertices around them; and the part of the normal refresher's index on the piece, whose
 * triangles may reach into other pieces. The piece then writes its output from the positions
 * of its rows alone. Where the edit is affine in the handle maps, the rows' affine form comes
 * along too, and a move needs only the maps' entries: the piece places its rows itself.
 */
#ifndef vtkLaplacianPieceEdit_h
#define vtkLaplacianPieceEdit_h

#include "AffineRows.h"
#include "vtkLaplacianNormalRefresher.h"
#include "vtkLaplacianOutputWriter.h"

#include <cstdint>

#include <vector>

class vtkDataArray;
class vtkLaplacianSurfaceAdapter;
class vtkPolyData;

namespace LaplacianEditing
{
class LaplacianEditor;
}

/// An edit as the filter that solved it holds it (vtkLaplacianDeformationFilter::GetEditState).
struct vtkLaplacianEditState
{
  const vtkLaplacianSurfaceAdapter* Surface = nullptr;
  const vtkLaplacianNormalRefresher* Normals = nullptr;
  const LaplacianEditing::LaplacianEditor* Editor = nullptr;
  const std::vector<LaplacianEditing::AffineMap>* Maps = nullptr;
  const LaplacianEditing::Positions* Solution = nullptr;
  /// Changes whenever the surface, region, system or rotation model is rebuilt.
  unsigned long ModelVersion = 0;
};

class vtkLaplacianPieceEdit
{
public:
  /// The points and cells of the surface's input that belong to one piece: the ranges
  /// [FirstPoint, FirstPoint + NumberOfPoints) and [FirstCell, FirstCell + NumberOfCells), and
  /// their ids in the piece.
  struct Range
  {
    vtkDataArray* PointIds = nullptr;
    vtkIdType FirstPoint = 0;
    vtkIdType NumberOfPoints = 0;
    vtkDataArray* CellIds = nullptr;
    vtkIdType FirstCell = 0;
    vtkIdType NumberOfCells = 0;
  };

  /// The share of `piece` in `edit`; with `affine` (the edit must be affine in the handle
  /// maps), the rows' affine form too.
  void Build(const vtkLaplacianEditState& edit, const Range& piece, bool affine);

  /// Whether `edit` is affine in the handle maps, and then the maps' entries
  /// (HandleMapParameters); the positions of some of its rows.
  static bool GetAffineParameters(const vtkLaplacianEditState& edit, Eigen::VectorXd& parameters);
  static LaplacianEditing::Positions GetRowPositions(
    const vtkLaplacianEditState& edit, const std::vector<int>& rows);

  /// The region rows whose positions the piece needs, in the order Write takes them.
  const std::vector<int>& GetRows() const { return this->Rows; }

  /// The rows' positions for the maps' entries (HandleMapParameters).
  LaplacianEditing::Positions Evaluate(const Eigen::VectorXd& parameters) const
  {
    return this->Affine.Evaluate(parameters);
  }

  /// The share as numbers, to send, and back; Unpack returns false on a malformed message.
  std::vector<double> Pack() const;
  bool Unpack(const std::vector<double>& message);

  /// The piece's edit for the rows at `positions` (the core's coordinates), as the output
  /// writer takes it; false when the piece has none (it keeps its points and normals).
  bool GetEdit(const LaplacianEditing::Positions& positions, vtkLaplacianOutputEdit& edit) const;

private:
  // The core's frame: input = core / Scale + Center.
  LaplacianEditing::Vector3 Center = LaplacianEditing::Vector3::Zero();
  double Scale = 1.0;
  std::vector<int> Rows;
  // Per vertex of the piece's normal index: its rest position and its slot in Rows (-1 fixed).
  std::vector<LaplacianEditing::Vector3> Rest;
  std::vector<int> SlotOfVertex;
  // The piece's points in the region: their ids in the piece, slots in Rows and roles.
  vtkLaplacianMovedPoints Moved;
  std::uint64_t Version = 0; // of the share, for the writer
  vtkLaplacianNormalRefresher Normals;
  LaplacianEditing::AffineRows Affine;
};

#endif
