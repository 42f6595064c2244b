// Drives vtkDeformationHandleWidget with recorded events, as VTK's BoxWidget2 test does: place
// the handle by clicking the surface, drag it, turn it, resize the ROI, release. Checks the
// handle transform and the filter's output numerically, the factorization count, and the final
// frame against a baseline. A second case deletes the widget in the middle of a drag; a third
// drags and places with VTK's picking manager on; a fourth places through PlaceWidget and drags
// with a rebound modifier; a fifth orbits by dragging the surface and commits by clicking; a sixth
// renders a translucent handle against a baseline; a seventh turns the handle about each axis of
// its frame; an eighth moves it along one axis and resizes the region with the wheel; a ninth
// checks the accessors ParaView drives against the filter's handle properties; a tenth drags
// two handle groups with a widget each, commits and undoes; an eleventh drags in the
// as-rigid-as-possible mode, a few iterations a frame, and settles the shape on the release; a
// twelfth previews a motion in place of the surface's actor and draws what the update draws; a
// thirteenth drags the boundary of a volume mesh, its interior following; a fourteenth draws
// the same surfaces through the preview's mapper and VTK's and compares the pixels.
// Usage: TestDeformationHandleWidget <case> [-V <baseline.png> -T <temp folder>]
#include "EditingScene.h"
#include "FilterTestHelpers.h"
#include "VolumeMeshes.h"

#include "vtkDeformationHandleRepresentation.h"
#include "vtkDeformationHandleWidget.h"
#include "vtkDeformationPreviewController.h"
#include "PreviewPartMapper.h"
#include "vtkActorCollection.h"
#include "vtkLaplacianVolumeDeformationFilter.h"

