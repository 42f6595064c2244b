#include "PreviewActors.h"

#include "vtkLaplacianDeformationFilter.h"
#include "vtkLaplacianDragPreview.h"

#include "vtkActor.h"
#include "vtkActorCollection.h"
#include "vtkCompositeDataIterator.h"
#include "vtkCompositeDataSet.h"
#include "vtkPointSet.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkRenderer.h"
#include "vtkSmartPointer.h"

namespace
{
// Whether `data` (or one of its blocks) has the points `points` draws.
bool HasPoints(vtkDataObject* data, vtkDataArray* points)
{
  if (auto* pointSet = vtkPointSet::SafeDownCast(data))
  {
    return pointSet->GetPoints() && pointSet->GetPoints()->GetData() == points;
  }
  auto* composite = vtkCompositeDataSet::SafeDownCast(data);
  if (!composite)
  {
    return false;
  }
  auto blocks = vtk::TakeSmartPointer(composite->NewIterator());
  for (blocks->InitTraversal(); !blocks->IsDoneWithTraversal(); blocks->GoToNextItem())
  {
    if (HasPoints(blocks->GetCurrentDataObject(), points))
    {
      return true;
    }
  }
  return false;
}
}

namespace LaplacianEditing
{
namespace Widgets
{
PreviewActors::PreviewActors()
{
  for (int part = 0; part < 2; ++part)
  {
    this->Parts[part]->SetMapper(this->Mappers[part]);
  }
}

PreviewActors::~PreviewActors()
{
  this->Remove();
}

bool PreviewActors::Show(vtkRenderer* renderer, vtkLaplacianDragPreview* preview,
  const double translation[3], const double rotation[3])
{
  const std::array<double, 6> motion = { translation[0], translation[1], translation[2],
    rotation[0], rotation[1], rotation[2] };
  if (this->Consumer && motion == this->Shown)
  {
    return true;
  }
  if (renderer != this->Renderer)
  {
    this->Remove();
  }
  vtkActor* consumer = this->Consumer ? this->Consumer.GetPointer()
    : renderer && preview          ? FindConsumer(renderer, preview)
                                   : nullptr;
  if (!consumer || !preview->Update(translation, rotation))
  {
    this->Hide();
    return false;
  }
  if (!this->Renderer)
  {
    this->Renderer = renderer;
    for (auto& part : this->Parts)
    {
      renderer->AddActor(part);
    }
  }
  if (!this->Consumer)
  {
    this->Consumer = consumer;
    this->ConsumerVisibility = consumer->GetVisibility();
    this->CopyLook(consumer);
    consumer->VisibilityOff();
  }
  this->Mappers[0]->SetInputData(preview->GetStillPart());
  this->Mappers[1]->SetInputData(preview->GetMovingPart());
  this->Shown = motion;
  return true;
}

void PreviewActors::Hide()
{
  // The parts stay in the renderer, hidden, so that their buffers on the graphics card serve
  // the next drag: the still part changes only with the region.
  for (auto& part : this->Parts)
  {
    part->VisibilityOff();
  }
  if (this->Consumer)
  {
    this->Consumer->SetVisibility(this->ConsumerVisibility);
  }
  this->Consumer = nullptr;
}

void PreviewActors::Remove()
{
  this->Hide();
  if (this->Renderer)
  {
    for (auto& part : this->Parts)
    {
      this->Renderer->RemoveActor(part);
    }
  }
  this->Renderer = nullptr;
}

void PreviewActors::CopyLook(vtkActor* consumer)
{
  for (int part = 0; part < 2; ++part)
  {
    // The actor's property, texture and placement; the mapper's colouring (lookup table, scalar
    // mode, array).
    this->Parts[part]->ShallowCopy(consumer);
    this->Parts[part]->SetMapper(this->Mappers[part]);
    this->Parts[part]->VisibilityOn();
    if (vtkMapper* mapper = consumer->GetMapper())
    {
      // vtkMapper's settings only: the OpenGL mapper's own copy takes its custom shader code
      // through deprecated accessors, which warn, and the parts have none.
      this->Mappers[part]->vtkMapper::ShallowCopy(mapper);
    }
  }
}

vtkActor* PreviewActors::FindConsumer(vtkRenderer* renderer, vtkLaplacianDragPreview* preview)
{
  vtkLaplacianDeformationFilter* filter = preview->GetFilter();
  vtkPoints* points = filter ? filter->GetOutput()->GetPoints() : nullptr;
  if (!points)
  {
    return nullptr;
  }
  vtkActorCollection* actors = renderer->GetActors();
  vtkCollectionSimpleIterator it;
  actors->InitTraversal(it);
  while (vtkActor* actor = actors->GetNextActor(it))
  {
    vtkMapper* mapper = actor->GetMapper();
    if (actor->GetVisibility() && mapper &&
      HasPoints(mapper->GetInputDataObject(0, 0), points->GetData()))
    {
      return actor;
    }
  }
  return nullptr;
}
}
}
