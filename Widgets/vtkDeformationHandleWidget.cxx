#include "vtkDeformationHandleWidget.h"

#include "vtkDeformationHandleRepresentation.h"
#include "vtkDeformationPreviewController.h"
#include "vtkLaplacianDeformationFilter.h"

#include "vtkAssemblyPath.h"
#include "vtkCallbackCommand.h"
#include "vtkCellPicker.h"
#include "vtkCommand.h"
#include "vtkDataSet.h"
#include "vtkEvent.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPickingManager.h"
#include "vtkPolyData.h"
#include "vtkProp.h"
#include "vtkPropCollection.h"
#include "vtkRenderWindowInteractor.h"
#include "vtkRenderer.h"
#include "vtkSmartPointer.h"
#include "vtkTransform.h"
#include "vtkWeakPointer.h"
#include "vtkWidgetCallbackMapper.h"
#include "vtkWidgetEvent.h"

#include <algorithm>
#include <cstdlib>

vtkStandardNewMacro(vtkDeformationHandleWidget);

struct vtkDeformationHandleWidget::vtkInternals
{
  vtkNew<vtkCellPicker> SurfacePicker;
  // The representation whose PlaceWidgetEvent reaches the filter, and the observer's tag.
  vtkWeakPointer<vtkWidgetRepresentation> ObservedRepresentation;
  unsigned long PlaceObserver = 0;
  // The drag preview of the representation's motion.
  vtkNew<vtkDeformationPreviewController> Preview;
  // The filter's commit and undo events.
  unsigned long CommitObservers[2] = { 0, 0 };
  // A press outside the handle places the handle if it is released where it went down (within
  // 3 pixels). The interactor style, which orbits meanwhile, holds the interactor's focus, so
  // the moves and the release are watched by a passive observer, which sees them all the same.
  // A passive observer must not add or remove observers, so it stays on the interactor until
  // the widget goes or moves to another interactor.
  bool PendingClick = false;
  int PressPosition[2] = { 0, 0 };
  // The one-shot timer that continues a settle the filter's SettleTimeLimit stopped (-1: none).
  int SettleTimer = -1;
  vtkWeakPointer<vtkRenderWindowInteractor> ClickInteractor;
  vtkNew<vtkCallbackCommand> ClickObserver;
  unsigned long ClickTags[2] = { 0, 0 };

  bool IsClick(const int position[2]) const
  {
    return this->PendingClick && std::abs(position[0] - this->PressPosition[0]) <= 3 &&
      std::abs(position[1] - this->PressPosition[1]) <= 3;
  }

  void WatchClicks(vtkRenderWindowInteractor* interactor)
  {
    if (this->ClickInteractor == interactor)
    {
      return;
    }
    this->StopWatchingClicks();
    this->ClickInteractor = interactor;
    this->ClickTags[0] = interactor->AddObserver(vtkCommand::MouseMoveEvent, this->ClickObserver);
    this->ClickTags[1] =
      interactor->AddObserver(vtkCommand::LeftButtonReleaseEvent, this->ClickObserver);
  }

  void StopWatchingClicks()
  {
    this->PendingClick = false;
    if (this->ClickInteractor)
    {
      this->ClickInteractor->RemoveObserver(this->ClickTags[0]);
      this->ClickInteractor->RemoveObserver(this->ClickTags[1]);
    }
    this->ClickInteractor = nullptr;
  }
};

