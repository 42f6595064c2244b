#include "vtkDeformationHandleRepresentation.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkCellPicker.h"
#include "vtkCommand.h"
#include "vtkInteractorObserver.h"
#include "vtkMath.h"
#include "vtkMatrix4x4.h"
#include "vtkObjectFactory.h"
#include "vtkPickingManager.h"
#include "vtkPolyDataMapper.h"
#include "vtkPropCollection.h"
#include "vtkProperty.h"
#include "vtkRegularPolygonSource.h"
#include "vtkRenderer.h"
#include "vtkSphereSource.h"
#include "vtkTransform.h"
#include "vtkTubeFilter.h"
#include "vtkWindow.h"

#include <algorithm>
#include <cmath>

vtkStandardNewMacro(vtkDeformationHandleRepresentation);

vtkDeformationHandleRepresentation::vtkDeformationHandleRepresentation()
{
  this->InteractionState = Outside;
  this->HandleProperty = vtkProperty::New();
  // Opaque wire spheres: the surface under the handle stays visible and sharp.
  this->HandleProperty->SetColor(0.95, 0.85, 0.10); // the paper's yellow handle
  this->HandleProperty->SetRepresentationToWireframe();
  this->HandleProperty->SetLineWidth(1.5);
  this->SelectedHandleProperty = vtkProperty::New();
  this->SelectedHandleProperty->DeepCopy(this->HandleProperty);
  this->SelectedHandleProperty->SetColor(1.0, 0.55, 0.0);
  this->SelectedHandleProperty->SetLineWidth(2.5);
  this->RingProperty = vtkProperty::New();
  this->RingProperty->SetColor(0.2, 0.45, 0.95);

  this->HandleSource->SetThetaResolution(24);
  this->HandleSource->SetPhiResolution(12);
  this->HandleMapper->SetInputConnection(this->HandleSource->GetOutputPort());
  this->HandleActor->SetMapper(this->HandleMapper);
  this->HandleActor->SetProperty(this->HandleProperty);

  this->RingSource->SetNumberOfSides(64);
  this->RingSource->GeneratePolygonOff();
  this->RingSource->GeneratePolylineOn();
  this->RingTube->SetInputConnection(this->RingSource->GetOutputPort());
  this->RingTube->SetNumberOfSides(8);
  this->RingMapper->SetInputConnection(this->RingTube->GetOutputPort());
  this->RingActor->SetMapper(this->RingMapper);
  this->RingActor->SetProperty(this->RingProperty);

  this->ROISource->SetThetaResolution(24);
  this->ROISource->SetPhiResolution(12);
  this->ROIMapper->SetInputConnection(this->ROISource->GetOutputPort());
  this->ROIActor->SetMapper(this->ROIMapper);
  this->ROIActor->GetProperty()->SetRepresentationToWireframe();
  this->ROIActor->GetProperty()->SetColor(0.85, 0.2, 0.15);

  this->ROIActor->VisibilityOff();

  for (vtkCellPicker* picker : { this->HandlePicker.Get(), this->RingPicker.Get() })
  {
    picker->SetTolerance(0.005);
    picker->PickFromListOn();
  }
  this->HandlePicker->AddPickList(this->HandleActor);
  this->RingPicker->AddPickList(this->RingActor);
  this->UpdateTransform();
}

vtkDeformationHandleRepresentation::~vtkDeformationHandleRepresentation()
{
  this->HandleProperty->Delete();
  this->SelectedHandleProperty->Delete();
  this->RingProperty->Delete();
}

vtkTransform* vtkDeformationHandleRepresentation::GetTransform()
{
  return this->Transform;
}

void vtkDeformationHandleRepresentation::SetCenter(double x, double y, double z)
{
  this->Center[0] = x;
  this->Center[1] = y;
  this->Center[2] = z;
  this->ResetTransform();
}

void vtkDeformationHandleRepresentation::ResetTransform()
{
  vtkMath::Identity3x3(this->Rotation);
  std::fill(this->Translation, this->Translation + 3, 0.0);
  this->UpdateTransform();
}

void vtkDeformationHandleRepresentation::UpdateTransform()
{
  // x' = R (x - c) + c + t
  vtkNew<vtkMatrix4x4> matrix;
  double rotatedCenter[3];
  vtkMath::Multiply3x3(this->Rotation, this->Center, rotatedCenter);
  for (int r = 0; r < 3; ++r)
  {
    for (int c = 0; c < 3; ++c)
    {
      matrix->SetElement(r, c, this->Rotation[r][c]);
    }
    matrix->SetElement(r, 3, this->Center[r] - rotatedCenter[r] + this->Translation[r]);
  }
  this->Transform->SetMatrix(matrix);
  this->Modified();
}

void vtkDeformationHandleRepresentation::GetCurrentCenter(double center[3])
{
  for (int i = 0; i < 3; ++i)
  {
    center[i] = this->Center[i] + this->Translation[i];
  }
}

