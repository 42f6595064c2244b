#include "CachedRangePoints.h"

#include "vtkDataArray.h"
#include "vtkObjectFactory.h"

namespace LaplacianEditing
{
namespace Pipeline
{
vtkStandardNewMacro(CachedRangePoints);

void CachedRangePoints::ComputeBounds()
{
  if (this->GetMTime() <= this->ComputeTime)
  {
    return;
  }
  if (this->Data->GetNumberOfTuples() == 0 || this->Data->GetNumberOfComponents() != 3)
  {
    this->Superclass::ComputeBounds();
    return;
  }
  for (int component = 0; component < 3; ++component)
  {
    this->Data->GetRange(this->Bounds + 2 * component, component);
  }
  this->ComputeTime.Modified();
}
}
}