vtkDeformationHandleWidget::vtkDeformationHandleWidget()
  : Internals(new vtkInternals)
{
  this->Internals->ClickObserver->SetClientData(this);
  this->Internals->ClickObserver->SetCallback(vtkDeformationHandleWidget::WatchClick);
  this->Internals->ClickObserver->PassiveObserverOn();
  this->Internals->SurfacePicker->SetTolerance(0.002);
  // Modifiers are bound here, in the event translator, so that applications can rebind them.
  this->CallbackMapper->SetCallbackMethod(vtkCommand::LeftButtonPressEvent, vtkEvent::NoModifier,
    0, 0, nullptr, vtkWidgetEvent::Select, this, vtkDeformationHandleWidget::SelectAction);
  this->CallbackMapper->SetCallbackMethod(vtkCommand::LeftButtonPressEvent,
    vtkEvent::ShiftModifier, 0, 0, nullptr, vtkWidgetEvent::Resize, this,
    vtkDeformationHandleWidget::ResizeAction);
  this->CallbackMapper->SetCallbackMethod(vtkCommand::LeftButtonPressEvent,
    vtkEvent::ControlModifier, 0, 0, nullptr, vtkWidgetEvent::Translate, this,
    vtkDeformationHandleWidget::ConstrainedAction);
  this->CallbackMapper->SetCallbackMethod(vtkCommand::LeftButtonReleaseEvent,
    vtkWidgetEvent::EndSelect, this, vtkDeformationHandleWidget::EndSelectAction);
  this->CallbackMapper->SetCallbackMethod(
    vtkCommand::MouseMoveEvent, vtkWidgetEvent::Move, this, vtkDeformationHandleWidget::MoveAction);
  this->CallbackMapper->SetCallbackMethod(vtkCommand::MouseWheelForwardEvent, vtkWidgetEvent::Up,
    this, vtkDeformationHandleWidget::GrowAction);
  this->CallbackMapper->SetCallbackMethod(vtkCommand::MouseWheelBackwardEvent,
    vtkWidgetEvent::Down, this, vtkDeformationHandleWidget::ShrinkAction);
  this->CallbackMapper->SetCallbackMethod(vtkCommand::TimerEvent, vtkWidgetEvent::TimedOut, this,
    vtkDeformationHandleWidget::SettleAction);
}

vtkDeformationHandleWidget::~vtkDeformationHandleWidget()
{
  this->Internals->StopWatchingClicks();
  this->Internals->Preview->SetRepresentation(nullptr);
  if (vtkWidgetRepresentation* observed = this->Internals->ObservedRepresentation)
  {
    observed->RemoveObserver(this->Internals->PlaceObserver);
  }
  this->SetDeformationFilter(nullptr);
  this->SetSurfaceProp(nullptr);
}

void vtkDeformationHandleWidget::SetRepresentation(vtkDeformationHandleRepresentation* representation)
{
  this->Superclass::SetWidgetRepresentation(representation);
  this->PairRepresentation();
}

vtkDeformationHandleRepresentation* vtkDeformationHandleWidget::GetDeformationHandleRepresentation()
{
  return vtkDeformationHandleRepresentation::SafeDownCast(this->WidgetRep);
}

void vtkDeformationHandleWidget::CreateDefaultRepresentation()
{
  if (!this->WidgetRep)
  {
    this->WidgetRep = vtkDeformationHandleRepresentation::New();
  }
}

void vtkDeformationHandleWidget::PairRepresentation()
{
  vtkInternals& internals = *this->Internals;
  if (internals.ObservedRepresentation != this->WidgetRep)
  {
    if (internals.ObservedRepresentation)
    {
      internals.ObservedRepresentation->RemoveObserver(internals.PlaceObserver);
    }
    internals.ObservedRepresentation = this->WidgetRep;
    if (this->WidgetRep)
    {
      // rep->PlaceWidget(bounds) moves and sizes the handle: the filter must edit there too.
      internals.PlaceObserver = this->WidgetRep->AddObserver(
        vtkCommand::PlaceWidgetEvent, this, &vtkDeformationHandleWidget::PushToFilter);
    }
    internals.Preview->SetRepresentation(this->GetDeformationHandleRepresentation());
  }
  vtkDeformationHandleRepresentation* rep = this->GetDeformationHandleRepresentation();
  vtkLaplacianDeformationFilter* filter = this->DeformationFilter;
  if (!filter || !rep)
  {
    return;
  }
  double center[3];
  if (this->HandleGroup == 0)
  {
    rep->SetCenter(filter->GetHandleCenter());
    // The representation works in mesh units, the filter in its RadiusUnits.
    const double scale = filter->GetRadiusScale();
    rep->SetHandleRadius(scale * filter->GetHandleRadius());
    rep->SetROIRadius(scale * filter->GetROIRadius());
  }
  else if (filter->GetHandleGroupCenter(this->HandleGroup, center))
  {
    rep->SetCenter(center);
  }
  filter->SetHandleTransform(this->HandleGroup, rep->GetTransform());
}