void vtkDeformationHandleRepresentation::PlaceWidget(double bds[6])
{
  // As VTK's representations do: bounds scaled by PlaceFactor about their centre.
  double bounds[6], center[3];
  this->AdjustBounds(bds, bounds, center);
  std::copy(bounds, bounds + 6, this->InitialBounds);
  double size = 0.0, diagonal2 = 0.0;
  for (int i = 0; i < 3; ++i)
  {
    const double side = bounds[2 * i + 1] - bounds[2 * i];
    size = std::max(size, side);
    diagonal2 += side * side;
  }
  this->InitialLength = std::sqrt(diagonal2);
  this->SetHandleRadius(0.05 * size);
  this->SetROIRadius(0.3 * size);
  this->SetCenter(center);
  // The widget passes the new handle on to its filter.
  this->InvokeEvent(vtkCommand::PlaceWidgetEvent, nullptr);
}

void vtkDeformationHandleRepresentation::RegisterPickers()
{
  // Called by SetRenderer and SetPickingManaged of vtkWidgetRepresentation. Unmanaged pickers
  // stay out of the manager, where they would compete with other widgets' picks.
  vtkPickingManager* manager = this->GetPickingManager();
  if (manager && this->PickingManaged)
  {
    manager->AddPicker(this->HandlePicker, this);
    manager->AddPicker(this->RingPicker, this);
  }
}

void vtkDeformationHandleRepresentation::DisplayToViewPlane(double x, double y, double world[3])
{
  double center[3], display[3], point[4];
  this->GetCurrentCenter(center);
  vtkInteractorObserver::ComputeWorldToDisplay(this->Renderer, center[0], center[1], center[2], display);
  vtkInteractorObserver::ComputeDisplayToWorld(this->Renderer, x, y, display[2], point);
  std::copy(point, point + 3, world);
}

int vtkDeformationHandleRepresentation::ComputeInteractionState(int X, int Y, int)
{
  if (!this->Renderer)
  {
    return this->InteractionState = Outside;
  }
  this->BuildRepresentation(); // pick what is drawn now
  if (this->GetAssemblyPath(X, Y, 0.0, this->HandlePicker))
  {
    this->InteractionState = OnHandle;
  }
  else if (this->GetAssemblyPath(X, Y, 0.0, this->RingPicker))
  {
    this->InteractionState = OnRing;
  }
  else
  {
    this->InteractionState = Outside;
  }
  return this->InteractionState;
}

void vtkDeformationHandleRepresentation::StartWidgetInteraction(double eventPosition[2])
{
  this->StartPosition[0] = eventPosition[0];
  this->StartPosition[1] = eventPosition[1];
  this->DisplayToViewPlane(eventPosition[0], eventPosition[1], this->StartWorld);
  std::copy(this->Translation, this->Translation + 3, this->StartTranslation);
  for (int r = 0; r < 3; ++r)
  {
    std::copy(this->Rotation[r], this->Rotation[r] + 3, this->StartRotation[r]);
  }
  this->Highlight(true);
  this->ROIActor->SetVisibility(this->InteractionState == ResizingROI);
}

void vtkDeformationHandleRepresentation::WidgetInteraction(double eventPosition[2])
{
  double world[3];
  this->DisplayToViewPlane(eventPosition[0], eventPosition[1], world);
  double center[3];
  this->GetCurrentCenter(center);
  switch (this->InteractionState)
  {
    case Translating:
    {
      double motion[3];
      vtkMath::Subtract(world, this->StartWorld, motion);
      if (this->ConstrainToAxis)
      {
        // Keep the component the motion follows most.
        const int axis = static_cast<int>(std::max_element(motion, motion + 3,
                           [](double a, double b) { return std::abs(a) < std::abs(b); }) -
          motion);
        for (int i = 0; i < 3; ++i)
        {
          motion[i] = i == axis ? motion[i] : 0.0;
        }
      }
      vtkMath::Add(this->StartTranslation, motion, this->Translation);
      break;
    }
    case Rotating:
    {
      // The angle swept around the centre on screen, about the view direction.
      double display[3];
      vtkInteractorObserver::ComputeWorldToDisplay(
        this->Renderer, center[0], center[1], center[2], display);
      const double from = std::atan2(this->StartPosition[1] - display[1], this->StartPosition[0] - display[0]);
      const double to = std::atan2(eventPosition[1] - display[1], eventPosition[0] - display[0]);
      double axis[3];
      this->Renderer->GetActiveCamera()->GetDirectionOfProjection(axis);
      vtkNew<vtkTransform> turn;
      turn->RotateWXYZ(vtkMath::DegreesFromRadians(from - to), axis);
      double turnMatrix[3][3];
      for (int r = 0; r < 3; ++r)
      {
        for (int c = 0; c < 3; ++c)
        {
          turnMatrix[r][c] = turn->GetMatrix()->GetElement(r, c);
        }
      }
      vtkMath::Multiply3x3(turnMatrix, this->StartRotation, this->Rotation);
      break;
    }
    case ResizingROI:
      this->ROIRadius = std::max(std::sqrt(vtkMath::Distance2BetweenPoints(world, center)),
        1.5 * this->HandleRadius);
      break;
    case ResizingHandle:
      this->HandleRadius = std::min(
        std::max(std::sqrt(vtkMath::Distance2BetweenPoints(world, center)), 1e-6 * this->ROIRadius),
        0.9 * this->ROIRadius);
      break;
    default:
      return;
  }
  this->UpdateTransform();
}

