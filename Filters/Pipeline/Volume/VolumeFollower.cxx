#include "VolumeFollower.h"

#include "OutputWriter.h"
#include "SMPFor.h"
#include "Stopwatch.h"

#include "vtkAlgorithm.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkFloatArray.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkUnsignedCharArray.h"
#include "vtkUnstructuredGrid.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <sstream>

namespace LaplacianEditing
{
namespace Pipeline
{
namespace
{
// A target within this fraction of the zone's mean edge of its point is met (and put on it).
constexpr double MetFraction = 1e-3;
// A miss within this many snaps (1% of the zone's mean edge) is the solve's tail, not a zone too
// tight to let the target through: the zone solves once more rather than growing. On homer's
// 973k tetrahedra, released after 300 drag steps, each of three growths (a factorization of a
// zone twice as wide, 9 to 13 s) left 2 or 3 points as short as before, farther out
// (Documentation/volumes.md).
constexpr double NearMissSnaps = 10.0;
// A cell whose scaled Jacobian at rest is below this is a sliver: a step that flattens it further
// is cut short, so that the points around it may stall short of their targets. On homer's 973k
// tetrahedra from tetgen, 0.4% of the cells are below 0.08 (the median is 0.54), yet six of the
// ten cells a release left short were (Documentation/volumes.md).
constexpr double SliverQuality = 0.1;
// How much stiffer than the mesh around it a target's pull is.
constexpr double TargetWeight = 1e4;
// A zone's deformation graph has a node for about this many zone points, within these bounds.
constexpr int PointsPerGraphNode = 40;
constexpr int FewestGraphNodes = 64;
constexpr int MostGraphNodes = 1500;
// Local-global iterations of the graph a drag step, from the last step's.
constexpr int GraphIterations = 4;
// A drag step repairs the cells that the graph's motion inverts: the free points one ring around
// them, by at most this many iterations of the injective solve (the first round; the next
// rounds, around the cells still inverted, three times as many), their neighbours put on the
// graph's shape where they come within this many snaps of it. On homer's 973k tetrahedra, 10
// iterations left 17 cells for 103 at the second step of a drag, 30 met them all.
constexpr int PatchRings = 1;
constexpr int RepairIterations = 10;
constexpr double RepairSnaps = 100.0;
constexpr int RepairRounds = 3;
// Moves this small, in diagonals, are rounding.
constexpr double StillDistance = 1e-12;

Vector3 Point(vtkPoints* points, vtkIdType id)
{
  Vector3 p;
  points->GetPoint(id, p.data());
  return p;
}
}

void VolumeFollower::SetFilter(vtkAlgorithm* filter)
{
  this->Filter = filter;
  const OutputArray::Holders holders = OutputWriter::PipelineHolders(filter);
  for (OutputArray* array : { &this->Points, &this->Quality, &this->Failures })
  {
    array->SetPipelineHolders(holders);
  }
  this->Displacement.SetPipelineHolders(holders);
}

std::string VolumeFollower::Update(vtkUnstructuredGrid* input, vtkPoints* rest)
{
  bool rebuilt = false;
  const std::string error = this->Mesh.Update(input, rebuilt);
  if (!error.empty())
  {
    this->Rest = nullptr;
    return error;
  }
  if (!rebuilt && rest == this->Rest && rest->GetMTime() == this->RestTime)
  {
    return {};
  }
  // A new mesh or new rest points (a commit): the zone and the rest arrays anew.
  this->Rest = rest;
  this->RestTime = rest->GetMTime();
  this->Zone = VolumeMesh::Zone();
  this->Region = 0;
  this->Followed = false;
  this->LocalOf.assign(input->GetNumberOfPoints(), -1);
  const vtkIdType cells = input->GetNumberOfCells();
  this->NoFailures = vtkSmartPointer<vtkUnsignedCharArray>::New();
  this->NoFailures->SetName("EditFailed");
  this->NoFailures->SetNumberOfValues(cells);
  this->NoFailures->FillValue(0);
  this->RestQuality = vtkSmartPointer<vtkFloatArray>::New();
  this->RestQuality->SetName("ScaledJacobian");
  this->RestQuality->SetNumberOfValues(cells);
  auto position = [rest](vtkIdType id) { return Point(rest, id); };
  SMPFor(0, static_cast<int>(cells), [&](int first, int last) {
    for (int cell = first; cell < last; ++cell)
    {
      this->RestQuality->SetValue(cell, static_cast<float>(this->Mesh.Quality(cell, position)));
    }
  });
  return {};
}

std::string VolumeFollower::FollowEdit(const OutputEdit* edit, vtkPoints* edited,
  Settings settings, vtkUnstructuredGrid* output, bool displacement, double from, double to)
{
  if (!edit)
  {
    this->Reset();
  }
  else
  {
    vtkAlgorithm* filter = this->Filter;
    const Stopwatch watch;
    const double limit = settings.TimeLimit;
    bool& outOfTime = this->LastFacts.OutOfTime; // Follow clears it before the first call
    settings.Progress = [filter, from, to, watch, limit, &outOfTime](double done) {
      filter->UpdateProgress(from + (to - from) * done);
      outOfTime = limit > 0.0 && watch.Seconds() >= limit;
      return !filter->GetAbortExecute() && !outOfTime;
    };
    const std::string error = this->Follow(edit->Moved->Ids, edited, edit->RegionVersion, settings);
    if (!error.empty())
    {
      return error;
    }
    const std::string warning = this->FailureWarning();
    if (!warning.empty() && !settings.Dragging)
    {
      vtkWarningWithObjectMacro(filter, << warning);
    }
  }
  this->Filter->UpdateProgress(to);
  this->Write(output, displacement);
  return {};
}

void VolumeFollower::Reset()
{
  this->Followed = false;
  this->CutSettleIterations = 0;
  this->LastFacts = Facts();
}

std::string VolumeFollower::SelectZone(const std::vector<vtkIdType>& moved, const Settings& settings)
{
  const Stopwatch watch;
  for (vtkIdType id : this->Zone.Points)
  {
    this->LocalOf[id] = -1;
  }
  vtkPoints* rest = this->Rest;
  this->Mesh.SelectZone(moved, this->Reach, rest, this->Zone);
  const int n = static_cast<int>(this->Zone.Points.size());
  // Coordinates about the zone's centre keep their precision on offset models.
  this->Center = Vector3::Zero();
  for (vtkIdType id : this->Zone.Points)
  {
    this->Center += Point(rest, id) / n;
  }
  Positions local(n, 3);
  for (int row = 0; row < n; ++row)
  {
    local.row(row) = (Point(rest, this->Zone.Points[row]) - this->Center).transpose();
  }
  double edges = 0.0;
  for (Eigen::Index t = 0; t < this->Zone.Tets.rows(); ++t)
  {
    edges += (local.row(this->Zone.Tets(t, 1)) - local.row(this->Zone.Tets(t, 0))).norm();
  }
  this->Snap = MetFraction * edges / std::max<Eigen::Index>(1, this->Zone.Tets.rows());
  const std::string error =
    this->Solver.Prepare(local, this->Zone.Tets, this->Zone.Kinds, TargetWeight, settings.Backend);
  this->Movable.clear();
  for (int row = 0; row < n; ++row)
  {
    this->LocalOf[this->Zone.Points[row]] = row;
    if (this->Zone.Kinds[row] != PointKind::Fixed)
    {
      this->Movable.push_back(this->Zone.Points[row]);
    }
  }
  std::sort(this->Movable.begin(), this->Movable.end());
  this->Solution = local; // the zone starts at rest
  this->ZoneRest = std::move(local);
  this->Graph = DeformationGraph();
  this->CutSettleIterations = 0;
  this->LastFacts.SetupTime += watch.Seconds();
  return error;
}

std::string VolumeFollower::Follow(const std::vector<vtkIdType>& moved, vtkPoints* edited,
  std::uint64_t region, const Settings& settings)
{
  this->LastFacts = Facts();
  vtkPoints* rest = this->Rest;
  // An edit that moved nothing beyond rounding (the surface editor solves a handle at rest to
  // within 1e-15): the rest, exactly.
  const bool still = std::all_of(moved.begin(), moved.end(), [&](vtkIdType id) {
    return (Point(edited, id) - Point(rest, id)).norm() <= StillDistance * this->Mesh.GetBoundary()->GetLength();
  });
  if (still)
  {
    this->Reset();
    return {};
  }
  const bool fromDrag = this->Dragged && region == this->Region && !this->Zone.Points.empty();
  if (region != this->Region || this->Zone.Points.empty())
  {
    // The reach: the region's radius about its centroid, at rest.
    Vector3 centroid = Vector3::Zero();
    for (vtkIdType id : moved)
    {
      centroid += Point(rest, id) / static_cast<double>(moved.size());
    }
    this->Reach = 0.0;
    for (vtkIdType id : moved)
    {
      this->Reach = std::max(this->Reach, (Point(rest, id) - centroid).norm());
    }
    this->Region = 0; // set once its zone is prepared
    std::string error = this->SelectZone(moved, settings);
    if (!error.empty())
    {
      return error;
    }
    this->Region = region;
  }
  // The targets, in the zone's rows and frame.
  Positions targets;
  auto frameTargets = [&]() {
    const int n = static_cast<int>(this->Zone.Points.size());
    targets.setZero(n, 3);
    this->Edited.setZero(n, 3);
    for (int row = 0; row < n; ++row)
    {
      if (this->Zone.Kinds[row] == PointKind::Targeted)
      {
        this->Edited.row(row) = Point(edited, this->Zone.Points[row]).transpose();
        targets.row(row) = this->Edited.row(row) - this->Center.transpose();
      }
    }
  };
  frameTargets();
  // A settle of the targets that a time limit cut goes on with the iterations left.
  const bool resumed = !settings.Dragging && this->CutSettleIterations > 0 &&
    targets.rows() == this->CutSettleTargets.rows() && targets == this->CutSettleTargets;
  if (!resumed)
  {
    this->CutSettleIterations = 0;
  }
  InjectiveOptions options;
  options.MaximumIterations = settings.Dragging
    ? settings.DragIterations
    : std::max(1, settings.Iterations - this->CutSettleIterations);
  // A drag step, and a release, start near their targets (the release at the drag's end): the
  // pull is as stiff as it will be from the start. Only a settle from rest loosens it first. A
  // settle that goes on after a cut goes on where the solver stopped, as if uncut.
  options.Continuation = !settings.Dragging && !fromDrag;
  options.Resume = resumed;
  options.Reweight = !settings.Dragging;
  if (!settings.Dragging)
  {
    options.Progress = settings.Progress;
  }
  // A drag step moves the zone's deformation graph to its targets and takes the graph's motion
  // since the last update onto the last update's shape (what earlier steps repaired stays so),
  // at the cost of the graph's nodes; it repairs the cells that this inverts. Where it cannot,
  // the step is an iteration of the injective solve.
  if (settings.Dragging && settings.Graph)
  {
    if (!this->Graph.IsBuilt())
    {
      // And the factor that a drag step falls back on and the release starts with, as a drag
      // without the graph factors it at its first step.
      const Stopwatch watch;
      std::string error = this->BuildGraph();
      if (error.empty())
      {
        error = this->Solver.FactorForDrag(this->LastFacts.Factorizations);
      }
      this->LastFacts.SetupTime += watch.Seconds();
      if (!error.empty())
      {
        this->Region = 0;
        return "Cannot follow the edit into the volume: " + error;
      }
    }
    const Stopwatch watch;
    this->FollowGraph(targets);
    this->LastFacts.SolveTime += watch.Seconds();
  }
  bool solvedAgain = false;
  for (; !this->LastFacts.ByGraph;)
  {
    const Stopwatch watch;
    const InjectiveReport report =
      this->Solver.Solve(targets, this->Solution, options, this->Snap, SMPFor);
    this->LastFacts.SolveTime += watch.Seconds();
    if (!report.Error.empty())
    {
      this->Region = 0;
      return "Cannot follow the edit into the volume: " + report.Error;
    }
    this->LastFacts.Iterations += report.Iterations;
    this->LastFacts.Factorizations += report.Factorizations;
    this->LastFacts.LargestMiss = report.LargestMiss;
    this->LastFacts.Stopped = report.Stopped;
    this->CutSettleIterations += settings.Dragging ? 0 : report.Iterations;
    if (report.LargestMiss <= this->Snap || settings.Dragging || report.Stopped)
    {
      break;
    }
    const bool nearMiss = report.LargestMiss <= NearMissSnaps * this->Snap;
    if (nearMiss && !solvedAgain)
    {
      solvedAgain = true;
      continue;
    }
    if (nearMiss || this->Zone.Complete)
    {
      break; // the cells around the points left short are marked EditFailed
    }
    // A target missed: the zone may be too tight to let it through.
    const Positions solved = this->Solution;
    const std::vector<vtkIdType> points = this->Zone.Points;
    const Vector3 center = this->Center;
    this->Reach *= 2.0;
    ++this->LastFacts.Growths;
    std::string error = this->SelectZone(moved, settings);
    if (!error.empty())
    {
      this->Region = 0;
      return error;
    }
    for (std::size_t row = 0; row < points.size(); ++row)
    {
      this->Solution.row(this->LocalOf[points[row]]) =
        solved.row(static_cast<Eigen::Index>(row)) + (center - this->Center).transpose();
    }
    frameTargets(); // the grown zone's
  }
  if (!settings.Dragging && this->Graph.IsBuilt())
  {
    // The graph follows every update, so that the next drag step's motion starts from these
    // targets.
    this->Graph.Solve(targets, this->GraphShape, GraphIterations, SMPFor);
  }
  this->Dragged = settings.Dragging;
  if (this->LastFacts.OutOfTime && this->LastFacts.Stopped &&
    this->CutSettleIterations < settings.Iterations)
  {
    this->CutSettleTargets = targets;
  }
  else
  {
    this->CutSettleIterations = 0;
    this->LastFacts.OutOfTime = false; // done, or no iterations left
  }
  this->LastFacts.ZonePoints = static_cast<int>(this->Zone.Points.size());
  this->LastFacts.ZoneTetrahedra = static_cast<int>(this->Zone.Tets.rows());
  // A stopped settle did not follow the edit: a commit settles it first.
  this->LastEdited = this->LastFacts.Stopped ? nullptr : edited;
  this->LastEditedTime = edited->GetMTime();
  // Each cell's quality, and the failures: cells around a point left short of its target, and
  // any cell Verdict would see folded that no corner tetrahedron shows (a hexahedron's centre).
  this->Place();
  const std::vector<vtkIdType>& cells = this->Zone.Cells;
  this->ZoneQuality.resize(cells.size());
  auto position = [this](vtkIdType id) { return this->Position(id); };
  const std::vector<double>& misses = this->Misses();
  auto missed = [&](vtkIdType id) {
    const int row = this->LocalOf[id];
    return row >= 0 && misses[row] > this->Snap;
  };
  const bool anyMissed = this->LastFacts.LargestMiss > this->Snap;
  std::vector<char>& failed = this->Failed;
  failed.resize(cells.size());
  SMPFor(0, static_cast<int>(cells.size()), [&](int first, int last) {
    // Tetrahedra from the zone's own rows, a batch at a time (this pass runs at every drag step,
    // and the grid's lookups cost it more than the arithmetic); other cells through the grid.
    constexpr int Batch = 64;
    const double* corners[4 * Batch];
    double quality[Batch];
    for (int begin = first; begin < last; begin += Batch)
    {
      const int end = std::min(last, begin + Batch);
      int tets = 0;
      for (int k = begin; k < end; ++k)
      {
        const int t = this->Zone.CellTets[k];
        for (int i = 0; i < 4 && t >= 0; ++i)
        {
          corners[4 * tets + i] = this->Placed.row(this->Zone.Tets(t, i)).data();
        }
        tets += t >= 0;
      }
      InjectiveDeformation::TetrahedronScaledJacobians(corners, tets, quality);
      for (int k = begin, next = 0; k < end; ++k)
      {
        const int t = this->Zone.CellTets[k];
        if (t >= 0)
        {
          this->ZoneQuality[k] = quality[next++];
          bool leftShort = false;
          for (int i = 0; i < 4 && anyMissed; ++i)
          {
            leftShort = leftShort || misses[this->Zone.Tets(t, i)] > this->Snap;
          }
          failed[k] = this->ZoneQuality[k] <= 0.0 || leftShort;
          continue;
        }
        this->ZoneQuality[k] = this->Mesh.Quality(cells[k], position);
        failed[k] = this->ZoneQuality[k] <= 0.0 || (anyMissed && this->Mesh.AnyPoint(cells[k], missed));
      }
    }
  });
  this->LastFacts.FailedCells = static_cast<int>(std::count(failed.begin(), failed.end(), 1));
  this->LastFacts.FailedSlivers = 0;
  for (std::size_t k = 0; k < cells.size() && this->LastFacts.FailedCells > 0; ++k)
  {
    this->LastFacts.FailedSlivers += failed[k] && this->RestQuality->GetValue(cells[k]) < SliverQuality;
  }
  this->Followed = true;
  return {};
}

std::string VolumeFollower::BuildGraph()
{
  const int nodes = std::clamp(static_cast<int>(this->Zone.Points.size()) / PointsPerGraphNode,
    FewestGraphNodes, MostGraphNodes);
  const std::string error =
    this->Graph.Build(this->ZoneRest, this->Zone.Tets, this->Zone.Kinds, nodes, SMPFor);
  this->GraphShape = this->ZoneRest;
  const Tetrahedra& tets = this->Zone.Tets;
  this->PointTetOffsets.assign(this->Zone.Points.size() + 1, 0);
  for (Eigen::Index t = 0; t < tets.rows(); ++t)
  {
    for (int i = 0; i < 4; ++i)
    {
      ++this->PointTetOffsets[tets(t, i) + 1];
    }
  }
  std::partial_sum(this->PointTetOffsets.begin(), this->PointTetOffsets.end(), this->PointTetOffsets.begin());
  this->PointTets.resize(this->PointTetOffsets.back());
  std::vector<int> next(this->PointTetOffsets.begin(), this->PointTetOffsets.end() - 1);
  for (Eigen::Index t = 0; t < tets.rows(); ++t)
  {
    for (int i = 0; i < 4; ++i)
    {
      this->PointTets[next[tets(t, i)]++] = static_cast<int>(t);
    }
  }
  return error;
}

void VolumeFollower::FollowGraph(const Positions& targets)
{
  Positions shape = this->GraphShape;
  this->Graph.Solve(targets, shape, GraphIterations, SMPFor);
  // A boundary point that the last step left short of its target (an injective step cut at a
  // flattening cell) now jumps onto it: the band around it takes the jump up.
  const Positions jumps = this->GraphShape - this->Solution;
  Positions followed = this->Solution;
  for (int row = 0; row < followed.rows(); ++row)
  {
    if (this->Zone.Kinds[row] == PointKind::Targeted)
    {
      followed.row(row) = targets.row(row);
    }
    else if (this->Zone.Kinds[row] == PointKind::Free)
    {
      followed.row(row) += shape.row(row) - this->GraphShape.row(row);
    }
  }
  this->Graph.Spread(jumps, followed, SMPFor);
  this->GraphShape = std::move(shape);
  this->LastFacts.GraphNodes = this->Graph.GetNumberOfNodes();
  const std::vector<int> inverted = InjectiveDeformation::Inverted(followed, this->Zone.Tets, SMPFor);
  if (!inverted.empty() && !this->Repair(inverted, followed))
  {
    return;
  }
  this->Solution = std::move(followed);
  this->LastFacts.ByGraph = true;
  this->LastFacts.RepairedCells = static_cast<int>(inverted.size());
  // A repair may leave boundary points near the cells it repaired short of their targets.
  this->GraphMisses.assign(this->Solution.rows(), 0.0);
  for (int row = 0; row < this->Solution.rows(); ++row)
  {
    if (this->Zone.Kinds[row] == PointKind::Targeted)
    {
      this->GraphMisses[row] = (this->Solution.row(row) - targets.row(row)).norm();
      this->LastFacts.LargestMiss = std::max(this->LastFacts.LargestMiss, this->GraphMisses[row]);
    }
  }
}

bool VolumeFollower::Repair(std::vector<int> inverted, Positions& followed)
{
  // A patch's points pulled onto the shape around them may stop short of it, and a cell past
  // the patch still be inverted: a patch around those then.
  for (int round = 0; round < RepairRounds && !inverted.empty(); ++round)
  {
    const std::size_t before = inverted.size();
    if (!this->RepairPatch(inverted, followed, round == 0 ? RepairIterations : 3 * RepairIterations))
    {
      return false;
    }
    inverted = InjectiveDeformation::Inverted(followed, this->Zone.Tets, SMPFor);
    if (round > 0 && inverted.size() >= before)
    {
      break; // the patches spread: the injective iteration takes the step
    }
  }
  return inverted.empty();
}

bool VolumeFollower::RepairPatch(
  const std::vector<int>& inverted, Positions& followed, int iterations)
{
  // The patch: the free points within PatchRings rings of the inverted tetrahedra.
  const Tetrahedra& tets = this->Zone.Tets;
  const int n = static_cast<int>(this->Zone.Points.size());
  std::vector<int> ring(n, -1);
  std::vector<int> front;
  for (int t : inverted)
  {
    for (int k = 0; k < 4; ++k)
    {
      const int p = tets(t, k);
      if (ring[p] < 0)
      {
        ring[p] = 0;
        front.push_back(p);
      }
    }
  }
  for (std::size_t f = 0; f < front.size(); ++f)
  {
    const int p = front[f];
    if (ring[p] >= PatchRings)
    {
      continue;
    }
    for (int k = this->PointTetOffsets[p]; k < this->PointTetOffsets[p + 1]; ++k)
    {
      for (int i = 0; i < 4; ++i)
      {
        const int q = tets(this->PointTets[k], i);
        if (ring[q] < 0)
        {
          ring[q] = ring[p] + 1;
          front.push_back(q);
        }
      }
    }
  }
  std::vector<int> local(n, -1), points;
  std::vector<PointKind> kinds;
  std::vector<int> patchTets;
  for (int p : front)
  {
    if (this->Zone.Kinds[p] != PointKind::Free)
    {
      continue;
    }
    for (int k = this->PointTetOffsets[p]; k < this->PointTetOffsets[p + 1]; ++k)
    {
      patchTets.push_back(this->PointTets[k]);
    }
  }
  std::sort(patchTets.begin(), patchTets.end());
  patchTets.erase(std::unique(patchTets.begin(), patchTets.end()), patchTets.end());
  Tetrahedra patch(static_cast<Eigen::Index>(patchTets.size()), 4);
  for (std::size_t t = 0; t < patchTets.size(); ++t)
  {
    for (int i = 0; i < 4; ++i)
    {
      const int p = tets(patchTets[t], i);
      if (local[p] < 0)
      {
        local[p] = static_cast<int>(points.size());
        points.push_back(p);
        // Its free points move; the others are pulled onto the graph's shape (or their targets).
        const bool free = this->Zone.Kinds[p] == PointKind::Free && ring[p] >= 0;
        kinds.push_back(free ? PointKind::Free : PointKind::Targeted);
      }
      patch(static_cast<Eigen::Index>(t), i) = local[p];
    }
  }
  const int m = static_cast<int>(points.size());
  Positions rest(m, 3), start(m, 3), goal(m, 3);
  for (int k = 0; k < m; ++k)
  {
    rest.row(k) = this->ZoneRest.row(points[k]);
    start.row(k) = this->Solution.row(points[k]); // the last step's shape: no cell inverted
    goal.row(k) = followed.row(points[k]);
  }
  InjectiveDeformation solver;
  if (!solver.Prepare(rest, patch, kinds, TargetWeight, SolverBackend::SimplicialLDLT).empty())
  {
    return false;
  }
  InjectiveOptions options;
  options.MaximumIterations = iterations;
  options.Continuation = false;
  const InjectiveReport report = solver.Solve(goal, start, options, RepairSnaps * this->Snap);
  if (!report.Error.empty())
  {
    return false;
  }
  for (int k = 0; k < m; ++k)
  {
    followed.row(points[k]) = start.row(k);
  }
  return true;
}

std::string VolumeFollower::FailureWarning() const
{
  if (this->LastFacts.FailedCells == 0 || this->LastFacts.Stopped)
  {
    return {};
  }
  std::ostringstream warning;
  warning << this->LastFacts.FailedCells
          << " cells could not follow the edit without inverting a cell: boundary points were "
             "left up to "
          << this->LastFacts.LargestMiss
          << " (mesh units) short of their edited positions (cell array EditFailed).";
  if (this->LastFacts.FailedSlivers > 0)
  {
    warning << " " << this->LastFacts.FailedSlivers
            << " of them were slivers at rest (scaled Jacobian below " << SliverQuality
            << "), which stall the points around them as they flatten: a mesh optimized for "
               "quality (tetgen's -O, gmsh's Optimize) has fewer.";
  }
  return warning.str();
}

void VolumeFollower::Place()
{
  const std::vector<double>& misses = this->Misses();
  this->Placed.resize(this->Solution.rows(), 3);
  SMPFor(0, static_cast<int>(this->Placed.rows()), [&](int first, int last) {
    for (int row = first; row < last; ++row)
    {
      // A target met is the boundary's edit exactly (the zone's frame would round it).
      const bool met = this->Zone.Kinds[row] == PointKind::Targeted && misses[row] == 0.0;
      if (met)
      {
        this->Placed.row(row) = this->Edited.row(row);
      }
      else
      {
        this->Placed.row(row) = this->Solution.row(row) + this->Center.transpose();
      }
    }
  });
}

Vector3 VolumeFollower::Position(vtkIdType id) const
{
  const int row = this->LocalOf[id];
  return row < 0 ? Point(this->Rest, id) : Vector3(this->Placed.row(row).transpose());
}

void VolumeFollower::Write(vtkUnstructuredGrid* output, bool displacement)
{
  const std::uint64_t key = ++this->Writes;
  static const std::vector<vtkIdType> none;
  const std::vector<vtkIdType>& moved = this->Followed ? this->Movable : none;
  const std::vector<vtkIdType>& cells = this->Followed ? this->Zone.Cells : none;
  output->SetPoints(this->Points.Update(this->Rest, moved, key, [&](vtkDataArray* points) {
    OutputArray::SetTuples<3>(points, moved, [&](vtkIdType i, double* p) {
      const Vector3 position = this->Position(moved[i]);
      std::copy(position.data(), position.data() + 3, p);
    });
  }));
  vtkDataArray* quality =
    this->Quality.Update(this->RestQuality, cells, key, [&](vtkDataArray* array) {
      OutputArray::SetTuples<1>(
        array, cells, [&](vtkIdType k, double* q) { *q = this->ZoneQuality[k]; });
    });
  vtkDataArray* failures =
    this->Failures.Update(this->NoFailures, cells, key, [&](vtkDataArray* array) {
      OutputArray::SetTuples<1>(
        array, cells, [&](vtkIdType k, double* failed) { *failed = this->Failed[k]; });
    });
  output->GetCellData()->AddArray(quality);
  output->GetCellData()->AddArray(failures);
  if (displacement)
  {
    output->GetPointData()->AddArray(
      this->Displacement.Update(this->Rest, output->GetPoints(), moved, key));
  }
}
}
}