vtkDeformationPreviewController* vtkDeformationHandleWidget::GetPreviewController()
{
  return this->Internals->Preview;
}

void vtkDeformationHandleWidget::SetHandleGroup(int group)
{
  group = std::max(group, 0);
  if (this->HandleGroup == group)
  {
    return;
  }
  // The group left behind keeps its transform if another widget drives it.
  vtkDeformationHandleRepresentation* rep = this->GetDeformationHandleRepresentation();
  if (this->DeformationFilter && rep &&
    this->DeformationFilter->GetHandleTransform(this->HandleGroup) == rep->GetTransform())
  {
    this->DeformationFilter->SetHandleTransform(this->HandleGroup, nullptr);
  }
  this->HandleGroup = group;
  this->PairRepresentation();
  this->Modified();
}

void vtkDeformationHandleWidget::SetSurfaceProp(vtkProp* prop)
{
  if (this->SurfaceProp == prop)
  {
    return;
  }
  vtkSetObjectBodyMacro(SurfaceProp, vtkProp, prop);
  // The pick list is set here, not at the pick: the picking manager may run the picker itself.
  vtkCellPicker* picker = this->Internals->SurfacePicker;
  picker->InitializePickList();
  picker->SetPickFromList(prop != nullptr);
  if (prop)
  {
    picker->AddPickList(prop);
  }
}

void vtkDeformationHandleWidget::RegisterPickers()
{
  vtkPickingManager* manager = this->GetPickingManager();
  if (manager && this->PickingManaged)
  {
    manager->AddPicker(this->Internals->SurfacePicker, this);
  }
}

void vtkDeformationHandleWidget::SetDeformationFilter(vtkLaplacianDeformationFilter* filter)
{
  if (this->DeformationFilter == filter)
  {
    return;
  }
  unsigned long(&tags)[2] = this->Internals->CommitObservers;
  if (this->DeformationFilter)
  {
    this->DeformationFilter->RemoveObserver(tags[0]);
    this->DeformationFilter->RemoveObserver(tags[1]);
    if (this->Interacting)
    {
      this->DeformationFilter->DraggingOff(); // unpaired mid-drag: the drag ends for it
    }
    this->DeformationFilter->UnRegister(this);
  }
  this->DeformationFilter = filter;
  if (filter)
  {
    filter->Register(this);
    tags[0] = filter->AddObserver(vtkLaplacianDeformationFilter::EditCommittedEvent, this,
      &vtkDeformationHandleWidget::RestAtCurrentCenter);
    tags[1] = filter->AddObserver(vtkLaplacianDeformationFilter::CommitUndoneEvent, this,
      &vtkDeformationHandleWidget::ResetHandle);
    this->CreateDefaultRepresentation();
    this->PairRepresentation();
  }
  this->Modified();
}

void vtkDeformationHandleWidget::PushToFilter()
{
  // Only group 0 has a region of its own; the others come from labels.
  vtkDeformationHandleRepresentation* rep = this->GetDeformationHandleRepresentation();
  if (this->DeformationFilter && rep && this->HandleGroup == 0)
  {
    this->DeformationFilter->SetHandleCenter(rep->GetCenter());
    const double scale = this->DeformationFilter->GetRadiusScale();
    this->DeformationFilter->SetHandleRadius(rep->GetHandleRadius() / scale);
    this->DeformationFilter->SetROIRadius(rep->GetROIRadius() / scale);
  }
}