#include "vtkCallbackCommand.h"
#include "vtkCamera.h"
#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkDataSetMapper.h"
#include "vtkEvent.h"
#include "vtkIntArray.h"
#include "vtkInteractorEventRecorder.h"
#include "vtkInteractorStyleTrackballCamera.h"
#include "vtkMatrix4x4.h"
#include "vtkPickingManager.h"
#include "vtkPoints.h"
#include "vtkPropCollection.h"
#include "vtkProperty.h"
#include "vtkRegressionTestImage.h"
#include "vtkRenderWindowInteractor.h"
#include "vtkTransform.h"
#include "vtkUnsignedCharArray.h"
#include "vtkWindowToImageFilter.h"
#include "vtkWidgetEvent.h"
#include "vtkWidgetEventTranslator.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <cstdio>
#include <iostream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace
{
int failures = 0;
const int ShiftModifier = 1;
const int ControlModifier = 2;

void Check(bool condition, const std::string& what)
{
  if (!condition)
  {
    std::cerr << "FAILED: " << what << "\n";
    ++failures;
  }
}

struct Scene
{
  vtkNew<vtkLaplacianDeformationFilter> Filter;
  vtkSmartPointer<vtkPolyData> Rest;
  vtkSmartPointer<vtkRenderer> Renderer;
  vtkNew<vtkRenderWindow> Window;
  vtkNew<vtkRenderWindowInteractor> Interactor;
  vtkNew<vtkInteractorEventRecorder> Recorder;

  Scene()
  {
    this->Rest = MakeBumpyPlane(60);
    this->Filter->SetInputData(this->Rest);
    this->Filter->SetHandleCenter(0.5, 0.5, 0.0);
    this->Filter->SetHandleRadius(0.06);
    this->Filter->SetROIRadius(0.4);
    this->Filter->SetRotationModeToExplicit();
    this->Filter->Update();
    const double full[4] = { 0.0, 0.0, 1.0, 1.0 };
    this->Renderer = EditingScene::MakeRenderer(this->Filter->GetOutput(), full);
    vtkActor* actor = vtkActor::SafeDownCast(this->Renderer->GetActors()->GetItemAsObject(0));
    actor->GetMapper()->SetInputConnection(this->Filter->GetOutputPort());
    XDisplay::AttachOrExit(this->Window); // checked before the interactor uses it
    this->Window->SetSize(500, 500);
    this->Window->SetMultiSamples(0);
    this->Window->AddRenderer(this->Renderer);
    this->Interactor->SetRenderWindow(this->Window);
    vtkNew<vtkInteractorStyleTrackballCamera> style;
    this->Interactor->SetInteractorStyle(style);
    vtkCamera* camera = this->Renderer->GetActiveCamera();
    camera->SetFocalPoint(0.5, 0.5, 0.1);
    camera->SetPosition(0.5, -1.2, 1.4);
    camera->SetViewUp(0.0, 0.0, 1.0);
    this->Renderer->ResetCameraClippingRange(); // pick rays span the clipping range
    this->Recorder->SetInteractor(this->Interactor);
    this->Recorder->ReadFromInputStringOn();
    this->Window->Render();
  }

  vtkActor* SurfaceActor()
  {
    return vtkActor::SafeDownCast(this->Renderer->GetActors()->GetItemAsObject(0));
  }

  // A widget paired with the filter, placing on the surface, switched on.
  vtkSmartPointer<vtkDeformationHandleWidget> MakeWidget(int group = 0)
  {
    auto widget = vtkSmartPointer<vtkDeformationHandleWidget>::New();
    widget->SetHandleGroup(group);
    widget->SetInteractor(this->Interactor);
    widget->SetDeformationFilter(this->Filter);
    widget->SetSurfaceProp(this->SurfaceActor());
    widget->On();
    this->Window->Render();
    return widget;
  }

  void Display(const double world[3], double display[2])
  {
    this->Renderer->SetWorldPoint(world[0], world[1], world[2], 1.0);
    this->Renderer->WorldToDisplay();
    display[0] = this->Renderer->GetDisplayPoint()[0];
    display[1] = this->Renderer->GetDisplayPoint()[1];
  }

  void Play(const std::string& events)
  {
    this->Recorder->SetInputString(events.c_str());
    this->Recorder->Play();
  }

  // The largest distance of the filter's handle vertices (those where `array` is `value`) from
  // where the representation's transform puts their rest positions.
  double HandleError(vtkDeformationHandleRepresentation* rep, const char* array = "EditRole",
    double value = vtkLaplacianDeformationFilter::ROLE_HANDLE)
  {
    vtkPolyData* output = this->Filter->GetOutput();
    vtkDataArray* roles = output->GetPointData()->GetArray(array);
    double worst = 0.0;
    for (vtkIdType i = 0; i < output->GetNumberOfPoints(); ++i)
    {
      if (roles->GetTuple1(i) == value)
      {
        double expected[3];
        rep->GetTransform()->TransformPoint(this->Rest->GetPoint(i), expected);
        worst = std::max(worst, std::sqrt(vtkMath::Distance2BetweenPoints(expected, output->GetPoint(i))));
      }
    }
    return worst;
  }
};

std::string Event(const char* name, double x, double y, int modifiers = 0)
{
  // The recorder's stream version 1: event x y ctrl shift keycode repeat keysym.
  char line[128];
  std::snprintf(line, sizeof(line), "%s %d %d %d %d 0 0 i\n", name, static_cast<int>(std::lround(x)),
    static_cast<int>(std::lround(y)), (modifiers & ControlModifier) ? 1 : 0,
    (modifiers & ShiftModifier) ? 1 : 0);
  return line;
}

// Press at `from`, move in steps along `path(t)` for t in (0, 1], release.
template <typename Path>
std::string Drag(const double from[2], Path path, int modifiers = 0)
{
  std::string events = Event("MouseMoveEvent", from[0], from[1], modifiers) +
    Event("LeftButtonPressEvent", from[0], from[1], modifiers);
  for (int step = 1; step <= 10; ++step)
  {
    double at[2];
    path(step / 10.0, at);
    events += Event("MouseMoveEvent", at[0], at[1], modifiers);
  }
  double end[2];
  path(1.0, end);
  return events + Event("LeftButtonReleaseEvent", end[0], end[1], modifiers);
}

int PlaceDragRotateResize(int argc, char* argv[])
{
  Scene scene;
  auto widget = scene.MakeWidget();
  vtkDeformationHandleRepresentation* rep = widget->GetDeformationHandleRepresentation();
  vtkNew<vtkCallbackCommand> counter;
  counter->SetCallback([](vtkObject*, unsigned long event, void* data, void*) {
    int* counts = static_cast<int*>(data);
    counts[event == vtkCommand::StartInteractionEvent ? 0 : (event == vtkCommand::InteractionEvent ? 1 : 2)]++;
  });
  int counts[3] = { 0, 0, 0 };
  counter->SetClientData(counts);
  widget->AddObserver(vtkCommand::StartInteractionEvent, counter);
  widget->AddObserver(vtkCommand::InteractionEvent, counter);
  widget->AddObserver(vtkCommand::EndInteractionEvent, counter);

  // 1. Place: click the surface at (0.7, 0.5).
  const double target[3] = { 0.7, 0.5, 0.0 };
  double click[2];
  scene.Display(target, click);
  scene.Play(Event("MouseMoveEvent", click[0], click[1]) +
    Event("LeftButtonPressEvent", click[0], click[1]) +
    Event("LeftButtonReleaseEvent", click[0], click[1]));
  const double* center = scene.Filter->GetHandleCenter();
  // The click lands on the front of the bump there, a little before its apex.
  Check(std::hypot(center[0] - 0.7, center[1] - 0.5) < 0.06, "handle placed at the picked vertex");
  scene.Window->Render();
  const int factorizations = scene.Filter->GetNumberOfFactorizations();

  // 2. Translate: drag the sphere 90 pixels up.
  double at[2];
  double current[3];
  rep->GetCurrentCenter(current);
  scene.Display(current, at);
  scene.Play(Drag(at, [&](double t, double p[2]) { p[0] = at[0]; p[1] = at[1] + 90.0 * t; }));
  double moved[3];
  rep->GetCurrentCenter(moved);
  double translation[3];
  vtkMath::Subtract(moved, current, translation);
  Check(vtkMath::Norm(translation) > 0.1, "the drag moved the handle");
  Check(translation[2] > 0.05, "screen up moves the handle up");
  double back[2];
  scene.Display(moved, back);
  Check(std::abs(back[0] - at[0]) < 2.0 && std::abs(back[1] - (at[1] + 90.0)) < 2.0,
    "the handle follows the cursor in the view plane");
  // The surface followed: the handle vertices sit on their targets.
  const double worst = scene.HandleError(rep);
  Check(worst < 2e-3, "the filter's handle vertices follow the widget's transform");

  // 3. Rotate: sweep a quarter turn along the ring.
  rep->GetCurrentCenter(current);
  scene.Display(current, at);
  double edge[3] = { current[0] + 1.4 * rep->GetHandleRadius(), current[1], current[2] };
  double ringPoint[2];
  scene.Display(edge, ringPoint);
  const double radius = std::hypot(ringPoint[0] - at[0], ringPoint[1] - at[1]);
  scene.Play(Drag(ringPoint, [&](double t, double p[2]) {
    p[0] = at[0] + radius * std::cos(0.5 * vtkMath::Pi() * t);
    p[1] = at[1] + radius * std::sin(0.5 * vtkMath::Pi() * t);
  }));
  vtkMatrix4x4* m = rep->GetTransform()->GetMatrix();
  const double trace = m->GetElement(0, 0) + m->GetElement(1, 1) + m->GetElement(2, 2);
  const double angle = vtkMath::DegreesFromRadians(std::acos(std::min(1.0, (trace - 1.0) / 2.0)));
  std::cout << "rotation " << angle << " degrees, translation " << vtkMath::Norm(translation) << "\n";
  Check(std::abs(angle - 90.0) < 5.0, "a quarter turn on the ring rotates the handle 90 degrees");
  Check(scene.Filter->GetNumberOfFactorizations() == factorizations,
    "moving and turning the handle does not refactor");

  // 4. Resize the ROI with Shift: one refactorization, on release.
  rep->GetCurrentCenter(current);
  scene.Display(current, at);
  scene.Play(Drag(at, [&](double t, double p[2]) { p[0] = at[0] + 60.0 * t; p[1] = at[1]; },
    ShiftModifier));
  Check(scene.Filter->GetNumberOfFactorizations() == factorizations + 1,
    "resizing the ROI refactors once");
  Check(std::abs(scene.Filter->GetROIRadius() - rep->GetROIRadius()) < 1e-12,
    "the filter gets the new ROI radius");
  Check(counts[0] == 4 && counts[2] == 4 && counts[1] >= 30, "interaction events fired");

  scene.Window->Render();
  const int image = vtkRegressionTestImageThreshold(scene.Window, 0.05);
  Check(image == vtkRegressionTester::PASSED, "the final frame matches the baseline");
  return failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}

int PickingManager()
{
  // An application with VTK's picking manager on: the sphere must stay pickable (the
  // representation's pickers are registered), so its drag moves the filter's handle and only
  // re-solves; and a click on the surface must still place the handle (the widget's picker).
  Scene scene;
  scene.Interactor->GetPickingManager()->EnabledOn();
  auto widget = scene.MakeWidget();
  vtkDeformationHandleRepresentation* rep = widget->GetDeformationHandleRepresentation();
  Check(scene.Filter->GetNumberOfFactorizations() == 1, "one factorization before the drag");
  const double* restCenter = scene.Filter->GetHandleCenter();
  const double start[3] = { restCenter[0], restCenter[1], restCenter[2] };
  double at[2];
  scene.Display(start, at);
  scene.Play(Drag(at, [&](double t, double p[2]) { p[0] = at[0]; p[1] = at[1] + 60.0 * t; }));
  // Where the filter's handle transform puts the filter's handle centre.
  double moved[3];
  scene.Filter->GetHandleTransform()->TransformPoint(scene.Filter->GetHandleCenter(), moved);
  const double distance = std::sqrt(vtkMath::Distance2BetweenPoints(start, moved));
  std::cout << "with the picking manager on, the handle moved by " << distance << "\n";
  Check(distance > 0.05 && moved[2] > start[2], "the handle is picked and dragged up");
  const double* center = scene.Filter->GetHandleCenter();
  Check(std::sqrt(vtkMath::Distance2BetweenPoints(center, start)) < 1e-12,
    "the drag leaves the handle's rest centre where it was");
  Check(scene.Filter->GetNumberOfFactorizations() == 1, "the drag does not refactor");

  // A click on a vertex of the surface outside the region of interest places the handle there.
  double target[3];
  scene.Rest->GetPoint(scene.Rest->FindPoint(0.1, 0.2, 0.0), target);
  double click[2];
  scene.Display(target, click);
  scene.Play(Event("MouseMoveEvent", click[0], click[1]) +
    Event("LeftButtonPressEvent", click[0], click[1]) +
    Event("LeftButtonReleaseEvent", click[0], click[1]));
  center = scene.Filter->GetHandleCenter();
  Check(std::sqrt(vtkMath::Distance2BetweenPoints(center, target)) < 0.02,
    "a click on the surface places the handle through the picking manager");
  double current[3];
  rep->GetCurrentCenter(current);
  Check(std::sqrt(vtkMath::Distance2BetweenPoints(center, current)) < 1e-12,
    "the representation shows the placed handle");
  return failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}

int OrbitClickAndCommit()
{
  // Editing as in any VTK application: a left drag that starts on the surface away from the
  // handle orbits the camera and leaves the edit alone; a click (press and release in place)
  // places the handle; a click elsewhere after an edit commits the edit first, so the edited
  // points stay.
  Scene scene;
  auto widget = scene.MakeWidget();
  vtkDeformationHandleRepresentation* rep = widget->GetDeformationHandleRepresentation();
  double center[3];
  rep->GetCurrentCenter(center);
  double at[2];
  scene.Display(center, at);
  scene.Play(Drag(at, [&](double t, double p[2]) { p[0] = at[0]; p[1] = at[1] + 60.0 * t; }));
  vtkNew<vtkPoints> edited;
  edited->DeepCopy(scene.Filter->GetOutput()->GetPoints());
  double lifted[3];
  rep->GetCurrentCenter(lifted);
  Check(std::sqrt(vtkMath::Distance2BetweenPoints(center, lifted)) > 0.05, "the handle was dragged");

  vtkNew<vtkMatrix4x4> transform;
  transform->DeepCopy(scene.Filter->GetHandleTransform()->GetMatrix());
  double position[3];
  scene.Renderer->GetActiveCamera()->GetPosition(position);
  double surface[3];
  scene.Rest->GetPoint(scene.Rest->FindPoint(0.15, 0.3, 0.0), surface);
  double from[2];
  scene.Display(surface, from);
  scene.Play(Drag(from, [&](double t, double p[2]) { p[0] = from[0] + 80.0 * t; p[1] = from[1]; }));
  double orbited[3];
  scene.Renderer->GetActiveCamera()->GetPosition(orbited);
  std::cout << "a drag on the surface moved the camera by "
            << std::sqrt(vtkMath::Distance2BetweenPoints(position, orbited)) << "\n";
  Check(std::sqrt(vtkMath::Distance2BetweenPoints(position, orbited)) > 0.2,
    "a drag on the surface orbits the camera");
  double still[3];
  rep->GetCurrentCenter(still);
  bool sameTransform = true;
  for (int i = 0; i < 16; ++i)
  {
    sameTransform &= scene.Filter->GetHandleTransform()->GetMatrix()->GetData()[i] ==
      transform->GetData()[i];
  }
  Check(sameTransform && std::sqrt(vtkMath::Distance2BetweenPoints(still, lifted)) < 1e-12 &&
      scene.Filter->GetNumberOfCommits() == 0,
    "the orbit leaves the handle transform and the edit");
  scene.Filter->Update();
  double worst = 0.0;
  for (vtkIdType i = 0; i < edited->GetNumberOfPoints(); ++i)
  {
    worst = std::max(worst,
      vtkMath::Distance2BetweenPoints(edited->GetPoint(i), scene.Filter->GetOutput()->GetPoint(i)));
  }
  // (The release of the handle drag re-solves once more, to within 1e-7.)
  std::cout << "after the orbit the surface moved by " << std::sqrt(worst) << "\n";
  Check(std::sqrt(worst) < 1e-6, "the orbit leaves the edited surface as it was");

  // A click on the surface away from the handle: the edit is committed, the handle moves there.
  scene.Renderer->ResetCameraClippingRange();
  scene.Window->Render();
  scene.Display(surface, from);
  scene.Play(Event("MouseMoveEvent", from[0], from[1]) +
    Event("LeftButtonPressEvent", from[0], from[1]) + Event("LeftButtonReleaseEvent", from[0], from[1]));
  Check(scene.Filter->GetNumberOfCommits() == 1, "a click elsewhere commits the edit in progress");
  // On the clicked vertex, where the committed edit left it (at the region's edge, within the
  // solver's precision); its neighbours are 1/60 away.
  Check(std::sqrt(vtkMath::Distance2BetweenPoints(scene.Filter->GetHandleCenter(), surface)) < 1e-6,
    "the click places the handle on the clicked vertex");
  Check(scene.Filter->GetHandleTransform()->GetMatrix()->IsIdentity(),
    "the placed handle starts from the identity");
  scene.Filter->Update();
  worst = 0.0;
  for (vtkIdType i = 0; i < edited->GetNumberOfPoints(); ++i)
  {
    worst = std::max(worst,
      vtkMath::Distance2BetweenPoints(edited->GetPoint(i), scene.Filter->GetOutput()->GetPoint(i)));
  }
  Check(std::sqrt(worst) < 1e-6, "the committed edit stays on the surface");
  return failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}

int TranslucentHandle(int argc, char* argv[])
{
  // An application may make the handle translucent: the renderer's translucent pass must draw it
  // (it drew horizontal stripes while the representation's actors lacked its property keys).
  Scene scene;
  auto widget = scene.MakeWidget();
  vtkProperty* property = widget->GetDeformationHandleRepresentation()->GetHandleProperty();
  property->SetRepresentationToSurface();
  property->SetOpacity(0.45);
  vtkCamera* camera = scene.Renderer->GetActiveCamera();
  camera->SetFocalPoint(0.5, 0.5, 0.05);
  camera->SetPosition(0.5, 0.15, 0.3);
  scene.Renderer->ResetCameraClippingRange();
  scene.Window->Render();
  const int image = vtkRegressionTestImageThreshold(scene.Window, 0.05);
  Check(image == vtkRegressionTester::PASSED, "the translucent handle matches the baseline");
  return failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}

int PlaceWidgetAndBindings()
{
  Scene scene;
  auto widget = scene.MakeWidget();
  vtkDeformationHandleRepresentation* rep = widget->GetDeformationHandleRepresentation();

  // rep->PlaceWidget(bounds), as in other VTK widgets: PlaceFactor scales the bounds about their
  // centre, and the paired filter takes the new handle. That handle is off the surface and small:
  // the filter's warnings say so (its feedback, tested elsewhere), here to an observer.
  vtkNew<vtkCallbackCommand> feedback;
  scene.Filter->AddObserver(vtkCommand::WarningEvent, feedback);
  double bounds[6] = { 0.2, 0.6, 0.1, 0.5, 0.0, 0.1 };
  rep->SetPlaceFactor(1.0);
  rep->PlaceWidget(bounds);
  const double* center = scene.Filter->GetHandleCenter();
  Check(std::abs(center[0] - 0.4) < 1e-12 && std::abs(center[1] - 0.3) < 1e-12 &&
      std::abs(center[2] - 0.05) < 1e-12,
    "PlaceWidget centres the filter's handle in the bounds");
  Check(std::abs(scene.Filter->GetHandleRadius() - 0.02) < 1e-12 &&
      std::abs(scene.Filter->GetROIRadius() - 0.12) < 1e-12,
    "PlaceWidget sizes the filter's radii from the bounds");
  rep->SetPlaceFactor(0.5);
  rep->PlaceWidget(bounds);
  Check(std::abs(scene.Filter->GetROIRadius() - 0.06) < 1e-12, "PlaceWidget follows PlaceFactor");

  // The modifiers are the event translator's bindings, documented in the header.
  vtkWidgetEventTranslator* translator = widget->GetEventTranslator();
  const unsigned long press = vtkCommand::LeftButtonPressEvent;
  Check(translator->GetTranslation(press, vtkEvent::NoModifier, 0, 0, nullptr) ==
        vtkWidgetEvent::Select &&
      translator->GetTranslation(press, vtkEvent::ShiftModifier, 0, 0, nullptr) ==
        vtkWidgetEvent::Resize &&
      translator->GetTranslation(press, vtkEvent::ControlModifier, 0, 0, nullptr) ==
        vtkWidgetEvent::Translate,
    "Select, Resize with Shift, Translate with Control");

  // Rebound as the header says: Control + drag on the sphere resizes the region, refactoring
  // once on release.
  translator->RemoveTranslation(press, vtkEvent::ControlModifier, 0, 0, nullptr);
  translator->SetTranslation(
    press, vtkEvent::ControlModifier, 0, 0, nullptr, vtkWidgetEvent::Resize);
  scene.Window->Render();
  const int factorizations = scene.Filter->GetNumberOfFactorizations();
  double current[3], at[2];
  rep->GetCurrentCenter(current);
  scene.Display(current, at);
  scene.Play(Drag(at, [&](double t, double p[2]) { p[0] = at[0] + 60.0 * t; p[1] = at[1]; },
    ControlModifier));
  Check(scene.Filter->GetROIRadius() > 0.07, "the rebound Control drag resizes the region");
  Check(scene.Filter->GetNumberOfFactorizations() == factorizations + 1,
    "the rebound resize refactors once");
  rep->GetCurrentCenter(current);
  Check(std::sqrt(vtkMath::Distance2BetweenPoints(current, center)) < 1e-12,
    "the rebound Control drag does not translate");
  return failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}


// The largest entry of R - (rotation by `degrees` about unit `axis`).
double RotationError(vtkMatrix4x4* m, const double axis[3], double degrees)
{
  vtkNew<vtkTransform> expected;
  expected->RotateWXYZ(degrees, axis);
  double worst = 0.0;
  for (int r = 0; r < 3; ++r)
  {
    for (int c = 0; c < 3; ++c)
    {
      worst = std::max(worst, std::abs(m->GetElement(r, c) - expected->GetMatrix()->GetElement(r, c)));
    }
  }
  return worst;
}

int RotateAboutEachAxis()
{
  // In a view oblique to all three axes, drag each of the handle's x, y and z rings 60 degrees
  // along itself: the handle turns 60 degrees about that axis (entries within sin 3 degrees),
  // the filter's handle vertices follow, and nothing is refactored. Then, in the scene's own
  // view, where the x ring is seen edge-on (a line), a drag along that line still turns the
  // handle about x.
  Scene scene;
  vtkCamera* camera = scene.Renderer->GetActiveCamera();
  camera->SetPosition(1.3, -1.0, 1.3);
  scene.Renderer->ResetCameraClippingRange();
  auto widget = scene.MakeWidget();
  vtkDeformationHandleRepresentation* rep = widget->GetDeformationHandleRepresentation();
  const int factorizations = scene.Filter->GetNumberOfFactorizations();
  for (int axis = 0; axis < 3; ++axis)
  {
    widget->ResetHandle();
    scene.Window->Render();
    double center[3], e1[3] = { 0.0, 0.0, 0.0 }, e2[3] = { 0.0, 0.0, 0.0 }, direction[3] = { 0.0, 0.0, 0.0 };
    rep->GetCurrentCenter(center);
    e1[(axis + 1) % 3] = 1.0; // the ring's plane, with e1 x e2 the axis
    e2[(axis + 2) % 3] = 1.0;
    direction[axis] = 1.0;
    const double r = 1.15 * rep->GetHandleRadius();
    // Start half-way between the other two rings, and sweep 60 degrees along the ring.
    auto ringPoint = [&](double degrees, double p[2]) {
      const double a = vtkMath::RadiansFromDegrees(degrees);
      double world[3];
      for (int i = 0; i < 3; ++i)
      {
        world[i] = center[i] + r * (std::cos(a) * e1[i] + std::sin(a) * e2[i]);
      }
      scene.Display(world, p);
    };
    // Grab the ring in front of the sphere, outside its disc on screen.
    double centerDisplay[2], view[3], start = 0.0, best = -1.0;
    scene.Display(center, centerDisplay);
    camera->GetDirectionOfProjection(view);
    for (double degrees = 0.0; degrees < 360.0; degrees += 5.0)
    {
      const double a = vtkMath::RadiansFromDegrees(degrees);
      double p[2], offset[3];
      for (int i = 0; i < 3; ++i)
      {
        offset[i] = std::cos(a) * e1[i] + std::sin(a) * e2[i];
      }
      ringPoint(degrees, p);
      const double score = std::hypot(p[0] - centerDisplay[0], p[1] - centerDisplay[1]);
      const bool nearAnotherRing = std::abs(std::cos(a)) < 0.3 || std::abs(std::sin(a)) < 0.3;
      if (!nearAnotherRing && vtkMath::Dot(offset, view) < -0.2 && score > best)
      {
        best = score;
        start = degrees;
      }
    }
    double from[2];
    ringPoint(start, from);
    scene.Play(Drag(from, [&](double t, double p[2]) { ringPoint(start + 60.0 * t, p); }));
    Check(rep->GetRotationAxis() == axis, "the drag picked ring " + std::to_string(axis));
    const double error = RotationError(rep->GetTransform()->GetMatrix(), direction, 60.0);
    std::cout << "ring " << axis << ": rotation error " << error << "\n";
    Check(error < std::sin(vtkMath::RadiansFromDegrees(3.0)),
      "a 60-degree sweep on ring " + std::to_string(axis) + " turns the handle 60 degrees about it");
  }
  // The filter follows the last turn.
  const double worst = scene.HandleError(rep);
  Check(worst < 2e-3, "the filter's handle vertices follow the turn");
  Check(scene.Filter->GetNumberOfFactorizations() == factorizations, "turning does not refactor");

  // Edge-on: from the front (-y), slightly above, the x ring is a vertical line on screen.
  widget->ResetHandle();
  camera->SetPosition(0.5, -1.2, 1.4);
  scene.Renderer->ResetCameraClippingRange();
  scene.Window->Render();
  double center[3], front[3], at[2];
  rep->GetCurrentCenter(center);
  const double r = 1.15 * rep->GetHandleRadius();
  // The x ring's point half-way between its nearest to the camera and its top on screen.
  double view[3], top[3], half[3];
  camera->GetDirectionOfProjection(view);
  const double x[3] = { 1.0, 0.0, 0.0 };
  vtkMath::Cross(x, view, top);
  vtkMath::Normalize(top);
  for (int i = 0; i < 3; ++i)
  {
    half[i] = top[i] - view[i];
  }
  half[0] = 0.0;
  vtkMath::Normalize(half);
  for (int i = 0; i < 3; ++i)
  {
    front[i] = center[i] + r * half[i];
  }
  scene.Display(front, at);
  scene.Play(Drag(at, [&](double t, double p[2]) { p[0] = at[0]; p[1] = at[1] + 15.0 * t; }));
  Check(rep->GetRotationAxis() == vtkDeformationHandleRepresentation::AxisX, "the edge-on x ring is picked");
  vtkMatrix4x4* m = rep->GetTransform()->GetMatrix();
  const double trace = m->GetElement(0, 0) + m->GetElement(1, 1) + m->GetElement(2, 2);
  const double angle = std::acos(std::min(1.0, (trace - 1.0) / 2.0));
  // The rotation axis, from the antisymmetric part; x turns the top of the ring toward -y.
  const double axisX = m->GetElement(2, 1) - m->GetElement(1, 2);
  const double axisNorm = std::hypot(axisX,
    std::hypot(m->GetElement(0, 2) - m->GetElement(2, 0), m->GetElement(1, 0) - m->GetElement(0, 1)));
  std::cout << "edge-on x ring: " << vtkMath::DegreesFromRadians(angle) << " degrees, axis x component "
            << (axisNorm > 0.0 ? axisX / axisNorm : 0.0) << "\n";
  Check(angle > vtkMath::RadiansFromDegrees(5.0) && axisNorm > 0.0 && std::abs(axisX) / axisNorm > 0.999,
    "a drag along the edge-on x ring turns the handle about x");
  return failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}

int ConstrainedMoveAndWheel()
{
  // Control + drag moves along one frame axis, drawn during the drag; the wheel over the handle
  // grows and shrinks the ROI (one refactorization a step), and away from it zooms the camera.
  Scene scene;
  auto widget = scene.MakeWidget();
  vtkDeformationHandleRepresentation* rep = widget->GetDeformationHandleRepresentation();
  vtkNew<vtkPropCollection> actors;
  rep->GetActors(actors);
  int mostVisible = 0;
  auto visible = [&]() {
    int count = 0;
    for (int i = 0; i < actors->GetNumberOfItems(); ++i)
    {
      count += vtkProp::SafeDownCast(actors->GetItemAsObject(i))->GetVisibility() ? 1 : 0;
    }
    return count;
  };
  const int atRest = visible();
  vtkNew<vtkCallbackCommand> watch;
  watch->SetCallback([](vtkObject*, unsigned long, void* data, void*) {
    (*static_cast<std::function<void()>*>(data))();
  });
  std::function<void()> record = [&]() { mostVisible = std::max(mostVisible, visible()); };
  watch->SetClientData(&record);
  widget->AddObserver(vtkCommand::InteractionEvent, watch);

  double start[3], at[2];
  rep->GetCurrentCenter(start);
  scene.Display(start, at);
  // Mostly right on screen (world x), a little up: only x moves.
  scene.Play(Drag(at, [&](double t, double p[2]) { p[0] = at[0] + 70.0 * t; p[1] = at[1] + 15.0 * t; },
    ControlModifier));
  double moved[3];
  rep->GetCurrentCenter(moved);
  std::cout << "constrained move: (" << moved[0] - start[0] << ", " << moved[1] - start[1] << ", "
            << moved[2] - start[2] << ")\n";
  Check(moved[0] - start[0] > 0.05, "the constrained drag moves along x");
  Check(moved[1] == start[1] && moved[2] == start[2], "and along x only");
  Check(mostVisible == atRest + 1, "the axis is drawn during the constrained drag");
  Check(visible() == atRest, "and hidden after it");

  const int factorizations = scene.Filter->GetNumberOfFactorizations();
  const double roi = rep->GetROIRadius();
  rep->GetCurrentCenter(moved);
  scene.Display(moved, at);
  scene.Play(Event("MouseMoveEvent", at[0], at[1]) + Event("MouseWheelForwardEvent", at[0], at[1]));
  scene.Window->Render();
  Check(std::abs(rep->GetROIRadius() - 1.1 * roi) < 1e-12, "the wheel over the handle grows the ROI");
  Check(std::abs(scene.Filter->GetROIRadius() - rep->GetROIRadius()) < 1e-12, "the filter follows");
  Check(scene.Filter->GetNumberOfFactorizations() == factorizations + 1, "one refactorization");
  scene.Play(Event("MouseWheelBackwardEvent", at[0], at[1]));
  scene.Window->Render();
  Check(std::abs(rep->GetROIRadius() - roi) < 1e-12, "and shrinks it back");

  const double distance = scene.Renderer->GetActiveCamera()->GetDistance();
  scene.Play(Event("MouseMoveEvent", 10.0, 10.0) + Event("MouseWheelForwardEvent", 10.0, 10.0));
  Check(std::abs(rep->GetROIRadius() - roi) < 1e-12, "the wheel elsewhere leaves the ROI");
  Check(scene.Renderer->GetActiveCamera()->GetDistance() < distance, "and zooms the camera");
  return failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}

int PropertyAccessors()
{
  // ParaView drives the representation through SetRestCenter, SetTranslation and
  // SetRotationAngles, and reads GetRotationAngles back: they follow the filter's
  // HandleCenter, HandleTranslation and HandleRotation, in any order.
  Scene scene;
  vtkNew<vtkDeformationHandleRepresentation> rep;
  rep->SetRotationAngles(10.0, -35.0, 70.0);
  rep->SetTranslation(0.05, -0.02, 0.1);
  rep->SetRestCenter(0.5, 0.5, 0.0);
  const double* angles = rep->GetRotationAngles();
  Check(std::abs(angles[0] - 10.0) < 1e-9 && std::abs(angles[1] + 35.0) < 1e-9 &&
      std::abs(angles[2] - 70.0) < 1e-9,
    "the rotation angles read back as set");
  scene.Filter->SetHandleCenter(0.5, 0.5, 0.0);
  scene.Filter->SetHandleTranslation(0.05, -0.02, 0.1);
  scene.Filter->SetHandleRotation(10.0, -35.0, 70.0);
  scene.Filter->Update();
  const double worst = scene.HandleError(rep);
  std::cout << "handle points from the properties vs the representation's transform: " << worst << "\n";
  Check(worst < 2e-3, "the representation's transform is the filter's property transform");
  // Near gimbal lock (y = 90 degrees) the angles still give the same rotation.
  rep->SetRotationAngles(30.0, 90.0, 0.0);
  vtkNew<vtkMatrix4x4> before;
  before->DeepCopy(rep->GetTransform()->GetMatrix());
  angles = rep->GetRotationAngles();
  rep->SetRotationAngles(angles[0], angles[1], angles[2]);
  double drift = 0.0;
  for (int r = 0; r < 3; ++r)
  {
    for (int c = 0; c < 3; ++c)
    {
      drift = std::max(drift, std::abs(before->GetElement(r, c) - rep->GetTransform()->GetMatrix()->GetElement(r, c)));
    }
  }
  Check(drift < 1e-9, "angles read at gimbal lock give the same rotation back");
  return failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}

int TwoHandleGroups()
{
  // Labels: handle groups 0 and 1 (labels 2 and 3) on either side of an ROI disc, one widget
  // each. Dragging one moves only its group; a commit through one widget rests both handles.
  Scene scene;
  vtkNew<vtkIntArray> labels;
  labels->SetName("Labels");
  const double centers[2][2] = { { 0.35, 0.5 }, { 0.65, 0.5 } };
  for (vtkIdType i = 0; i < scene.Rest->GetNumberOfPoints(); ++i)
  {
    const double* p = scene.Rest->GetPoint(i);
    int label = std::hypot(p[0] - 0.5, p[1] - 0.5) < 0.4 ? 1 : 0;
    for (int g = 0; g < 2; ++g)
    {
      label = std::hypot(p[0] - centers[g][0], p[1] - centers[g][1]) < 0.06 ? 2 + g : label;
    }
    labels->InsertNextValue(label);
  }
  scene.Rest->GetPointData()->AddArray(labels);
  scene.Filter->SetSelectionModeToArray();
  scene.Filter->SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, "Labels");
  scene.Filter->SetHandleCenter(centers[0][0], centers[0][1], 0.0);
  scene.Filter->SetROIRadius(0.1); // drawn only: the labels choose the region
  scene.Filter->Update();
  auto first = scene.MakeWidget(0);
  auto second = scene.MakeWidget(1);
  vtkDeformationHandleRepresentation* reps[2] = { first->GetDeformationHandleRepresentation(),
    second->GetDeformationHandleRepresentation() };
  double pivot[3];
  reps[1]->GetCurrentCenter(pivot);
  Check(std::hypot(pivot[0] - centers[1][0], pivot[1] - centers[1][1]) < 0.02,
    "the second widget starts at its group's centroid");
  const int factorizations = scene.Filter->GetNumberOfFactorizations();

  // Drag the first handle up 50 pixels and the second down 50.
  double moves[2][3];
  for (int g = 0; g < 2; ++g)
  {
    double start[3], at[2];
    reps[g]->GetCurrentCenter(start);
    scene.Display(start, at);
    const double dy = g == 0 ? 50.0 : -50.0;
    scene.Play(Drag(at, [&](double t, double p[2]) { p[0] = at[0]; p[1] = at[1] + dy * t; }));
    reps[g]->GetCurrentCenter(moves[g]);
    vtkMath::Subtract(moves[g], start, moves[g]);
  }
  std::cout << "group moves: " << vtkMath::Norm(moves[0]) << ", " << vtkMath::Norm(moves[1]) << "\n";
  Check(vtkMath::Norm(moves[0]) > 0.05 && vtkMath::Norm(moves[1]) > 0.05, "both handles moved");
  Check(vtkMath::Dot(moves[0], moves[1]) < 0.0, "in opposite directions");
  scene.Filter->Update();
  for (int g = 0; g < 2; ++g)
  {
    const double error = scene.HandleError(reps[g], "Labels", 2 + g);
    std::cout << "group " << g << " off its widget's transform by " << error << "\n";
    Check(error < 2e-3, "each group follows its own widget");
  }
  Check(scene.Filter->GetNumberOfFactorizations() == factorizations, "dragging refactors nothing");

  // Commit through the second widget: both handles rest, and the shape stays.
  vtkNew<vtkPolyData> edited;
  edited->DeepCopy(scene.Filter->GetOutput());
  second->CommitEdit();
  scene.Filter->Update();
  for (int g = 0; g < 2; ++g)
  {
    Check(reps[g]->GetTransform()->GetMatrix()->IsIdentity(), "a commit rests every handle");
  }
  const double kept = MaxPointDistance(edited, scene.Filter->GetOutput());
  std::cout << "after the commit, the surface moved by " << kept << "\n";
  Check(kept < 1e-9, "a commit keeps the edited shape");

  // Undo through the first: back to the input, both handles at rest.
  reps[1]->SetTranslation(0.0, 0.0, 0.1);
  Check(first->UndoCommit(), "the commit is undone");
  scene.Filter->Update();
  Check(reps[1]->GetTransform()->GetMatrix()->IsIdentity(), "an undo rests every handle");
  const double restored = MaxPointDistance(scene.Rest, scene.Filter->GetOutput());
  std::cout << "after the undo, off the input by " << restored << "\n";
  Check(restored < 1e-9, "an undo restores the input");

  // A click on the surface between the handles places the first handle there; the second
  // keeps its pivot at its group's centroid.
  double target[3], pivotBefore[3], at[2];
  scene.Rest->GetPoint(scene.Rest->FindPoint(0.5, 0.25, 0.0), target);
  reps[1]->GetCurrentCenter(pivotBefore);
  scene.Renderer->ResetCameraClippingRange();
  scene.Window->Render();
  scene.Display(target, at);
  scene.Play(Event("MouseMoveEvent", at[0], at[1]) + Event("LeftButtonPressEvent", at[0], at[1]) +
    Event("LeftButtonReleaseEvent", at[0], at[1]));
  double placed[3], pivotAfter[3];
  reps[0]->GetCurrentCenter(placed);
  reps[1]->GetCurrentCenter(pivotAfter);
  std::cout << "click: first handle " << std::sqrt(vtkMath::Distance2BetweenPoints(placed, target))
            << " from the clicked point, second pivot moved by "
            << std::sqrt(vtkMath::Distance2BetweenPoints(pivotBefore, pivotAfter)) << "\n";
  Check(std::sqrt(vtkMath::Distance2BetweenPoints(placed, target)) < 1e-9,
    "a click places the first handle");
  Check(std::sqrt(vtkMath::Distance2BetweenPoints(pivotBefore, pivotAfter)) < 1e-12,
    "a click leaves the other group's pivot at its centroid");
  return failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}

