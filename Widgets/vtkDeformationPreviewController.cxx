#include "vtkDeformationPreviewController.h"

#include "PreviewActors.h"
#include "vtkDeformationHandleRepresentation.h"
#include "vtkLaplacianDeformationFilter.h"
#include "vtkLaplacianDragPreview.h"

#include "vtkCommand.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkWeakPointer.h"

vtkStandardNewMacro(vtkDeformationPreviewController);

struct vtkDeformationPreviewController::vtkInternals
{
  vtkWeakPointer<vtkDeformationHandleRepresentation> Representation;
  unsigned long Observer = 0;
  vtkNew<vtkLaplacianDragPreview> Preview;
  LaplacianEditing::Widgets::PreviewActors Actors;

  void StopObserving()
  {
    if (this->Representation)
    {
      this->Representation->RemoveObserver(this->Observer);
    }
    this->Representation = nullptr;
  }
};

vtkDeformationPreviewController::vtkDeformationPreviewController()
  : Internals(new vtkInternals)
{
}

vtkDeformationPreviewController::~vtkDeformationPreviewController()
{
  this->Internals->Actors.Remove();
  this->Internals->StopObserving();
}

void vtkDeformationPreviewController::SetRepresentation(
  vtkDeformationHandleRepresentation* representation)
{
  vtkInternals& internals = *this->Internals;
  if (internals.Representation == representation)
  {
    return;
  }
  internals.Actors.Remove();
  internals.StopObserving();
  internals.Representation = representation;
  if (representation)
  {
    // A new motion (a drag, or ParaView's properties), or the representation hidden.
    internals.Observer = representation->AddObserver(
      vtkCommand::ModifiedEvent, this, &vtkDeformationPreviewController::Update);
  }
  this->Update();
  this->Modified();
}

vtkDeformationHandleRepresentation* vtkDeformationPreviewController::GetRepresentation()
{
  return this->Internals->Representation;
}

void vtkDeformationPreviewController::SetFilter(vtkLaplacianDeformationFilter* filter)
{
  if (filter != this->Internals->Preview->GetFilter())
  {
    this->Internals->Actors.Hide();
    this->Internals->Preview->SetFilter(filter);
    this->Update();
    this->Modified();
  }
}

vtkLaplacianDeformationFilter* vtkDeformationPreviewController::GetFilter()
{
  return this->Internals->Preview->GetFilter();
}

void vtkDeformationPreviewController::SetPreviewing(vtkTypeBool previewing)
{
  if (this->Previewing != previewing)
  {
    this->Previewing = previewing;
    this->Update();
    this->Modified();
  }
}

int vtkDeformationPreviewController::IsPreviewShown()
{
  return this->Internals->Actors.IsShown() ? 1 : 0;
}

double vtkDeformationPreviewController::GetPreviewTime()
{
  return this->Internals->Preview->GetUpdateTime();
}

void vtkDeformationPreviewController::Update()
{
  // A hidden representation previews nothing, so that the output's actor stays.
  vtkInternals& internals = *this->Internals;
  vtkDeformationHandleRepresentation* rep = internals.Representation;
  if (this->Previewing && rep && rep->GetRenderer() && rep->GetVisibility())
  {
    internals.Actors.Show(
      rep->GetRenderer(), internals.Preview, rep->GetTranslation(), rep->GetRotationAngles());
  }
  else
  {
    internals.Actors.Hide();
  }
}

void vtkDeformationPreviewController::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Representation: " << this->GetRepresentation() << "\n";
  os << indent << "Filter: " << this->GetFilter() << "\n";
  os << indent << "Previewing: " << (this->Previewing ? "On" : "Off")
     << (this->IsPreviewShown() ? " (shown)" : "") << "\n";
}
