#include "vtkLaplacianDeformationFilter.h"

#include "vtkLaplacianDragPreview.h"
#include "vtkLaplacianEditSolver.h"
#include "vtkLaplacianHandleMaps.h"
#include "vtkLaplacianNormalRefresher.h"
#include "vtkLaplacianOutputWriter.h"
#include "vtkLaplacianPieceEdit.h"
#include "vtkLaplacianRegionSelector.h"
#include "vtkLaplacianRestShape.h"
#include "vtkLaplacianSurfaceAdapter.h"

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
#include <chrono>
#include <initializer_list>
#include <string>

namespace le = LaplacianEditing;

vtkStandardNewMacro(vtkLaplacianDeformationFilter);

// The filter's enums are the core's, value for value.
static_assert(static_cast<int>(le::LaplacianWeights::Uniform) ==
    vtkLaplacianDeformationFilter::WEIGHTS_UNIFORM &&
  static_cast<int>(le::LaplacianWeights::Cotangent) ==
    vtkLaplacianDeformationFilter::WEIGHTS_COTANGENT);
static_assert(static_cast<int>(le::RotationMode::None) ==
    vtkLaplacianDeformationFilter::ROTATION_NONE &&
  static_cast<int>(le::RotationMode::Explicit) == vtkLaplacianDeformationFilter::ROTATION_EXPLICIT &&
  static_cast<int>(le::RotationMode::Implicit) == vtkLaplacianDeformationFilter::ROTATION_IMPLICIT &&
  static_cast<int>(le::RotationMode::AsRigidAsPossible) ==
    vtkLaplacianDeformationFilter::ROTATION_AS_RIGID_AS_POSSIBLE);
static_assert(static_cast<int>(le::SolverBackend::Cholmod) ==
    vtkLaplacianDeformationFilter::SOLVER_CHOLMOD &&
  static_cast<int>(le::SolverBackend::SimplicialLDLT) ==
    vtkLaplacianDeformationFilter::SOLVER_SIMPLICIAL_LDLT &&
  static_cast<int>(le::SolverBackend::Distributed) == vtkLaplacianDeformationFilter::SOLVER_MUMPS);
static_assert(static_cast<int>(le::FillOrdering::Automatic) ==
    vtkLaplacianDeformationFilter::ORDERING_AUTOMATIC &&
  static_cast<int>(le::FillOrdering::AMD) == vtkLaplacianDeformationFilter::ORDERING_AMD &&
  static_cast<int>(le::FillOrdering::METIS) == vtkLaplacianDeformationFilter::ORDERING_METIS &&
  static_cast<int>(le::FillOrdering::NestedDissection) ==
    vtkLaplacianDeformationFilter::ORDERING_NESTED_DISSECTION);
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
using Clock = std::chrono::steady_clock;

double SecondsSince(Clock::time_point start)
{
  return std::chrono::duration<double>(Clock::now() - start).count();
}

const char* EnumName(int value, std::initializer_list<const char*> names)
{
  return value >= 0 && value < static_cast<int>(names.size()) ? names.begin()[value] : "?";
}
}

// The stages of an edit, in the order RequestData runs them.
struct vtkLaplacianDeformationFilter::vtkInternals
{
  vtkLaplacianRestShape Rest;
  vtkLaplacianRegionSelector Region;
  vtkLaplacianSurfaceAdapter Surface;
  vtkLaplacianEditSolver Solver;
  vtkLaplacianHandleMaps Handles;
  vtkLaplacianNormalRefresher Normals;
  vtkLaplacianOutputWriter Writer;
  vtkLaplacianDragPreview Preview;
  double Diagonal = 0.0; // of the rest surface's bounding box
  // Whether the last EditSurface solved an edit, and when; whether a preview solved since.
  bool Edited = false;
  vtkTimeStamp EditTime;
  bool Previewed = false;
};

vtkLaplacianDeformationFilter::vtkLaplacianDeformationFilter()
  : Internals(new vtkInternals)
{
  if (!IsCholmodAvailable())
  {
    this->Solver = SOLVER_SIMPLICIAL_LDLT;
  }
  this->SetInputArrayToProcess(
    0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, vtkDataSetAttributes::SCALARS);
  this->SetNumberOfInputPorts(2);
  this->Internals->Writer.SetFilter(this);
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
  return this->Superclass::FillInputPortInformation(port, info);
}

