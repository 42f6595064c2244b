#include "CachedRangePoints.h"

#include "vtkDataArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkNew.h"
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

void CachedRangePoints::StoreRanges(vtkDataArray* data, const double* ranges, bool finite)
{
  const int components = data->GetNumberOfComponents();
  vtkNew<vtkInformationVector> perComponent;
  perComponent->SetNumberOfInformationObjects(components);
  for (int c = 0; c < components; ++c)
  {
    perComponent->GetInformationObject(c)->Set(vtkDataArray::COMPONENT_RANGE(), ranges + 2 * c, 2);
  }
  data->GetInformation()->Set(
    finite ? vtkAbstractArray::PER_FINITE_COMPONENT() : vtkAbstractArray::PER_COMPONENT(), perComponent);
}
}
}
