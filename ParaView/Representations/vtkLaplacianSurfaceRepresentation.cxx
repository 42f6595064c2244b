#include "vtkLaplacianSurfaceRepresentation.h"

#include "UsedPointsBounds.h"
#include "vtkLaplacianSurfaceMapper.h"
#include "vtkObjectFactory.h"
#include "vtkPVView.h"

struct vtkLaplacianSurfaceRepresentation::vtkInternals
{
  LaplacianEditing::Representations::UsedPointsBounds Bounds;
};

vtkStandardNewMacro(vtkLaplacianSurfaceRepresentation);

vtkLaplacianSurfaceRepresentation::vtkLaplacianSurfaceRepresentation()
  : Internals(new vtkInternals)
{
  // The superclass's constructor made a vtkCompositePolyDataMapper2, named its selection's id
  // arrays and set it up (SetupDefaults, which expects subclasses to call it again).
  auto* previous = vtkCompositePolyDataMapper2::SafeDownCast(this->Mapper);
  vtkLaplacianSurfaceMapper* mapper = vtkLaplacianSurfaceMapper::New();
  mapper->SetProcessIdArrayName(previous->GetProcessIdArrayName());
  mapper->SetCompositeIdArrayName(previous->GetCompositeIdArrayName());
  mapper->SetPointIdArrayName(previous->GetPointIdArrayName());
  mapper->SetCellIdArrayName(previous->GetCellIdArrayName());
  this->Mapper->Delete();
  this->Mapper = mapper;
  this->SetupDefaults();
}

vtkLaplacianSurfaceRepresentation::~vtkLaplacianSurfaceRepresentation() = default;

int vtkLaplacianSurfaceRepresentation::RequestData(
  vtkInformation* request, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  const int status = this->Superclass::RequestData(request, inputVector, outputVector);
  // Before the view's update asks for the geometry's visible bounds.
  this->Internals->Bounds.Fill(this->MultiBlockMaker->GetOutputDataObject(0));
  return status;
}

int vtkLaplacianSurfaceRepresentation::ProcessViewRequest(
  vtkInformationRequestKey* request, vtkInformation* inInfo, vtkInformation* outInfo)
{
  const int status = this->Superclass::ProcessViewRequest(request, inInfo, outInfo);
  if (status && request == vtkPVView::REQUEST_RENDER())
  {
    // The piece the mapper draws, before the render asks for its bounds.
    this->Internals->Bounds.Fill(vtkPVView::GetDeliveredPiece(inInfo, this));
  }
  return status;
}

int vtkLaplacianSurfaceRepresentation::GetNumberOfCellPasses()
{
  return this->Internals->Bounds.GetNumberOfCellPasses();
}

bool vtkLaplacianSurfaceRepresentation::GetDrewSurfaceAlone()
{
  return static_cast<vtkLaplacianSurfaceMapper*>(this->Mapper)->GetDrewSurfaceAlone();
}

int vtkLaplacianSurfaceRepresentation::GetNumberOfIndexBuilds()
{
  return static_cast<vtkLaplacianSurfaceMapper*>(this->Mapper)->GetNumberOfIndexBuilds();
}

void vtkLaplacianSurfaceRepresentation::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "NumberOfCellPasses: " << this->GetNumberOfCellPasses() << "\n";
}
