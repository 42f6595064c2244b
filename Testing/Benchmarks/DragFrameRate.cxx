// Frames per second of a handle drag: each frame moves the handle, updates the filter and
// renders its output (run under Xvfb). Prints one JSON line.
//
//   DragFrameRate MESH ROI_FRACTION [FRAMES] [MODE] [widget]
//
// MESH is a file (MeshReader.h) or sphere:THETAxPHI (sphere:2000x1002 has 2M points). The
// handle sits on vertex 0 (on a sphere, the vertex nearest (0.5, 0, 0)) with a radius of 3% of
// the bounding-box diagonal, or a third of the ROI radius if that is less; the ROI radius is
// ROI_FRACTION of the diagonal; FRAMES defaults to 60; MODE is the rotation mode number (0
// none, default). Without "widget" each frame sets the handle transform directly, lifting the
// handle by 10% of the diagonal over the drag (this path uses only the filter's basic API, so
// the same program measures older versions too). With "widget" a vtkDeformationHandleWidget is
// dragged by recorded mouse events, 2 pixels up per frame, as a user would, and released.
//
// Before the drag, ten still renders of the same scene are timed: a frame's milliseconds over
// their median is what the drag adds to drawing the surface. It also prints the drag's
// slowest frame and the release's (the widget's; frames per second leave it out), each
// update's as-rigid-as-possible iterations (mode 3), and that mode's energy at the last frame
// of the drag and after the release, over the energy converged at the same pose.
#include "BenchmarkMeasures.h"
#include "MeshReader.h"
#include "XDisplay.h"

#include "vtkLaplacianDeformationFilter.h"

#include "vtkDeformationHandleRepresentation.h"
#include "vtkDeformationHandleWidget.h"

#include "vtkActor.h"
#include "vtkCallbackCommand.h"
#include "vtkCommand.h"
#include "vtkInteractorEventRecorder.h"
#include "vtkMath.h"
#include "vtkPolyDataMapper.h"
#include "vtkRenderWindow.h"
#include "vtkRenderWindowInteractor.h"
#include "vtkRenderer.h"
#include "vtkTransform.h"

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <iostream>
#include <string>
#include <vector>

namespace
{
using Clock = BenchmarkMeasures::Clock;
using BenchmarkMeasures::SecondsSince;

// The handle's vertex: 0, or on a generated sphere the one on its equator at +x.
vtkIdType HandleVertex(vtkPolyData* mesh, const std::string& name)
{
  if (name.rfind("sphere:", 0) != 0)
  {
    return 0;
  }
  const double target[3] = { 0.5, 0.0, 0.0 };
  vtkIdType nearest = 0;
  double best = VTK_DOUBLE_MAX;
  for (vtkIdType i = 0; i < mesh->GetNumberOfPoints(); ++i)
  {
    const double distance = vtkMath::Distance2BetweenPoints(mesh->GetPoint(i), target);
    nearest = distance < best ? i : nearest;
    best = std::min(best, distance);
  }
  return nearest;
}

// The scene: the filter's output in an 800 x 600 offscreen window.
struct Scene
{
  vtkNew<vtkLaplacianDeformationFilter> Filter;
  vtkNew<vtkTransform> Drag;
  vtkNew<vtkPolyDataMapper> Mapper;
  vtkNew<vtkActor> Actor;
  vtkNew<vtkRenderer> Renderer;
  vtkNew<vtkRenderWindow> Window;

  Scene(vtkPolyData* mesh, vtkIdType handle, double roiFraction, int mode)
  {
    XDisplay::AttachOrExit(this->Window);
    const double diagonal = mesh->GetLength();
    this->Filter->SetInputData(mesh);
    this->Filter->SetHandleCenter(mesh->GetPoint(handle));
    this->Filter->SetHandleRadius(std::min(0.03, roiFraction / 3.0) * diagonal);
    this->Filter->SetROIRadius(roiFraction * diagonal);
    this->Filter->SetRotationMode(mode);
    this->Filter->SetHandleTransform(this->Drag);
    this->Mapper->SetInputConnection(this->Filter->GetOutputPort());
    this->Mapper->ScalarVisibilityOff();
    this->Actor->SetMapper(this->Mapper);
    this->Renderer->AddActor(this->Actor);
    this->Window->SetSize(800, 600);
    this->Window->OffScreenRenderingOn();
    this->Window->AddRenderer(this->Renderer);
    this->Window->Render(); // select and factor
    this->Renderer->ResetCamera();
  }