bool vtkDeformationHandleWidget::PickSurface(int x, int y, vtkIdType& pointId)
{
  if (!this->CurrentRenderer)
  {
    return false;
  }
  vtkCellPicker* picker = this->Internals->SurfacePicker;
  // Through the picking manager where it is on, so that the handle in front of the surface
  // wins. (vtkInteractorObserver::GetAssemblyPath does not check PickingManaged.)
  vtkAssemblyPath* path = nullptr;
  if (this->PickingManaged)
  {
    path = this->GetAssemblyPath(x, y, 0.0, picker);
  }
  else
  {
    picker->Pick(x, y, 0.0, this->CurrentRenderer);
    path = picker->GetPath();
  }
  // Without a surface prop, any prop but the handle's own.
  vtkNew<vtkPropCollection> handleActors;
  this->GetDeformationHandleRepresentation()->GetActors(handleActors);
  if (path && !this->SurfaceProp && handleActors->IsItemPresent(picker->GetViewProp()))
  {
    path = nullptr;
  }
  // The output keeps the input's point ids.
  pointId = path ? picker->GetPointId() : -1;
  return pointId >= 0;
}

void vtkDeformationHandleWidget::PlaceHandle(const double point[3])
{
  this->CreateDefaultRepresentation();
  this->GetDeformationHandleRepresentation()->SetCenter(point);
  this->PushToFilter();
  this->Render();
}

void vtkDeformationHandleWidget::ResetHandle()
{
  this->CreateDefaultRepresentation();
  this->GetDeformationHandleRepresentation()->ResetTransform();
  this->Render();
}

void vtkDeformationHandleWidget::CommitEdit()
{
  // The filter keeps the commits; its input connection stays as it is. Its event puts every
  // paired handle at rest; a refused commit leaves the edit as it is.
  if (this->DeformationFilter)
  {
    this->DeformationFilter->CommitEdit();
  }
}

bool vtkDeformationHandleWidget::UndoCommit()
{
  return this->DeformationFilter && this->DeformationFilter->UndoCommit();
}

void vtkDeformationHandleWidget::RestAtCurrentCenter()
{
  double center[3];
  this->CreateDefaultRepresentation();
  this->GetDeformationHandleRepresentation()->GetCurrentCenter(center);
  this->PlaceHandle(center);
}

void vtkDeformationHandleWidget::SelectAction(vtkAbstractWidget* widget)
{
  static_cast<vtkDeformationHandleWidget*>(widget)->BeginInteraction(false, false);
}

void vtkDeformationHandleWidget::ResizeAction(vtkAbstractWidget* widget)
{
  static_cast<vtkDeformationHandleWidget*>(widget)->BeginInteraction(true, false);
}

void vtkDeformationHandleWidget::ConstrainedAction(vtkAbstractWidget* widget)
{
  static_cast<vtkDeformationHandleWidget*>(widget)->BeginInteraction(false, true);
}

void vtkDeformationHandleWidget::BeginInteraction(bool resize, bool constrain)
{
  vtkDeformationHandleRepresentation* rep = this->GetDeformationHandleRepresentation();
  const int x = this->Interactor->GetEventPosition()[0];
  const int y = this->Interactor->GetEventPosition()[1];
  this->SetCurrentRenderer(this->Interactor->FindPokedRenderer(x, y));
  rep->SetRenderer(this->CurrentRenderer);
  const int state = rep->ComputeInteractionState(x, y);
  if (state == vtkDeformationHandleRepresentation::Outside)
  {
    // Not ours: the interactor style orbits the camera. A release at the same place is a click,
    // which places the handle (ClickAction).
    vtkInternals& internals = *this->Internals;
    internals.WatchClicks(this->Interactor);
    internals.PendingClick = true;
    internals.PressPosition[0] = x;
    internals.PressPosition[1] = y;
    return;
  }
  using Rep = vtkDeformationHandleRepresentation;
  rep->SetInteractionState(state == Rep::OnHandle ? (resize ? Rep::ResizingROI : Rep::Translating)
                                                  : (resize ? Rep::ResizingHandle : Rep::Rotating));
  rep->SetConstrainToAxis(constrain);
  double position[2] = { static_cast<double>(x), static_cast<double>(y) };
  rep->StartWidgetInteraction(position);
  this->Interacting = true;
  if (this->DeformationFilter && !resize)
  {
    this->DeformationFilter->DraggingOn(); // every frame of the drag costs about the same
  }
  this->GrabFocus(this->EventCallbackCommand);
  this->EventCallbackCommand->SetAbortFlag(1);
  this->StartInteraction();
  this->InvokeEvent(vtkCommand::StartInteractionEvent, nullptr);
  this->Render();
}

