#include "vtkLaplacianDisplacementGrid.h"

#include "DisplacementLattice.h"

#include "vtkDataSetAttributes.h"
#include "vtkDoubleArray.h"
#include "vtkErrorCode.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPointSet.h"
#include "vtkStreamingDemandDrivenPipeline.h"

#include <algorithm>

namespace le = LaplacianEditing;

vtkStandardNewMacro(vtkLaplacianDisplacementGrid);

vtkLaplacianDisplacementGrid::vtkLaplacianDisplacementGrid()
{
  this->SetNumberOfInputPorts(2);
  this->SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, "Displacement");
}

vtkLaplacianDisplacementGrid::~vtkLaplacianDisplacementGrid() = default;

void vtkLaplacianDisplacementGrid::SetReferenceImageData(vtkDataObject* image)
{
  this->SetInputData(1, image);
}

int vtkLaplacianDisplacementGrid::FillInputPortInformation(int port, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), port == 0 ? "vtkPointSet" : "vtkImageData");
  if (port == 1)
  {
    info->Set(vtkAlgorithm::INPUT_IS_OPTIONAL(), 1);
  }
  return 1;
}

int vtkLaplacianDisplacementGrid::RequestInformation(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkInformation* out = outputVector->GetInformationObject(0);
  vtkInformation* reference = inputVector[1]->GetInformationObject(0);
  if (reference && reference->Has(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT()))
  {
    out->CopyEntry(reference, vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT());
    out->CopyEntry(reference, vtkDataObject::ORIGIN());
    out->CopyEntry(reference, vtkDataObject::SPACING());
  }
  else
  {
    const int extent[6] = { 0, std::max(1, this->Dimensions[0] - 1), 0,
      std::max(1, this->Dimensions[1] - 1), 0, std::max(1, this->Dimensions[2] - 1) };
    out->Set(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), extent, 6);
  }
  vtkDataObject::SetPointDataActiveScalarInfo(out, VTK_DOUBLE, 3);
  return 1;
}

int vtkLaplacianDisplacementGrid::RequestUpdateExtent(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector*)
{
  // The whole reference image: only its geometry is read.
  if (vtkInformation* reference = inputVector[1]->GetInformationObject(0))
  {
    reference->Set(vtkStreamingDemandDrivenPipeline::UPDATE_EXTENT(),
      reference->Get(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT()), 6);
  }
  return 1;
}

int vtkLaplacianDisplacementGrid::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkPointSet* input = vtkPointSet::GetData(inputVector[0]);
  vtkImageData* reference = vtkImageData::GetData(inputVector[1]);
  vtkImageData* output = vtkImageData::GetData(outputVector);
  this->SetErrorCode(vtkErrorCode::NoError);
  vtkDataArray* displacement = input ? this->GetInputArrayToProcess(0, input) : nullptr;
  if (!input || input->GetNumberOfPoints() == 0 || !displacement ||
    displacement->GetNumberOfComponents() != 3)
  {
    vtkErrorMacro(<< "The input needs points and a three-component Displacement point array (a "
                     "warp's output with OutputDisplacement on).");
    this->SetErrorCode(vtkErrorCode::UserError);
    return 1;
  }
  // Where the field is known and what it is there: at the rest positions (the points minus
  // their displacement) the displacement, or, inverse, at the points the way back.
  const vtkIdType n = input->GetNumberOfPoints();
  le::Positions rest(n, 3), moves(n, 3);
  for (vtkIdType i = 0; i < n; ++i)
  {
    double p[3], d[3];
    input->GetPoint(i, p);
    displacement->GetTuple(i, d);
    for (int k = 0; k < 3; ++k)
    {
      rest(i, k) = this->Inverse ? p[k] : p[k] - d[k];
      moves(i, k) = this->Inverse ? -d[k] : d[k];
    }
  }
  le::LatticeGeometry lattice;
  int extent[6];
  if (reference)
  {
    reference->GetExtent(extent);
    double origin[3], spacing[3];
    reference->GetOrigin(origin);
    reference->GetSpacing(spacing);
    for (int a = 0; a < 3; ++a)
    {
      lattice.Dimensions[a] = extent[2 * a + 1] - extent[2 * a] + 1;
      lattice.Spacing[a] = spacing[a];
      lattice.Origin[a] = origin[a] + extent[2 * a] * spacing[a];
    }
    output->SetOrigin(origin);
    output->SetSpacing(spacing);
  }
  else
  {
    const le::Vector3 low = rest.colwise().minCoeff().transpose();
    const le::Vector3 high = rest.colwise().maxCoeff().transpose();
    const double margin = this->Padding * (high - low).maxCoeff();
    for (int a = 0; a < 3; ++a)
    {
      lattice.Dimensions[a] = std::max(2, this->Dimensions[a]);
      lattice.Origin[a] = low[a] - margin;
      const double span = high[a] - low[a] + 2.0 * margin;
      lattice.Spacing[a] = span > 0.0 ? span / (lattice.Dimensions[a] - 1) : 1.0;
      extent[2 * a] = 0;
      extent[2 * a + 1] = lattice.Dimensions[a] - 1;
    }
    output->SetOrigin(lattice.Origin.data());
    output->SetSpacing(lattice.Spacing.data());
  }
  output->SetExtent(extent);
  le::Positions nodes;
  const std::string error =
    le::FitDisplacementLattice(lattice, rest, moves, this->Smoothness, nodes);
  if (!error.empty())
  {
    vtkErrorMacro(<< "Cannot fit the displacement grid: " << error << ".");
    this->SetErrorCode(vtkErrorCode::UserError);
    return 1;
  }
  vtkNew<vtkDoubleArray> field;
  field->SetName("Displacement");
  field->SetNumberOfComponents(3);
  field->SetNumberOfTuples(nodes.rows());
  for (Eigen::Index row = 0; row < nodes.rows(); ++row)
  {
    field->SetTuple3(row, nodes(row, 0), nodes(row, 1), nodes(row, 2));
  }
  output->GetPointData()->SetScalars(field);
  output->GetPointData()->SetVectors(field);
  return 1;
}

void vtkLaplacianDisplacementGrid::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Dimensions: " << this->Dimensions[0] << " " << this->Dimensions[1] << " "
     << this->Dimensions[2] << "\n";
  os << indent << "Padding: " << this->Padding << "\n";
  os << indent << "Smoothness: " << this->Smoothness << "\n";
  os << indent << "Inverse: " << (this->Inverse ? "On" : "Off") << "\n";
}
