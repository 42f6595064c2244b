// Drives vtkDeformationHandleWidget with recorded events, as VTK's BoxWidget2 test does: place
// the handle by clicking the surface, drag it, turn it, resize the ROI, release. Checks the
// handle transform and the filter's output numerically, the factorization count, and the final
// frame against a baseline. A second case deletes the widget in the middle of a drag; a third
// drags and places with VTK's picking manager on; a fourth places through PlaceWidget and drags
// with a rebound modifier; a fifth orbits by dragging the surface and commits by clicking; a sixth
// renders a translucent handle against a baseline.
// Usage: TestDeformationHandleWidget <case> [-V <baseline.png> -T <temp folder>]
#include "EditingScene.h"

#include "vtkDeformationHandleRepresentation.h"
#include "vtkDeformationHandleWidget.h"

#include "vtkCallbackCommand.h"
#include "vtkCamera.h"
#include "vtkEvent.h"
#include "vtkInteractorEventRecorder.h"
#include "vtkInteractorStyleTrackballCamera.h"
#include "vtkMatrix4x4.h"
#include "vtkPickingManager.h"
#include "vtkPoints.h"
#include "vtkProperty.h"
#include "vtkRegressionTestImage.h"
#include "vtkRenderWindowInteractor.h"
#include "vtkWidgetEvent.h"
#include "vtkWidgetEventTranslator.h"

#include <cmath>
#include <cstdio>
#include <iostream>
#include <sstream>
#include <string>

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
    vtkNew<vtkBumpyPlaneSource> source;
    source->SetResolution(60);
    source->Update();
    this->Rest = source->GetOutput();
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
  vtkSmartPointer<vtkDeformationHandleWidget> MakeWidget()
  {
    auto widget = vtkSmartPointer<vtkDeformationHandleWidget>::New();
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
  vtkPolyData* output = scene.Filter->GetOutput();
  vtkDataArray* roles = output->GetPointData()->GetArray("EditRole");
  double worst = 0.0;
  for (vtkIdType i = 0; i < output->GetNumberOfPoints(); ++i)
  {
    if (roles->GetTuple1(i) == vtkLaplacianDeformationFilter::ROLE_HANDLE)
    {
      double expected[3];
      rep->GetTransform()->TransformPoint(scene.Rest->GetPoint(i), expected);
      worst = std::max(worst, std::sqrt(vtkMath::Distance2BetweenPoints(expected, output->GetPoint(i))));
    }
  }
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
  const std::string name = argc > 1 ? argv[1] : "";
  if (name == "PlaceDragRotateResize")
  {
    return PlaceDragRotateResize(argc, argv);
  }
  if (name == "DeleteMidInteraction")
  {
    return DeleteMidInteraction();
  }
  if (name == "PickingManager")
  {
    return PickingManager();
  }
  if (name == "PlaceWidgetAndBindings")
  {
    return PlaceWidgetAndBindings();
  }
  if (name == "OrbitClickAndCommit")
  {
    return OrbitClickAndCommit();
  }
  if (name == "TranslucentHandle")
  {
    return TranslucentHandle(argc, argv);
  }
  std::cerr << "usage: " << argv[0]
            << " PlaceDragRotateResize|DeleteMidInteraction|PickingManager|PlaceWidgetAndBindings|"
               "OrbitClickAndCommit|TranslucentHandle"
               " [-V baseline -T temp]\n";
  return EXIT_FAILURE;
}
