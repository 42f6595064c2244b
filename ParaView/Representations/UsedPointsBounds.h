// UsedPointsBounds: a surface's cells' bounds (the bounds of the points its cells use), known
// without a pass over the cells while only the points move.
//
// ParaView's representation and its mapper take a surface's bounds from its cells
// (vtkPolyData::GetCellsBounds, so that unused points do not count): a pass over every cell
// whenever a point moved, cached on each data object. After an edit moved points, and kept the
// cells, the representation's geometry and the piece delivered to its mapper each made that pass,
// most of a drag's release on a 2M-point surface (performance.md, "Frames per second during a
// drag"). Here the pass is made once per set of cells, to learn whether every point belongs to a
// cell. Where one does, the cells' bounds are the points' bounds (an edit's output keeps them as
// cached ranges, CachedRangePoints), and Fill puts them in the data object's own cache, where VTK's
// pass would have put them.
#ifndef LaplacianEditing_Representations_UsedPointsBounds_h
#define LaplacianEditing_Representations_UsedPointsBounds_h

#include "vtkType.h"
#include "vtkWeakPointer.h"

#include <array>

class vtkCellArray;
class vtkDataObject;
class vtkPolyData;

namespace LaplacianEditing
{
namespace Representations
{
class UsedPointsBounds
{
public:
  /// Fills the cells' bounds of `data`, a surface or a composite of one surface, where its cells
  /// use every point; true if it did. Otherwise VTK computes them, as before.
  bool Fill(vtkDataObject* data);

  /// How many times the cells were passed over.
  int GetNumberOfCellPasses() const { return this->CellPasses; }

private:
  bool AllPointsUsed(vtkPolyData* surface);

  // The cells last checked, and whether they use every one of NumberOfPoints points.
  std::array<vtkWeakPointer<vtkCellArray>, 4> Cells;
  std::array<vtkMTimeType, 4> CellsTimes = {};
  vtkIdType NumberOfPoints = -1;
  bool AllUsed = false;
  int CellPasses = 0;
};
}
}

#endif
