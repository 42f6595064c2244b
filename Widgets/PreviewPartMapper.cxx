#include "PreviewPartMapper.h"

#include "vtkActor.h"
#include "vtkCellArray.h"
#include "vtkMath.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkProperty.h"
#include "vtkRenderer.h"

namespace LaplacianEditing
{
namespace Widgets
{
vtkStandardNewMacro(PreviewPartMapper);

void PreviewPartMapper::BuildIBO(vtkRenderer* renderer, vtkActor* actor, vtkPolyData* input)
{
  if (renderer->GetSelector())
  {
    this->IndexKey = {}; // rebuilt after the selection too
    this->Superclass::BuildIBO(renderer, actor, input);
    return;
  }
  vtkCellArray* polygons = input->GetPolys();
  if (polygons->GetMTime() != this->PolygonsChecked)
  {
    this->OnlyTriangles = polygons->GetMaxCellSize() <= 3;
    this->PolygonsChecked = polygons->GetMTime();
  }
  vtkProperty* property = actor->GetProperty();
  vtkDataArray* edgeFlags = input->GetPointData()->GetAttribute(vtkDataSetAttributes::EDGEFLAG);
  const std::array<vtkMTimeType, 9> key = { input->GetVerts()->GetMTime(),
    input->GetLines()->GetMTime(), polygons->GetMTime(), input->GetStrips()->GetMTime(),
    static_cast<vtkMTimeType>(property->GetRepresentation()),
    edgeFlags ? edgeFlags->GetMTime() : 0,
    static_cast<vtkMTimeType>(property->GetEdgeVisibility()),
    static_cast<vtkMTimeType>(property->GetVertexVisibility()),
    this->OnlyTriangles || !input->GetPoints() ? 0 : input->GetPoints()->GetMTime() };
  if (key != this->IndexKey)
  {
    this->IndexKey = key;
    ++this->IndexBuilds;
    this->Superclass::BuildIBO(renderer, actor, input);
  }
}

void PreviewPartMapper::ComputeBounds()
{
  vtkPolyData* input = this->GetInput();
  if (!input || !input->GetPoints() || input->GetNumberOfPoints() == 0)
  {
    vtkMath::UninitializeBounds(this->Bounds);
    return;
  }
  // The ranges vtkDataArray caches, which the vertex buffer's shift and scale read next.
  vtkDataArray* points = input->GetPoints()->GetData();
  for (int component = 0; component < 3; ++component)
  {
    points->GetRange(this->Bounds + 2 * component, component);
  }
}
}
}
