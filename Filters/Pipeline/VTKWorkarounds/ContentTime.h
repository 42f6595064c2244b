// ContentTime: when a point set's points, cells or point and cell arrays last changed.
//
// Unlike GetMTime(), not when a pipeline copies the same arrays into the data set anew
// (ParaView's post filter does on every update), which would rebuild every cache on every move
// and drop the commits.
#ifndef LaplacianEditing_Pipeline_ContentTime_h
#define LaplacianEditing_Pipeline_ContentTime_h

#include "vtkLaplacianEditingFiltersModule.h" // for export macro
#include "vtkType.h"

class vtkPointSet;

namespace LaplacianEditing
{
namespace Pipeline
{
/// A vtkPolyData's four cell arrays or a vtkUnstructuredGrid's cells and types count as cells.
VTKLAPLACIANEDITINGFILTERS_EXPORT vtkMTimeType ContentTime(vtkPointSet* data);
}
}

#endif