int ARAPDragCapsIterations()
{
  // In the as-rigid-as-possible mode a drag turns the filter's Dragging on: each frame runs at
  // most DragARAPIterations, the drag never refactors, and the release turns it off, so that
  // one more update settles the shape with ARAPIterations in full.
  Scene scene;
  scene.Filter->SetRotationModeToAsRigidAsPossible();
  scene.Filter->Update();
  const vtkMTimeType before = scene.Filter->GetMTime();
  scene.Filter->DraggingOn();
  Check(scene.Filter->GetMTime() == before, "turning Dragging on does not modify the filter");
  scene.Filter->DraggingOff();
  Check(scene.Filter->GetMTime() > before, "turning it off does");
  scene.Filter->Update();
  auto widget = scene.MakeWidget();
  const int factorizations = scene.Filter->GetNumberOfFactorizations();

  struct Update
  {
    bool Dragging;
    int Iterations;
    double Energy;
  };
  std::vector<Update> updates;
  vtkNew<vtkCallbackCommand> watch;
  watch->SetCallback([](vtkObject* caller, unsigned long, void* data, void*) {
    auto* filter = static_cast<vtkLaplacianDeformationFilter*>(caller);
    static_cast<std::vector<Update>*>(data)->push_back(
      { filter->GetDragging() != 0, filter->GetNumberOfARAPIterations(), filter->GetARAPEnergy() });
  });
  watch->SetClientData(&updates);
  scene.Filter->AddObserver(vtkCommand::EndEvent, watch);

  double center[3], at[2];
  widget->GetDeformationHandleRepresentation()->GetCurrentCenter(center);
  scene.Display(center, at);
  scene.Play(Drag(at, [&](double t, double p[2]) { p[0] = at[0]; p[1] = at[1] + 120.0 * t; }));
  scene.Window->Render();
  scene.Filter->RemoveObserver(watch);

  Check(updates.size() == 11, "one update a move and one after the release (" +
      std::to_string(updates.size()) + ")");
  Check(scene.Filter->GetNumberOfFactorizations() == factorizations, "the drag does not refactor");
  if (updates.size() < 2)
  {
    return EXIT_FAILURE;
  }
  bool capped = true;
  for (std::size_t k = 0; k + 1 < updates.size(); ++k)
  {
    capped = capped && updates[k].Dragging && updates[k].Iterations >= 1 &&
      updates[k].Iterations <= scene.Filter->GetDragARAPIterations();
  }
  Check(capped, "every update of the drag runs with Dragging on and at most 2 iterations");
  const Update& dragEnd = updates[updates.size() - 2];
  const Update& released = updates.back();
  Check(!released.Dragging && !scene.Filter->GetDragging(), "the release turns Dragging off");
  Check(released.Energy <= dragEnd.Energy * (1.0 + 1e-12), "the release's update lowers the energy");

  // The same pose, converged.
  vtkNew<vtkLaplacianDeformationFilter> converged;
  converged->SetInputData(scene.Rest);
  converged->SetHandleCenter(scene.Filter->GetHandleCenter());
  converged->SetHandleRadius(scene.Filter->GetHandleRadius());
  converged->SetROIRadius(scene.Filter->GetROIRadius());
  converged->SetHandleTransform(scene.Filter->GetHandleTransform());
  converged->SetRotationModeToAsRigidAsPossible();
  converged->SetARAPIterations(10000);
  converged->SetConvergence(1e-12);
  converged->Update();
  const double best = converged->GetARAPEnergy();
  std::cout << "ARAP drag: iterations";
  for (const Update& update : updates)
  {
    std::cout << " " << update.Iterations;
  }
  std::cout << "; energy over converged at the drag's end " << dragEnd.Energy / best
            << ", after the release " << released.Energy / best << "\n";
  Check(best > 0.0 && dragEnd.Energy <= 1.05 * best, "the drag ends within 5% of converged");
  Check(released.Iterations == scene.Filter->GetARAPIterations() &&
      released.Energy <= 1.01 * best,
    "the release settles: ARAPIterations in full, within 1% of converged");
  return failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}

