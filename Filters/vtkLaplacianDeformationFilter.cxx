#include "vtkLaplacianDeformationFilter.h"

#include "EditPipeline.h"
#include "HandleMotion.h"
#include "HandleSource.h"
#include "RestShape.h"

#include "vtkDataArray.h"
#include "vtkDataSetAttributes.h"
#include "vtkErrorCode.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkIntArray.h"
#include "vtkLinearTransform.h"
#include "vtkObjectFactory.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSelection.h"
#include "vtkTransform.h"

#include <algorithm>
#include <initializer_list>
#include <string>

namespace le = LaplacianEditing;
namespace lep = LaplacianEditing::Pipeline;

vtkStandardNewMacro(vtkLaplacianDeformationFilter);

// The filter's own enums are the core's, value for value (the shared ones:
// vtkLaplacianEditFilter.cxx).
static_assert(static_cast<int>(le::DistanceMethod::FastMarching) ==
    vtkLaplacianDeformationFilter::DISTANCE_FAST_MARCHING &&
  static_cast<int>(le::DistanceMethod::EdgePaths) ==
    vtkLaplacianDeformationFilter::DISTANCE_EDGE_PATHS);
static_assert(static_cast<int>(le::VertexRole::Fixed) == vtkLaplacianDeformationFilter::ROLE_FIXED &&
  static_cast<int>(le::VertexRole::Anchor) == vtkLaplacianDeformationFilter::ROLE_ANCHOR &&
  static_cast<int>(le::VertexRole::Free) == vtkLaplacianDeformationFilter::ROLE_FREE &&
  static_cast<int>(le::VertexRole::Handle) == vtkLaplacianDeformationFilter::ROLE_HANDLE);

namespace
{
const char* EnumName(int value, std::initializer_list<const char*> names)
{
  return value >= 0 && value < static_cast<int>(names.size()) ? names.begin()[value] : "?";
}
}

// The filter's own state: the rest shape (commits), where its edits come from (the handle and
// its region), and the pipeline that runs them.
struct vtkLaplacianDeformationFilter::vtkInternals
{
  explicit vtkInternals(vtkLaplacianDeformationFilter* filter)
    : Source(filter)
    , Pipeline(filter->GetEditPipeline())
  {
  }

  lep::RestShape Rest;
  lep::HandleSource Source;
  lep::EditPipeline& Pipeline; // vtkLaplacianEditFilter's
  double Diagonal = 0.0; // of the rest surface's bounding box
  // When the last update solved an edit (a preview needs one of the current properties).
  vtkTimeStamp EditTime;
  // GetHandleGroupCenter's answer for callers that take no output arguments; (0, 0, 0) for a
  // group the last region did not have.
  double GroupCenter[3] = { 0.0, 0.0, 0.0 };
};

vtkLaplacianDeformationFilter::vtkLaplacianDeformationFilter()
  : Internals(new vtkInternals(this))
{
  this->SetInputArrayToProcess(
    0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, vtkDataSetAttributes::SCALARS);
  this->SetNumberOfInputPorts(2);
}

vtkLaplacianDeformationFilter::~vtkLaplacianDeformationFilter() = default;

void vtkLaplacianDeformationFilter::SetSelectionData(vtkSelection* selection)
{
  this->SetInputData(1, selection);
}

int vtkLaplacianDeformationFilter::FillInputPortInformation(int port, vtkInformation* info)
{
  if (port == 1)
  {
    info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkSelection");
    info->Set(vtkAlgorithm::INPUT_IS_OPTIONAL(), 1);
    return 1;
  }
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPolyData");
  return 1;
}

int vtkLaplacianDeformationFilter::FillOutputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkDataObject::DATA_TYPE_NAME(), "vtkPolyData");
  return 1;
}

vtkPolyData* vtkLaplacianDeformationFilter::GetOutput()
{
  return this->GetOutput(0);
}

vtkPolyData* vtkLaplacianDeformationFilter::GetOutput(int port)
{
  return vtkPolyData::SafeDownCast(this->GetOutputDataObject(port));
}

void vtkLaplacianDeformationFilter::SetHandleTransform(int group, vtkLinearTransform* transform)
{
  if (group < 0)
  {
    vtkErrorMacro(<< "handle group " << group << " is negative");
    return;
  }
  if (this->Internals->Source.GetHandles().SetTransform(group, transform))
  {
    this->Modified();
  }
}

vtkLinearTransform* vtkLaplacianDeformationFilter::GetHandleTransform(int group)
{
  return this->Internals->Source.GetHandles().GetTransform(group);
}

int vtkLaplacianDeformationFilter::GetNumberOfHandleTransforms()
{
  return this->Internals->Source.GetHandles().GetNumberOfTransforms();
}

