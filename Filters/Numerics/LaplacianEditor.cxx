#include "LaplacianEditor.h"

#include <algorithm>

namespace LaplacianEditing
{
bool RegionRequest::operator==(const RegionRequest& other) const
{
  if (this->Selection != other.Selection || this->AnchorPadding != other.AnchorPadding ||
    this->Distances != other.Distances)
  {
    return false;
  }
  if (this->Selection == Kind::Labeled)
  {
    return this->LabelsVersion == other.LabelsVersion && this->GrowRadius == other.GrowRadius;
  }
  if (this->Selection == Kind::Components)
  {
    return this->Seeds == other.Seeds;
  }
  return this->CenterVertex == other.CenterVertex && this->HandleRadius == other.HandleRadius &&
    this->ROIRadius == other.ROIRadius;
}

void LaplacianEditor::SetMesh(std::shared_ptr<const SurfaceMesh> mesh)
{
  this->Mesh = std::move(mesh);
  this->Ready = false;
  this->HasRegionRequest = false;
  this->HasSystemOptions = false;
  this->Region = EditRegion();
  this->Normals.reset();
  this->Frames.reset();
  this->Implicit.reset();
  this->Arap.reset();
  this->LargeArap.reset();
  this->LastFailure.reset();
}

double LaplacianEditor::GetFactorBytes() const
{
  if (!this->Ready)
  {
    return 0.0;
  }
  return this->System.GetFactor().GetFactorBytes() +
    (this->Implicit ? this->Implicit->GetFactor().GetFactorBytes() : 0.0) +
    (this->Arap ? this->Arap->GetFactor().GetFactorBytes() : 0.0) +
    (this->LargeArap ? this->LargeArap->GetFactorBytes() : 0.0);
}

bool LaplacianEditor::IsFactorDistributed() const
{
  return this->Ready &&
    (this->System.GetFactor().IsDistributed() ||
      (this->Implicit && this->Implicit->GetFactor().IsDistributed()) ||
      (this->Arap && this->Arap->GetFactor().IsDistributed()));
}

void LaplacianEditor::Record(const SparseCholesky& factor)
{
  ++this->NumberOfFactorizations;
  this->AnalysisSeconds = factor.GetAnalysisSeconds();
  this->FactorizationSeconds = factor.GetFactorizationSeconds();
}

std::string LaplacianEditor::SelectRegion(
  const RegionRequest& request, const std::function<std::vector<int>()>& labels)
{
  if (request.Selection == RegionRequest::Kind::Components)
  {
    return SelectComponents(*this->Mesh, request.Seeds, this->Region);
  }
  if (request.Selection == RegionRequest::Kind::Labeled)
  {
    return SelectLabeledRegion(*this->Mesh, labels(), request.AnchorPadding, this->Region,
      request.Distances, request.GrowRadius);
  }
  return SelectGeodesicRegion(*this->Mesh, request.CenterVertex, request.HandleRadius,
    request.ROIRadius, request.AnchorPadding, this->Region, request.Distances);
}

EditStatus LaplacianEditor::Fail(bool rotationModel, RotationMode mode, std::string error)
{
  // What failed stays unbuilt; what was built before it stays valid.
  this->Ready = false;
  this->LastFailure.reset(new Failure{ this->RegionRequested, this->SystemRequested,
    rotationModel, mode, this->RotationRequested.Formulation,
    this->RotationRequested.PreserveDetailScale, error });
  EditStatus status;
  status.Error = std::move(error);
  return status;
}

EditStatus LaplacianEditor::UpdateRegion(const RegionRequest& region,
  const std::function<std::vector<int>()>& labels, const DeformationOptions& system)
{
  EditStatus status;
  this->Ready = false;
  this->RegionRequested = region;
  this->SystemRequested = system;
  if (!this->Mesh)
  {
    status.Error = "no surface to edit";
    return status;
  }
  const Failure* failed = this->LastFailure.get();
  if (failed && !failed->RotationModel && failed->Region == region && failed->System == system)
  {
    status.Error = failed->Error;
    return status;
  }
  if (!this->HasRegionRequest || this->RegionBuiltFrom != region)
  {
    this->HasRegionRequest = false;
    this->HasSystemOptions = false;
    const std::string error = this->SelectRegion(region, labels);
    if (!error.empty())
    {
      return this->Fail(false, RotationMode::None, "cannot select the region: " + error);
    }
    this->RegionBuiltFrom = region;
    this->HasRegionRequest = true;
    status.Work |= RebuiltRegion;
  }
  if (!this->HasSystemOptions || this->SystemBuiltFrom != system)
  {
    this->HasSystemOptions = false;
    this->Normals.reset();
    this->Frames.reset();
    this->Implicit.reset();
    this->Arap.reset();
    this->LargeArap.reset();
    this->System = DeformationSystem();
    this->PointCorrection = Positions();
    this->NumberOfFactorizationAttempts += system.LeastSquares ? 1 : 0;
    const std::string error =
      system.LeastSquares ? this->System.Build(*this->Mesh, this->Region, system) : std::string();
    if (!error.empty())
    {
      return this->Fail(false, RotationMode::None, "cannot factor the editing system: " + error);
    }
    if (system.LeastSquares)
    {
      this->Record(this->System.GetFactor());
    }
    this->SystemBuiltFrom = system;
    this->HasSystemOptions = true;
    status.Work |= RebuiltSystem;
  }
  if (status.Work != RebuiltNothing)
  {
    this->LastFailure.reset();
  }
  return status;
}

EditStatus LaplacianEditor::UpdateRotationModel(const RotationOptions& rotation)
{
  EditStatus status;
  this->Ready = false;
  if (!this->HasSystemOptions)
  {
    status.Error = "the editor has no region: UpdateRegion first";
    return status;
  }
  const Failure* failed = this->LastFailure.get();
  if (failed && failed->RotationModel && failed->Mode == rotation.Mode &&
    failed->Formulation == rotation.Formulation &&
    failed->PreserveDetailScale == rotation.PreserveDetailScale)
  {
    status.Error = failed->Error;
    return status;
  }
  if ((rotation.Mode == RotationMode::AsRigidAsPossible) == this->SystemBuiltFrom.LeastSquares)
  {
    status.Error = "the region's system was built for another mode: UpdateRegion with "
                   "LeastSquares off for the as-rigid-as-possible mode, on for the others";
    return status;
  }
  bool built = false;
  const std::string error = this->BuildRotationModel(rotation, built);
  if (!error.empty())
  {
    this->RotationRequested = rotation;
    return this->Fail(true, rotation.Mode, "cannot prepare the rotation mode: " + error);
  }
  status.Work = built ? RebuiltRotationModel : RebuiltNothing;
  this->Rotation = rotation;
  this->Ready = true;
  return status;
}

std::string LaplacianEditor::BuildRotationModel(const RotationOptions& rotation, bool& built)
{
  built = false;
  if (rotation.Mode == RotationMode::Explicit &&
    (!this->Normals || this->Normals->GetRadius() != rotation.NormalSmoothingRadius))
  {
    this->Normals = std::make_unique<SmoothNormals>();
    this->Normals->Build(*this->Mesh, this->Region.Vertices, rotation.NormalSmoothingRadius,
      this->RegionBuiltFrom.Distances, this->Loop);
    this->Frames = std::make_unique<LocalFrames>();
    this->Frames->Build(*this->Mesh, this->Region.Vertices,
      this->Normals->Compute(this->System.GetRestPositions()),
      this->SystemBuiltFrom.Order >= 2 ? this->System.GetFirstOrderDifferentialCoordinates()
                                       : this->System.GetRestDifferentialCoordinates());
    built = true;
  }
  else if (rotation.Mode == RotationMode::AsRigidAsPossible && this->IsLarge(rotation))
  {
    if (!this->LargeArap || this->LargeArapNodes != rotation.ProxyNodes)
    {
      const std::string error = this->BuildLargeArap(rotation.ProxyNodes);
      if (!error.empty())
      {
        return error;
      }
      built = true;
    }
  }
  else if (rotation.Mode == RotationMode::AsRigidAsPossible && !this->Arap)
  {
    const std::string error = this->BuildArap();
    if (!error.empty())
    {
      return error;
    }
    built = true;
  }
  else if (rotation.Mode == RotationMode::Implicit &&
    (!this->Implicit || !(this->ImplicitBuiltWith == rotation.Formulation)))
  {
    this->Implicit.reset();
    auto implicit = std::make_unique<ImplicitSimilaritySystem>();
    ++this->NumberOfFactorizationAttempts;
    const std::string error = implicit->Build(*this->Mesh, this->Region, this->System,
      this->SystemBuiltFrom, rotation.Formulation, this->Loop);
    if (!error.empty())
    {
      return error;
    }
    this->Record(implicit->GetFactor());
    this->Implicit = std::move(implicit);
    this->ImplicitBuiltWith = rotation.Formulation;
    built = true;
  }
  if (rotation.Mode == RotationMode::Implicit && rotation.PreserveDetailScale && !this->Arap)
  {
    const std::string error = this->BuildArap();
    if (!error.empty())
    {
      return "the implicit mode's rigid step (turn PreserveDetailScale off to skip it) needs "
             "the as-rigid-as-possible system: " + error;
    }
    built = true;
  }
  return {};
}

std::string LaplacianEditor::BuildArap()
{
  auto arap = std::make_unique<AsRigidAsPossibleSolver>();
  ++this->NumberOfFactorizationAttempts;
  const std::string error = arap->Build(*this->Mesh, this->Region, this->SystemBuiltFrom, this->Loop);
  if (!error.empty())
  {
    return error;
  }
  this->Record(arap->GetFactor());
  this->Arap = std::move(arap);
  this->ArapWarmStart = {};
  this->Straightened = {};
  this->PointsUnmeetable = false;
  return {};
}

bool LaplacianEditor::IsLarge(const RotationOptions& rotation) const
{
  return rotation.LargeRegionVertices > 0 && !this->SystemBuiltFrom.Points &&
    this->Region.GetNumberOfVertices() > rotation.LargeRegionVertices;
}

std::string LaplacianEditor::BuildLargeArap(int proxyNodes)
{
  auto large = std::make_unique<ProxyArapSolver>();
  ++this->NumberOfFactorizationAttempts;
  const std::string error = large->Build(this->Mesh, this->Region, this->SystemBuiltFrom, proxyNodes, this->Loop);
  if (!error.empty())
  {
    return error;
  }
  ++this->NumberOfFactorizations;
  this->AnalysisSeconds = this->FactorizationSeconds = 0.0;
  this->LargeArap = std::move(large);
  this->LargeArapNodes = proxyNodes;
  return {};
}

bool LaplacianEditor::IsAffineInHandleMaps() const
{
  const RotationMode mode = this->Rotation.Mode;
  return this->Ready && !this->SystemBuiltFrom.Points &&
    (mode == RotationMode::None || (mode == RotationMode::Implicit && !this->Rotation.PreserveDetailScale));
}

const PointConstraints& LaplacianEditor::GetPoints() const
{
  static const PointConstraints none;
  return this->SystemBuiltFrom.LeastSquares ? this->System.GetPoints()
    : this->Arap                            ? this->Arap->GetPoints()
                                            : none;
}

Positions LaplacianEditor::FitPoints(
  const std::function<Positions(const Positions&)>& solve, const PointTargets* points)
{
  if (!points || this->GetPoints().IsEmpty())
  {
    return solve(Positions());
  }
  Positions solution;
  double miss = 0.0;
  this->GetPoints().Fit(solve, *points, this->PointCorrection, solution, miss);
  return solution;
}

AffineRows LaplacianEditor::GetAffineRows(const std::vector<int>& rows) const
{
  return this->Rotation.Mode == RotationMode::Implicit ? this->Implicit->GetAffineRows(rows)
                                                        : this->System.GetAffineRows(rows);
}

EditStatus LaplacianEditor::Solve(
  const std::vector<AffineMap>& handleMaps, Positions& roiPositions, const PointTargets* points)
{
  EditStatus status;
  if (!this->Ready)
  {
    status.Error = "the editor has no region: Update first";
    return status;
  }
  if (!this->GetPoints().IsEmpty() &&
    (!points || points->Targets.rows() != this->GetPoints().GetNumberOfPoints()))
  {
    status.Error = "the system has point constraints: give a target for each point";
    return status;
  }
  RotationOptions rotation = this->Rotation;
  if (!rotation.Arap.Dragging)
  {
    rotation.Arap.Progress = this->Progress;
  }
  if (rotation.Mode == RotationMode::AsRigidAsPossible && this->IsLarge(rotation))
  {
    this->LastArap = rotation.Arap.Dragging
      ? this->LargeArap->Drag(handleMaps, rotation.Arap, roiPositions, this->Loop)
      : this->LargeArap->Settle(handleMaps, rotation.Arap, roiPositions, this->Loop);
    if (!this->LargeArap->GetSettleError().empty())
    {
      status.Error = "cannot settle at full resolution: " + this->LargeArap->GetSettleError();
    }
  }
  else if (rotation.Mode == RotationMode::AsRigidAsPossible)
  {
    // A drag continues from the last result; a new region starts from the rest edges.
    if (this->ArapWarmStart.Points.rows() != this->Region.GetNumberOfVertices())
    {
      this->ArapWarmStart = this->Arap->InitialGuess(handleMaps, points);
    }
    // Where more points than corners share triangles, no shape meets them all: the exact fit's
    // corrections then stall and raise the energy, which ends the iteration after one step
    // (10,000 landmarks on bumps.obj: 1 iteration, 14 times the RMS error of a least-squares
    // fit). Such points are fit in the least-squares sense, at the pull the factor has. A
    // feasible fit ends within Tolerance; one that cannot meet them misses by far more.
    constexpr double UnmeetableMiss = 100.0;
    const PointTargets* arapPoints = points;
    PointTargets leastSquares;
    auto fitInLeastSquares = [&] {
      leastSquares = *points;
      leastSquares.Exact = false;
      arapPoints = &leastSquares;
    };
    if (points && points->Exact && this->PointsUnmeetable)
    {
      fitInLeastSquares();
    }
    this->LastArap = this->Arap->Solve(
      handleMaps, this->ArapWarmStart, rotation.Arap, this->Loop, nullptr, arapPoints);
    if (arapPoints && arapPoints->Exact &&
      this->GetPoints().LargestMiss(this->ArapWarmStart.Points, points->Targets) >
        UnmeetableMiss * points->Tolerance)
    {
      this->PointsUnmeetable = true;
      fitInLeastSquares();
      const int exactIterations = this->LastArap.Iterations;
      this->LastArap = this->Arap->Solve(
        handleMaps, this->ArapWarmStart, rotation.Arap, this->Loop, nullptr, arapPoints);
      this->LastArap.Iterations += exactIterations;
    }
    roiPositions = this->ArapWarmStart.Points;
  }
  else if (rotation.Mode == RotationMode::Implicit && rotation.PreserveDetailScale)
  {
    // The rigid step's global step meets the points itself.
    roiPositions = this->Implicit->Solve(handleMaps, this->Loop, points ? points->Targets : Positions());
    this->Straightened.Points.swap(roiPositions);
    this->Arap->Straighten(handleMaps, this->Straightened, this->Loop, points);
    roiPositions = this->Straightened.Points;
  }
  else if (rotation.Mode == RotationMode::Implicit)
  {
    roiPositions = this->FitPoints(
      [&](const Positions& targets) { return this->Implicit->Solve(handleMaps, this->Loop, targets); },
      points);
  }
  else
  {
    roiPositions = this->FitPoints(
      [&](const Positions& targets) { return this->System.Solve(handleMaps, targets); }, points);
    for (int pass = 0; rotation.Mode == RotationMode::Explicit &&
         pass < std::max(rotation.Iterations, 1);
         ++pass)
    {
      Positions rotated = this->Frames->Rotate(
        roiPositions, this->Normals->Compute(roiPositions, this->Loop), this->Loop);
      if (this->SystemBuiltFrom.Order >= 2)
      {
        rotated = this->System.ComposeSecondOrder(rotated);
      }
      roiPositions = this->FitPoints(
        [&](const Positions& targets) {
          return this->System.SolveWithDifferentialCoordinates(rotated, handleMaps, this->Loop, targets);
        },
        points);
    }
  }
  this->LargestPointMiss = points ? this->GetPoints().LargestMiss(roiPositions, points->Targets) : 0.0;
  if (!roiPositions.allFinite())
  {
    status.Error = "the solve produced non-finite coordinates; the handle transform may be "
                   "degenerate";
  }
  return status;
}
}
