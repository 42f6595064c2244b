// OutputWriter: writes a solved edit into a filter's output: moved points, refreshed normals and the EditRole array, in place between updates.
//
// The output is the rest surface with all its point and cell data; the writer replaces the
// points, the point and cell normals near the edit, and adds EditRole. Every point outside the
// region keeps its rest coordinates exactly.
//
// In-place contract: the output's points, normals and EditRole arrays are the writer's, kept
// between updates (OutputArray). A handle move rewrites only the region's points,
// the normals of the region and its ring, and the roles where they change, and marks those
// arrays Modified; nothing in proportion to the mesh is allocated or copied. A whole copy is
// made for a new rest array (a new input or new content, a commit) and whenever the array the
// output held is still held by someone else than the outputs of the filters connected to the
// output (a reference kept, a shallow copy, a rendering cache): such an array is never written
// again (copy on write). Those outputs share it until the next update recomputes them.
#ifndef LaplacianEditing_Pipeline_OutputWriter_h
#define LaplacianEditing_Pipeline_OutputWriter_h

#include "DisplacementArray.h"
#include "EditTypes.h"
#include "OutputArray.h"

#include "vtkSmartPointer.h"

#include <cstdint>
#include <vector>

class vtkAlgorithm;
class vtkDataArray;
class vtkLookupTable;
class vtkPolyData;
class vtkSignedCharArray;

namespace LaplacianEditing
{
namespace Pipeline
{
class OutputWriter
{
public:
  using Edit = OutputEdit;

  /// Writes `edit` into `output`, a shallow copy of `rest`; null: nothing moved (the rest
  /// arrays, and every role fixed). With `options`: EditRole, the active scalars where the output
  /// has none, with an indexed lookup table of the paper's Fig. 2 colours (RoleColors), and
  /// Displacement.
  void Write(vtkPolyData* rest, vtkPolyData* output, const Edit* edit, const OutputOptions& options);

  /// The filter whose output port 0 the writer writes: references that the outputs of the
  /// filters connected to it hold do not count as sharing.
  void SetFilter(vtkAlgorithm* filter);

  /// How many references to `object` the outputs of the filters connected to `filter`'s port 0
  /// hold (as their points, their points' array unless through `ownPoints`, or a point or cell
  /// array).
  static int CountDownstreamReferences(
    vtkAlgorithm* filter, vtkObjectBase* object, vtkObjectBase* ownPoints);
  /// The same count as the output arrays of `filter` take it (OutputArray::SetPipelineHolders).
  static OutputArray::Holders PipelineHolders(vtkAlgorithm* filter);

  /// Whole copies of a rest array made so far (points, normals and roles), for tests.
  vtkIdType GetNumberOfCopies() const;

private:
  vtkDataArray* UpdateRoles(vtkIdType count, const Edit* edit);
  // The moved points in the order of their solution rows (their ids, rows and offsets), once
  // per region. The points' write reads the solution in that order: in the ids' order it read
  // three columns at random a point, the largest part of a 610k-vertex region's write; and it
  // reads the rows and offsets copied in that order, where their lookup through the points'
  // indices in edit.Moved was, at random again, 37% of the write's samples.
  void OrderByRows(const Edit& edit);

  OutputArray Points;
  OutputArray PointNormals;
  OutputArray CellNormals;
  OutputArray Roles;
  DisplacementArray Displacement;
  // EditRole's rest: every point fixed; never written.
  vtkSmartPointer<vtkSignedCharArray> FixedRoles;
  vtkSmartPointer<vtkLookupTable> RoleColors;
  std::uint64_t Writes = 0;
  std::vector<vtkIdType> RowOrderedIds;
  std::vector<int> RowOrderedRows;
  std::vector<Vector3> RowOrderedOffsets; // empty where edit.Moved's are
  std::uint64_t RowOrderVersion = ~std::uint64_t(0);
};

}
}

#endif