bool vtkLaplacianDeformationFilter::IsCholmodAvailable()
{
  return le::SparseCholesky::IsAvailable(le::SolverBackend::Cholmod);
}

void vtkLaplacianDeformationFilter::SetHandleTransform(int group, vtkLinearTransform* transform)
{
  if (group < 0)
  {
    vtkErrorMacro(<< "handle group " << group << " is negative");
    return;
  }
  if (this->Internals->Handles.SetTransform(group, transform))
  {
    this->Modified();
  }
}

vtkLinearTransform* vtkLaplacianDeformationFilter::GetHandleTransform(int group)
{
  return this->Internals->Handles.GetTransform(group);
}

int vtkLaplacianDeformationFilter::GetNumberOfHandleTransforms()
{
  return this->Internals->Handles.GetNumberOfTransforms();
}

void vtkLaplacianDeformationFilter::RemoveAllHandleTransforms()
{
  if (this->Internals->Handles.RemoveAllTransforms())
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
  if (this->Internals->Handles.SetMotion(static_cast<int>(group),
        { translationX, translationY, translationZ, rotationX, rotationY, rotationZ }))
  {
    this->Modified();
  }
}

bool vtkLaplacianDeformationFilter::GetHandleGroupMotion(int group, double motion[6])
{
  return this->Internals->Handles.GetMotion(group, motion);
}

int vtkLaplacianDeformationFilter::GetNumberOfHandleGroupMotions()
{
  return this->Internals->Handles.GetNumberOfMotions();
}

void vtkLaplacianDeformationFilter::RemoveAllHandleGroupMotions()
{
  if (this->Internals->Handles.RemoveAllMotions())
  {
    this->Modified();
  }
}

vtkMTimeType vtkLaplacianDeformationFilter::GetMTime()
{
  return std::max(this->Superclass::GetMTime(), this->Internals->Handles.GetTransformsMTime());
}

void vtkLaplacianDeformationFilter::SetDragging(vtkTypeBool dragging)
{
  if (this->Dragging == dragging)
  {
    return;
  }
  this->Dragging = dragging;
  this->SettleAfterDrag = !dragging;
  if (!dragging && !this->Internals->Previewed)
  {
    // The next update settles the pose the drag left. A previewed drag left the output as it
    // was: the update that applies its motion settles it.
    this->Modified();
  }
}

int vtkLaplacianDeformationFilter::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  this->EditSurface(vtkPolyData::GetData(inputVector[0]), vtkPolyData::GetData(outputVector));
  return 1;
}

void vtkLaplacianDeformationFilter::EditSurface(vtkPolyData* input, vtkPolyData* output)
{
  this->ResetStatistics();
  this->RunStages(input, output);
  const vtkLaplacianEditSolver::Facts& facts = this->Internals->Solver.GetFacts();
  this->SetupTime = facts.SetupTime;
  this->AnalysisTime = facts.AnalysisTime;
  this->FactorizationTime = facts.FactorizationTime;
  this->SolveTime = facts.SolveTime;
  this->NumberOfARAPIterations = facts.NumberOfARAPIterations;
  this->ARAPEnergy = facts.ARAPEnergy;
}

void vtkLaplacianDeformationFilter::RunStages(vtkPolyData* input, vtkPolyData* output)
{
  // Each stage is skipped when its cache holds; progress after each that may take seconds
  // (graph, region and its factor, rotation model and its factor).
  this->Internals->Edited = false;
  this->Internals->Previewed = false;
  output->ShallowCopy(input);
  if (!this->CheckInput(input))
  {
    return;
  }
  vtkPolyData* rest = this->Internals->Rest.Get(input);
  output->ShallowCopy(rest);
  this->UpdateProgress(0.1);
  if (!this->UpdateSurfaceGraph(rest) || this->GetAbortExecute())
  {
    return;
  }
  this->UpdateProgress(0.3);
  if (!this->UpdateRegion(rest) || this->GetAbortExecute())
  {
    return;
  }
  this->UpdateProgress(0.6);
  if (!this->UpdateRotationModel() || this->GetAbortExecute())
  {
    return;
  }
  this->UpdateProgress(0.9);
  if (this->Solve(this->HandleTranslation, this->HandleRotation))
  {
    this->WriteOutput(rest, output);
    this->Internals->EditTime.Modified();
  }
  this->UpdateProgress(1.0);
}