  // The median of ten renders of the unchanged scene.
  double StillRenderSeconds()
  {
    std::vector<double> seconds;
    for (int k = 0; k < 10; ++k)
    {
      const Clock::time_point start = Clock::now();
      this->Window->Render();
      seconds.push_back(SecondsSince(start));
    }
    std::sort(seconds.begin(), seconds.end());
    return seconds[seconds.size() / 2];
  }
};

// The widget on the handle, and the recorded events of a drag 2 pixels up a frame.
std::string WidgetDrag(Scene& scene, vtkRenderWindowInteractor* interactor,
  vtkDeformationHandleWidget* widget, int frames)
{
  interactor->SetRenderWindow(scene.Window);
  widget->SetInteractor(interactor);
  widget->SetDeformationFilter(scene.Filter);
  widget->On();
  scene.Renderer->ResetCameraClippingRange();
  scene.Window->Render();
  double center[3];
  widget->GetDeformationHandleRepresentation()->GetCurrentCenter(center);
  scene.Renderer->SetWorldPoint(center[0], center[1], center[2], 1.0);
  scene.Renderer->WorldToDisplay();
  const int x = static_cast<int>(scene.Renderer->GetDisplayPoint()[0]);
  const int y = static_cast<int>(scene.Renderer->GetDisplayPoint()[1]);
  auto line = [](const char* name, int px, int py) {
    return std::string(name) + " " + std::to_string(px) + " " + std::to_string(py) + " 0 0 0 0 i\n";
  };
  std::string events = line("MouseMoveEvent", x, y) + line("LeftButtonPressEvent", x, y);
  for (int frame = 1; frame <= frames; ++frame)
  {
    events += line("MouseMoveEvent", x, y + 2 * frame);
  }
  return events + line("LeftButtonReleaseEvent", x, y + 2 * frames);
}

// Each update's time and iterations, and the energy of the updates during the drag and last.
struct Trace
{
  vtkLaplacianDeformationFilter* Filter;
  Clock::time_point Last;
  double Slowest = 0.0;
  double FirstFrame = -1.0; // the drag's first frame, after the press
  std::vector<int> Iterations;
  std::vector<double> Energies;
  std::size_t DragUpdates = 0; // the updates before the release
  bool Released = false;
  double ReleaseSeconds = 0.0; // the frame the release renders
  vtkNew<vtkCallbackCommand> RenderEnd, FilterEnd, Release;

  explicit Trace(vtkLaplacianDeformationFilter* filter)
    : Filter(filter)
  {
    this->RenderEnd->SetClientData(this);
    this->RenderEnd->SetCallback([](vtkObject*, unsigned long, void* data, void*) {
      auto& t = *static_cast<Trace*>(data);
      const double frame = SecondsSince(t.Last);
      if (t.Released)
      {
        t.ReleaseSeconds = frame;
      }
      else
      {
        t.Slowest = std::max(t.Slowest, frame);
        t.FirstFrame = t.FirstFrame < 0.0 ? frame : t.FirstFrame;
      }
      t.Last = Clock::now();
    });
    this->FilterEnd->SetClientData(this);
    this->FilterEnd->SetCallback([](vtkObject*, unsigned long, void* data, void*) {
      auto& t = *static_cast<Trace*>(data);
      t.Iterations.push_back(t.Filter->GetNumberOfARAPIterations());
      t.Energies.push_back(t.Filter->GetARAPEnergy());
    });
    this->Release->SetClientData(this);
    this->Release->SetCallback([](vtkObject*, unsigned long, void* data, void*) {
      auto& t = *static_cast<Trace*>(data);
      t.DragUpdates = t.Energies.size();
      t.Released = true;
      t.Last = Clock::now();
    });
  }
};

// The ARAP mode's iterations each update, and its energies over converged.
void ReportARAP(vtkLaplacianDeformationFilter* filter, const Trace& trace, bool widget)
{
  std::cout << ", \"arap_iterations\": [";
  for (std::size_t k = 0; k < trace.Iterations.size(); ++k)
  {
    std::cout << (k ? ", " : "") << trace.Iterations[k];
  }
  const std::size_t dragUpdates = widget ? trace.DragUpdates : trace.Energies.size();
  const double dragged = trace.Energies[std::max<std::size_t>(dragUpdates, 1) - 1];
  const double released = trace.Energies.back();
  filter->SetARAPIterations(10000);
  filter->SetConvergence(1e-9);
  filter->Update();
  const double converged = filter->GetARAPEnergy();
  std::cout << "], \"arap_energy_over_converged\": {\"drag_end\": " << dragged / converged
            << ", \"after_release\": " << released / converged << "}";
}
}

