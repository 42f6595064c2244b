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
  if (this->Data->GetNumberOfTuples() == 0)
  {
    this->Superclass::ComputeBounds();
    return;
  }
  RangeBounds(this->Data, this->Bounds);
  this->ComputeTime.Modified();
}

void CachedRangePoints::RangeBounds(vtkDataArray* data, double bounds[6])
{
  for (int component = 0; component < 3; ++component)
  {
    data->GetRange(bounds + 2 * component, component);
  }
}
}
}