int ReleaseSettlesBetweenEvents()
{
  // A large region (its proxy dragged, its release settled by Newton's steps) whose filter's
  // SettleTimeLimit every step reaches: the release's update stops after one step, and the
  // widget continues the settle between the interactor's events, one step an update, until it
  // ends. An update that comes while the full-resolution system still builds on its thread (on
  // a loaded machine) takes no step: it waits at most one report interval. Required: the
  // release leaves the filter settling; the event loop then runs more updates of at most one
  // step each, at least two of them a step, and the settle ends with the filter no longer
  // settling, within 1% of the converged energy (the factored filter's, run to convergence).
  Scene scene;
  vtkLaplacianDeformationFilter* filter = scene.Filter;
  filter->SetRotationModeToAsRigidAsPossible();
  filter->SetLargeRegionVertices(200);
  filter->SetProxyNodes(200);
  filter->SetARAPIterations(50);
  filter->SetSettleTimeLimit(1e-9);
  filter->Update();
  auto widget = scene.MakeWidget();

  std::vector<int> iterations;
  vtkNew<vtkCallbackCommand> watch;
  watch->SetCallback([](vtkObject* caller, unsigned long, void* data, void*) {
    auto* edit = static_cast<vtkLaplacianDeformationFilter*>(caller);
    static_cast<std::vector<int>*>(data)->push_back(edit->GetNumberOfARAPIterations());
  });
  watch->SetClientData(&iterations);
  double center[3], at[2];
  widget->GetDeformationHandleRepresentation()->GetCurrentCenter(center);
  scene.Display(center, at);
  scene.Play(Drag(at, [&](double t, double p[2]) { p[0] = at[0]; p[1] = at[1] + 120.0 * t; }));
  Check(filter->GetSettling() != 0, "the release's update stops its settle at the time limit");

  // The event loop, until the settle ends (or 60 s pass).
  filter->AddObserver(vtkCommand::EndEvent, watch);
  vtkNew<vtkCallbackCommand> stop;
  stop->SetClientData(scene.Interactor.Get());
  stop->SetCallback([](vtkObject* caller, unsigned long, void* interactor, void*) {
    auto* edit = vtkLaplacianDeformationFilter::SafeDownCast(caller);
    if (!edit || !edit->GetSettling())
    {
      static_cast<vtkRenderWindowInteractor*>(interactor)->TerminateApp();
    }
  });
  filter->AddObserver(vtkCommand::EndEvent, stop);
  scene.Interactor->AddObserver(vtkCommand::TimerEvent, stop);
  scene.Interactor->CreateOneShotTimer(60000);
  scene.Interactor->Start();
  filter->RemoveObserver(watch);

  bool stepwise = true;
  int stepped = 0;
  for (int count : iterations)
  {
    stepwise = stepwise && (count == 0 || count == 1);
    stepped += count;
  }
  std::cout << "settle continued in " << iterations.size() << " updates, " << stepped
            << " of them a step\n";
  Check(!filter->GetSettling(), "the settle ends");
  Check(stepped >= 2, "the event loop continues the settle");
  Check(stepwise, "at most one step an update");

  vtkNew<vtkLaplacianDeformationFilter> converged;
  converged->SetInputData(scene.Rest);
  converged->SetHandleCenter(filter->GetHandleCenter());
  converged->SetHandleRadius(filter->GetHandleRadius());
  converged->SetROIRadius(filter->GetROIRadius());
  converged->SetHandleTransform(filter->GetHandleTransform());
  converged->SetRotationModeToAsRigidAsPossible();
  converged->SetARAPIterations(10000);
  converged->SetConvergence(1e-12);
  converged->Update();
  const double best = converged->GetARAPEnergy();
  std::cout << "settled energy over converged " << filter->GetARAPEnergy() / best << "\n";
  Check(best > 0.0 && filter->GetARAPEnergy() <= 1.01 * best, "settled within 1% of converged");
  return failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}

