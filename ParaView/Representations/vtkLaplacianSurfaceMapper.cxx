#include "vtkLaplacianSurfaceMapper.h"

#include "OnlySurface.h"
#include "PreviewPartMapper.h"
#include "vtkCompositeDataDisplayAttributes.h"
#include "vtkObjectFactory.h"
#include "vtkPolyData.h"
#include "vtkRenderer.h"
#include "vtkSelection.h"

vtkStandardNewMacro(vtkLaplacianSurfaceMapper);

vtkLaplacianSurfaceMapper::vtkLaplacianSurfaceMapper() = default;

vtkLaplacianSurfaceMapper::~vtkLaplacianSurfaceMapper() = default;

vtkPolyData* vtkLaplacianSurfaceMapper::SurfaceDrawnAlone(vtkRenderer* renderer)
{
  // A hardware selection's passes, and the highlight of an interactive selection (the
  // representation's SetSelection), are the composite mapper's.
  vtkSelection* highlighted = this->GetSelection();
  if (renderer->GetSelector() || (highlighted && highlighted->GetNumberOfNodes() > 0))
  {
    return nullptr;
  }
  vtkCompositeDataDisplayAttributes* blocks = this->GetCompositeDataDisplayAttributes();
  if (blocks &&
    (blocks->HasBlockColors() || blocks->HasBlockOpacities() || blocks->HasBlockMaterials()))
  {
    return nullptr;
  }
  bool hidden = false;
  if (blocks)
  {
    blocks->VisitVisibilities([&hidden](vtkDataObject*, bool visible) {
      hidden = !visible;
      return hidden;
    });
  }
  return hidden ? nullptr
                : LaplacianEditing::Representations::OnlySurface(this->GetInputDataObject(0, 0));
}

void vtkLaplacianSurfaceMapper::Render(vtkRenderer* renderer, vtkActor* actor)
{
  vtkPolyData* surface = this->SurfaceDrawnAlone(renderer);
  this->DrewSurfaceAlone = surface != nullptr;
  if (!surface)
  {
    this->Superclass::Render(renderer, actor);
    return;
  }
  // The colouring (lookup table, scalar mode and array, range) and texture seams; each setter
  // changes nothing where the value is the same.
  this->SurfaceMapper->vtkMapper::ShallowCopy(this);
  this->SurfaceMapper->SetSeamlessU(this->GetSeamlessU());
  this->SurfaceMapper->SetSeamlessV(this->GetSeamlessV());
  this->SurfaceMapper->SetInputData(surface);
  this->SurfaceMapper->Render(renderer, actor);
}

void vtkLaplacianSurfaceMapper::ReleaseGraphicsResources(vtkWindow* window)
{
  this->SurfaceMapper->ReleaseGraphicsResources(window);
  this->Superclass::ReleaseGraphicsResources(window);
}

int vtkLaplacianSurfaceMapper::GetNumberOfIndexBuilds()
{
  return this->SurfaceMapper->GetNumberOfIndexBuilds();
}

void vtkLaplacianSurfaceMapper::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "DrewSurfaceAlone: " << this->DrewSurfaceAlone << "\n";
  os << indent << "NumberOfIndexBuilds: " << this->SurfaceMapper->GetNumberOfIndexBuilds() << "\n";
}