void vtkLaplacianDeformationFilter::RemoveAllHandleTransforms()
{
  if (this->Internals->Source.GetHandles().RemoveAllTransforms())
  {
    this->Modified();
  }
}

void vtkLaplacianDeformationFilter::SetHandleGroupMotion(vtkIdType group, double translationX,
  double translationY, double translationZ, double rotationX, double rotationY, double rotationZ)
{
  if (group < 1 || group > VTK_INT_MAX)
  {
    vtkErrorMacro(<< "handle group " << group << " cannot take a motion: motions are for groups "
                  << "1 and above (group 0 moves with HandleTranslation and HandleRotation)");
    return;
  }
  if (this->Internals->Source.GetHandles().SetMotion(static_cast<int>(group),
        { translationX, translationY, translationZ, rotationX, rotationY, rotationZ }))
  {
    this->Modified();
  }
}

bool vtkLaplacianDeformationFilter::GetHandleGroupMotion(int group, double motion[6])
{
  return this->Internals->Source.GetHandles().GetMotion(group, motion);
}

int vtkLaplacianDeformationFilter::GetNumberOfHandleGroupMotions()
{
  return this->Internals->Source.GetHandles().GetNumberOfMotions();
}

void vtkLaplacianDeformationFilter::RemoveAllHandleGroupMotions()
{
  if (this->Internals->Source.GetHandles().RemoveAllMotions())
  {
    this->Modified();
  }
}

vtkMTimeType vtkLaplacianDeformationFilter::GetMTime()
{
  return std::max(
    this->Superclass::GetMTime(), this->Internals->Source.GetHandles().GetTransformsMTime());
}

int vtkLaplacianDeformationFilter::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  this->EditSurface(vtkPolyData::GetData(inputVector[0]), vtkPolyData::GetData(outputVector));
  return 1;
}

void vtkLaplacianDeformationFilter::EditSurface(vtkPolyData* input, vtkPolyData* output)
{
  vtkInternals& internals = *this->Internals;
  internals.Pipeline.BeginUpdate();
  if (output)
  {
    output->ShallowCopy(input);
  }
  if (!this->CheckInput(input))
  {
    return;
  }
  vtkPolyData* rest = internals.Rest.Get(input);
  if (output)
  {
    output->ShallowCopy(rest);
  }
  internals.Diagonal = rest->GetLength();
  internals.Source.Parameters = this->RegionParameters();
  std::copy_n(this->HandleRotation, 3, internals.Source.Rotation);
  std::copy_n(this->HandleTranslation, 3, internals.Source.Translation);
  if (internals.Pipeline.Run(rest, output, internals.Source, this->Settings(),
        this->MergeCoincidentPoints != 0, this->Outputs()))
  {
    internals.EditTime.Modified();
  }
}

double vtkLaplacianDeformationFilter::AbsoluteRadius(double radius) const
{
  const double diagonal = this->WholeDiagonal > 0.0 ? this->WholeDiagonal : this->Internals->Diagonal;
  return this->RadiusUnits == RADIUS_DIAGONAL_FRACTION ? radius * diagonal : radius;
}

double vtkLaplacianDeformationFilter::GetRadiusScale()
{
  auto* input = vtkPolyData::SafeDownCast(this->GetInputDataObject(0, 0));
  const double own = input && input->GetNumberOfPoints() > 0 ? input->GetLength() : 0.0;
  const double diagonal = this->WholeDiagonal > 0.0 ? this->WholeDiagonal : own;
  return this->RadiusUnits == RADIUS_DIAGONAL_FRACTION && diagonal > 0.0 ? diagonal : 1.0;
}

lep::RegionParameters vtkLaplacianDeformationFilter::RegionParameters() const
{
  lep::RegionParameters parameters;
  parameters.FromArray = this->SelectionMode == SELECTION_ARRAY;
  std::copy_n(this->HandleCenter, 3, parameters.HandleCenter);
  parameters.HandleRadius = this->AbsoluteRadius(this->HandleRadius);
  parameters.ROIRadius = this->AbsoluteRadius(this->ROIRadius);
  parameters.AnchorPadding = this->AnchorPadding;
  parameters.DistanceMethod = this->DistanceMethod;
  parameters.NormalSmoothingRadius =
    this->NormalSmoothingRadius > 0.0 ? this->AbsoluteRadius(this->NormalSmoothingRadius) : 0.0;
  return parameters;
}

lep::SolverSettings vtkLaplacianDeformationFilter::Settings()
{
  lep::SolverSettings settings = this->SharedSettings();
  settings.HandleWeight = this->HandleWeight;
  settings.AnchorWeight = this->AnchorWeight;
  settings.Distributed = this->GetDistributedSolver();
  settings.NormalSmoothingRadius = this->RegionParameters().NormalSmoothingRadius;
  settings.LargeRegionVertices = this->LargeRegionVertices;
  settings.ProxyNodes = this->ProxyNodes;
  return settings;
}

