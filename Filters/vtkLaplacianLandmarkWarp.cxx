#include "vtkLaplacianLandmarkWarp.h"

#include "EditPipeline.h"
#include "LandmarkPairs.h"
#include "LandmarkSource.h"

#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPointSet.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkUnstructuredGrid.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <vector>
#include <sstream>

namespace le = LaplacianEditing;
namespace lep = LaplacianEditing::Pipeline;

vtkStandardNewMacro(vtkLaplacianLandmarkWarp);
vtkCxxSetObjectMacro(vtkLaplacianLandmarkWarp, SourceLandmarks, vtkPoints);
vtkCxxSetObjectMacro(vtkLaplacianLandmarkWarp, TargetLandmarks, vtkPoints);

namespace
{
// The pull of an exact fit's soft constraints: strong enough that the corrections converge in
// a few rounds, against the system's stiffness.
constexpr double ExactFitWeight = 100.0;
// An exact fit that ends farther than this fraction of the diagonal from a target warns.
constexpr double UnmetFraction = 1e-8;
// The explicit mode's automatic support, a fraction of the diagonal.
constexpr double AutomaticSmoothingFraction = 0.05;
}

// Where the warp's edits come from (the landmarks), the pipeline that runs them, and the
// targets of port 1 as vtkPoints.
struct vtkLaplacianLandmarkWarp::vtkInternals
{
  explicit vtkInternals(vtkLaplacianLandmarkWarp* warp)
    : Source(warp)
    , Pipeline(warp->GetEditPipeline())
  {
  }

  lep::LandmarkSource Source;
  lep::EditPipeline& Pipeline; // vtkLaplacianEditFilter's
  vtkNew<vtkPoints> PortTargets;
  // Ports 1 and 2's landmarks, paired.
  vtkNew<vtkPoints> PairedSources;
  vtkNew<vtkPoints> PairedTargets;
  // Targets moved in place of the given ones, and the targets with them.
  std::map<vtkIdType, std::array<double, 3>> MovedTargets;
  vtkNew<vtkPoints> EditedTargets;
  // The last update's targets.
  vtkNew<vtkDoubleArray> WarpedTargets;
  // A volume mesh's boundary surface as warped.
  vtkNew<vtkPolyData> WarpedBoundary;
};

