// Renders a mesh before and after an edit side by side, the edited copy coloured by the
// filter's EditRole array like the paper's Fig. 2 (fixed grey, anchors red, free green,
// handle yellow). Shared by the demo and the image regression tests.
#ifndef EditingScene_h
#define EditingScene_h

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkNew.h"
#include "vtkPNGWriter.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSmartPointer.h"
#include "vtkTransform.h"
#include "vtkWindowToImageFilter.h"

#include <algorithm>
#include <string>
#include <vector>

#include "BumpyPlane.h"
#include "XDisplay.h"
#include "vtkLaplacianDeformationFilter.h"

namespace EditingScene
{
/// The embedded default edit: lift one side of a bumpy plane (the paper's Fig. 6, top), with
/// explicit detail rotations. Returns the unedited plane.
inline vtkSmartPointer<vtkPolyData> SetUpBumpyPlaneEdit(vtkLaplacianDeformationFilter* filter)
{
  vtkSmartPointer<vtkPolyData> plane = MakeBumpyPlane();
  filter->SetInputData(plane);
  filter->SetHandleCenter(0.8, 0.5, 0.0);
  filter->SetHandleRadius(0.08);
  filter->SetROIRadius(0.6);
  filter->SetRotationModeToExplicit();
  vtkNew<vtkTransform> lift;
  lift->Translate(0.0, 0.0, 0.3);
  filter->SetHandleTransform(lift);
  return plane;
}

/// A renderer showing `mesh` through a vtkPolyDataMapper with its default settings: the
/// filter's output shows its EditRole array, which is the active scalars and carries its colours.
inline vtkSmartPointer<vtkRenderer> MakeRenderer(vtkPolyData* mesh, const double viewport[4])
{
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputData(mesh);
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  actor->GetProperty()->SetInterpolationToFlat();
  auto renderer = vtkSmartPointer<vtkRenderer>::New();
  renderer->AddActor(actor);
  renderer->SetViewport(viewport[0], viewport[1], viewport[2], viewport[3]);
  renderer->SetBackground(1.0, 1.0, 1.0);
  return renderer;
}

/// Frames `mesh` as a user expects a first view: axis `up` (0 x, 1 y, 2 z) up on the screen,
/// looking along the horizontal axis of smaller extent from its + side, so that the longer
/// horizontal extent lies across the screen. Returns that view axis.
inline int FrameMesh(vtkRenderer* renderer, vtkPolyData* mesh, int up)
{
  double bounds[6];
  mesh->GetBounds(bounds);
  const int a = (up + 1) % 3, b = (up + 2) % 3;
  const int view = bounds[2 * a + 1] - bounds[2 * a] < bounds[2 * b + 1] - bounds[2 * b] ? a : b;
  vtkCamera* camera = renderer->GetActiveCamera();
  double position[3] = { 0.0, 0.0, 0.0 }, viewUp[3] = { 0.0, 0.0, 0.0 };
  position[view] = 1.0;
  viewUp[up] = 1.0;
  camera->SetFocalPoint(0.0, 0.0, 0.0);
  camera->SetPosition(position);
  camera->SetViewUp(viewUp);
  renderer->ResetCamera(bounds);
  return view;
}

/// A point that stands out in that first view: on the camera's side of the centre along axis
/// `view`, the farthest from the centre across the screen (an ear tip, a fingertip).
inline vtkIdType ProtrudingPoint(vtkPolyData* mesh, int view)
{
  double center[3];
  mesh->GetCenter(center);
  vtkIdType best = 0;
  double bestDistance = -1.0;
  for (vtkIdType i = 0; i < mesh->GetNumberOfPoints(); ++i)
  {
    const double* p = mesh->GetPoint(i);
    double across = 0.0;
    for (int k = 0; k < 3; ++k)
    {
      across += k == view ? 0.0 : (p[k] - center[k]) * (p[k] - center[k]);
    }
    if (p[view] >= center[view] && across > bestDistance)
    {
      best = i;
      bestDistance = across;
    }
  }
  return best;
}

/// Writes what `window` shows to a PNG file.
inline void SaveScreenshot(vtkRenderWindow* window, const std::string& path)
{
  vtkNew<vtkWindowToImageFilter> grab;
  grab->SetInput(window);
  vtkNew<vtkPNGWriter> png;
  png->SetInputConnection(grab->GetOutputPort());
  png->SetFileName(path.c_str());
  png->Write();
}

/// Bounds of the points of `meshes` that the edit moved or held (EditRole other than fixed).
inline void GetRegionBounds(const std::vector<vtkPolyData*>& meshes, double bounds[6])
{
  for (int i = 0; i < 3; ++i)
  {
    bounds[2 * i] = VTK_DOUBLE_MAX;
    bounds[2 * i + 1] = VTK_DOUBLE_MIN;
  }
  for (vtkPolyData* mesh : meshes)
  {
    vtkDataArray* roles = mesh->GetPointData()->GetArray("EditRole");
    for (vtkIdType p = 0; roles && p < mesh->GetNumberOfPoints(); ++p)
    {
      if (roles->GetTuple1(p) != 0)
      {
        const double* x = mesh->GetPoint(p);
        for (int i = 0; i < 3; ++i)
        {
          bounds[2 * i] = std::min(bounds[2 * i], x[i]);
          bounds[2 * i + 1] = std::max(bounds[2 * i + 1], x[i]);
        }
      }
    }
  }
}

/// An offscreen window showing `meshes` side by side, all seen from one camera looking along
/// `viewDirection` with `viewUp`, framing `frameBounds` (by default, all the meshes).
inline vtkSmartPointer<vtkRenderWindow> MakeComparisonWindow(
  const std::vector<vtkPolyData*>& meshes, const double viewDirection[3], const double viewUp[3],
  int panelWidth = 400, int height = 400, const double* frameBounds = nullptr)
{
  auto window = vtkSmartPointer<vtkRenderWindow>::New();
  XDisplay::AttachOrExit(window);
  const int panels = static_cast<int>(meshes.size());
  window->SetSize(panelWidth * panels, height);
  window->SetMultiSamples(0);
  window->OffScreenRenderingOn();

  // One camera for all panels.
  double bounds[6] = { VTK_DOUBLE_MAX, VTK_DOUBLE_MIN, VTK_DOUBLE_MAX, VTK_DOUBLE_MIN,
    VTK_DOUBLE_MAX, VTK_DOUBLE_MIN };
  for (vtkPolyData* mesh : meshes)
  {
    double b[6];
    mesh->GetBounds(b);
    for (int i = 0; i < 6; ++i)
    {
      bounds[i] = frameBounds ? frameBounds[i]
                              : (i % 2 ? std::max(bounds[i], b[i]) : std::min(bounds[i], b[i]));
    }
  }
  vtkCamera* camera = nullptr;
  for (int i = 0; i < panels; ++i)
  {
    const double viewport[4] = { static_cast<double>(i) / panels, 0.0,
      static_cast<double>(i + 1) / panels, 1.0 };
    auto renderer = MakeRenderer(meshes[i], viewport);
    window->AddRenderer(renderer);
    if (!camera)
    {
      camera = renderer->GetActiveCamera();
      camera->SetFocalPoint(0, 0, 0);
      camera->SetPosition(-viewDirection[0], -viewDirection[1], -viewDirection[2]);
      camera->SetViewUp(viewUp[0], viewUp[1], viewUp[2]);
      renderer->ResetCamera(bounds);
      camera->Zoom(1.2);
    }
    else
    {
      renderer->SetActiveCamera(camera);
    }
  }
  return window;
}
}

#endif
