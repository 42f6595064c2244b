#include "ContentTime.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkUnsignedCharArray.h"
#include "vtkUnstructuredGrid.h"

#include <algorithm>

namespace LaplacianEditing
{
namespace Pipeline
{
vtkMTimeType ContentTime(vtkPointSet* data)
{
  vtkMTimeType time = data->GetPoints() ? data->GetPoints()->GetMTime() : 0;
  auto include = [&time](vtkObject* part) { time = std::max(time, part ? part->GetMTime() : 0); };
  if (auto* surface = vtkPolyData::SafeDownCast(data))
  {
    for (vtkCellArray* cells :
      { surface->GetVerts(), surface->GetLines(), surface->GetPolys(), surface->GetStrips() })
    {
      include(cells);
    }
  }
  if (auto* grid = vtkUnstructuredGrid::SafeDownCast(data))
  {
    include(grid->GetCells());
    include(grid->GetCellTypesArray());
  }
  for (vtkFieldData* attributes : { static_cast<vtkFieldData*>(data->GetPointData()),
         static_cast<vtkFieldData*>(data->GetCellData()) })
  {
    for (int i = 0; i < attributes->GetNumberOfArrays(); ++i)
    {
      include(attributes->GetAbstractArray(i));
    }
  }
  return time;
}
}
}
