#include "vtkLaplacianDragPreview.h"

#include "EditPipeline.h"
#include "PreviewParts.h"
#include "Stopwatch.h"
#include "vtkLaplacianDeformationFilter.h"

#include "vtkObjectFactory.h"
#include "vtkPolyData.h"

namespace lep = LaplacianEditing::Pipeline;

vtkStandardNewMacro(vtkLaplacianDragPreview);

struct vtkLaplacianDragPreview::vtkInternals
{
  lep::PreviewParts Parts;
  double UpdateTime = 0.0;
};

vtkLaplacianDragPreview::vtkLaplacianDragPreview()
  : Internals(new vtkInternals)
{
}

vtkLaplacianDragPreview::~vtkLaplacianDragPreview()
{
  this->SetFilter(nullptr);
}

void vtkLaplacianDragPreview::SetFilter(vtkLaplacianDeformationFilter* filter)
{
  if (this->Filter == filter)
  {
    return;
  }
  this->Release();
  vtkSetObjectBodyMacro(Filter, vtkLaplacianDeformationFilter, filter);
}

bool vtkLaplacianDragPreview::Update(const double translation[3], const double rotation[3])
{
  const LaplacianEditing::Stopwatch stopwatch;
  vtkLaplacianDeformationFilter* filter = this->Filter;
  lep::OutputEdit solved;
  if (!filter || !filter->SolveDragStep(translation, rotation) || !filter->GetSolvedEdit(solved))
  {
    return false;
  }
  lep::PreviewParts& parts = this->Internals->Parts;
  if (!parts.IsBuiltFor(solved.RegionVersion))
  {
    parts.Build(filter->GetRestSurface(), filter->GetOutput(), solved);
  }
  parts.Write(solved);
  this->Internals->UpdateTime = stopwatch.Seconds();
  return true;
}

double vtkLaplacianDragPreview::GetUpdateTime()
{
  return this->Internals->UpdateTime;
}

bool vtkLaplacianDragPreview::Update(double tx, double ty, double tz, double rx, double ry, double rz)
{
  const double translation[3] = { tx, ty, tz }, rotation[3] = { rx, ry, rz };
  return this->Update(translation, rotation);
}

vtkPolyData* vtkLaplacianDragPreview::GetStillPart()
{
  return this->Internals->Parts.GetStillPart();
}

vtkPolyData* vtkLaplacianDragPreview::GetMovingPart()
{
  return this->Internals->Parts.GetMovingPart();
}

void vtkLaplacianDragPreview::Release()
{
  this->Internals->Parts.Release();
}

void vtkLaplacianDragPreview::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Filter: " << this->Filter << "\n";
  os << indent << "MovingPart: " << this->GetMovingPart()->GetNumberOfPoints() << " points\n";
  os << indent << "UpdateTime: " << this->Internals->UpdateTime << " s\n";
}
