#include "OnlySurface.h"

#include "vtkCompositeDataIterator.h"
#include "vtkCompositeDataSet.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"

namespace LaplacianEditing
{
namespace Representations
{
vtkPolyData* OnlySurface(vtkDataObject* data)
{
  auto* composite = vtkCompositeDataSet::SafeDownCast(data);
  if (!composite)
  {
    return vtkPolyData::SafeDownCast(data);
  }
  vtkPolyData* surface = nullptr;
  auto iterator = vtkSmartPointer<vtkCompositeDataIterator>::Take(composite->NewIterator());
  iterator->SkipEmptyNodesOn();
  for (iterator->InitTraversal(); !iterator->IsDoneWithTraversal(); iterator->GoToNextItem())
  {
    auto* leaf = vtkPolyData::SafeDownCast(iterator->GetCurrentDataObject());
    if (!leaf || surface)
    {
      return nullptr;
    }
    surface = leaf;
  }
  return surface;
}
}
}
