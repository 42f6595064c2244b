#include "vtkDeformationHandleRepresentation.h"

#include "vtkActor.h"
#include "vtkAssemblyNode.h"
#include "vtkAssemblyPath.h"
#include "vtkCamera.h"
#include "vtkCellPicker.h"
#include "vtkCommand.h"
#include "vtkInteractorObserver.h"
#include "HandleMotion.h"
#include "vtkLineSource.h"
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
#include <array>
#include <cmath>

vtkStandardNewMacro(vtkDeformationHandleRepresentation);

namespace lep = LaplacianEditing::Pipeline;

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
  // The frame's rings in the usual axis colours; the view ring a lighter blue.
  double ringColors[4][3] = { { 0.9, 0.2, 0.2 }, { 0.25, 0.75, 0.25 }, { 0.2, 0.35, 0.95 },
    { 0.45, 0.7, 1.0 } };
  for (int axis = AxisX; axis <= ViewAxis; ++axis)
  {
    this->RingProperties[axis]->SetColor(ringColors[axis]);
    this->RingSources[axis]->SetNumberOfSides(64);
    this->RingSources[axis]->GeneratePolygonOff();
    this->RingSources[axis]->GeneratePolylineOn();
    this->RingTubes[axis]->SetInputConnection(this->RingSources[axis]->GetOutputPort());
    this->RingTubes[axis]->SetNumberOfSides(8);
    this->RingMappers[axis]->SetInputConnection(this->RingTubes[axis]->GetOutputPort());
    this->RingActors[axis]->SetMapper(this->RingMappers[axis]);
    this->RingActors[axis]->SetProperty(this->RingProperties[axis]);
    this->Picker->AddPickList(this->RingActors[axis]);
  }

  this->HandleSource->SetThetaResolution(24);
  this->HandleSource->SetPhiResolution(12);
  this->HandleMapper->SetInputConnection(this->HandleSource->GetOutputPort());
  this->HandleActor->SetMapper(this->HandleMapper);
  this->HandleActor->SetProperty(this->HandleProperty);

  this->ROISource->SetThetaResolution(24);
  this->ROISource->SetPhiResolution(12);
  this->ROIMapper->SetInputConnection(this->ROISource->GetOutputPort());
  this->ROIActor->SetMapper(this->ROIMapper);
  this->ROIActor->GetProperty()->SetRepresentationToWireframe();
  this->ROIActor->GetProperty()->SetColor(0.85, 0.2, 0.15);

  this->ROIActor->VisibilityOff();

  this->AxisMapper->SetInputConnection(this->AxisSource->GetOutputPort());
  this->AxisActor->SetMapper(this->AxisMapper);
  this->AxisActor->GetProperty()->SetLineWidth(2.0);
  this->AxisActor->VisibilityOff();

  this->Picker->SetTolerance(0.005);
  this->Picker->PickFromListOn();
  this->Picker->AddPickList(this->HandleActor);
  this->UpdateTransform();
}

vtkDeformationHandleRepresentation::~vtkDeformationHandleRepresentation()
{
  this->HandleProperty->Delete();
  this->SelectedHandleProperty->Delete();
}

vtkProperty* vtkDeformationHandleRepresentation::GetRingProperty(int axis)
{
  return axis >= AxisX && axis <= ViewAxis ? this->RingProperties[axis].Get() : nullptr;
}

void vtkDeformationHandleRepresentation::GetFrameAxis(int axis, double direction[3])
{
  for (int i = 0; i < 3; ++i)
  {
    direction[i] = this->Rotation[i][axis];
  }
}

void vtkDeformationHandleRepresentation::GetRotationAxisDirection(int axis, double direction[3])
{
  if (axis == ViewAxis)
  {
    this->Renderer->GetActiveCamera()->GetDirectionOfProjection(direction);
  }
  else
  {
    this->GetFrameAxis(axis, direction);
  }
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

void vtkDeformationHandleRepresentation::SetRestCenter(double x, double y, double z)
{
  this->Center[0] = x;
  this->Center[1] = y;
  this->Center[2] = z;
  this->UpdateTransform();
}

void vtkDeformationHandleRepresentation::SetTranslation(double x, double y, double z)
{
  this->Translation[0] = x;
  this->Translation[1] = y;
  this->Translation[2] = z;
  this->UpdateTransform();
}

void vtkDeformationHandleRepresentation::SetRotationAngles(double x, double y, double z)
{
  const double angles[3] = { x, y, z };
  lep::HandleMotion::RotationMatrix(angles, this->Rotation);
  this->UpdateTransform();
}

void vtkDeformationHandleRepresentation::ResetTransform()
{
  vtkMath::Identity3x3(this->Rotation);
  std::fill(this->Translation, this->Translation + 3, 0.0);
  this->UpdateTransform();
}

void vtkDeformationHandleRepresentation::UpdateTransform()
{
  lep::HandleMotion::Angles(this->Rotation, this->RotationAngles);

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
    manager->AddPicker(this->Picker, this);
  }
}

