#include "vtkLaplacianEditSolver.h"

#include "vtkLaplacianSurfaceAdapter.h"

#include "vtkObject.h"
#include "vtkSMP.h"
#include "vtkSMPTools.h"
#include "vtkVersionMacros.h"

#include <chrono>
#include <cstring>

namespace le = LaplacianEditing;

namespace
{
using Clock = std::chrono::steady_clock;

double SecondsSince(Clock::time_point start)
{
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// The filters' enums are the core's, value for value (static_asserts in the filter).
le::DeformationOptions SystemOptions(const vtkLaplacianEditSolver::Options& options, double availableMemory)
{
  le::DeformationOptions system;
  system.Weights = static_cast<le::LaplacianWeights>(options.LaplacianWeights);
  system.Order = options.OperatorOrder;
  system.HandleWeight = options.HandleWeight;
  system.AnchorWeight = options.AnchorWeight;
  system.Backend = static_cast<le::SolverBackend>(options.Solver);
  system.Ordering = static_cast<le::FillOrdering>(options.Ordering);
  system.LeastSquares = options.RotationMode != static_cast<int>(le::RotationMode::AsRigidAsPossible);
  system.MaximumFactorBytes = 1048576.0 *
    (options.MaximumFactorMemory > 0.0 ? options.MaximumFactorMemory : availableMemory);
  system.Distributed = options.Distributed;
  system.Points = options.Points;
  system.PointsVersion = options.PointsVersion;
  system.PointWeight = options.PointWeight;
  system.Bending = options.Bending;
  return system;
}

le::RotationOptions RotationOptions(const vtkLaplacianEditSolver::Options& options, double regionRadius)
{
  le::RotationOptions rotation;
  rotation.Mode = static_cast<le::RotationMode>(options.RotationMode);
  rotation.NormalSmoothingRadius =
    options.NormalSmoothingRadius > 0.0 ? options.NormalSmoothingRadius : 0.2 * regionRadius;
  rotation.Iterations = options.NumberOfIterations;
  rotation.PreserveDetailScale = options.PreserveDetailScale;
  const bool paper = options.ImplicitFormulation == 1;
  rotation.Formulation.PerEdge = !paper;
  rotation.Formulation.AllowScaling = paper;
  rotation.Arap.MaximumIterations = options.ARAPIterations;
  rotation.Arap.Tolerance = options.Convergence;
  rotation.Arap.Accelerate = options.Acceleration;
  rotation.Arap.Extrapolate = options.Extrapolation;
  return rotation;
}
}

vtkLaplacianEditSolver::vtkLaplacianEditSolver()
{
  // The core's per-move loops run on VTK's SMP backend. ParaView's VTK runs it on one thread
  // unless told otherwise (VTK_SMP_BACKEND_IN_USE): the core's loops take VTK's thread pool
  // there, which halves an ARAP drag's frame on two cores.
  this->Editor.SetParallelFor([](int begin, int end, const std::function<void(int, int)>& body) {
    auto run = [&] { vtkSMPTools::For(begin, end, [&](int first, int last) { body(first, last); }); };
#if VTK_SMP_ENABLE_STDTHREAD && VTK_VERSION_NUMBER >= VTK_VERSION_CHECK(9, 2, 0)
    if (std::strcmp(vtkSMPTools::GetBackend(), "Sequential") == 0)
    {
      vtkSMPTools::LocalScope(vtkSMPTools::Config{ std::string("STDThread") }, run);
      return;
    }
#endif
    run();
  });
}

void vtkLaplacianEditSolver::SetMesh(std::shared_ptr<const le::SurfaceMesh> mesh)
{
  this->Editor.SetMesh(std::move(mesh));
  this->AvailableMemory = vtkLaplacianSurfaceAdapter::GetAutomaticFactorLimit();
}

std::string vtkLaplacianEditSolver::UpdateRegion(const le::RegionRequest& region,
  const std::function<std::vector<int>()>& labels, const Options& options, unsigned& rebuilt)
{
  rebuilt = le::RebuiltNothing;
  if (options.Solver == static_cast<int>(le::SolverBackend::Distributed) && !options.Distributed)
  {
    return "The MUMPS solver factors across MPI processes: it needs "
           "vtkPLaplacianDeformationFilter in an MPI run, in a build with MUMPS. Use CHOLMOD or "
           "SimplicialLDLT here.";
  }
  const Clock::time_point start = Clock::now();
  const le::EditStatus status =
    this->Editor.UpdateRegion(region, labels, SystemOptions(options, this->AvailableMemory));
  if (!status.Ok())
  {
    return "Cannot edit: " + status.Error + ".";
  }
  rebuilt = status.Work;
  if (status.Work != le::RebuiltNothing)
  {
    ++this->ModelVersion;
    this->LastFacts.SetupTime = SecondsSince(start);
  }
  return {};
}

std::string vtkLaplacianEditSolver::UpdateRotationModel(const Options& options, vtkObject* reporter)
{
  this->RotationMode = static_cast<le::RotationMode>(options.RotationMode);
  const Clock::time_point start = Clock::now();
  const le::EditStatus status =
    this->Editor.UpdateRotationModel(RotationOptions(options, this->Editor.GetRegion().Radius));
  if (!status.Ok())
  {
    return "Cannot edit: " + status.Error + ".";
  }
  Facts& facts = this->LastFacts;
  if (status.Work != le::RebuiltNothing)
  {
    ++this->ModelVersion;
    facts.SetupTime += SecondsSince(start);
    const bool firstOrderEnergy =
      options.RotationMode == static_cast<int>(le::RotationMode::AsRigidAsPossible) ||
      (options.RotationMode == static_cast<int>(le::RotationMode::Implicit) &&
        options.ImplicitFormulation == 0);
    if (options.OperatorOrder == 2 && firstOrderEnergy)
    {
      vtkWarningWithObjectMacro(reporter, << "OperatorOrder 2 has no effect in this rotation "
        << "mode: its energy compares one-ring edges, a first-order measure. The bi-Laplacian "
        << "applies in the None and Explicit modes and in the Paper implicit formulation.");
    }
  }
  if (facts.SetupTime > 0.0)
  {
    facts.AnalysisTime = this->Editor.GetAnalysisSeconds();
    facts.FactorizationTime = this->Editor.GetFactorizationSeconds();
  }
  return {};
}

std::string vtkLaplacianEditSolver::Solve(
  const std::vector<le::AffineMap>& maps, const le::PointTargets* points)
{
  this->Maps = maps;
  const Clock::time_point start = Clock::now();
  const le::EditStatus status = this->Editor.Solve(this->Maps, this->Solution, points);
  Facts& facts = this->LastFacts;
  facts.SolveTime = SecondsSince(start);
  facts.LargestPointMiss = this->Editor.GetLargestPointMiss();
  if (this->RotationMode == le::RotationMode::AsRigidAsPossible)
  {
    facts.NumberOfARAPIterations = this->Editor.GetLastArapResult().Iterations;
    facts.ARAPEnergy = this->Editor.GetLastArapResult().Energy;
  }
  return status.Ok() ? std::string() : "Cannot edit: " + status.Error + ".";
}
