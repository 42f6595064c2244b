// Frames per second of a handle drag: each frame moves the handle, updates the filter and
// renders its output (run under Xvfb). Prints one JSON line.
//
//   DragFrameRate MESH ROI_FRACTION [FRAMES] [MODE] [widget]
//
// The handle sits on vertex 0 with a radius of 3% of the bounding-box diagonal; the ROI radius
// is ROI_FRACTION of the diagonal; FRAMES defaults to 60; MODE is the rotation mode number (0
// none, default). Without "widget" each frame sets the handle transform directly, lifting the
// handle by 10% of the diagonal over the drag (this path uses only the filter's basic API, so
// the same program measures older versions too). With "widget" a vtkDeformationHandleWidget is
// dragged by recorded mouse events, 2 pixels up per frame, as a user would, and released.
//
// It also prints the drag's slowest frame and the release's (the widget's; frames per second
// leave it out), each update's as-rigid-as-possible iterations (mode 3),
// and that mode's energy at the last frame of the drag and after the release, over the energy
// converged at the same pose.
#include "MeshReader.h"

#include "vtkLaplacianDeformationFilter.h"

#include "vtkDeformationHandleRepresentation.h"
#include "vtkDeformationHandleWidget.h"

#include "vtkActor.h"
#include "vtkCallbackCommand.h"
#include "vtkCommand.h"
#include "vtkInteractorEventRecorder.h"
#include "vtkMath.h"
#include "vtkRenderWindowInteractor.h"
#include "vtkPolyDataMapper.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkTransform.h"