// What the window shows, as RGB bytes.
std::vector<unsigned char> Frame(vtkRenderWindow* window)
{
  window->Render();
  vtkNew<vtkWindowToImageFilter> grab;
  grab->SetInput(window);
  grab->ReadFrontBufferOff();
  grab->Update();
  vtkDataArray* pixels = grab->GetOutput()->GetPointData()->GetScalars();
  const auto* bytes = vtkUnsignedCharArray::SafeDownCast(pixels)->GetPointer(0);
  return { bytes, bytes + pixels->GetNumberOfValues() };
}

// The share of pixels that differ by more than `tolerance` in a channel.
double DifferingPixels(const std::vector<unsigned char>& a, const std::vector<unsigned char>& b,
  int tolerance = 8)
{
  std::size_t differing = 0;
  for (std::size_t i = 0; i + 2 < a.size(); i += 3)
  {
    bool differs = false;
    for (int c = 0; c < 3; ++c)
    {
      differs = differs || std::abs(int(a[i + c]) - int(b[i + c])) > tolerance;
    }
    differing += differs;
  }
  return a.empty() ? 1.0 : 3.0 * differing / a.size();
}

int PreviewDrawsWhatTheUpdateDraws()
{
  // A representation whose motion is previewed, as ParaView's panel drives one: the controller
  // beside it, the motion set as its properties, the pipeline left alone until the motion is
  // applied. Along a drag of four frames, each part's index buffers are built once: only the
  // cells shape them (VTK's own key would rebuild them at every move of the points).
  Scene scene;
  vtkNew<vtkDeformationHandleRepresentation> rep;
  vtkNew<vtkDeformationPreviewController> preview;
  preview->SetRepresentation(rep);
  rep->SetRenderer(scene.Renderer);
  rep->SetCenter(scene.Filter->GetHandleCenter());
  rep->SetHandleRadius(scene.Filter->GetHandleRadius());
  rep->SetROIRadius(scene.Filter->GetROIRadius());
  scene.Renderer->AddViewProp(rep);
  int updates = 0;
  vtkNew<vtkCallbackCommand> counter;
  counter->SetCallback(
    [](vtkObject*, unsigned long, void* data, void*) { ++*static_cast<int*>(data); });
  counter->SetClientData(&updates);
  scene.Filter->AddObserver(vtkCommand::EndEvent, counter);
  const std::vector<unsigned char> before = Frame(scene.Window);

  preview->SetFilter(scene.Filter);
  preview->PreviewingOn();
  for (int frame = 1; frame <= 3; ++frame)
  {
    rep->SetTranslation(0.0, -0.0125 * frame, 0.03 * frame);
    rep->SetRotationAngles(5.0 * frame, 0.0, 0.0);
    scene.Window->Render();
  }
  rep->SetTranslation(0.0, -0.05, 0.12);
  rep->SetRotationAngles(20.0, 0.0, 0.0);
  Check(preview->IsPreviewShown(), "the preview shows");
  Check(!scene.SurfaceActor()->GetVisibility(), "the surface's actor is hidden while previewing");
  const std::vector<unsigned char> previewed = Frame(scene.Window);
  std::vector<int> indexBuilds;
  vtkActorCollection* actors = scene.Renderer->GetActors(); // rebuilt at each call
  vtkCollectionSimpleIterator it;
  actors->InitTraversal(it);
  while (vtkActor* actor = actors->GetNextActor(it))
  {
    if (auto* part = LaplacianEditing::Widgets::PreviewPartMapper::SafeDownCast(actor->GetMapper()))
    {
      indexBuilds.push_back(part->GetNumberOfIndexBuilds());
    }
  }
  std::cout << "index buffer builds of the parts over four frames:";
  for (int builds : indexBuilds)
  {
    std::cout << " " << builds;
  }
  std::cout << "\n";
  Check(indexBuilds == std::vector<int>{ 1, 1 },
    "each part's index buffers are built once over the drag's four frames");
  Check(updates == 0, "previewing updates nothing (" + std::to_string(updates) + " updates)");
  Check(preview->GetPreviewTime() > 0.0, "the last preview's solve and write are timed");
  rep->VisibilityOff();
  Check(!preview->IsPreviewShown() && scene.SurfaceActor()->GetVisibility(),
    "a hidden representation previews nothing");
  rep->VisibilityOn();
  Check(preview->IsPreviewShown(), "shown again, it previews");

  preview->PreviewingOff();
  Check(!preview->IsPreviewShown() && scene.SurfaceActor()->GetVisibility(),
    "turning previewing off shows the surface's actor again");
  scene.Filter->SetHandleTranslation(rep->GetTranslation());
  scene.Filter->SetHandleRotation(rep->GetRotationAngles());
  const std::vector<unsigned char> applied = Frame(scene.Window);
  const double moved = DifferingPixels(before, applied);
  const double mismatch = DifferingPixels(previewed, applied);
  std::cout << "pixels the motion changes " << moved << ", pixels where the preview differs from "
            << "the update " << mismatch << "\n";
  Check(moved > 0.02, "the motion changes the picture");
  Check(mismatch < 0.001, "the preview draws what the update draws (0.1% of pixels)");
  return failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}

