// An interactive Laplacian editor: open a mesh (or the embedded bumpy plane), drag the handle,
// watch the surface follow.
//
//   InteractiveEditor [--mode none|explicit|implicit|arap] [--up x|y|z]
//                     [--offscreen SCREENSHOT.png] [MESH]
//
// MESH: OBJ, PLY, STL, OFF, VTP or VTK. The first view puts the up axis (default y, the scans'
// convention) up and the mesh's longer horizontal extent across the screen; the first handle
// sits on the point that stands out most in that view, with radii of 0.03 and 0.15 of the
// mesh's diagonal. Mouse: a left drag orbits the camera, as in any VTK application; a click on
// the surface places the handle there (an edit in progress is committed first); drag the sphere
// to move the handle (Control: along one axis), the ring to turn it; Shift + drag the sphere
// resizes the region, Shift + drag the ring the handle. Keys: m rotation mode, r reset, c commit
// the edit, u undo the commit, s save edited.vtp, q quit. With --offscreen it plays a scripted
// drag instead and saves a screenshot (no window needs to show). A file it cannot read: one
// line on stderr, exit code 1.
#include "EditingScene.h"
#include "MeshReader.h"
#include "XDisplay.h"

#include "vtkDeformationHandleRepresentation.h"
#include "vtkDeformationHandleWidget.h"

#include "vtkCallbackCommand.h"
#include "vtkCamera.h"
#include "vtkInteractorEventRecorder.h"
#include "vtkInteractorStyleTrackballCamera.h"
#include "vtkRenderWindowInteractor.h"
#include "vtkTextActor.h"
#include "vtkTextProperty.h"
#include "vtkXMLPolyDataWriter.h"

#include <algorithm>
#include <cstdio>
#include <iostream>
#include <optional>
#include <string>

