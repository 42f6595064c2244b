#include "vtkLaplacianLandmarkWarp.h"

#include "SparseCholesky.h"
#include "vtkLaplacianEditSolver.h"
#include "vtkLaplacianLandmarkBinder.h"
#include "vtkLaplacianNormalRefresher.h"
#include "vtkLaplacianOutputWriter.h"
#include "vtkLaplacianSurfaceAdapter.h"

#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkErrorCode.h"
#include "vtkFieldData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPointSet.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkStreamingDemandDrivenPipeline.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <sstream>

namespace le = LaplacianEditing;

vtkStandardNewMacro(vtkLaplacianLandmarkWarp);
vtkCxxSetObjectMacro(vtkLaplacianLandmarkWarp, SourceLandmarks, vtkPoints);
vtkCxxSetObjectMacro(vtkLaplacianLandmarkWarp, TargetLandmarks, vtkPoints);

// The warp's enums are the deformation filter's, and so the core's, value for value.
static_assert(static_cast<int>(le::RotationMode::AsRigidAsPossible) ==
    vtkLaplacianLandmarkWarp::ROTATION_AS_RIGID_AS_POSSIBLE &&
  static_cast<int>(le::RotationMode::None) == vtkLaplacianLandmarkWarp::ROTATION_NONE &&
  static_cast<int>(le::LaplacianWeights::Cotangent) == vtkLaplacianLandmarkWarp::WEIGHTS_COTANGENT &&
  static_cast<int>(le::SolverBackend::SimplicialLDLT) == vtkLaplacianLandmarkWarp::SOLVER_SIMPLICIAL_LDLT);

namespace
{
using Clock = std::chrono::steady_clock;

double SecondsSince(Clock::time_point start)
{
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// The pull of an exact fit's soft constraints: strong enough that the corrections converge in
// a few rounds, against the system's stiffness.
constexpr double ExactFitWeight = 100.0;
// An exact fit that ends farther than this fraction of the diagonal from a target warns.
constexpr double UnmetFraction = 1e-8;
}

// The stages of a warp, in the order RequestData runs them.
struct vtkLaplacianLandmarkWarp::vtkInternals
{
  vtkLaplacianSurfaceAdapter Surface;
  vtkLaplacianLandmarkBinder Binder;
  vtkLaplacianEditSolver Solver;
  vtkLaplacianNormalRefresher Normals;
  vtkLaplacianOutputWriter Writer;
  double Diagonal = 0.0;
  // The landmarks of port 1, as vtkPoints.
  vtkNew<vtkPoints> PortTargets;
};

vtkLaplacianLandmarkWarp::vtkLaplacianLandmarkWarp()
  : Internals(new vtkInternals)
{
  if (!le::SparseCholesky::IsAvailable(le::SolverBackend::Cholmod))
  {
    this->Solver = SOLVER_SIMPLICIAL_LDLT;
  }
  this->SetNumberOfInputPorts(2);
  this->SetInputArrayToProcess(0, 1, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, "Target");
  this->Internals->Writer.SetFilter(this);
}

vtkLaplacianLandmarkWarp::~vtkLaplacianLandmarkWarp()
{
  this->SetSourceLandmarks(nullptr);
  this->SetTargetLandmarks(nullptr);
}

void vtkLaplacianLandmarkWarp::SetLandmarksData(vtkDataObject* landmarks)
{
  this->SetInputData(1, landmarks);
}

int vtkLaplacianLandmarkWarp::FillInputPortInformation(int port, vtkInformation* info)
{
  if (port == 1)
  {
    info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPointSet");
    info->Set(vtkAlgorithm::INPUT_IS_OPTIONAL(), 1);
    return 1;
  }
  return this->Superclass::FillInputPortInformation(port, info);
}

vtkMTimeType vtkLaplacianLandmarkWarp::GetMTime()
{
  vtkMTimeType time = this->Superclass::GetMTime();
  for (vtkPoints* points : { this->SourceLandmarks, this->TargetLandmarks })
  {
    time = points ? std::max(time, points->GetMTime()) : time;
  }
  return time;
}

int vtkLaplacianLandmarkWarp::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkPolyData* input = vtkPolyData::GetData(inputVector[0]);
  vtkPolyData* output = vtkPolyData::GetData(outputVector);
  this->SetErrorCode(vtkErrorCode::NoError);
  this->Internals->Solver.ResetFacts();
  this->NumberOfLandmarks = 0;
  this->NumberOfWarpedVertices = 0;
  this->BindingTime = 0.0;
  output->ShallowCopy(input);
  vtkPoints* sources = nullptr;
  vtkPoints* targets = nullptr;
  // A warp needs the whole surface: one piece of a distributed one would tear at its edges.
  const int pieces = outputVector->GetInformationObject(0)->Get(
    vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_PIECES());
  if (pieces > 1)
  {
    this->Check("The warp needs the whole surface and was asked for one of " +
      std::to_string(pieces) + " pieces; run it in a serial session (the built-in server, or "
      "one process)");
    return 1;
  }
  // Each stage reports its own error; the output stays the input.
  if (!this->Check(vtkLaplacianSurfaceAdapter::CheckSurface(input)) ||
    !this->FindLandmarks(sources, targets))
  {
    return 1;
  }
  this->UpdateProgress(0.1);
  if (!this->UpdateSurface(input) || this->GetAbortExecute())
  {
    return 1;
  }
  this->UpdateProgress(0.3);
  if (!this->BindLandmarks(sources) || this->GetAbortExecute())
  {
    return 1;
  }
  this->UpdateProgress(0.4);
  if (!this->UpdateSystem(input) || this->GetAbortExecute())
  {
    return 1;
  }
  this->UpdateProgress(0.8);
  if (this->Solve(targets))
  {
    this->WriteOutput(input, output, targets);
  }
  this->UpdateProgress(1.0);
  return 1;
}