lep::OutputOptions vtkLaplacianDeformationFilter::Outputs() const
{
  lep::OutputOptions options;
  options.Roles = this->GenerateEditRoles != 0;
  options.RoleColors = this->RoleColors != 0;
  options.Displacement = this->OutputDisplacement != 0;
  return options;
}

bool vtkLaplacianDeformationFilter::CheckInput(vtkPolyData* input)
{
  lep::EditPipeline& pipeline = this->Internals->Pipeline;
  if (!pipeline.Check(lep::SurfaceAdapter::CheckSurface(input)))
  {
    return false;
  }
  auto* selection = vtkSelection::SafeDownCast(this->GetInputDataObject(1, 0));
  if (selection && this->ROIRadius <= 0.0)
  {
    return pipeline.Check("ROIRadius must be positive: with a selection on input port 1, the "
                          "ROI is every point within ROIRadius of the selected handle.");
  }
  if (!selection && this->SelectionMode == SELECTION_GEODESIC &&
    !(this->HandleRadius > 0.0 && this->ROIRadius > 0.0))
  {
    return pipeline.Check("HandleRadius and ROIRadius must be positive.");
  }
  const bool fromArray = this->SelectionMode == SELECTION_ARRAY;
  vtkDataArray* array = !selection && fromArray ? this->GetInputArrayToProcess(0, input) : nullptr;
  return pipeline.Check(this->Internals->Source.GetSelector().SelectLabels(input, selection,
    fromArray, array, [this](vtkPolyData* surface, vtkSelection* handle) {
      return this->SelectionLabels(surface, handle);
    }));
}

vtkSmartPointer<vtkIntArray> vtkLaplacianDeformationFilter::SelectionLabels(
  vtkPolyData* input, vtkSelection* selection)
{
  return lep::RegionSelector::LabelSelection(input, selection, 0);
}

void vtkLaplacianDeformationFilter::WriteEdit(
  vtkPolyData* rest, vtkPolyData* output, const lep::OutputEdit* edit)
{
  this->Internals->Pipeline.Write(
    rest, output, edit, this->Outputs());
}

bool vtkLaplacianDeformationFilter::SolveDragStep(
  const double translation[3], const double rotation[3])
{
  // Only the handle's motion may differ from the last update's: no property, transform or
  // input content changed since.
  vtkInternals& internals = *this->Internals;
  auto* input = vtkPolyData::SafeDownCast(this->GetInputDataObject(0, 0));
  if (!internals.Pipeline.HasSolved() || !input || this->GetMTime() > internals.EditTime ||
    lep::SurfaceAdapter::GetContentTime(input) > internals.EditTime)
  {
    return false;
  }
  // On the update's region and factors: nothing is rebuilt.
  std::copy_n(translation, 3, internals.Source.Translation);
  std::copy_n(rotation, 3, internals.Source.Rotation);
  return internals.Pipeline.SolveDragStep(internals.Source, this->Settings());
}

vtkPolyData* vtkLaplacianDeformationFilter::GetRestSurface()
{
  auto* input = vtkPolyData::SafeDownCast(this->GetInputDataObject(0, 0));
  return input ? this->Internals->Rest.Get(input) : nullptr;
}

vtkIdType vtkLaplacianDeformationFilter::GetNumberOfOutputCopies()
{
  return this->Internals->Pipeline.GetWriter().GetNumberOfCopies();
}

void vtkLaplacianDeformationFilter::CommitEdit()
{
  vtkPolyData* input = vtkPolyData::SafeDownCast(this->GetInputDataObject(0, 0));
  if (!input)
  {
    vtkErrorMacro(<< "CommitEdit needs an input.");
    return;
  }
  this->Update();
  vtkPolyData* output = this->GetOutput();
  if (this->GetErrorCode() != vtkErrorCode::NoError || !output->GetPoints())
  {
    return;
  }
  // The handle property transform moves HandleCenter along; the edit starts anew from there.
  double center[3];
  lep::HandleMotion::Transform(this->HandleCenter, this->HandleRotation, this->HandleTranslation)
    ->TransformPoint(this->HandleCenter, center);
  this->Internals->Rest.Commit(output->GetPoints());
  if (!this->GetHandleTransform(0))
  {
    this->SetHandleCenter(center);
  }
  this->SetHandleTranslation(0.0, 0.0, 0.0);
  this->SetHandleRotation(0.0, 0.0, 0.0);
  this->RemoveAllHandleGroupMotions();
  this->Modified();
  this->InvokeEvent(EditCommittedEvent);
}

bool vtkLaplacianDeformationFilter::UndoCommit()
{
  if (!this->Internals->Rest.Undo())
  {
    return false;
  }
  this->Modified();
  this->InvokeEvent(CommitUndoneEvent);
  return true;
}