void vtkDeformationHandleWidget::WatchClick(
  vtkObject* caller, unsigned long event, void* clientData, void*)
{
  auto* self = static_cast<vtkDeformationHandleWidget*>(clientData);
  vtkInternals& internals = *self->Internals;
  const int* position = static_cast<vtkRenderWindowInteractor*>(caller)->GetEventPosition();
  if (event == vtkCommand::MouseMoveEvent)
  {
    internals.PendingClick = internals.IsClick(position); // a drag is the camera's
    return;
  }
  const bool click = internals.IsClick(position);
  internals.PendingClick = false;
  if (click && self->Enabled) // (the widget may have been switched off since the press)
  {
    self->ClickAction(position[0], position[1]);
  }
}

void vtkDeformationHandleWidget::ClickAction(int x, int y)
{
  if (this->HandleGroup != 0)
  {
    return; // a further group turns about its centroid: a click places only group 0's handle
  }
  // The picked point is resolved after the commit, so that it is the point as the user sees
  // it: the committed rest shape is the edited one.
  vtkIdType pointId = -1;
  double point[3];
  if (!this->PickSurface(x, y, pointId))
  {
    return;
  }
  this->InvokeEvent(vtkCommand::StartInteractionEvent, nullptr);
  vtkTransform* transform = this->GetDeformationHandleRepresentation()->GetTransform();
  if (this->DeformationFilter && !transform->GetMatrix()->IsIdentity())
  {
    this->DeformationFilter->CommitEdit(); // placing the handle elsewhere keeps the edit
  }
  if (this->DeformationFilter)
  {
    this->DeformationFilter->GetRestPoint(pointId, point);
  }
  else
  {
    this->Internals->SurfacePicker->GetDataSet()->GetPoint(pointId, point);
  }
  this->PlaceHandle(point);
  this->InvokeEvent(vtkCommand::EndInteractionEvent, nullptr);
}

void vtkDeformationHandleWidget::MoveAction(vtkAbstractWidget* widget)
{
  auto* self = static_cast<vtkDeformationHandleWidget*>(widget);
  if (!self->Interacting)
  {
    return;
  }
  double position[2] = { static_cast<double>(self->Interactor->GetEventPosition()[0]),
    static_cast<double>(self->Interactor->GetEventPosition()[1]) };
  self->GetDeformationHandleRepresentation()->WidgetInteraction(position);
  self->EventCallbackCommand->SetAbortFlag(1);
  self->InvokeEvent(vtkCommand::InteractionEvent, nullptr);
  self->Render(); // the filter re-solves for the new transform as the surface renders
}

void vtkDeformationHandleWidget::GrowAction(vtkAbstractWidget* widget)
{
  static_cast<vtkDeformationHandleWidget*>(widget)->ScaleRegion(1.1);
}

void vtkDeformationHandleWidget::ShrinkAction(vtkAbstractWidget* widget)
{
  static_cast<vtkDeformationHandleWidget*>(widget)->ScaleRegion(1.0 / 1.1);
}