bool vtkLaplacianLandmarkWarp::Check(const std::string& error)
{
  if (error.empty())
  {
    return true;
  }
  vtkErrorMacro(<< error);
  this->SetErrorCode(vtkErrorCode::UserError);
  return false;
}

bool vtkLaplacianLandmarkWarp::FindLandmarks(vtkPoints*& sources, vtkPoints*& targets)
{
  if (auto* landmarks = vtkPointSet::SafeDownCast(this->GetInputDataObject(1, 0)))
  {
    // Port 1: its points, and the targets' array.
    sources = landmarks->GetPoints();
    vtkDataArray* array = this->GetInputArrayToProcess(0, landmarks);
    if (!sources || !array || array->GetNumberOfComponents() != 3)
    {
      return this->Check("The landmarks on input port 1 need points (the sources) and a point "
                        "array of three components holding the targets (\"Target\" unless "
                        "SetInputArrayToProcess names another).");
    }
    this->Internals->PortTargets->SetData(array);
    targets = this->Internals->PortTargets;
  }
  else
  {
    sources = this->SourceLandmarks;
    targets = this->TargetLandmarks;
  }
  if (!sources || !targets || sources->GetNumberOfPoints() == 0)
  {
    return this->Check("No landmarks: SetSourceLandmarks and SetTargetLandmarks, or connect a "
                      "point set with a Target point array to input port 1.");
  }
  if (sources->GetNumberOfPoints() != targets->GetNumberOfPoints())
  {
    std::ostringstream message;
    message << "There are " << sources->GetNumberOfPoints() << " source landmarks and "
            << targets->GetNumberOfPoints() << " targets: give each source landmark one target.";
    return this->Check(message.str());
  }
  this->NumberOfLandmarks = static_cast<int>(sources->GetNumberOfPoints());
  return true;
}

bool vtkLaplacianLandmarkWarp::UpdateSurface(vtkPolyData* input)
{
  vtkInternals& internals = *this->Internals;
  internals.Diagonal = input->GetLength();
  bool rebuilt = false;
  const std::string error = internals.Surface.Update(
    input, this->MergeCoincidentPoints != 0, vtkLaplacianSurfaceAdapter::Reach(), rebuilt);
  if (rebuilt)
  {
    internals.Solver.SetMesh(internals.Surface.GetMesh());
  }
  return this->Check(error);
}