int vtkLaplacianDeformationFilter::GetNumberOfCommits()
{
  return this->Internals->Rest.GetNumberOfCommits();
}

bool vtkLaplacianDeformationFilter::GetRestPoint(vtkIdType id, double point[3])
{
  return this->Internals->Rest.GetPoint(
    vtkPolyData::SafeDownCast(this->GetInputDataObject(0, 0)), id, point);
}

bool vtkLaplacianDeformationFilter::GetHandleGroupCenter(int group, double center[3])
{
  const double* found = this->Internals->Source.GetHandles().GetGroupCenter(group);
  if (found)
  {
    std::copy_n(found, 3, center);
  }
  return found != nullptr;
}

double* vtkLaplacianDeformationFilter::GetHandleGroupCenter(int group)
{
  double* center = this->Internals->GroupCenter;
  const double* found = this->Internals->Source.GetHandles().GetGroupCenter(group);
  std::fill_n(center, 3, 0.0);
  if (found)
  {
    std::copy_n(found, 3, center);
  }
  return center;
}

int vtkLaplacianDeformationFilter::GetNumberOfHandleGroups()
{
  return this->Internals->Pipeline.GetEditor().GetRegion().NumberOfHandleGroups;
}

int vtkLaplacianDeformationFilter::GetNumberOfROIVertices()
{
  return this->Internals->Pipeline.GetFacts().NumberOfROIVertices;
}

int vtkLaplacianDeformationFilter::GetNumberOfHandleVertices()
{
  return this->Internals->Pipeline.GetFacts().NumberOfHandleVertices;
}

int vtkLaplacianDeformationFilter::GetNumberOfSurfaceVertices()
{
  return this->Internals->Pipeline.GetFacts().NumberOfSurfaceVertices;
}

vtkTypeBool vtkLaplacianDeformationFilter::GetFactoredAcrossProcesses()
{
  return this->Internals->Pipeline.GetEditor().IsFactorDistributed();
}

void vtkLaplacianDeformationFilter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  this->PrintRegionProperties(os, indent);
  this->PrintSolverProperties(os, indent);
  os << indent << "Region of the last update:\n";
  this->PrintLastUpdate(os, indent.GetNextIndent());
}

void vtkLaplacianDeformationFilter::PrintRegionProperties(ostream& os, vtkIndent indent)
{
  auto printVector = [&](const char* label, const double v[3]) {
    os << indent << label << ": (" << v[0] << ", " << v[1] << ", " << v[2] << ")\n";
  };
  os << indent << "SelectionMode: " << EnumName(this->SelectionMode, { "Geodesic", "Array" }) << "\n";
  os << indent << "Selection input: "
     << (this->GetNumberOfInputConnections(1) > 0 ? "connected" : "none")
     << "\n";
  os << indent << "RadiusUnits: "
     << EnumName(this->RadiusUnits, { "Absolute", "DiagonalFraction" }) << "\n";
  printVector("HandleCenter", this->HandleCenter);
  printVector("HandleTranslation", this->HandleTranslation);
  printVector("HandleRotation", this->HandleRotation);
  os << indent << "HandleRadius: " << this->HandleRadius << "\n";
  os << indent << "ROIRadius: " << this->ROIRadius << "\n";
  os << indent << "AnchorPadding: " << this->AnchorPadding << "\n";
  os << indent << "DistanceMethod: "
     << EnumName(this->DistanceMethod, { "FastMarching", "EdgePaths" }) << "\n";
  this->Internals->Source.GetHandles().PrintSelf(os, indent);
  os << indent << "NumberOfCommits: " << this->Internals->Rest.GetNumberOfCommits() << "\n";
}

void vtkLaplacianDeformationFilter::PrintSolverProperties(ostream& os, vtkIndent indent)
{
  os << indent << "HandleWeight: " << this->HandleWeight << "\n";
  os << indent << "AnchorWeight: " << this->AnchorWeight << "\n";
  os << indent << "LargeRegionVertices: " << this->LargeRegionVertices << "\n";
  os << indent << "ProxyNodes: " << this->ProxyNodes << "\n";
  os << indent << "GenerateEditRoles: " << (this->GenerateEditRoles ? "On" : "Off") << "\n";
  os << indent << "RoleColors: " << (this->RoleColors ? "On" : "Off") << "\n";
}

void vtkLaplacianDeformationFilter::PrintLastUpdate(ostream& os, vtkIndent next)
{
  os << next << "NumberOfROIVertices: " << this->GetNumberOfROIVertices() << "\n";
  os << next << "NumberOfHandleVertices: " << this->GetNumberOfHandleVertices() << "\n";
  os << next << "NumberOfSurfaceVertices: " << this->GetNumberOfSurfaceVertices() << "\n";
  os << next << "FactoredAcrossProcesses: " << this->GetFactoredAcrossProcesses() << "\n";
}
