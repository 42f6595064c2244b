#include "EditPipeline.h"

#include "SMPFor.h"
#include "Stopwatch.h"

#include "vtkAlgorithm.h"
#include "vtkErrorCode.h"
#include "vtkPolyData.h"

#include <algorithm>

namespace LaplacianEditing
{
namespace Pipeline
{
EditPipeline::EditPipeline(vtkAlgorithm* filter, std::function<void(unsigned long)> setErrorCode)
  : Filter(filter)
  , SetErrorCode(std::move(setErrorCode))
{
  this->Writer.SetFilter(filter);
  this->Editor.SetParallelFor(SMPFor);
  // A settle's iterations report their progress, and an abort ends them at the last shape:
  // that is the output, a valid edit, and the next update continues from it. The flag is read
  // after the event too, where an observer of the event sets it.
  // A time limit ends them the same way, and the next update continues them (IsSettling).
  this->Editor.SetProgress([this](double done) {
    const int iterations = this->Solving.ARAPIterations;
    const double settled =
      (this->SettleIterations + done * iterations) / std::max(1, this->SettleIterations + iterations);
    if (this->Aborted(0.9 + 0.1 * settled) || this->Filter->GetAbortExecute())
    {
      return false;
    }
    const double limit = this->Solving.TimeLimit;
    this->OutOfTime = limit > 0.0 && this->SolveClock.Seconds() >= limit;
    return !this->OutOfTime;
  });
}

void EditPipeline::BeginUpdate()
{
  this->SetErrorCode(vtkErrorCode::NoError);
  const int surfaceVertices = this->LastFacts.NumberOfSurfaceVertices;
  this->LastFacts = Facts();
  this->LastFacts.NumberOfSurfaceVertices = surfaceVertices;
  this->Solved = false;
  this->Previewed = false;
  this->SetProgressSpan(0.0, 1.0);
}

void EditPipeline::SetProgressSpan(double start, double end)
{
  this->ProgressStart = start;
  this->ProgressEnd = end;
}

void EditPipeline::ReportProgress(double progress)
{
  this->Filter->UpdateProgress(
    this->ProgressStart + progress * (this->ProgressEnd - this->ProgressStart));
}

bool EditPipeline::Check(const std::string& error)
{
  if (error.empty())
  {
    return true;
  }
  vtkErrorWithObjectMacro(this->Filter, << error);
  this->SetErrorCode(vtkErrorCode::UserError);
  return false;
}

bool EditPipeline::Aborted(double progress)
{
  if (this->Filter->GetAbortExecute())
  {
    return true;
  }
  this->ReportProgress(progress);
  return false;
}

bool EditPipeline::Run(vtkPolyData* rest, vtkPolyData* output, EditSource& source,
  const SolverSettings& settings, bool merge, const OutputOptions& options)
{
  // Progress after each step that may take seconds (graph, region and its factor, rotation
  // model and its factor); the abort flag is read between them.
  this->ReportProgress(0.1);
  if (!this->UpdateSurface(rest, source.ComputeReach(rest), merge) || this->Aborted(0.3) ||
    !this->UpdateRegion(rest, source, settings) || this->Aborted(0.6))
  {
    return false;
  }
  EditMotions motions;
  if (!this->Check(source.ChooseMotions(this->Surface, this->Editor.GetRegion(), motions)))
  {
    return false;
  }
  SolverSettings update = this->ContinueSettle(settings, motions);
  const std::uint64_t version = this->ModelVersion;
  bool ready = this->UpdateRotationModel(update);
  if (ready && update.Continue && this->ModelVersion != version)
  {
    this->Unfinished = Continuation(); // the model was rebuilt: its settle starts afresh
    update = this->ContinueSettle(settings, motions);
    ready = this->UpdateRotationModel(update);
  }
  this->SettleIterations = update.Continue ? std::max(0, settings.ARAPIterations - update.ARAPIterations) : 0;
  this->Unfinished = Continuation();
  this->Settle = false;
  if (!ready || this->Aborted(0.9))
  {
    return false;
  }
  this->Solved = this->Solve(motions, update);
  const ArapResult& result = this->Editor.GetLastArapResult();
  if (this->Solved && this->OutOfTime && !result.Converged && result.Iterations < update.ARAPIterations)
  {
    this->Unfinished = Continuation{ update.ARAPIterations - result.Iterations, update.Settle,
      std::move(motions), this->ModelVersion };
  }
  if (this->Solved && output)
  {
    const Stopwatch watch;
    const OutputEdit edit = this->GetEdit();
    this->Write(rest, output, &edit, options);
    this->LastFacts.SolveTime += watch.Seconds();
  }
  this->ReportProgress(1.0);
  return this->Solved;
}

bool EditPipeline::UpdateSurface(vtkPolyData* rest, const Reach& reach, bool merge)
{
  const Stopwatch watch;
  bool rebuilt = false;
  const std::string error = this->Surface.Update(rest, merge, reach, rebuilt);
  if (rebuilt)
  {
    // The limit is taken once per surface, so that a move never refactors for it.
    this->Editor.SetMesh(this->Surface.GetMesh());
    this->AvailableMemory = SolverSettings::AutomaticFactorLimit();
    ++this->ModelVersion;
  }
  if (!this->Check(error))
  {
    return false;
  }
  if (rebuilt)
  {
    this->LastFacts.NumberOfSurfaceVertices = this->Surface.GetMesh()->GetNumberOfVertices();
    this->LastFacts.TopologyTime = watch.Seconds();
  }
  return true;
}

bool EditPipeline::UpdateRegion(vtkPolyData* rest, EditSource& source, const SolverSettings& settings)
{
  if (settings.Solver == static_cast<int>(SolverBackend::Distributed) && !settings.Distributed)
  {
    return this->Check("The MUMPS solver factors across MPI processes: it needs "
                       "vtkPLaplacianDeformationFilter in an MPI run, in a build with MUMPS. Use "
                       "CHOLMOD or SimplicialLDLT here.");
  }
  RegionChoice choice;
  if (!this->Check(source.ChooseRegion(rest, this->Surface, choice)))
  {
    return false;
  }
  DeformationOptions system = settings.System(this->AvailableMemory);
  system.Points = choice.Points;
  system.PointsVersion = choice.PointsVersion;
  system.PointWeight = choice.PointWeight;
  const Stopwatch watch;
  const EditStatus status = this->Editor.UpdateRegion(choice.Request, choice.Labels, system);
  if (!this->Check(status.Ok() ? std::string() : "Cannot edit: " + status.Error + "."))
  {
    return false;
  }
  if (status.Work == RebuiltNothing)
  {
    return true;
  }
  ++this->ModelVersion;
  this->LastFacts.SetupTime = watch.Seconds();
  const EditRegion& region = this->Editor.GetRegion();
  this->Surface.IndexRegion(region);
  if (choice.FollowUnreferenced)
  {
    this->Surface.AddFollowers(rest);
  }
  this->Normals.Index(rest, this->Surface);
  if (status.Work & RebuiltRegion)
  {
    source.RegionSelected(choice.Request, region, this->Surface);
  }
  return true;
}

bool EditPipeline::UpdateRotationModel(const SolverSettings& settings)
{
  this->Mode = static_cast<RotationMode>(settings.RotationMode);
  const Stopwatch watch;
  const EditStatus status =
    this->Editor.UpdateRotationModel(settings.Rotation(this->Editor.GetRegion().Radius, this->Surface.GetScale()));
  if (!this->Check(status.Ok() ? std::string() : "Cannot edit: " + status.Error + "."))
  {
    return false;
  }
  Facts& facts = this->LastFacts;
  if (status.Work != RebuiltNothing)
  {
    ++this->ModelVersion;
    facts.SetupTime += watch.Seconds();
    const bool firstOrderEnergy =
      settings.RotationMode == static_cast<int>(RotationMode::AsRigidAsPossible) ||
      (settings.RotationMode == static_cast<int>(RotationMode::Implicit) &&
        settings.ImplicitFormulation == 0);
    if (settings.OperatorOrder == 2 && firstOrderEnergy)
    {
      vtkWarningWithObjectMacro(this->Filter, << "OperatorOrder 2 has no effect in this rotation "
        << "mode: its energy compares one-ring edges, a first-order measure. The bi-Laplacian "
        << "applies in the None and Explicit modes and in the Paper implicit formulation.");
    }
  }
  if (facts.SetupTime > 0.0)
  {
    facts.AnalysisTime = this->Editor.GetAnalysisSeconds();
    facts.FactorizationTime = this->Editor.GetFactorizationSeconds();
  }
  return true;
}

SolverSettings EditPipeline::ContinueSettle(
  const SolverSettings& settings, const EditMotions& motions) const
{
  SolverSettings update = settings;
  update.Settle = this->Settle;
  const Continuation& cut = this->Unfinished;
  const Positions& targets = motions.Points.Targets;
  const Positions& cutTargets = cut.Motions.Points.Targets;
  if (cut.Iterations > 0 && !settings.Dragging && cut.ModelVersion == this->ModelVersion &&
    cut.Motions.Maps == motions.Maps && cut.Motions.HasPoints == motions.HasPoints &&
    (!motions.HasPoints || (cutTargets.rows() == targets.rows() && cutTargets == targets)))
  {
    update.Settle = cut.Settle;
    update.ARAPIterations = cut.Iterations;
    update.Continue = true;
  }
  return update;
}

bool EditPipeline::Solve(const EditMotions& motions, const SolverSettings& settings)
{
  const EditRegion& region = this->Editor.GetRegion();
  this->Maps = motions.Maps;
  this->Solving = settings;
  this->OutOfTime = false;
  const Stopwatch watch;
  this->SolveClock = Stopwatch(); // the time limit's clock
  const EditStatus status = this->Editor.Solve(
    this->Maps, this->Solution, motions.HasPoints ? &motions.Points : nullptr);
  Facts& facts = this->LastFacts;
  facts.SolveTime = watch.Seconds();
  facts.LargestPointMiss = this->Editor.GetLargestPointMiss();
  if (this->Mode == RotationMode::AsRigidAsPossible)
  {
    facts.NumberOfARAPIterations = this->Editor.GetLastArapResult().Iterations;
    facts.ARAPEnergy = this->Editor.GetLastArapResult().Energy;
  }
  if (!this->Check(status.Ok() ? std::string() : "Cannot edit: " + status.Error + "."))
  {
    return false;
  }
  facts.NumberOfROIVertices = region.GetNumberOfVertices();
  facts.NumberOfHandleVertices = static_cast<int>(
    std::count(region.Roles.begin(), region.Roles.end(), VertexRole::Handle));
  return true;
}

bool EditPipeline::Resolve(EditSource& source, const SolverSettings& settings)
{
  if (!this->Solved)
  {
    return this->Check("No edit to solve again: a Resolve follows an update that solved.");
  }
  // A solve for new targets, not a settle: no time limit, and no cut settle left to continue.
  this->Unfinished = Continuation();
  this->SettleIterations = 0;
  SolverSettings solve = settings;
  solve.TimeLimit = 0.0;
  EditMotions motions;
  this->Solved = this->UpdateRotationModel(solve) &&
    this->Check(source.ChooseMotions(this->Surface, this->Editor.GetRegion(), motions)) &&
    this->Solve(motions, solve);
  return this->Solved;
}

bool EditPipeline::SolveDragStep(EditSource& source, SolverSettings settings)
{
  settings.Dragging = true;
  settings.Settle = this->Settle;
  if (!this->Resolve(source, settings))
  {
    return false;
  }
  this->Previewed = true;
  return true;
}

void EditPipeline::Write(
  vtkPolyData* rest, vtkPolyData* output, const OutputEdit* edit, const OutputOptions& options)
{
  this->Writer.Write(rest, output, edit, options);
}

bool EditPipeline::SetDragging(bool dragging)
{
  this->Settle = !dragging;
  if (dragging)
  {
    this->Unfinished = Continuation(); // a grab ends a cut settle; the release settles afresh
  }
  return !dragging && !this->Previewed;
}

OutputEdit EditPipeline::GetEdit() const
{
  return this->Surface.GetEdit(this->Solution, &this->Normals, this->ModelVersion);
}

EditState EditPipeline::GetState() const
{
  EditState state;
  state.Surface = &this->Surface;
  state.Normals = &this->Normals;
  state.Editor = &this->Editor;
  state.Maps = &this->Maps;
  state.Solution = &this->Solution;
  state.ModelVersion = this->ModelVersion;
  return state;
}
}
}