namespace
{
const char* Help =
  "mouse: drag = orbit | click surface = place handle (commits the edit) | drag sphere = move\n"
  "       (Ctrl: one axis) | drag ring = turn | Shift+drag sphere = region | Shift+drag ring = handle\n"
  "keys:  m rotation mode | r reset | c commit edit | u undo commit | s save edited.vtp | q quit";
const char* ModeNames[] = { "none", "explicit", "implicit", "arap" };

struct Editor
{
  vtkLaplacianDeformationFilter* Filter;
  vtkDeformationHandleWidget* Widget;
  vtkTextActor* Status;
};

void ShowStatus(Editor& editor)
{
  char text[256];
  std::snprintf(text, sizeof(text), "rotation mode: %s   ROI vertices: %d",
    ModeNames[editor.Filter->GetRotationMode()], editor.Filter->GetNumberOfROIVertices());
  editor.Status->SetInput(text);
}

// The status follows the filter: after a key, and after a click or a resize (the region changed).
void Refresh(Editor& editor)
{
  editor.Filter->Update();
  ShowStatus(editor);
  editor.Widget->GetInteractor()->Render();
}

void OnInteractionEnd(vtkObject*, unsigned long, void* data, void*)
{
  Refresh(*static_cast<Editor*>(data));
}

void OnKey(vtkObject* caller, unsigned long, void* data, void*)
{
  auto* interactor = static_cast<vtkRenderWindowInteractor*>(caller);
  Editor& editor = *static_cast<Editor*>(data);
  const std::string key = interactor->GetKeySym() ? interactor->GetKeySym() : "";
  if (key == "m")
    editor.Filter->SetRotationMode((editor.Filter->GetRotationMode() + 1) % 4);
  else if (key == "r")
    editor.Widget->ResetHandle();
  else if (key == "c")
    editor.Widget->CommitEdit();
  else if (key == "u")
    editor.Widget->UndoCommit();
  else if (key == "s")
  {
    vtkNew<vtkXMLPolyDataWriter> writer;
    writer->SetInputConnection(editor.Filter->GetOutputPort());
    writer->SetFileName("edited.vtp");
    writer->Write();
    std::cout << "saved edited.vtp\n";
  }
  else
    return;
  Refresh(editor);
}

std::string Event(const char* name, double x, double y)
{
  char line[96];
  std::snprintf(line, sizeof(line), "%s %d %d 0 0 0 0 i\n", name, static_cast<int>(x), static_cast<int>(y));
  return line;
}

struct Options
{
  std::string Mesh;
  std::string Screenshot;
  int Mode = vtkLaplacianDeformationFilter::ROTATION_EXPLICIT;
  int Up = 1;
};

// The command line into `options`; an exit code when the program should stop (help, an error).
std::optional<int> ParseArguments(int argc, char* argv[], Options& options)
{
  const std::string usage = std::string("usage: ") + argv[0] +
    " [--mode none|explicit|implicit|arap] [--up x|y|z] [--offscreen SCREENSHOT.png] [MESH]";
  for (int i = 1; i < argc; ++i)
  {
    const std::string arg = argv[i];
    const std::string value = i + 1 < argc ? argv[i + 1] : "";
    if (arg == "--mode" && std::count(std::begin(ModeNames), std::end(ModeNames), value))
      options.Mode =
        static_cast<int>(std::find(std::begin(ModeNames), std::end(ModeNames), value) - ModeNames), ++i;
    else if (arg == "--up" && (value == "x" || value == "y" || value == "z"))
      options.Up = value[0] - 'x', ++i;
    else if (arg == "--offscreen" && !value.empty())
      options.Screenshot = value, ++i;
    else if (arg == "-h" || arg == "--help")
    {
      std::cout << usage << "\n" << Help << "\n";
      return EXIT_SUCCESS;
    }
    else if (arg[0] != '-' && options.Mesh.empty())
      options.Mesh = arg;
    else
    {
      std::cerr << "error: unexpected argument '" << arg << "'; " << usage << "\n";
      return EXIT_FAILURE;
    }
  }
  return std::nullopt;
}

// The mesh to edit, the filter set up on it, and the scene: the embedded bumpy plane without a
// path; nullptr, with the reason on stderr, for a file it cannot read.
vtkSmartPointer<vtkRenderer> SetUpScene(const Options& options, vtkLaplacianDeformationFilter* filter)
{
  vtkSmartPointer<vtkPolyData> mesh;
  if (options.Mesh.empty())
  {
    mesh = EditingScene::SetUpBumpyPlaneEdit(filter);
    filter->SetHandleTransform(nullptr);
  }
  else
  {
    std::string error;
    mesh = MeshReader::Read(options.Mesh, error);
    if (!mesh)
    {
      std::cerr << "error: " << error << "\n";
      return nullptr;
    }
    filter->SetInputData(mesh);
    filter->SetRadiusUnitsToDiagonalFraction();
    filter->SetHandleRadius(0.03);
    filter->SetROIRadius(0.15);
  }
  filter->SetRotationMode(options.Mode);
  const double full[4] = { 0.0, 0.0, 1.0, 1.0 };
  vtkSmartPointer<vtkRenderer> renderer = EditingScene::MakeRenderer(mesh, full);
  if (options.Mesh.empty())
  {
    renderer->GetActiveCamera()->SetPosition(0.0, -1.0, 1.0);
    renderer->ResetCamera();
  }
  else
  {
    // The first handle on the point that stands out most in the first view.
    const int view = EditingScene::FrameMesh(renderer, mesh, options.Up);
    filter->SetHandleCenter(mesh->GetPoint(EditingScene::ProtrudingPoint(mesh, view)));
  }
  filter->Update();
  auto* surface = vtkActor::SafeDownCast(renderer->GetActors()->GetItemAsObject(0));
  surface->GetMapper()->SetInputConnection(filter->GetOutputPort());
  return renderer;
}

// The help at the bottom, the status at the top.
void AddTexts(vtkRenderer* renderer, vtkTextActor* help, vtkTextActor* status)
{
  help->SetInput(Help);
  help->GetTextProperty()->SetFontSize(13);
  help->GetTextProperty()->SetColor(0.1, 0.1, 0.1);
  help->SetDisplayPosition(10, 10);
  status->GetTextProperty()->SetFontSize(15);
  status->GetTextProperty()->SetColor(0.1, 0.1, 0.1);
  status->GetTextProperty()->SetVerticalJustificationToTop();
  status->GetPositionCoordinate()->SetCoordinateSystemToNormalizedDisplay();
  status->SetPosition(0.01, 0.97);
  renderer->AddActor2D(help);
  renderer->AddActor2D(status);
}

// Offscreen: drags the handle up by a fifth of the window, as a user would; returns how far the
// handle moved.
double PlayDrag(vtkRenderer* renderer, vtkDeformationHandleWidget* widget)
{
  double center[3];
  widget->GetDeformationHandleRepresentation()->GetCurrentCenter(center);
  renderer->SetWorldPoint(center[0], center[1], center[2], 1.0);
  renderer->WorldToDisplay();
  const double x = renderer->GetDisplayPoint()[0], y = renderer->GetDisplayPoint()[1];
  std::string events = Event("MouseMoveEvent", x, y) + Event("LeftButtonPressEvent", x, y);
  for (int step = 1; step <= 10; ++step)
  {
    events += Event("MouseMoveEvent", x, y + 14.0 * step);
  }
  events += Event("LeftButtonReleaseEvent", x, y + 140.0);
  vtkNew<vtkInteractorEventRecorder> recorder;
  recorder->SetInteractor(widget->GetInteractor());
  recorder->ReadFromInputStringOn();
  recorder->SetInputString(events.c_str());
  recorder->Play(); // the release refreshes the status
  double moved[3];
  widget->GetDeformationHandleRepresentation()->GetCurrentCenter(moved);
  return std::sqrt(vtkMath::Distance2BetweenPoints(center, moved));
}
}