void vtkDeformationHandleWidget::ScaleRegion(double factor)
{
  // Over the handle or a ring, the wheel resizes the ROI; elsewhere the camera zooms as usual.
  vtkDeformationHandleRepresentation* rep = this->GetDeformationHandleRepresentation();
  const int x = this->Interactor->GetEventPosition()[0];
  const int y = this->Interactor->GetEventPosition()[1];
  this->SetCurrentRenderer(this->Interactor->FindPokedRenderer(x, y));
  rep->SetRenderer(this->CurrentRenderer);
  if (this->Interacting || rep->ComputeInteractionState(x, y) == vtkDeformationHandleRepresentation::Outside)
  {
    return;
  }
  rep->SetROIRadius(std::max(factor * rep->GetROIRadius(), 1.5 * rep->GetHandleRadius()));
  this->EventCallbackCommand->SetAbortFlag(1);
  this->InvokeEvent(vtkCommand::StartInteractionEvent, nullptr);
  this->PushToFilter(); // a new region: one refactorization per wheel step
  this->InvokeEvent(vtkCommand::InteractionEvent, nullptr);
  this->InvokeEvent(vtkCommand::EndInteractionEvent, nullptr);
  this->Render();
}

void vtkDeformationHandleWidget::EndSelectAction(vtkAbstractWidget* widget)
{
  auto* self = static_cast<vtkDeformationHandleWidget*>(widget);
  if (!self->Interacting)
  {
    return;
  }
  vtkDeformationHandleRepresentation* rep = self->GetDeformationHandleRepresentation();
  const int state = rep->GetInteractionState();
  double position[2] = { static_cast<double>(self->Interactor->GetEventPosition()[0]),
    static_cast<double>(self->Interactor->GetEventPosition()[1]) };
  rep->EndWidgetInteraction(position);
  if (state == vtkDeformationHandleRepresentation::ResizingROI ||
    state == vtkDeformationHandleRepresentation::ResizingHandle)
  {
    self->PushToFilter(); // one refactorization per resize, on release
  }
  self->Interacting = false;
  if (self->DeformationFilter)
  {
    self->DeformationFilter->DraggingOff(); // the render below settles the released shape
  }
  self->ReleaseFocus();
  self->EventCallbackCommand->SetAbortFlag(1);
  self->EndInteraction();
  self->InvokeEvent(vtkCommand::EndInteractionEvent, nullptr);
  self->Render();
  self->ScheduleSettle();
}

void vtkDeformationHandleWidget::ScheduleSettle()
{
  // After the events waiting, so that a grab or a camera move comes first.
  vtkInternals& internals = *this->Internals;
  if (internals.SettleTimer < 0 && this->Interactor && this->DeformationFilter &&
    this->DeformationFilter->GetSettling())
  {
    internals.SettleTimer = this->Interactor->CreateOneShotTimer(1);
  }
}

void vtkDeformationHandleWidget::SettleAction(vtkAbstractWidget* widget)
{
  auto* self = static_cast<vtkDeformationHandleWidget*>(widget);
  vtkInternals& internals = *self->Internals;
  if (!self->CallData || internals.SettleTimer < 0 ||
    *static_cast<int*>(self->CallData) != internals.SettleTimer)
  {
    return; // another observer's timer
  }
  internals.SettleTimer = -1;
  self->EventCallbackCommand->SetAbortFlag(1);
  if (self->Interacting || !self->DeformationFilter)
  {
    return; // a grab ended the settle
  }
  // Updated here, not only through the render: the output may be drawn through a copy.
  self->DeformationFilter->ContinueSettling();
  self->DeformationFilter->Update();
  self->Render();
  self->ScheduleSettle();
}

void vtkDeformationHandleWidget::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "DeformationFilter: " << this->DeformationFilter << "\n";
  os << indent << "HandleGroup: " << this->HandleGroup << "\n";
  os << indent << "SurfaceProp: " << this->SurfaceProp << "\n";
  os << indent << "Interacting: " << this->Interacting << "\n";
  os << indent << "PreviewController:\n";
  this->Internals->Preview->PrintSelf(os, indent.GetNextIndent());
}
