// Frames per second of a simulated handle drag: each frame sets a new handle transform, updates
// the filter and renders its output in an offscreen window (run under Xvfb). Prints one JSON
// line. Uses only the filter's basic API, so the same program measures older versions too.
//
//   DragFrameRate MESH ROI_FRACTION [FRAMES] [MODE]
//
// The handle sits on vertex 0 with a radius of 3% of the bounding-box diagonal; the ROI radius
// is ROI_FRACTION of the diagonal; the drag lifts the handle by 10% of the diagonal along +z
// over FRAMES frames (default 60). MODE is the rotation mode number (0 none, default).
#include "MeshReader.h"

#include "vtkLaplacianDeformationFilter.h"

#include "vtkActor.h"
#include "vtkPolyDataMapper.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkTransform.h"

#include <chrono>
#include <cstdlib>
#include <iostream>
#include <string>

int main(int argc, char* argv[])
{
  if (argc < 3)
  {
    std::cerr << "usage: " << argv[0] << " MESH ROI_FRACTION [FRAMES] [MODE]\n";
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

  const auto start = std::chrono::steady_clock::now();
  for (int frame = 1; frame <= frames; ++frame)
  {
    drag->Identity();
    drag->Translate(0.0, 0.0, 0.1 * diagonal * frame / frames);
    window->Render();
  }
  const double seconds =
    std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::cout << "{\"mesh\": \"" << argv[1] << "\", \"roi_vertices\": "
            << filter->GetNumberOfROIVertices() << ", \"mode\": " << filter->GetRotationMode()
            << ", \"frames\": " << frames << ", \"frames_per_second\": " << frames / seconds
            << ", \"factorizations\": " << filter->GetNumberOfFactorizations() << "}\n";
  return EXIT_SUCCESS;
}