bool vtkLaplacianLandmarkWarp::BindLandmarks(vtkPoints* sources)
{
  vtkInternals& internals = *this->Internals;
  const Clock::time_point start = Clock::now();
  bool rebound = false;
  if (!this->Check(internals.Binder.Update(
        sources, internals.Surface, this->MaximumBindingDistance * internals.Diagonal, rebound)))
  {
    return false;
  }
  if (!rebound)
  {
    return true;
  }
  this->BindingTime = SecondsSince(start);
  const std::vector<double>& distances = internals.Binder.GetDistances();
  const double tolerance = this->BindingTolerance * internals.Diagonal;
  const auto farthest = std::max_element(distances.begin(), distances.end());
  const auto far = std::count_if(
    distances.begin(), distances.end(), [tolerance](double d) { return d > tolerance; });
  if (far > 0)
  {
    vtkWarningMacro(<< far << " source landmark(s) lie farther from the surface than "
                    << "BindingTolerance (" << this->BindingTolerance
                    << " of the diagonal), the farthest, landmark " << (farthest - distances.begin())
                    << ", " << *farthest << " away. Each is bound to the nearest surface point, "
                    << "which moves by the landmark's displacement.");
  }
  return true;
}

vtkLaplacianSolverOptions vtkLaplacianLandmarkWarp::SolverOptions() const
{
  const vtkInternals& internals = *this->Internals;
  vtkLaplacianSolverOptions options;
  options.LaplacianWeights = this->LaplacianWeights;
  options.Solver = this->Solver;
  options.RotationMode = this->RotationMode;
  options.NormalSmoothingRadius =
    this->NormalSmoothingRadius * internals.Diagonal * internals.Surface.GetScale();
  options.NumberOfIterations = this->NumberOfIterations;
  options.PreserveDetailScale = this->PreserveDetailScale != 0;
  options.ARAPIterations =
    this->Dragging ? std::min(this->DragARAPIterations, this->ARAPIterations) : this->ARAPIterations;
  options.Convergence = this->Convergence;
  options.Points = internals.Binder.GetPoints();
  options.PointsVersion = internals.Binder.GetVersion();
  options.PointWeight = this->ExactFit ? ExactFitWeight : this->LandmarkWeight;
  options.Bending = this->BendingWeight;
  return options;
}

bool vtkLaplacianLandmarkWarp::UpdateSystem(vtkPolyData* input)
{
  vtkInternals& internals = *this->Internals;
  le::RegionRequest request;
  request.Selection = le::RegionRequest::Kind::Components;
  request.Seeds = internals.Binder.GetSeeds();
  const vtkLaplacianSolverOptions options = this->SolverOptions();
  unsigned rebuilt = le::RebuiltNothing;
  const std::string error = internals.Solver.UpdateRegion(
    request, [] { return std::vector<int>(); }, options, rebuilt);
  this->NumberOfFactorizations = internals.Solver.GetEditor().GetNumberOfFactorizations();
  if (!this->Check(error))
  {
    return false;
  }
  if (rebuilt != le::RebuiltNothing)
  {
    internals.Surface.IndexRegion(internals.Solver.GetEditor().GetRegion());
    internals.Normals.Index(input, internals.Surface);
  }
  const bool ok = this->Check(internals.Solver.UpdateRotationModel(options, this));
  this->NumberOfFactorizations = internals.Solver.GetEditor().GetNumberOfFactorizations();
  this->NumberOfWarpedVertices = internals.Solver.GetEditor().GetRegion().GetNumberOfVertices();
  return ok;
}

bool vtkLaplacianLandmarkWarp::Solve(vtkPoints* targets)
{
  vtkInternals& internals = *this->Internals;
  le::PointTargets points;
  points.Exact = this->ExactFit != 0;
  if (!this->Check(internals.Binder.Targets(targets, internals.Surface, points)))
  {
    return false;
  }
  if (!this->Check(internals.Solver.Solve({}, &points)))
  {
    return false;
  }
  const vtkLaplacianEditSolver::Facts& facts = internals.Solver.GetFacts();
  this->SetupTime = facts.SetupTime;
  this->SolveTime = facts.SolveTime;
  this->NumberOfARAPIterations = facts.NumberOfARAPIterations;
  this->ARAPEnergy = facts.ARAPEnergy;
  // The core's miss, in fractions of the diagonal and in double precision (the output's float
  // points would add their rounding).
  if (this->ExactFit && !this->Dragging && facts.LargestPointMiss > UnmetFraction)
  {
    vtkWarningMacro(<< "The landmarks cannot all be met: the farthest ends "
                    << facts.LargestPointMiss << " of the diagonal from its target. A triangle "
                    << "moves affinely, so where more landmarks than corners share a few "
                    << "triangles they are fit in the least-squares sense; use fewer landmarks "
                    << "there, a finer mesh, or a soft fit (ExactFitOff).");
  }
  return true;
}