int PartMapperDrawsWhatVTKDraws()
{
  // The preview's mapper builds its own index buffers for a surface of triangles: the
  // connectivity uploaded whole. Drawn through it and through VTK's mapper, the same data gives
  // the same pixels: with 32- and 64-bit ids, coloured by cell (primitive ids map to cells),
  // and where VTK builds the buffers (edges shown, wireframe, a quad), back and forth.
  Scene scene;
  vtkSmartPointer<vtkPolyData> surface = MakeBumpyPlane(24);
  vtkNew<vtkIntArray> cellIds;
  cellIds->SetName("CellId");
  for (vtkIdType cell = 0; cell < surface->GetNumberOfCells(); ++cell)
  {
    cellIds->InsertNextValue(static_cast<int>(cell % 7));
  }
  surface->GetCellData()->SetScalars(cellIds);
  vtkNew<vtkPolyDataMapper> vtkMapper;
  vtkNew<LaplacianEditing::Widgets::PreviewPartMapper> partMapper;
  for (vtkPolyDataMapper* mapper : { vtkMapper.Get(), static_cast<vtkPolyDataMapper*>(partMapper) })
  {
    mapper->SetInputData(surface);
    mapper->SetScalarModeToUseCellData();
    mapper->SetScalarRange(0.0, 6.0);
  }
  vtkActor* actor = scene.SurfaceActor();
  vtkProperty* property = actor->GetProperty();
  property->SetEdgeColor(0.1, 0.1, 0.1);
  auto compare = [&](const std::string& what) {
    actor->SetMapper(vtkMapper);
    const std::vector<unsigned char> expected = Frame(scene.Window);
    actor->SetMapper(partMapper);
    const std::vector<unsigned char> drawn = Frame(scene.Window);
    const double differing = DifferingPixels(expected, drawn, 0);
    std::cout << what << ": index builds " << partMapper->GetNumberOfIndexBuilds()
              << ", pixels that differ " << differing << "\n";
    Check(differing == 0.0, what + ": the preview's mapper draws what VTK's draws");
  };
  compare("triangles");
  property->EdgeVisibilityOn();
  compare("triangles with edges");
  property->EdgeVisibilityOff();
  property->SetRepresentationToWireframe();
  compare("wireframe");
  property->SetRepresentationToSurface();
  compare("triangles again");
  surface->GetPolys()->ConvertTo64BitStorage();
  surface->GetPolys()->Modified(); // a cell array's edits leave that to their maker, as VTK's key
  surface->Modified();
  compare("64-bit ids");
  const vtkIdType quad[4] = { 0, 1, 26, 25 }; // a row of the 25 x 25 grid and the next
  surface->GetPolys()->InsertNextCell(4, quad);
  cellIds->InsertNextValue(3);
  surface->GetPolys()->Modified();
  cellIds->Modified();
  surface->Modified();
  compare("a quad among the triangles");
  Check(partMapper->GetNumberOfIndexBuilds() == 6, "each change of the cells or the look rebuilds once");
  return failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}