bool vtkLaplacianDeformationFilter::Fail(const std::string& message)
{
  vtkErrorMacro(<< message);
  this->SetErrorCode(vtkErrorCode::UserError);
  return false;
}

bool vtkLaplacianDeformationFilter::Check(const std::string& error)
{
  return error.empty() || this->Fail(error);
}

void vtkLaplacianDeformationFilter::ResetStatistics()
{
  this->SetErrorCode(vtkErrorCode::NoError);
  this->NumberOfROIVertices = 0;
  this->NumberOfHandleVertices = 0;
  this->TopologyTime = 0.0;
  this->Internals->Solver.ResetFacts();
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

vtkLaplacianRegionSelector::Parameters vtkLaplacianDeformationFilter::RegionParameters() const
{
  vtkLaplacianRegionSelector::Parameters parameters;
  parameters.FromArray = this->SelectionMode == SELECTION_ARRAY;
  std::copy(this->HandleCenter, this->HandleCenter + 3, parameters.HandleCenter);
  parameters.HandleRadius = this->AbsoluteRadius(this->HandleRadius);
  parameters.ROIRadius = this->AbsoluteRadius(this->ROIRadius);
  parameters.AnchorPadding = this->AnchorPadding;
  parameters.DistanceMethod = this->DistanceMethod;
  parameters.NormalSmoothingRadius =
    this->NormalSmoothingRadius > 0.0 ? this->AbsoluteRadius(this->NormalSmoothingRadius) : 0.0;
  return parameters;
}

vtkLaplacianEditSolver::Options vtkLaplacianDeformationFilter::SolverOptions(bool dragStep)
{
  vtkLaplacianEditSolver::Options options;
  options.LaplacianWeights = this->LaplacianWeights;
  options.OperatorOrder = this->OperatorOrder;
  options.HandleWeight = this->HandleWeight;
  options.AnchorWeight = this->AnchorWeight;
  options.Solver = this->Solver;
  options.Ordering = this->Ordering;
  options.MaximumFactorMemory = this->MaximumFactorMemory;
  options.Distributed = this->GetDistributedSolver();
  options.RotationMode = this->RotationMode;
  options.NormalSmoothingRadius = this->NormalSmoothingRadius > 0.0
    ? this->AbsoluteRadius(this->NormalSmoothingRadius) * this->Internals->Surface.GetScale()
    : 0.0;
  options.NumberOfIterations = this->NumberOfIterations;
  options.PreserveDetailScale = this->PreserveDetailScale != 0;
  options.ImplicitFormulation = this->ImplicitFormulation;
  // A drag caps each update's iterations; the update after it settles the shape in full.
  options.ARAPIterations = this->Dragging || dragStep
    ? std::min(this->DragARAPIterations, this->ARAPIterations)
    : this->ARAPIterations;
  options.Convergence = this->SettleAfterDrag ? 0.0 : this->Convergence;
  options.Acceleration = this->Acceleration != 0;
  options.Extrapolation = this->Extrapolation != 0;
  return options;
}

bool vtkLaplacianDeformationFilter::CheckInput(vtkPolyData* input)
{
  if (!this->Check(vtkLaplacianSurfaceAdapter::CheckSurface(input)))
  {
    return false;
  }
  auto* selection = vtkSelection::SafeDownCast(this->GetInputDataObject(1, 0));
  if (selection && this->ROIRadius <= 0.0)
  {
    return this->Fail("ROIRadius must be positive: with a selection on input port 1, the ROI is "
                      "every point within ROIRadius of the selected handle.");
  }
  if (!selection && this->SelectionMode == SELECTION_GEODESIC &&
    !(this->HandleRadius > 0.0 && this->ROIRadius > 0.0))
  {
    return this->Fail("HandleRadius and ROIRadius must be positive.");
  }
  const bool fromArray = this->SelectionMode == SELECTION_ARRAY;
  vtkDataArray* array = !selection && fromArray ? this->GetInputArrayToProcess(0, input) : nullptr;
  return this->Check(this->Internals->Region.SelectLabels(input, selection, fromArray, array,
    [this](vtkPolyData* surface, vtkSelection* handle) { return this->SelectionLabels(surface, handle); }));
}

vtkSmartPointer<vtkIntArray> vtkLaplacianDeformationFilter::SelectionLabels(
  vtkPolyData* input, vtkSelection* selection)
{
  return vtkLaplacianRegionSelector::LabelSelection(input, selection, 0);
}

bool vtkLaplacianDeformationFilter::UpdateSurfaceGraph(vtkPolyData* rest)
{
  // The surface graph depends on the rest surface and on the part of it the edit can reach.
  vtkInternals& internals = *this->Internals;
  internals.Diagonal = rest->GetLength();
  const auto& reach = internals.Region.ComputeReach(rest, this->RegionParameters());
  const Clock::time_point start = Clock::now();
  bool rebuilt = false;
  const std::string error =
    internals.Surface.Update(rest, this->MergeCoincidentPoints != 0, reach, rebuilt);
  if (rebuilt)
  {
    internals.Solver.SetMesh(internals.Surface.GetMesh());
  }
  if (!this->Check(error))
  {
    return false;
  }
  if (rebuilt)
  {
    this->NumberOfSurfaceVertices = internals.Surface.GetMesh()->GetNumberOfVertices();
    this->TopologyTime = SecondsSince(start);
  }
  return true;
}

bool vtkLaplacianDeformationFilter::UpdateRegion(vtkPolyData* rest)
{
  vtkInternals& internals = *this->Internals;
  const vtkLaplacianSurfaceAdapter& surface = internals.Surface;
  const vtkLaplacianRegionSelector::Parameters parameters = this->RegionParameters();
  const le::RegionRequest request = internals.Region.Request(rest, surface, parameters);
  vtkDataArray* labels = internals.Region.GetLabels();
  unsigned rebuilt = le::RebuiltNothing;
  const std::string error = internals.Solver.UpdateRegion(
    request, [&] { return surface.VertexLabels(labels); }, this->SolverOptions(), rebuilt);
  this->UpdateFactorizationCounts();
  if (!this->Check(error))
  {
    return false;
  }
  const le::EditRegion& region = internals.Solver.GetEditor().GetRegion();
  if (rebuilt & le::RebuiltRegion)
  {
    internals.Region.Warn(this, request, region, surface, parameters, internals.Diagonal);
  }
  if (rebuilt != le::RebuiltNothing)
  {
    internals.Surface.IndexRegion(region);
    internals.Handles.FindGroupCenters(region, surface);
    internals.Normals.Index(rest, surface);
  }
  return true;
}

bool vtkLaplacianDeformationFilter::UpdateRotationModel()
{
  vtkInternals& internals = *this->Internals;
  const vtkLaplacianEditSolver::Options options = this->SolverOptions();
  this->SettleAfterDrag = false;
  const std::string error = internals.Solver.UpdateRotationModel(options, this);
  this->UpdateFactorizationCounts();
  this->FactorMemory = internals.Solver.GetFactorMemory();
  this->FactoredAcrossProcesses = internals.Solver.GetEditor().IsFactorDistributed();
  return this->Check(error);
}

void vtkLaplacianDeformationFilter::UpdateFactorizationCounts()
{
  const le::LaplacianEditor& editor = this->Internals->Solver.GetEditor();
  this->NumberOfFactorizations = editor.GetNumberOfFactorizations();
  this->NumberOfFactorizationAttempts = editor.GetNumberOfFactorizationAttempts();
}

bool vtkLaplacianDeformationFilter::Solve(const double translation[3], const double rotation[3])
{
  vtkInternals& internals = *this->Internals;
  const int groups = internals.Solver.GetEditor().GetRegion().NumberOfHandleGroups;
  if (!this->Check(internals.Solver.Solve(
        internals.Handles.Maps(groups, internals.Surface, this->HandleCenter, rotation, translation))))
  {
    return false;
  }
  internals.Edited = true;
  const le::EditRegion& region = internals.Solver.GetEditor().GetRegion();
  this->NumberOfROIVertices = region.GetNumberOfVertices();
  this->NumberOfHandleVertices = static_cast<int>(
    std::count(region.Roles.begin(), region.Roles.end(), le::VertexRole::Handle));
  return true;
}

vtkLaplacianOutputEdit vtkLaplacianDeformationFilter::SolvedEdit() const
{
  const vtkInternals& internals = *this->Internals;
  return internals.Surface.GetEdit(
    internals.Solver.GetSolution(), &internals.Normals, internals.Solver.GetModelVersion());
}

void vtkLaplacianDeformationFilter::WriteOutput(vtkPolyData* rest, vtkPolyData* output)
{
  vtkInternals& internals = *this->Internals;
  const Clock::time_point start = Clock::now();
  const vtkLaplacianOutputEdit edit = this->SolvedEdit();
  this->WriteEdit(rest, output, &edit);
  internals.Solver.GetFacts().SolveTime += SecondsSince(start);
}

bool vtkLaplacianDeformationFilter::PreviewHandleMotion(
  const double translation[3], const double rotation[3])
{
  // Only the handle's motion may differ from the last update's: no property, transform or
  // input content changed since.
  vtkInternals& internals = *this->Internals;
  auto* input = vtkPolyData::SafeDownCast(this->GetInputDataObject(0, 0));
  if (!internals.Edited || !input || this->GetMTime() > internals.EditTime ||
    vtkLaplacianSurfaceAdapter::GetContentTime(input) > internals.EditTime)
  {
    return false;
  }
  // A drag step, as during a drag with Dragging on; the region and its factors are the
  // update's, so nothing is rebuilt.
  if (!this->Check(internals.Solver.UpdateRotationModel(this->SolverOptions(true), this)) ||
    !this->Solve(translation, rotation))
  {
    return false;
  }
  const vtkLaplacianOutputEdit edit = this->SolvedEdit();
  if (!internals.Preview.IsBuiltFor(edit.RegionVersion))
  {
    internals.Preview.Build(internals.Rest.Get(input), this->GetOutput(), edit);
  }
  internals.Preview.Write(edit);
  internals.Previewed = true;
  return true;
}

bool vtkLaplacianDeformationFilter::PreviewHandleMotion(
  double tx, double ty, double tz, double rx, double ry, double rz)
{
  const double translation[3] = { tx, ty, tz }, rotation[3] = { rx, ry, rz };
  return this->PreviewHandleMotion(translation, rotation);
}

vtkPolyData* vtkLaplacianDeformationFilter::GetPreviewStillPart()
{
  return this->Internals->Preview.GetStillPart();
}

vtkPolyData* vtkLaplacianDeformationFilter::GetPreviewMovingPart()
{
  return this->Internals->Preview.GetMovingPart();
}

void vtkLaplacianDeformationFilter::ReleasePreview()
{
  this->Internals->Preview.Release();
}

void vtkLaplacianDeformationFilter::WriteEdit(
  vtkPolyData* rest, vtkPolyData* output, const vtkLaplacianOutputEdit* edit)
{
  this->Internals->Writer.Write(
    rest, output, edit, this->GenerateEditRoles != 0, this->RoleColors != 0);
}

vtkIdType vtkLaplacianDeformationFilter::GetNumberOfOutputCopies()
{
  return this->Internals->Writer.GetNumberOfCopies();
}

bool vtkLaplacianDeformationFilter::GetEditState(vtkLaplacianEditState& state) const
{
  const vtkInternals& internals = *this->Internals;
  state.Surface = &internals.Surface;
  state.Normals = &internals.Normals;
  state.Editor = &internals.Solver.GetEditor();
  state.Maps = &internals.Solver.GetMaps();
  state.Solution = &internals.Solver.GetSolution();
  state.ModelVersion = internals.Solver.GetModelVersion();
  return internals.Edited;
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
  vtkLaplacianHandleMaps::MotionTransform(
    this->HandleCenter, this->HandleRotation, this->HandleTranslation)
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
  return this->Internals->Handles.GetGroupCenter(group, center);
}

double* vtkLaplacianDeformationFilter::GetHandleGroupCenter(int group)
{
  if (!this->GetHandleGroupCenter(group, this->ReturnedGroupCenter))
  {
    std::fill_n(this->ReturnedGroupCenter, 3, 0.0);
  }
  return this->ReturnedGroupCenter;
}

int vtkLaplacianDeformationFilter::GetNumberOfHandleGroups()
{
  return this->Internals->Solver.GetEditor().GetRegion().NumberOfHandleGroups;
}


void vtkLaplacianDeformationFilter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  this->PrintRegionProperties(os, indent);
  this->PrintSolverProperties(os, indent);
  os << indent << "Last update:\n";
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
  os << indent << "MergeCoincidentPoints: " << (this->MergeCoincidentPoints ? "On" : "Off") << "\n";
  this->Internals->Handles.PrintSelf(os, indent);
  os << indent << "NumberOfCommits: " << this->Internals->Rest.GetNumberOfCommits() << "\n";
}