bool vtkDeformationHandleRepresentation::DisplayToPlane(
  double x, double y, const double normal[3], double world[3])
{
  // The ray through (x, y), from the near to the far clipping plane, meets the plane.
  double nearPoint[4], farPoint[4], center[3], ray[3], toCenter[3];
  vtkInteractorObserver::ComputeDisplayToWorld(this->Renderer, x, y, 0.0, nearPoint);
  vtkInteractorObserver::ComputeDisplayToWorld(this->Renderer, x, y, 1.0, farPoint);
  this->GetCurrentCenter(center);
  vtkMath::Subtract(farPoint, nearPoint, ray);
  vtkMath::Subtract(center, nearPoint, toCenter);
  const double along = vtkMath::Dot(ray, normal);
  if (std::abs(along) < 1e-3 * vtkMath::Norm(ray) * vtkMath::Norm(normal))
  {
    return false;
  }
  const double t = vtkMath::Dot(toCenter, normal) / along;
  for (int i = 0; i < 3; ++i)
  {
    world[i] = nearPoint[i] + t * ray[i];
  }
  return true;
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
  // One picker for the sphere and the rings: the picking manager weighs the whole handle
  // against other widgets. A ring seen edge-on is a line across the sphere, so the inner part
  // of the sphere's disc on screen belongs to the sphere whatever is picked in front of it.
  vtkAssemblyPath* path = this->GetAssemblyPath(X, Y, 0.0, this->Picker);
  if (!path)
  {
    return this->InteractionState = Outside;
  }
  vtkProp* picked = path->GetFirstNode()->GetViewProp();
  double center[3], centerDisplay[3], rim[3], rimDisplay[3], up[3];
  this->GetCurrentCenter(center);
  this->Renderer->GetActiveCamera()->GetViewUp(up);
  vtkMath::Normalize(up);
  for (int i = 0; i < 3; ++i)
  {
    rim[i] = center[i] + this->HandleRadius * up[i];
  }
  vtkInteractorObserver::ComputeWorldToDisplay(this->Renderer, center[0], center[1], center[2], centerDisplay);
  vtkInteractorObserver::ComputeWorldToDisplay(this->Renderer, rim[0], rim[1], rim[2], rimDisplay);
  const double radius = std::hypot(rimDisplay[0] - centerDisplay[0], rimDisplay[1] - centerDisplay[1]);
  const bool inner = std::hypot(X - centerDisplay[0], Y - centerDisplay[1]) < 0.6 * radius;
  if (picked == this->HandleActor || inner)
  {
    return this->InteractionState = OnHandle;
  }
  for (int axis = AxisX; axis <= ViewAxis; ++axis)
  {
    this->RotationAxis = picked == this->RingActors[axis] ? axis : this->RotationAxis;
  }
  return this->InteractionState = OnRing;
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
  this->GetRotationAxisDirection(this->RotationAxis, this->StartAxis);
  vtkMath::Normalize(this->StartAxis);
  if (this->InteractionState == Rotating)
  {
    this->StartRingTangent();
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
      this->Translate(world);
      break;
    case Rotating:
      this->Rotate(eventPosition, center);
      break;
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

void vtkDeformationHandleRepresentation::Translate(const double world[3])
{
  double motion[3];
  vtkMath::Subtract(world, this->StartWorld, motion);
  if (this->ConstrainToAxis)
  {
    // Along the frame axis the motion follows most, drawn while the drag lasts.
    int best = AxisX;
    double along = 0.0, direction[3];
    for (int axis = AxisX; axis <= AxisZ; ++axis)
    {
      this->GetFrameAxis(axis, direction);
      const double component = vtkMath::Dot(motion, direction);
      if (std::abs(component) > std::abs(along))
      {
        along = component;
        best = axis;
      }
    }
    this->GetFrameAxis(best, direction);
    vtkMath::MultiplyScalar(direction, along);
    std::copy(direction, direction + 3, motion);
    this->GetFrameAxis(best, direction);
    this->AxisActor->GetProperty()->SetColor(this->RingProperties[best]->GetColor());
    this->ShowAxis(direction);
  }
  vtkMath::Add(this->StartTranslation, motion, this->Translation);
}

void vtkDeformationHandleRepresentation::Rotate(const double eventPosition[2], const double center[3])
{
  // A ring seen well: the angle the cursor swept about the axis in the ring's plane since the
  // drag started. A ring seen nearly edge-on: the cursor's motion along the ring's tangent on
  // screen, a radian per projected ring radius.
  double angle = 0.0, now[3], from[3], to[3], cross[3];
  if (this->TangentPerRadian[0] != 0.0 || this->TangentPerRadian[1] != 0.0)
  {
    const double dx = eventPosition[0] - this->StartPosition[0];
    const double dy = eventPosition[1] - this->StartPosition[1];
    angle = (dx * this->TangentPerRadian[0] + dy * this->TangentPerRadian[1]) /
      (this->TangentPerRadian[0] * this->TangentPerRadian[0] +
        this->TangentPerRadian[1] * this->TangentPerRadian[1]);
  }
  else if (this->DisplayToPlane(eventPosition[0], eventPosition[1], this->StartAxis, now))
  {
    vtkMath::Subtract(this->StartWorld, center, from);
    vtkMath::Subtract(now, center, to);
    vtkMath::Cross(from, to, cross);
    angle = std::atan2(vtkMath::Dot(cross, this->StartAxis), vtkMath::Dot(from, to));
  }
  vtkNew<vtkTransform> turn;
  turn->RotateWXYZ(vtkMath::DegreesFromRadians(angle), this->StartAxis);
  double turnMatrix[3][3];
  for (int r = 0; r < 3; ++r)
  {
    for (int c = 0; c < 3; ++c)
    {
      turnMatrix[r][c] = turn->GetMatrix()->GetElement(r, c);
    }
  }
  vtkMath::Multiply3x3(turnMatrix, this->StartRotation, this->Rotation);
}

void vtkDeformationHandleRepresentation::EndWidgetInteraction(double[2])
{
  this->Highlight(false);
  this->ROIActor->VisibilityOff();

  this->AxisMapper->SetInputConnection(this->AxisSource->GetOutputPort());
  this->AxisActor->SetMapper(this->AxisMapper);
  this->AxisActor->GetProperty()->SetLineWidth(2.0);
  this->AxisActor->VisibilityOff();
  this->AxisActor->VisibilityOff();
  this->InteractionState = Outside;
}

void vtkDeformationHandleRepresentation::StartRingTangent()
{
  this->TangentPerRadian[0] = this->TangentPerRadian[1] = 0.0;
  double view[3], center[3];
  this->GetRotationAxisDirection(ViewAxis, view);
  vtkMath::Normalize(view);
  const bool edgeOn = std::abs(vtkMath::Dot(view, this->StartAxis)) < 0.25;
  if (!edgeOn &&
    this->DisplayToPlane(this->StartPosition[0], this->StartPosition[1], this->StartAxis, this->StartWorld))
  {
    return; // the angle is measured in the ring's plane
  }
  // The grabbed ring point: the cursor's point in the view plane, brought onto the ring; its
  // tangent, a ring radius long, on screen.
  this->GetCurrentCenter(center);
  double radial[3], tangent[3], end[3], centerDisplay[3], endDisplay[3];
  vtkMath::Subtract(this->StartWorld, center, radial);
  const double off = vtkMath::Dot(radial, this->StartAxis);
  for (int i = 0; i < 3; ++i)
  {
    radial[i] -= off * this->StartAxis[i];
  }
  if (vtkMath::Normalize(radial) == 0.0)
  {
    vtkMath::Cross(this->StartAxis, view, radial);
    vtkMath::Normalize(radial);
  }
  vtkMath::Cross(this->StartAxis, radial, tangent);
  const double ring = 1.15 * this->HandleRadius;
  for (int i = 0; i < 3; ++i)
  {
    end[i] = center[i] + ring * tangent[i];
  }
  vtkInteractorObserver::ComputeWorldToDisplay(this->Renderer, center[0], center[1], center[2], centerDisplay);
  vtkInteractorObserver::ComputeWorldToDisplay(this->Renderer, end[0], end[1], end[2], endDisplay);
  this->TangentPerRadian[0] = endDisplay[0] - centerDisplay[0];
  this->TangentPerRadian[1] = endDisplay[1] - centerDisplay[1];
  if (std::hypot(this->TangentPerRadian[0], this->TangentPerRadian[1]) < 1.0)
  {
    this->TangentPerRadian[0] = this->TangentPerRadian[1] = 0.0; // no direction on screen
  }
}

void vtkDeformationHandleRepresentation::ShowAxis(const double direction[3])
{
  double center[3], ends[2][3];
  this->GetCurrentCenter(center);
  for (int i = 0; i < 3; ++i)
  {
    ends[0][i] = center[i] - this->ROIRadius * direction[i];
    ends[1][i] = center[i] + this->ROIRadius * direction[i];
  }
  this->AxisSource->SetPoint1(ends[0]);
  this->AxisSource->SetPoint2(ends[1]);
  this->AxisActor->VisibilityOn();
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
  // The shapes sit at the origin (their sources' default centre) and their actors at the
  // centre, so that a drag moves the actors and rebuilds (and uploads) nothing: the four tubes
  // and two spheres would be rebuilt and uploaded at every move otherwise. The axis of a
  // constrained move is drawn where it is, in world coordinates.
  double center[3], view[3];
  this->GetCurrentCenter(center);
  for (vtkActor* actor : this->Actors())
  {
    if (actor != this->AxisActor)
    {
      actor->SetPosition(center);
    }
  }
  camera->GetDirectionOfProjection(view);
  const std::array<double, 14> shape = { this->HandleRadius, this->ROIRadius, this->Rotation[0][0],
    this->Rotation[0][1], this->Rotation[0][2], this->Rotation[1][0], this->Rotation[1][1],
    this->Rotation[1][2], this->Rotation[2][0], this->Rotation[2][1], this->Rotation[2][2], view[0],
    view[1], view[2] };
  if (shape != this->ShapeKey)
  {
    this->ShapeKey = shape;
    this->HandleSource->SetRadius(this->HandleRadius);
    for (int axis = AxisX; axis <= ViewAxis; ++axis)
    {
      double ringNormal[3];
      this->GetRotationAxisDirection(axis, ringNormal);
      this->RingSources[axis]->SetNormal(ringNormal);
      this->RingSources[axis]->SetRadius((axis == ViewAxis ? 1.4 : 1.15) * this->HandleRadius);
      this->RingTubes[axis]->SetRadius(0.06 * this->HandleRadius);
      this->RingTubes[axis]->Update();
    }
    this->ROISource->SetRadius(this->ROIRadius);
    // The pickers read the mappers' inputs: bring them up to date now, not at the next render.
    this->HandleSource->Update();
    this->ROISource->Update();
  }
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
  for (vtkActor* actor : this->Actors())
  {
    actors->AddItem(actor);
  }
}

void vtkDeformationHandleRepresentation::ReleaseGraphicsResources(vtkWindow* window)
{
  for (vtkActor* actor : this->Actors())
  {
    actor->ReleaseGraphicsResources(window);
  }
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
  for (vtkActor* actor : this->Actors())
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

std::array<vtkActor*, 7> vtkDeformationHandleRepresentation::Actors()
{
  return { this->RingActors[AxisX], this->RingActors[AxisY], this->RingActors[AxisZ],
    this->RingActors[ViewAxis], this->HandleActor, this->ROIActor, this->AxisActor };
}

vtkTypeBool vtkDeformationHandleRepresentation::HasTranslucentPolygonalGeometry()
{
  const std::array<vtkActor*, 7> actors = this->Actors();
  return std::any_of(actors.begin(), actors.end(),
    [](vtkActor* actor) { return actor->GetVisibility() && actor->HasTranslucentPolygonalGeometry(); });
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
  os << indent << "RotationAxis: " << this->RotationAxis << "\n";
}