int VolumeDrag()
{
  // The widget pairs with a volume filter's surface filter: a drag of the handle moves the
  // beam's end, each move updates the volume (one iteration of its interior, Dragging on) and
  // the release settles it; no cell inverts.
  vtkSmartPointer<vtkUnstructuredGrid> beam = VolumeMeshes::HexBeam(20, 4, 4, 4.0);
  vtkNew<vtkLaplacianVolumeDeformationFilter> volume;
  volume->SetInputData(beam);
  volume->SetHandleCenter(4.0, 0.5, 0.5);
  volume->SetHandleRadius(0.3);
  volume->SetROIRadius(2.0);
  vtkNew<vtkDataSetMapper> mapper;
  mapper->SetInputConnection(volume->GetOutputPort());
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  vtkNew<vtkRenderer> renderer;
  renderer->AddActor(actor);
  vtkNew<vtkRenderWindow> window;
  XDisplay::AttachOrExit(window);
  window->SetSize(500, 400);
  window->SetMultiSamples(0);
  window->AddRenderer(renderer);
  vtkNew<vtkRenderWindowInteractor> interactor;
  interactor->SetRenderWindow(window);
  vtkNew<vtkInteractorStyleTrackballCamera> style;
  interactor->SetInteractorStyle(style);
  vtkCamera* camera = renderer->GetActiveCamera();
  camera->SetFocalPoint(2.0, 0.5, 0.5);
  camera->SetPosition(2.0, -8.0, 0.5);
  camera->SetViewUp(0.0, 0.0, 1.0);
  renderer->ResetCameraClippingRange();
  window->Render();
  vtkNew<vtkDeformationHandleWidget> widget;
  widget->SetInteractor(interactor);
  widget->SetDeformationFilter(volume->GetSurfaceFilter());
  widget->SetSurfaceProp(actor);
  widget->On();
  window->Render();

  std::vector<int> dragging;
  vtkNew<vtkCallbackCommand> watch;
  watch->SetCallback([](vtkObject* caller, unsigned long, void* data, void*) {
    static_cast<std::vector<int>*>(data)->push_back(
      static_cast<vtkLaplacianVolumeDeformationFilter*>(caller)->GetDragging());
  });
  watch->SetClientData(&dragging);
  volume->AddObserver(vtkCommand::EndEvent, watch);
  double center[3], at[2];
  widget->GetDeformationHandleRepresentation()->GetCurrentCenter(center);
  renderer->SetWorldPoint(center[0], center[1], center[2], 1.0);
  renderer->WorldToDisplay();
  at[0] = renderer->GetDisplayPoint()[0];
  at[1] = renderer->GetDisplayPoint()[1];
  vtkNew<vtkInteractorEventRecorder> recorder;
  recorder->SetInteractor(interactor);
  recorder->ReadFromInputStringOn();
  recorder->SetInputString(
    Drag(at, [&](double t, double p[2]) { p[0] = at[0]; p[1] = at[1] + 60.0 * t; }).c_str());
  recorder->Play();
  window->Render();
  volume->RemoveObserver(watch);

  const int during = static_cast<int>(std::count(dragging.begin(), dragging.end(), 1));
  Check(during >= 5 && !dragging.empty() && dragging.back() == 0,
    "the drag updates the volume with Dragging on (" + std::to_string(during) + " of " +
      std::to_string(dragging.size()) + " updates), the release once more with it off");
  double top = -1e300;
  for (vtkIdType i = 0; i < beam->GetNumberOfPoints(); ++i)
  {
    top = std::max(top, volume->GetOutput()->GetPoint(i)[2]);
  }
  Check(top > 1.3, "the beam's end rose with the handle (top at " + std::to_string(top) + ")");
  Check(VolumeMeshes::Measure(volume->GetOutput()).Inverted == 0, "no cell inverted");
  Check(volume->GetNumberOfFailedCells() == 0, "every boundary point met its edit");
  return failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}