vtkLaplacianLandmarkWarp::vtkLaplacianLandmarkWarp()
  : Internals(new vtkInternals(this))
{
  // A warp's defaults: it solves to convergence at once, where an edit is dragged.
  this->RotationMode = ROTATION_AS_RIGID_AS_POSSIBLE;
  this->LaplacianWeights = WEIGHTS_COTANGENT;
  this->ARAPIterations = 100;
  this->Convergence = 1e-4;
  this->SetNumberOfInputPorts(3);
  this->SetInputArrayToProcess(0, 1, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, "Target");
  this->Internals->EditedTargets->SetDataTypeToDouble();
  this->Internals->WarpedTargets->SetNumberOfComponents(3);
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

void vtkLaplacianLandmarkWarp::SetTargetLandmarksData(vtkDataObject* targets)
{
  this->SetInputData(2, targets);
}

void vtkLaplacianLandmarkWarp::SetMovedTarget(vtkIdType landmark, double x, double y, double z)
{
  const std::array<double, 3> target = { { x, y, z } };
  auto& moved = this->Internals->MovedTargets;
  const auto found = moved.find(landmark);
  if (found == moved.end() || found->second != target)
  {
    moved[landmark] = target;
    this->Modified();
  }
}

int vtkLaplacianLandmarkWarp::GetNumberOfMovedTargets()
{
  return static_cast<int>(this->Internals->MovedTargets.size());
}

void vtkLaplacianLandmarkWarp::RemoveAllMovedTargets()
{
  if (!this->Internals->MovedTargets.empty())
  {
    this->Internals->MovedTargets.clear();
    this->Modified();
  }
}

vtkDoubleArray* vtkLaplacianLandmarkWarp::GetWarpedTargets()
{
  return this->Internals->WarpedTargets;
}

vtkPoints* vtkLaplacianLandmarkWarp::MoveTargets(vtkPoints* targets)
{
  const auto& moved = this->Internals->MovedTargets;
  if (moved.empty())
  {
    return targets;
  }
  vtkPoints* edited = this->Internals->EditedTargets;
  edited->GetData()->DeepCopy(targets->GetData());
  const vtkIdType count = targets->GetNumberOfPoints();
  for (const auto& target : moved)
  {
    if (target.first >= 0 && target.first < count)
    {
      edited->SetPoint(target.first, target.second.data());
    }
    else if (!this->Dragging)
    {
      vtkWarningMacro(<< "A moved target names landmark " << target.first << ", and there are "
                      << count << " landmarks: it is left out (RemoveAllMovedTargets forgets it).");
    }
  }
  edited->Modified();
  return edited;
}

int vtkLaplacianLandmarkWarp::FillInputPortInformation(int port, vtkInformation* info)
{
  if (port > 0)
  {
    info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPointSet");
    info->Set(vtkAlgorithm::INPUT_IS_OPTIONAL(), 1);
    return 1;
  }
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPolyData");
  info->Append(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkUnstructuredGrid");
  return 1;
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
  vtkPointSet* input = vtkPointSet::GetData(inputVector[0]);
  vtkPointSet* output = vtkPointSet::GetData(outputVector);
  lep::EditPipeline& pipeline = this->Internals->Pipeline;
  pipeline.BeginUpdate();
  this->NumberOfLandmarks = 0;
  output->ShallowCopy(input);
  // A warp needs the whole surface: one piece of a distributed one would tear at its edges.
  const int pieces = outputVector->GetInformationObject(0)->Get(
    vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_PIECES());
  if (pieces > 1)
  {
    pipeline.Check("The warp needs the whole surface and was asked for one of " +
      std::to_string(pieces) + " pieces; run it in a serial session (the built-in server, or "
      "one process)");
    return 1;
  }
  // A volume mesh warps through its boundary surface.
  auto* grid = vtkUnstructuredGrid::SafeDownCast(input);
  vtkPolyData* surface = grid ? this->VolumeBoundary(grid) : vtkPolyData::SafeDownCast(input);
  vtkPolyData* warped = grid ? this->Internals->WarpedBoundary.Get() : vtkPolyData::SafeDownCast(output);
  vtkPoints* sources = nullptr;
  vtkPoints* targets = nullptr;
  if (!surface || !pipeline.Check(lep::SurfaceAdapter::CheckSurface(surface)) ||
    !this->FindLandmarks(sources, targets))
  {
    return 1;
  }
  warped->ShallowCopy(surface);
  const double diagonal = surface->GetLength();
  lep::LandmarkSource& source = this->Internals->Source;
  source.Sources = sources;
  source.Targets = targets;
  source.Tolerance = this->BindingTolerance * diagonal;
  source.MaximumDistance = this->MaximumBindingDistance * diagonal;
  source.Exact = this->ExactFit != 0;
  source.Weight = this->ExactFit ? ExactFitWeight : this->LandmarkWeight;
  source.FollowUnreferenced = !grid; // a grid's interior follows its own way
  lep::OutputOptions outputs;
  outputs.Displacement = this->OutputDisplacement && !grid; // a grid's comes from its follower
  if (pipeline.Run(
        surface, warped, source, this->Settings(diagonal), this->MergeCoincidentPoints != 0, outputs))
  {
    this->ReportFit(warped, targets);
    if (grid &&
      this->FollowBoundary(warped->GetPoints(), vtkUnstructuredGrid::SafeDownCast(output), 0.9, 1.0))
    {
      output->GetFieldData()->AddArray(warped->GetFieldData()->GetArray("LandmarkDistance"));
    }
  }
  return 1;
}

bool vtkLaplacianLandmarkWarp::FindLandmarks(vtkPoints*& sources, vtkPoints*& targets)
{
  lep::EditPipeline& pipeline = this->Internals->Pipeline;
  auto* pairedTargets = vtkPointSet::SafeDownCast(this->GetInputDataObject(2, 0));
  if (auto* landmarks = vtkPointSet::SafeDownCast(this->GetInputDataObject(1, 0)); pairedTargets)
  {
    if (!landmarks)
    {
      return pipeline.Check("Target landmarks on input port 2 need the source landmarks on input "
                            "port 1.");
    }
    if (!pipeline.Check(lep::PairLandmarks(landmarks, pairedTargets,
          this->Internals->PairedSources, this->Internals->PairedTargets)))
    {
      return false;
    }
    sources = this->Internals->PairedSources;
    targets = this->Internals->PairedTargets;
  }
  else if (landmarks)
  {
    // Port 1: its points, and the targets' array.
    sources = landmarks->GetPoints();
    vtkDataArray* array = this->GetInputArrayToProcess(0, landmarks);
    if (!sources || !array || array->GetNumberOfComponents() != 3)
    {
      return pipeline.Check("The landmarks on input port 1 need points (the sources) and a "
                            "point array of three components holding the targets (\"Target\" "
                            "unless SetInputArrayToProcess names another).");
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
    return pipeline.Check("No landmarks: SetSourceLandmarks and SetTargetLandmarks, or connect "
                          "a point set with a Target point array to input port 1.");
  }
  if (sources->GetNumberOfPoints() != targets->GetNumberOfPoints())
  {
    std::ostringstream message;
    message << "There are " << sources->GetNumberOfPoints() << " source landmarks and "
            << targets->GetNumberOfPoints() << " targets: give each source landmark one target.";
    return pipeline.Check(message.str());
  }
  this->NumberOfLandmarks = static_cast<int>(sources->GetNumberOfPoints());
  targets = this->MoveTargets(targets);
  this->Internals->WarpedTargets->DeepCopy(targets->GetData());
  return true;
}

lep::SolverSettings vtkLaplacianLandmarkWarp::Settings(double diagonal) const
{
  lep::SolverSettings settings = this->SharedSettings();
  settings.NormalSmoothingRadius = this->NormalSmoothingRadius > 0.0
    ? this->NormalSmoothingRadius
    : AutomaticSmoothingFraction * diagonal;
  settings.Bending = this->BendingWeight;
  settings.SplinePrior = this->SplinePriorWeight;
  return settings;
}

void vtkLaplacianLandmarkWarp::ReportFit(vtkPolyData* output, vtkPoints* targets)
{
  // The core's miss, in fractions of the diagonal and in double precision (the output's float
  // points would add their rounding).
  const double miss = this->Internals->Pipeline.GetFacts().LargestPointMiss;
  if (this->ExactFit && !this->Dragging && miss > UnmetFraction)
  {
    vtkWarningMacro(<< "The landmarks cannot all be met: the farthest ends " << miss
                    << " of the diagonal from its target. A triangle moves affinely, so where "
                    << "more landmarks than corners share a few triangles they are fit in the "
                    << "least-squares sense; use fewer landmarks there, a finer mesh, or a soft "
                    << "fit (ExactFitOff).");
  }
  vtkNew<vtkDoubleArray> misses;
  misses->SetName("LandmarkDistance");
  this->Internals->Source.GetBinder().Misses(
    output->GetPoints(), this->Internals->Pipeline.GetSurface(), targets, misses);
  output->GetFieldData()->AddArray(misses);
  double largest = 0.0, squares = 0.0;
  for (vtkIdType i = 0; i < misses->GetNumberOfTuples(); ++i)
  {
    largest = std::max(largest, misses->GetValue(i));
    squares += misses->GetValue(i) * misses->GetValue(i);
  }
  this->MaximumLandmarkDistance = largest;
  this->RMSLandmarkDistance =
    std::sqrt(squares / std::max<vtkIdType>(misses->GetNumberOfTuples(), 1));
}

int vtkLaplacianLandmarkWarp::GetNumberOfWarpedVertices()
{
  return this->Internals->Pipeline.GetEditor().GetRegion().GetNumberOfVertices();
}

double vtkLaplacianLandmarkWarp::GetBindingTime()
{
  return this->Internals->Source.GetBindingTime();
}

void vtkLaplacianLandmarkWarp::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "SourceLandmarks: " << this->SourceLandmarks << "\n";
  os << indent << "TargetLandmarks: " << this->TargetLandmarks << "\n";
  os << indent << "NumberOfMovedTargets: " << this->Internals->MovedTargets.size() << "\n";
  os << indent << "BindingTolerance: " << this->BindingTolerance << "\n";
  os << indent << "MaximumBindingDistance: " << this->MaximumBindingDistance << "\n";
  os << indent << "ExactFit: " << (this->ExactFit ? "On" : "Off") << "\n";
  os << indent << "LandmarkWeight: " << this->LandmarkWeight << "\n";
  os << indent << "BendingWeight: " << this->BendingWeight << "\n";
  os << indent << "SplinePriorWeight: " << this->SplinePriorWeight << "\n";
  os << indent << "NumberOfLandmarks: " << this->NumberOfLandmarks << "\n";
  os << indent << "NumberOfWarpedVertices: " << this->GetNumberOfWarpedVertices() << "\n";
  os << indent << "MaximumLandmarkDistance: " << this->MaximumLandmarkDistance << "\n";
  os << indent << "RMSLandmarkDistance: " << this->RMSLandmarkDistance << "\n";
  os << indent << "BindingTime: " << this->GetBindingTime() << "\n";
}
