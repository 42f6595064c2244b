// PieceEdit: one piece's share of an edit solved on another rank.
//
// The rank that solves a distributed edit makes one per piece, once per region: which of the
// piece's points the region moves, from which rows and with which EditRole; the rest positions
// of the vertices around them; and the part of the normal refresher's index on the piece, whose
// triangles may reach into other pieces. The piece then writes its output from the positions
// of its rows alone. Where the edit is affine in the handle maps, the rows' affine form comes
// along too, and a move needs only the maps' entries: the piece places its rows itself.
#ifndef LaplacianEditing_Parallel_PieceEdit_h
#define LaplacianEditing_Parallel_PieceEdit_h

#include "AffineRows.h"
#include "EditTypes.h"
#include "NormalRefresher.h"

#include <cstdint>
#include <vector>

class vtkDataArray;

namespace LaplacianEditing
{
namespace Parallel
{
class PieceEdit
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
  void Build(const Pipeline::EditState& edit, const Range& piece, bool affine);

  /// Whether `edit` is affine in the handle maps, and then the maps' entries
  /// (HandleMapParameters); the positions of some of its rows.
  static bool GetAffineParameters(const Pipeline::EditState& edit, Eigen::VectorXd& parameters);
  static Positions GetRowPositions(
    const Pipeline::EditState& edit, const std::vector<int>& rows);

  /// The region rows whose positions the piece needs, in the order Write takes them.
  const std::vector<int>& GetRows() const { return this->Rows; }

  /// The rows' positions for the maps' entries (HandleMapParameters).
  Positions Evaluate(const Eigen::VectorXd& parameters) const
  {
    return this->Affine.Evaluate(parameters);
  }

  /// The share as numbers, to send, and back; Unpack returns false on a malformed message.
  std::vector<double> Pack() const;
  bool Unpack(const std::vector<double>& message);

  /// The piece's edit for the rows at `positions` (the core's coordinates), as the output
  /// writer takes it; false when the piece has none (it keeps its points and normals).
  bool GetEdit(const Positions& positions, Pipeline::OutputEdit& edit) const;

private:
  // The core's frame: input = core / Scale + Center.
  Vector3 Center = Vector3::Zero();
  double Scale = 1.0;
  std::vector<int> Rows;
  // Per vertex of the piece's normal index: its rest position and its slot in Rows (-1 fixed).
  std::vector<Vector3> Rest;
  std::vector<int> SlotOfVertex;
  // The piece's points in the region: their ids in the piece, slots in Rows and roles.
  Pipeline::MovedPoints Moved;
  std::uint64_t Version = 0; // of the share, for the writer
  Pipeline::NormalRefresher Normals;
  AffineRows Affine;
};
}
}

#endif