int DeleteMidInteraction()
{
  Scene scene;
  double at[2];
  {
    auto widget = scene.MakeWidget();
    double current[3];
    widget->GetDeformationHandleRepresentation()->GetCurrentCenter(current);
    scene.Display(current, at);
    scene.Play(Event("MouseMoveEvent", at[0], at[1]) + Event("LeftButtonPressEvent", at[0], at[1]) +
      Event("MouseMoveEvent", at[0], at[1] + 20.0));
  } // the widget goes away while the button is down
  scene.Play(Event("MouseMoveEvent", at[0], at[1] + 40.0) +
    Event("LeftButtonReleaseEvent", at[0], at[1] + 40.0));
  scene.Window->Render();
  Check(scene.Filter->GetNumberOfFactorizations() >= 1, "the filter still works");
  return failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
}

int main(int argc, char* argv[])
{
  const std::map<std::string, std::function<int()>> cases = {
    { "PlaceDragRotateResize", [&] { return PlaceDragRotateResize(argc, argv); } },
    { "DeleteMidInteraction", DeleteMidInteraction }, { "PickingManager", PickingManager },
    { "PlaceWidgetAndBindings", PlaceWidgetAndBindings },
    { "OrbitClickAndCommit", OrbitClickAndCommit },
    { "TranslucentHandle", [&] { return TranslucentHandle(argc, argv); } },
    { "RotateAboutEachAxis", RotateAboutEachAxis },
    { "ConstrainedMoveAndWheel", ConstrainedMoveAndWheel },
    { "PropertyAccessors", PropertyAccessors }, { "TwoHandleGroups", TwoHandleGroups },
    { "ARAPDragCapsIterations", ARAPDragCapsIterations },
    { "ReleaseSettlesBetweenEvents", ReleaseSettlesBetweenEvents },
    { "PreviewDrawsWhatTheUpdateDraws", PreviewDrawsWhatTheUpdateDraws },
    { "PartMapperDrawsWhatVTKDraws", PartMapperDrawsWhatVTKDraws },
    { "VolumeDrag", VolumeDrag } };
  const auto found = cases.find(argc > 1 ? argv[1] : "");
  if (found != cases.end())
  {
    return found->second();
  }
  std::cerr << "usage: " << argv[0] << " <case> [-V baseline -T temp], the cases:";
  for (const auto& entry : cases)
  {
    std::cerr << " " << entry.first;
  }
  std::cerr << "\n";
  return EXIT_FAILURE;
}
