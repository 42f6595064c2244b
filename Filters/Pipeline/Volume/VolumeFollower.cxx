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
  bool solvedAgain = false;
  for (;;)
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
  const std::vector<double>& misses = this->Solver.GetMisses();
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
  const std::vector<double>& misses = this->Solver.GetMisses();
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