int main(int argc, char* argv[])
{
  if (argc < 3)
  {
    std::cerr << "usage: " << argv[0] << " MESH ROI_FRACTION [FRAMES] [MODE] [widget]\n";
    return EXIT_FAILURE;
  }
  std::string error;
  vtkSmartPointer<vtkPolyData> mesh = MeshReader::Read(argv[1], error);
  if (!mesh)
  {
    std::cerr << "error: " << error << "\n";
    return EXIT_FAILURE;
  }
  const int frames = argc > 3 ? std::max(1, std::atoi(argv[3])) : 60;
  const bool useWidget = argc > 5 && std::string(argv[5]) == "widget";
  Scene scene(mesh, HandleVertex(mesh, argv[1]), std::atof(argv[2]), argc > 4 ? std::atoi(argv[4]) : 0);
  vtkLaplacianDeformationFilter* filter = scene.Filter;
  vtkNew<vtkRenderWindowInteractor> interactor;
  vtkNew<vtkDeformationHandleWidget> widget;
  vtkNew<vtkInteractorEventRecorder> recorder;
  const std::string events = useWidget ? WidgetDrag(scene, interactor, widget, frames) : "";
  recorder->SetInteractor(interactor);
  recorder->ReadFromInputStringOn();
  recorder->SetInputString(events.c_str());
  const double still = scene.StillRenderSeconds();

  Trace trace(filter);
  widget->AddObserver(vtkCommand::EndInteractionEvent, trace.Release);
  scene.Window->AddObserver(vtkCommand::EndEvent, trace.RenderEnd);
  filter->AddObserver(vtkCommand::EndEvent, trace.FilterEnd);
  const Clock::time_point start = Clock::now();
  trace.Last = start;
  if (useWidget)
  {
    recorder->Play(); // each move renders through the widget
  }
  for (int frame = 1; !useWidget && frame <= frames; ++frame)
  {
    scene.Drag->Identity();
    scene.Drag->Translate(0.0, 0.0, 0.1 * mesh->GetLength() * frame / frames);
    scene.Window->Render();
  }
  const double seconds = SecondsSince(start) - trace.ReleaseSeconds; // the drag's frames alone
  scene.Window->RemoveObserver(trace.RenderEnd);
  filter->RemoveObserver(trace.FilterEnd);
  // How far the drag took the handle, to show the frames really moved it.
  double origin[3] = { 0.0, 0.0, 0.0 }, moved[3];
  filter->GetHandleTransform()->TransformPoint(origin, moved);
  std::cout << "{\"mesh\": \"" << argv[1] << "\", \"points\": " << mesh->GetNumberOfPoints()
            << ", \"roi_vertices\": " << filter->GetNumberOfROIVertices()
            << ", \"mode\": " << filter->GetRotationMode() << ", \"driver\": \""
            << (useWidget ? "widget" : "transform") << "\", \"frames\": " << frames
            << ", \"frames_per_second\": " << frames / seconds
            << ", \"frame_ms\": " << 1000.0 * seconds / frames
            << ", \"still_ms\": " << 1000.0 * still
            << ", \"frame_over_still\": " << seconds / frames / still
            << ", \"handle_moved\": " << vtkMath::Norm(moved)
            << ", \"factorizations\": " << filter->GetNumberOfFactorizations()
            << ", \"output_copies\": " << filter->GetNumberOfOutputCopies()
            << ", \"slowest_frame_seconds\": " << trace.Slowest
            << ", \"first_frame_over_still\": " << trace.FirstFrame / still
            << ", \"release_seconds\": " << trace.ReleaseSeconds
            << ", \"release_over_still\": " << trace.ReleaseSeconds / still;
  if (filter->GetRotationMode() == vtkLaplacianDeformationFilter::ROTATION_AS_RIGID_AS_POSSIBLE &&
    !trace.Energies.empty())
  {
    ReportARAP(filter, trace, useWidget);
  }
  std::cout << "}\n";
  return EXIT_SUCCESS;
}