void vtkLaplacianDeformationFilter::PrintSolverProperties(ostream& os, vtkIndent indent)
{
  os << indent << "HandleWeight: " << this->HandleWeight << "\n";
  os << indent << "AnchorWeight: " << this->AnchorWeight << "\n";
  os << indent << "LaplacianWeights: "
     << EnumName(this->LaplacianWeights, { "Uniform", "Cotangent" }) << "\n";
  os << indent << "OperatorOrder: " << this->OperatorOrder << "\n";
  os << indent << "RotationMode: "
     << EnumName(this->RotationMode, { "None", "Explicit", "Implicit", "AsRigidAsPossible" }) << "\n";
  os << indent << "NormalSmoothingRadius: " << this->NormalSmoothingRadius << "\n";
  os << indent << "NumberOfIterations: " << this->NumberOfIterations << "\n";
  os << indent << "PreserveDetailScale: " << (this->PreserveDetailScale ? "On" : "Off") << "\n";
  os << indent << "ImplicitFormulation: "
     << EnumName(this->ImplicitFormulation, { "PerEdge", "Paper" }) << "\n";
  os << indent << "ARAPIterations: " << this->ARAPIterations << "\n";
  os << indent << "Dragging: " << (this->Dragging ? "On" : "Off") << "\n";
  os << indent << "DragARAPIterations: " << this->DragARAPIterations << "\n";
  os << indent << "Convergence: " << this->Convergence << "\n";
  os << indent << "Acceleration: " << (this->Acceleration ? "On" : "Off") << "\n";
  os << indent << "Extrapolation: " << (this->Extrapolation ? "On" : "Off") << "\n";
  os << indent << "Solver: " << EnumName(this->Solver, { "CHOLMOD", "SimplicialLDLT", "MUMPS" }) << "\n";
  os << indent << "Ordering: "
     << EnumName(this->Ordering, { "Automatic", "AMD", "METIS", "NestedDissection" }) << "\n";
  os << indent << "MaximumFactorMemory: " << this->MaximumFactorMemory << " MB";
  if (this->MaximumFactorMemory <= 0.0)
  {
    os << " (automatic: " << vtkLaplacianSurfaceAdapter::GetAutomaticFactorLimit() << " MB now)";
  }
  os << "\n";
  os << indent << "GenerateEditRoles: " << (this->GenerateEditRoles ? "On" : "Off") << "\n";
  os << indent << "RoleColors: " << (this->RoleColors ? "On" : "Off") << "\n";
}

void vtkLaplacianDeformationFilter::PrintLastUpdate(ostream& os, vtkIndent next)
{
  os << next << "NumberOfROIVertices: " << this->NumberOfROIVertices << "\n";
  os << next << "NumberOfHandleVertices: " << this->NumberOfHandleVertices << "\n";
  os << next << "TopologyTime: " << this->TopologyTime << " s\n";
  os << next << "SetupTime: " << this->SetupTime << " s (analysis " << this->AnalysisTime
     << " s, factorization " << this->FactorizationTime << " s)\n";
  os << next << "SolveTime: " << this->SolveTime << " s\n";
  os << next << "NumberOfARAPIterations: " << this->NumberOfARAPIterations << "\n";
  os << next << "ARAPEnergy: " << this->ARAPEnergy << "\n";
  os << next << "NumberOfSurfaceVertices: " << this->NumberOfSurfaceVertices << "\n";
  os << next << "FactorMemory: " << this->FactorMemory << " MB\n";
  os << next << "FactoredAcrossProcesses: " << this->FactoredAcrossProcesses << "\n";
  os << next << "NumberOfFactorizations: " << this->NumberOfFactorizations << " (attempted "
     << this->NumberOfFactorizationAttempts << ")\n";
}