int main(int argc, char* argv[])
{
  Options options;
  if (const std::optional<int> exitCode = ParseArguments(argc, argv, options))
  {
    return *exitCode;
  }
  vtkNew<vtkLaplacianDeformationFilter> filter;
  const vtkSmartPointer<vtkRenderer> renderer = SetUpScene(options, filter);
  if (!renderer)
  {
    return EXIT_FAILURE;
  }
  vtkNew<vtkTextActor> help, status;
  AddTexts(renderer, help, status);
  vtkNew<vtkRenderWindow> window;
  std::string error;
  if (!XDisplay::Attach(window, error)) // before the interactor can use a display it never checks
  {
    std::cerr << error << "\n";
    return EXIT_FAILURE;
  }
  window->SetSize(900, 700);
  window->SetWindowName("Laplacian mesh editing");
  window->AddRenderer(renderer);
  window->SetOffScreenRendering(!options.Screenshot.empty());
  vtkNew<vtkRenderWindowInteractor> interactor;
  interactor->SetRenderWindow(window);
  vtkNew<vtkInteractorStyleTrackballCamera> style;
  interactor->SetInteractorStyle(style);

  vtkNew<vtkDeformationHandleWidget> widget;
  widget->SetInteractor(interactor);
  widget->SetDeformationFilter(filter);
  widget->SetSurfaceProp(vtkActor::SafeDownCast(renderer->GetActors()->GetItemAsObject(0)));
  widget->On();

  Editor editor{ filter, widget, status };
  ShowStatus(editor);
  vtkNew<vtkCallbackCommand> keys;
  keys->SetCallback(OnKey);
  keys->SetClientData(&editor);
  interactor->AddObserver(vtkCommand::KeyPressEvent, keys);
  vtkNew<vtkCallbackCommand> interactionEnd;
  interactionEnd->SetCallback(OnInteractionEnd);
  interactionEnd->SetClientData(&editor);
  widget->AddObserver(vtkCommand::EndInteractionEvent, interactionEnd);
  interactor->Initialize();
  window->Render();
  if (options.Screenshot.empty())
  {
    interactor->Start();
    return EXIT_SUCCESS;
  }
  const double distance = PlayDrag(renderer, widget);
  EditingScene::SaveScreenshot(window, options.Screenshot);
  std::cout << "handle moved by " << distance << "; wrote " << options.Screenshot << "\n";
  return distance > 0.0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