void vtkDeformationHandleRepresentation::EndWidgetInteraction(double[2])
{
  this->Highlight(false);
  this->ROIActor->VisibilityOff();
  this->InteractionState = Outside;
}

void vtkDeformationHandleRepresentation::Highlight(bool on)
{
  this->HandleActor->SetProperty(on ? this->SelectedHandleProperty : this->HandleProperty);
}

void vtkDeformationHandleRepresentation::BuildRepresentation()
{
  if (!this->Renderer || !this->Renderer->GetActiveCamera())
  {
    return;
  }
  // Rebuild when the representation or the camera changed.
  vtkCamera* camera = this->Renderer->GetActiveCamera();
  if (this->BuildTime > this->GetMTime() && this->BuildTime > camera->GetMTime())
  {
    return;
  }
  double center[3], normal[3];
  this->GetCurrentCenter(center);
  camera->GetDirectionOfProjection(normal);
  this->HandleSource->SetCenter(center);
  this->HandleSource->SetRadius(this->HandleRadius);
  this->RingSource->SetCenter(center);
  this->RingSource->SetNormal(normal);
  this->RingSource->SetRadius(1.4 * this->HandleRadius);
  this->RingTube->SetRadius(0.08 * this->HandleRadius);
  this->ROISource->SetCenter(center);
  this->ROISource->SetRadius(this->ROIRadius);
  // The pickers read the mappers' inputs: bring them up to date now, not at the next render.
  this->HandleSource->Update();
  this->RingTube->Update();
  this->ROISource->Update();
  this->BuildTime.Modified();
}

double* vtkDeformationHandleRepresentation::GetBounds()
{
  double center[3];
  this->GetCurrentCenter(center);
  const double r = std::max(this->ROIRadius, 1.4 * this->HandleRadius);
  for (int i = 0; i < 3; ++i)
  {
    this->Bounds[2 * i] = center[i] - r;
    this->Bounds[2 * i + 1] = center[i] + r;
  }
  return this->Bounds;
}

void vtkDeformationHandleRepresentation::GetActors(vtkPropCollection* actors)
{
  actors->AddItem(this->HandleActor);
  actors->AddItem(this->RingActor);
  actors->AddItem(this->ROIActor);
}

void vtkDeformationHandleRepresentation::ReleaseGraphicsResources(vtkWindow* window)
{
  this->HandleActor->ReleaseGraphicsResources(window);
  this->RingActor->ReleaseGraphicsResources(window);
  this->ROIActor->ReleaseGraphicsResources(window);
}

int vtkDeformationHandleRepresentation::RenderActors(
  int (vtkProp::*render)(vtkViewport*), vtkViewport* viewport)
{
  // Each actor draws in the pass its property calls for (applications may make them
  // translucent), with the representation's property keys: without them, the renderer's
  // translucent pass (order-independent transparency or depth peeling) draws a translucent
  // actor with the wrong shader, as horizontal stripes.
  this->BuildRepresentation();
  int count = 0;
  for (vtkActor* actor : { this->RingActor.Get(), this->HandleActor.Get(), this->ROIActor.Get() })
  {
    if (actor->GetVisibility())
    {
      actor->SetPropertyKeys(this->GetPropertyKeys());
      count += (actor->*render)(viewport);
    }
  }
  return count;
}

int vtkDeformationHandleRepresentation::RenderOpaqueGeometry(vtkViewport* viewport)
{
  return this->RenderActors(&vtkProp::RenderOpaqueGeometry, viewport);
}

int vtkDeformationHandleRepresentation::RenderTranslucentPolygonalGeometry(vtkViewport* viewport)
{
  return this->RenderActors(&vtkProp::RenderTranslucentPolygonalGeometry, viewport);
}

vtkTypeBool vtkDeformationHandleRepresentation::HasTranslucentPolygonalGeometry()
{
  return this->RingActor->HasTranslucentPolygonalGeometry() ||
    this->HandleActor->HasTranslucentPolygonalGeometry() ||
    (this->ROIActor->GetVisibility() && this->ROIActor->HasTranslucentPolygonalGeometry());
}

void vtkDeformationHandleRepresentation::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Center: (" << this->Center[0] << ", " << this->Center[1] << ", "
     << this->Center[2] << ")\n";
  os << indent << "Translation: (" << this->Translation[0] << ", " << this->Translation[1]
     << ", " << this->Translation[2] << ")\n";
  os << indent << "HandleRadius: " << this->HandleRadius << "\n";
  os << indent << "ROIRadius: " << this->ROIRadius << "\n";
  os << indent << "ConstrainToAxis: " << this->ConstrainToAxis << "\n";
  os << indent << "HandleProperty: " << this->HandleProperty << "\n";
  os << indent << "SelectedHandleProperty: " << this->SelectedHandleProperty << "\n";
  os << indent << "RingProperty: " << this->RingProperty << "\n";
}