#include <chrono>
#include <cstdlib>
#include <iostream>
#include <string>
#include <vector>

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
  const double diagonal = mesh->GetLength();
  vtkNew<vtkLaplacianDeformationFilter> filter;
  filter->SetInputData(mesh);
  filter->SetHandleCenter(mesh->GetPoint(0));
  filter->SetHandleRadius(0.03 * diagonal);
  filter->SetROIRadius(std::atof(argv[2]) * diagonal);
  filter->SetRotationMode(argc > 4 ? std::atoi(argv[4]) : 0);
  vtkNew<vtkTransform> drag;
  filter->SetHandleTransform(drag);

  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputConnection(filter->GetOutputPort());
  mapper->ScalarVisibilityOff();
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  vtkNew<vtkRenderer> renderer;
  renderer->AddActor(actor);
  vtkNew<vtkRenderWindow> window;
  window->SetSize(800, 600);
  window->OffScreenRenderingOn();
  window->AddRenderer(renderer);
  window->Render(); // select and factor
  renderer->ResetCamera();

  const bool useWidget = argc > 5 && std::string(argv[5]) == "widget";
  vtkNew<vtkRenderWindowInteractor> interactor;
  vtkNew<vtkDeformationHandleWidget> widget;
  vtkNew<vtkInteractorEventRecorder> recorder;
  std::string events;
  if (useWidget)
  {
    interactor->SetRenderWindow(window);
    widget->SetInteractor(interactor);
    widget->SetDeformationFilter(filter);
    widget->On();
    renderer->ResetCameraClippingRange();
    window->Render();
    double center[3];
    widget->GetDeformationHandleRepresentation()->GetCurrentCenter(center);
    renderer->SetWorldPoint(center[0], center[1], center[2], 1.0);
    renderer->WorldToDisplay();
    const int x = static_cast<int>(renderer->GetDisplayPoint()[0]);
    const int y = static_cast<int>(renderer->GetDisplayPoint()[1]);
    auto line = [](const char* name, int px, int py) {
      return std::string(name) + " " + std::to_string(px) + " " + std::to_string(py) + " 0 0 0 0 i\n";
    };
    events = line("MouseMoveEvent", x, y) + line("LeftButtonPressEvent", x, y);
    for (int frame = 1; frame <= frames; ++frame)
    {
      events += line("MouseMoveEvent", x, y + 2 * frame);
    }
    events += line("LeftButtonReleaseEvent", x, y + 2 * frames);
    recorder->SetInteractor(interactor);
    recorder->ReadFromInputStringOn();
    recorder->SetInputString(events.c_str());
  }

  // Each update's time and iterations, and the energy of the updates during the drag and last.
  struct Trace
  {
    vtkLaplacianDeformationFilter* Filter;
    std::chrono::steady_clock::time_point Last;
    double Slowest = 0.0;
    std::vector<int> Iterations;
    std::vector<double> Energies;
    std::size_t DragUpdates = 0; // the updates before the release
    bool Released = false;
    double ReleaseSeconds = 0.0; // the frame the release renders
  } trace{ filter, std::chrono::steady_clock::now() };
  vtkNew<vtkCallbackCommand> renderEnd;
  renderEnd->SetClientData(&trace);
  renderEnd->SetCallback([](vtkObject*, unsigned long, void* data, void*) {
    auto& t = *static_cast<Trace*>(data);
    const auto now = std::chrono::steady_clock::now();
    const double frame = std::chrono::duration<double>(now - t.Last).count();
    if (t.Released)
    {
      t.ReleaseSeconds = frame;
    }
    else
    {
      t.Slowest = std::max(t.Slowest, frame);
    }
    t.Last = now;
  });
  vtkNew<vtkCallbackCommand> filterEnd;
  filterEnd->SetClientData(&trace);
  filterEnd->SetCallback([](vtkObject*, unsigned long, void* data, void*) {
    auto& t = *static_cast<Trace*>(data);
    t.Iterations.push_back(t.Filter->GetNumberOfARAPIterations());
    t.Energies.push_back(t.Filter->GetARAPEnergy());
  });
  vtkNew<vtkCallbackCommand> release;
  release->SetClientData(&trace);
  release->SetCallback([](vtkObject*, unsigned long, void* data, void*) {
    auto& t = *static_cast<Trace*>(data);
    t.DragUpdates = t.Energies.size();
    t.Released = true;
    t.Last = std::chrono::steady_clock::now();
  });
  widget->AddObserver(vtkCommand::EndInteractionEvent, release);
  window->AddObserver(vtkCommand::EndEvent, renderEnd);
  filter->AddObserver(vtkCommand::EndEvent, filterEnd);

  const auto start = std::chrono::steady_clock::now();
  trace.Last = start;
  if (useWidget)
  {
    recorder->Play(); // each move renders through the widget
  }
  else
  {
    for (int frame = 1; frame <= frames; ++frame)
    {
      drag->Identity();
      drag->Translate(0.0, 0.0, 0.1 * diagonal * frame / frames);
      window->Render();
    }
  }
  // The drag's frames, without the release's.
  const double seconds =
    std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() -
    trace.ReleaseSeconds;
  window->RemoveObserver(renderEnd);
  filter->RemoveObserver(filterEnd);
  // How far the drag took the handle, to show the frames really moved it.
  double origin[3] = { 0.0, 0.0, 0.0 }, moved[3];
  filter->GetHandleTransform()->TransformPoint(origin, moved);
  std::cout << "{\"mesh\": \"" << argv[1] << "\", \"roi_vertices\": "
            << filter->GetNumberOfROIVertices() << ", \"mode\": " << filter->GetRotationMode()
            << ", \"driver\": \"" << (useWidget ? "widget" : "transform") << "\", \"frames\": "
            << frames << ", \"frames_per_second\": " << frames / seconds
            << ", \"handle_moved\": " << vtkMath::Norm(moved)
            << ", \"factorizations\": " << filter->GetNumberOfFactorizations()
            << ", \"slowest_frame_seconds\": " << trace.Slowest
            << ", \"release_seconds\": " << trace.ReleaseSeconds;
  if (filter->GetRotationMode() == vtkLaplacianDeformationFilter::ROTATION_AS_RIGID_AS_POSSIBLE &&
    !trace.Energies.empty())
  {
    std::cout << ", \"arap_iterations\": [";
    for (std::size_t k = 0; k < trace.Iterations.size(); ++k)
    {
      std::cout << (k ? ", " : "") << trace.Iterations[k];
    }
    const std::size_t dragUpdates = useWidget ? trace.DragUpdates : trace.Energies.size();
    const double dragged = trace.Energies[std::max<std::size_t>(dragUpdates, 1) - 1];
    const double released = trace.Energies.back();
    filter->SetARAPIterations(10000);
    filter->SetConvergence(1e-9);
    filter->Update();
    const double converged = filter->GetARAPEnergy();
    std::cout << "], \"arap_energy_over_converged\": {\"drag_end\": " << dragged / converged
              << ", \"after_release\": " << released / converged << "}";
  }
  std::cout << "}\n";
  return EXIT_SUCCESS;
}
