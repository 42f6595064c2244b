// Renders a mesh before and after an edit side by side, the edited copy coloured by the
// filter's EditRole array like the paper's Fig. 2 (fixed grey, anchors red, free green,
// handle yellow). Shared by the demo and the image regression tests.
#ifndef EditingScene_h
#define EditingScene_h

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkLookupTable.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSmartPointer.h"
#include "vtkTransform.h"

#include "vtkBumpyPlaneSource.h"
#include "vtkLaplacianDeformationFilter.h"

namespace EditingScene
{
inline vtkSmartPointer<vtkLookupTable> RoleColors()
{
  auto table = vtkSmartPointer<vtkLookupTable>::New();
  table->SetNumberOfTableValues(4);
  table->SetTableValue(0, 0.75, 0.75, 0.75); // fixed
  table->SetTableValue(1, 0.85, 0.20, 0.15); // anchor
  table->SetTableValue(2, 0.35, 0.75, 0.35); // free
  table->SetTableValue(3, 0.95, 0.85, 0.10); // handle
  table->SetTableRange(0, 3);
  table->Build();
  return table;
}

/// The embedded default edit: lift one side of a bumpy plane (the paper's Fig. 6, top).
/// Returns the unedited plane.
inline vtkSmartPointer<vtkPolyData> SetUpBumpyPlaneEdit(vtkLaplacianDeformationFilter* filter)
{
  vtkNew<vtkBumpyPlaneSource> source;
  source->Update();
  filter->SetInputData(source->GetOutput());
  filter->SetHandleCenter(0.8, 0.5, 0.0);
  filter->SetHandleRadius(0.08);
  filter->SetROIRadius(0.6);
  vtkNew<vtkTransform> lift;
  lift->Translate(0.0, 0.0, 0.3);
  filter->SetHandleTransform(lift);
  return source->GetOutput();
}

/// A renderer showing `mesh`, coloured by EditRole when it has one.
inline vtkSmartPointer<vtkRenderer> MakeRenderer(vtkPolyData* mesh, const double viewport[4])
{
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputData(mesh);
  if (mesh->GetPointData()->GetArray("EditRole"))
  {
    mapper->SetLookupTable(RoleColors());
    mapper->SetColorModeToMapScalars(); // EditRole is unsigned char: map it, do not show it raw
    mapper->SetScalarModeToUsePointFieldData();
    mapper->SelectColorArray("EditRole");
    mapper->SetScalarRange(0, 3);
    mapper->ScalarVisibilityOn();
  }
  else
  {
    mapper->ScalarVisibilityOff();
  }
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  actor->GetProperty()->SetInterpolationToFlat();
  auto renderer = vtkSmartPointer<vtkRenderer>::New();
  renderer->AddActor(actor);
  renderer->SetViewport(viewport[0], viewport[1], viewport[2], viewport[3]);
  renderer->SetBackground(1.0, 1.0, 1.0);
  return renderer;
}

/// An offscreen window: `before` on the left, `after` on the right, seen from one camera
/// looking along `viewDirection` with `viewUp`.
inline vtkSmartPointer<vtkRenderWindow> MakeBeforeAfterWindow(vtkPolyData* before,
  vtkPolyData* after, const double viewDirection[3], const double viewUp[3], int width = 800,
  int height = 400)
{
  const double left[4] = { 0.0, 0.0, 0.5, 1.0 };
  const double right[4] = { 0.5, 0.0, 1.0, 1.0 };
  auto window = vtkSmartPointer<vtkRenderWindow>::New();
  window->SetSize(width, height);
  window->SetMultiSamples(0);
  window->OffScreenRenderingOn();
  auto first = MakeRenderer(before, left);
  auto second = MakeRenderer(after, right);
  window->AddRenderer(first);
  window->AddRenderer(second);

  // Frame both meshes with one camera.
  double bounds[6], other[6];
  before->GetBounds(bounds);
  after->GetBounds(other);
  for (int i = 0; i < 3; ++i)
  {
    bounds[2 * i] = std::min(bounds[2 * i], other[2 * i]);
    bounds[2 * i + 1] = std::max(bounds[2 * i + 1], other[2 * i + 1]);
  }
  vtkCamera* camera = first->GetActiveCamera();
  camera->SetFocalPoint(0, 0, 0);
  camera->SetPosition(-viewDirection[0], -viewDirection[1], -viewDirection[2]);
  camera->SetViewUp(viewUp[0], viewUp[1], viewUp[2]);
  first->ResetCamera(bounds);
  camera->Zoom(1.2);
  second->SetActiveCamera(camera);
  return window;
}
}

#endif
