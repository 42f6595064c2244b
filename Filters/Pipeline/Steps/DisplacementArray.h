// DisplacementArray: a filter's Displacement point array, its output points minus its rest
// points, written in place with them (OutputArray): a move writes its region's tuples.
#ifndef LaplacianEditing_Pipeline_DisplacementArray_h
#define LaplacianEditing_Pipeline_DisplacementArray_h

#include "OutputArray.h"

#include "vtkSmartPointer.h"

#include <cstdint>
#include <vector>

class vtkDataArray;
class vtkPoints;

namespace LaplacianEditing
{
namespace Pipeline
{
class DisplacementArray
{
public:
  void SetPipelineHolders(const OutputArray::Holders& holders)
  {
    this->Array.SetPipelineHolders(holders);
  }

  /// `moved` minus `rest` at the points `ids`, zero elsewhere; `key` changes with every update
  /// (OutputArray::Update). Of the points' value type, three components, named Displacement.
  vtkDataArray* Update(
    vtkPoints* rest, vtkPoints* moved, const std::vector<vtkIdType>& ids, std::uint64_t key);

private:
  OutputArray Array;
  vtkSmartPointer<vtkDataArray> Zeros; // the rest: nothing moved
};
}
}

#endif