void vtkLaplacianLandmarkWarp::WriteOutput(vtkPolyData* input, vtkPolyData* output, vtkPoints* targets)
{
  vtkInternals& internals = *this->Internals;
  const Clock::time_point start = Clock::now();
  const le::Positions& solution = internals.Solver.GetSolution();
  const vtkLaplacianOutputEdit edit = internals.Surface.GetEdit(
    solution, &internals.Normals, internals.Solver.GetModelVersion());
  internals.Writer.Write(input, output, &edit, false, false);
  vtkNew<vtkDoubleArray> misses;
  misses->SetName("LandmarkDistance");
  internals.Binder.Misses(output->GetPoints(), internals.Surface, targets, misses);
  output->GetFieldData()->AddArray(misses);
  double largest = 0.0, squares = 0.0;
  for (vtkIdType i = 0; i < misses->GetNumberOfTuples(); ++i)
  {
    largest = std::max(largest, misses->GetValue(i));
    squares += misses->GetValue(i) * misses->GetValue(i);
  }
  this->MaximumLandmarkDistance = largest;
  this->RMSLandmarkDistance = std::sqrt(squares / std::max<vtkIdType>(misses->GetNumberOfTuples(), 1));
  this->SolveTime += SecondsSince(start);
}

void vtkLaplacianLandmarkWarp::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "SourceLandmarks: " << this->SourceLandmarks << "\n";
  os << indent << "TargetLandmarks: " << this->TargetLandmarks << "\n";
  os << indent << "RotationMode: " << this->RotationMode << "\n";
  os << indent << "LaplacianWeights: " << this->LaplacianWeights << "\n";
  os << indent << "ExactFit: " << (this->ExactFit ? "On" : "Off") << "\n";
  os << indent << "LandmarkWeight: " << this->LandmarkWeight << "\n";
  os << indent << "BendingWeight: " << this->BendingWeight << "\n";
  os << indent << "ARAPIterations: " << this->ARAPIterations << "\n";
  os << indent << "Convergence: " << this->Convergence << "\n";
  os << indent << "Dragging: " << (this->Dragging ? "On" : "Off") << "\n";
  os << indent << "DragARAPIterations: " << this->DragARAPIterations << "\n";
  os << indent << "NormalSmoothingRadius: " << this->NormalSmoothingRadius << "\n";
  os << indent << "NumberOfIterations: " << this->NumberOfIterations << "\n";
  os << indent << "PreserveDetailScale: " << (this->PreserveDetailScale ? "On" : "Off") << "\n";
  os << indent << "BindingTolerance: " << this->BindingTolerance << "\n";
  os << indent << "MaximumBindingDistance: " << this->MaximumBindingDistance << "\n";
  os << indent << "MergeCoincidentPoints: " << (this->MergeCoincidentPoints ? "On" : "Off") << "\n";
  os << indent << "Solver: " << this->Solver << "\n";
  os << indent << "NumberOfLandmarks: " << this->NumberOfLandmarks << "\n";
  os << indent << "NumberOfWarpedVertices: " << this->NumberOfWarpedVertices << "\n";
  os << indent << "NumberOfFactorizations: " << this->NumberOfFactorizations << "\n";
  os << indent << "NumberOfARAPIterations: " << this->NumberOfARAPIterations << "\n";
  os << indent << "ARAPEnergy: " << this->ARAPEnergy << "\n";
  os << indent << "MaximumLandmarkDistance: " << this->MaximumLandmarkDistance << "\n";
  os << indent << "RMSLandmarkDistance: " << this->RMSLandmarkDistance << "\n";
  os << indent << "BindingTime: " << this->BindingTime << "\n";
  os << indent << "SetupTime: " << this->SetupTime << "\n";
  os << indent << "SolveTime: " << this->SolveTime << "\n";
}
