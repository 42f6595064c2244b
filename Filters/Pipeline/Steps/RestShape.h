// RestShape: the shape an edit starts from: the input, or the input with committed points.
//
// CommitEdit makes an edit's result the rest shape of the next edit without touching the
// pipeline connection; Undo goes back one commit. A new input, or new content in the same
// input, forgets the commits.
#ifndef LaplacianEditing_Pipeline_RestShape_h
#define LaplacianEditing_Pipeline_RestShape_h

#include "vtkPointSet.h" // for vtkSmartPointer<vtkPointSet>
#include "vtkPolyData.h" // for the vtkPolyData overload
#include "vtkSmartPointer.h"

#include <vector>

class vtkPoints;

namespace LaplacianEditing
{
namespace Pipeline
{
class RestShape
{
public:
  /// The rest shape of an edit of `input` (a surface or a volume mesh): `input` itself, or,
  /// after a commit, a shallow copy of it with the committed points.
  vtkPointSet* Get(vtkPointSet* input);
  vtkPolyData* Get(vtkPolyData* input)
  {
    return static_cast<vtkPolyData*>(this->Get(static_cast<vtkPointSet*>(input)));
  }

  /// Makes a copy of `points` the rest positions of the next edit.
  void Commit(vtkPoints* points);
  /// Forgets the last commit; false if there is none.
  bool Undo();
  int GetNumberOfCommits() const { return static_cast<int>(this->Commits.size()); }

  /// The rest position of point `id` of `input`; false for an id it does not have.
  bool GetPoint(vtkPointSet* input, vtkIdType id, double point[3]) const;

private:
  // Committed rest positions, newest last, for the input of the given content time.
  std::vector<vtkSmartPointer<vtkPoints>> Commits;
  vtkMTimeType CommittedInput = 0;
  vtkPointSet* LastInput = nullptr;
  vtkSmartPointer<vtkPointSet> CommittedRest;
};

}
}

#endif
