#include "vtkLaplacianSurfaceRegistration.h"

#include "EditPipeline.h"
#include "FitSource.h"
#include "FoldGuard.h"
#include "LandmarkPairs.h"
#include "SMPFor.h"
#include "SmoothWarp.h"
#include "Stopwatch.h"
#include "TargetMatcher.h"

#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkCleanPolyData.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkErrorCode.h"
#include "vtkFieldData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkIntArray.h"
#include "vtkIterativeClosestPointTransform.h"
#include "vtkLandmarkTransform.h"
#include "vtkMath.h"
#include "vtkMatrix4x4.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkTransform.h"
#include "vtkUnsignedCharArray.h"
#include "vtkUnstructuredGrid.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace lep = LaplacianEditing::Pipeline;

vtkStandardNewMacro(vtkLaplacianSurfaceRegistration);

namespace
{
// The landmarks' own fit, before the matches: met exactly, as the landmark warp meets them, with
// its pull towards their thin-plate spline.
constexpr double LandmarkFitWeight = 100.0;
constexpr double LandmarkSplinePrior = 1.0;
// The explicit mode's automatic support, a fraction of the diagonal (as the warp's).
constexpr double AutomaticSmoothingFraction = 0.05;
// A volume's interior follows the fit in the last share of the progress.
constexpr double VolumeProgress = 0.9;
// VTK's ICP: enough sampled points and iterations for a pose, not a fit.
constexpr int PoseLandmarks = 2000;
constexpr int PoseIterations = 100;
// The match pull and the bending weight are calibrated on templates whose mean edge is this
// share of the diagonal or longer (RegistrationBenchmark's: 0.49% for the Armadillo's 37k
// vertices, up to 1.8%). A finer template keeps their meaning: each vertex's pull holds less
// area (a quarter at half the spacing), and ARAP's bending term weakens with the square of the
// spacing (ArapBending.h). Without this, the Armadillo subdivided to 149k vertices turned 1,893
// triangles over where the 37k template turns one (RegistrationBenchmark --subdivide 1).
constexpr double CalibratedSpacing = 0.0045;
// The smooth warp: its centres and the points it is fitted to (spread by farthest points), its
// smoothness from stiff to loose over the rounds, the point-to-point share of its matches, and
// each landmark's weight in fitted points (RegistrationBenchmark; template-fitting.md).
constexpr int WarpCentres = 200;
constexpr int WarpSamples = 2000;
constexpr double WarpFirstSmoothness = 0.4;
constexpr double WarpLastSmoothness = 4e-6;
constexpr double WarpPointShare = 0.01;
constexpr double WarpLandmarkWeight = 10.0;
// The warp's fit replaces the stages' where they stay farther from the target than it does by
// more than this share of the diagonal (the root-mean-square of the excess point-to-plane
// distance over the trusted matches): the target is then a strained image of the template,
// which the stages' rigid prior resists. RegistrationBenchmark's turned head (a smooth shear)
// exceeds it by 0.42-0.46% in its five cases, its bend (isometric) by 0.07-0.11%.
constexpr double WarpMisfitMargin = 0.002;

LaplacianEditing::Positions PointRows(vtkPoints* points)
{
  LaplacianEditing::Positions rows(points->GetNumberOfPoints(), 3);
  for (vtkIdType i = 0; i < points->GetNumberOfPoints(); ++i)
  {
    double p[3];
    points->GetPoint(i, p);
    rows.row(i) << p[0], p[1], p[2];
  }
  return rows;
}

// The mean length of the triangles' edges (interior edges counted twice).
double MeanEdgeLength(vtkPolyData* surface)
{
  double sum = 0.0;
  vtkIdType edges = 0;
  vtkIdType count = 0;
  const vtkIdType* corners = nullptr;
  auto polygons = vtk::TakeSmartPointer(surface->GetPolys()->NewIterator());
  for (polygons->GoToFirstCell(); !polygons->IsDoneWithTraversal(); polygons->GoToNextCell())
  {
    polygons->GetCurrentCell(count, corners);
    for (vtkIdType k = 0; k < count; ++k)
    {
      double a[3], b[3];
      surface->GetPoint(corners[k], a);
      surface->GetPoint(corners[(k + 1) % count], b);
      sum += std::sqrt(vtkMath::Distance2BetweenPoints(a, b));
      ++edges;
    }
  }
  return edges > 0 ? sum / edges : 0.0;
}
}

struct vtkLaplacianSurfaceRegistration::vtkInternals
{
  explicit vtkInternals(vtkLaplacianSurfaceRegistration* filter)
    : Pipeline(filter->GetEditPipeline())
  {
  }

  lep::EditPipeline& Pipeline; // vtkLaplacianEditFilter's
  lep::FitSource Source;
  lep::TargetMatcher Matcher;
  lep::TargetMatcher::Criteria Criteria;
  lep::TargetMatcher::Matches Matches;
  lep::FoldGuard Guard;
  // The pose (template frame to target frame), and the landmarks' targets in the template's
  // frame.
  vtkNew<vtkTransform> Pose;
  vtkNew<vtkPoints> FrameTargets;
  vtkNew<vtkPoints> LandmarkSources; // paired by label
  vtkNew<vtkPoints> LandmarkTargets;
  double Diagonal = 1.0;
  // The share of the progress the rounds report in (the rest is a volume's).
  double RoundsShare = 1.0;
};

vtkLaplacianSurfaceRegistration::vtkLaplacianSurfaceRegistration()
  : Internals(new vtkInternals(this))
{
  // A fit's defaults: as rigid as possible with cotangent weights, each round converged as far
  // as the next round's new matches make worth it.
  this->RotationMode = ROTATION_AS_RIGID_AS_POSSIBLE;
  this->LaplacianWeights = WEIGHTS_COTANGENT;
  this->ARAPIterations = 30;
  this->Convergence = 1e-3;
  this->OutputDisplacement = 1;
  this->SetNumberOfInputPorts(4);
  this->SetInputArrayToProcess(0, 2, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, "Target");
}

vtkLaplacianSurfaceRegistration::~vtkLaplacianSurfaceRegistration() = default;

void vtkLaplacianSurfaceRegistration::SetTargetData(vtkDataObject* target)
{
  this->SetInputData(1, target);
}

void vtkLaplacianSurfaceRegistration::SetLandmarksData(vtkDataObject* landmarks)
{
  this->SetInputData(2, landmarks);
}

void vtkLaplacianSurfaceRegistration::SetTargetLandmarksData(vtkDataObject* landmarks)
{
  this->SetInputData(3, landmarks);
}

vtkLinearTransform* vtkLaplacianSurfaceRegistration::GetPose()
{
  return this->Internals->Pose;
}

int vtkLaplacianSurfaceRegistration::FillInputPortInformation(int port, vtkInformation* info)
{
  if (port == 0)
  {
    info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPolyData");
    info->Append(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkUnstructuredGrid");
    return 1;
  }
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPointSet");
  info->Set(vtkAlgorithm::INPUT_IS_OPTIONAL(), port >= 2 ? 1 : 0);
  return 1;
}

int vtkLaplacianSurfaceRegistration::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  const LaplacianEditing::Stopwatch watch;
  vtkPointSet* input = vtkPointSet::GetData(inputVector[0]);
  vtkPointSet* target = vtkPointSet::GetData(inputVector[1]);
  vtkPointSet* landmarks = vtkPointSet::GetData(inputVector[2]);
  vtkPointSet* subjectLandmarks = vtkPointSet::GetData(inputVector[3]);
  vtkPointSet* output = vtkPointSet::GetData(outputVector);
  vtkInternals& internals = *this->Internals;
  lep::EditPipeline& pipeline = internals.Pipeline;
  pipeline.BeginUpdate();
  output->ShallowCopy(input);
  this->NumberOfRounds = 0;
  this->WarpKept = 0;
  this->RMSDistanceToTarget = 0.0;
  this->TrustedFraction = 0.0;
  this->FitTime = 0.0;
  internals.Pose->Identity();
  const int pieces = outputVector->GetInformationObject(0)->Get(
    vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_PIECES());
  if (pieces > 1)
  {
    pipeline.Check("The fit needs the whole template and was asked for one of " +
      std::to_string(pieces) + " pieces; run it in a serial session (the built-in server, or "
      "one process)");
    return 1;
  }
  // A volume mesh is fitted through its boundary surface, its interior following.
  auto* grid = vtkUnstructuredGrid::SafeDownCast(input);
  vtkPolyData* surface = grid ? this->VolumeBoundary(grid) : vtkPolyData::SafeDownCast(input);
  vtkPoints* sources = nullptr;
  vtkPoints* targets = nullptr;
  if (!surface || !pipeline.Check(lep::SurfaceAdapter::CheckSurface(surface)) ||
    !pipeline.Check(internals.Matcher.SetTarget(target)) ||
    !this->FindLandmarks(landmarks, subjectLandmarks, sources, targets))
  {
    return 1;
  }
  internals.Diagonal = surface->GetLength();
  internals.Source.FollowUnreferenced = !grid; // a grid's interior follows its own way
  internals.RoundsShare = grid ? VolumeProgress : 1.0;
  lep::TargetMatcher::Criteria& criteria = internals.Criteria;
  criteria.MaximumDistance = this->MaximumMatchDistance * internals.Diagonal;
  criteria.MinimumCosine = std::cos(vtkMath::RadiansFromDegrees(this->MaximumNormalAngle));
  vtkNew<vtkPolyData> shape;
  shape->ShallowCopy(surface);
  // An aborted fit ends at its last round's shape; a failed one passes the template through.
  const bool fitted = this->FindPose(shape, target, sources, targets) && this->Fit(surface, shape);
  if (!fitted && (this->GetErrorCode() != vtkErrorCode::NoError || this->NumberOfRounds == 0))
  {
    return 1;
  }
  if (this->LandOnTarget)
  {
    // The fit's last shape onto its trusted matches, where no triangle turns over.
    lep::TargetMatcher::Matches& matches = internals.Matches;
    internals.Matcher.Match(shape, internals.Criteria, matches);
    internals.Guard.Land(shape, matches.Landings, matches.Trusted);
  }
  internals.Guard.MendSlivers(surface, shape);
  if (grid)
  {
    // The interior follows in the template's frame; the pose is applied after.
    vtkNew<vtkUnstructuredGrid> followed;
    followed->ShallowCopy(grid);
    if (!this->FollowBoundary(shape->GetPoints(), followed, VolumeProgress, 1.0))
    {
      return 1;
    }
    output->ShallowCopy(followed);
  }
  else
  {
    output->ShallowCopy(shape);
  }
  this->WriteOutput(input, shape, output);
  this->FitTime = watch.Seconds();
  vtkNew<vtkDoubleArray> seconds;
  seconds->SetName("FitSeconds");
  seconds->InsertNextValue(this->FitTime);
  output->GetFieldData()->AddArray(seconds);
  return 1;
}

bool vtkLaplacianSurfaceRegistration::FindLandmarks(
  vtkPointSet* landmarks, vtkPointSet* subjectLandmarks, vtkPoints*& sources, vtkPoints*& targets)
{
  lep::EditPipeline& pipeline = this->Internals->Pipeline;
  if (!landmarks)
  {
    return !subjectLandmarks ||
      pipeline.Check("The target's landmarks on input port 3 need the template's on input port 2.");
  }
  vtkPoints* paired = this->Internals->LandmarkTargets;
  paired->SetDataTypeToDouble();
  if (subjectLandmarks)
  {
    // Two sets of markups, paired by label.
    if (!pipeline.Check(lep::PairLandmarks(
          landmarks, subjectLandmarks, this->Internals->LandmarkSources, paired)))
    {
      return false;
    }
    sources = this->Internals->LandmarkSources;
  }
  else
  {
    vtkDataArray* array = this->GetInputArrayToProcess(0, landmarks);
    if (!landmarks->GetPoints() || !array || array->GetNumberOfComponents() != 3)
    {
      return pipeline.Check("The landmarks on input port 2 need points (on the template) and a "
                            "point array of three components holding their places on the target "
                            "(\"Target\" unless SetInputArrayToProcess names another), or the "
                            "target's landmarks on input port 3, paired by label.");
    }
    sources = landmarks->GetPoints();
    paired->SetNumberOfPoints(array->GetNumberOfTuples());
    for (vtkIdType i = 0; i < array->GetNumberOfTuples(); ++i)
    {
      paired->SetPoint(i, array->GetTuple3(i));
    }
  }
  const vtkIdType count = sources->GetNumberOfPoints();
  if (count < 3 && this->PoseMode != POSE_NONE)
  {
    return pipeline.Check("The pose needs at least three landmark pairs, and there are " +
      std::to_string(count) + ": give three or more, none (the pose then comes from iterative "
      "closest points), or set PoseMode to POSE_NONE.");
  }
  for (vtkIdType i = 0; i < count; ++i)
  {
    double target[3];
    paired->GetPoint(i, target);
    if (!std::isfinite(target[0]) || !std::isfinite(target[1]) || !std::isfinite(target[2]))
    {
      return pipeline.Check("Landmark " + std::to_string(i) + "'s target has a NaN or infinite "
                            "coordinate.");
    }
  }
  targets = paired;
  return true;
}

bool vtkLaplacianSurfaceRegistration::FindPose(
  vtkPolyData* fitted, vtkPointSet* target, vtkPoints* sources, vtkPoints* targets)
{
  vtkInternals& internals = *this->Internals;
  if (this->PoseMode != POSE_NONE && sources)
  {
    vtkNew<vtkLandmarkTransform> fit;
    fit->SetSourceLandmarks(sources);
    fit->SetTargetLandmarks(targets);
    this->PoseMode == POSE_RIGID ? fit->SetModeToRigidBody() : fit->SetModeToSimilarity();
    fit->Update();
    internals.Pose->SetMatrix(fit->GetMatrix());
  }
  else if (this->PoseMode != POSE_NONE)
  {
    // ICP needs cells on its target: a cloud gets a vertex each.
    vtkNew<vtkPolyData> cloud;
    cloud->SetPoints(target->GetPoints());
    vtkNew<vtkCellArray> vertices;
    for (vtkIdType i = 0; i < target->GetNumberOfPoints(); ++i)
    {
      vertices->InsertNextCell(1, &i);
    }
    cloud->SetVerts(vertices);
    // ICP samples the source's points: only those the surface uses (not a volume's interior).
    vtkNew<vtkCleanPolyData> used;
    used->SetInputData(fitted);
    used->PointMergingOff();
    used->Update();
    vtkNew<vtkIterativeClosestPointTransform> icp;
    icp->SetSource(used->GetOutput());
    icp->SetTarget(internals.Matcher.IsSurface() ? target : cloud.Get());
    this->PoseMode == POSE_RIGID ? icp->GetLandmarkTransform()->SetModeToRigidBody()
                                 : icp->GetLandmarkTransform()->SetModeToSimilarity();
    icp->StartByMatchingCentroidsOn();
    icp->SetMaximumNumberOfLandmarks(PoseLandmarks);
    icp->SetMaximumNumberOfIterations(PoseIterations);
    icp->CheckMeanDistanceOn();
    icp->Update();
    internals.Pose->SetMatrix(icp->GetMatrix());
  }
  // The fit runs in the template's frame: the target and the landmarks' targets come back by
  // the pose's inverse.
  vtkNew<vtkTransform> back;
  back->SetMatrix(internals.Pose->GetMatrix());
  back->Inverse();
  vtkSmartPointer<vtkPointSet> framed;
  framed.TakeReference(target->NewInstance());
  framed->ShallowCopy(target);
  vtkNew<vtkPoints> framedPoints;
  framedPoints->SetDataTypeToDouble();
  back->TransformPoints(target->GetPoints(), framedPoints);
  framed->SetPoints(framedPoints);
  lep::FitSource& source = internals.Source;
  source.LandmarkSources = sources;
  source.LandmarkTargets = nullptr;
  source.MaximumBindingDistance = this->MaximumBindingDistance * internals.Diagonal;
  source.LandmarkPull = this->LandmarkWeight;
  if (sources)
  {
    internals.FrameTargets->SetDataTypeToDouble();
    internals.FrameTargets->Reset();
    back->TransformPoints(targets, internals.FrameTargets);
    source.LandmarkTargets = internals.FrameTargets;
  }
  return internals.Pipeline.Check(internals.Matcher.SetTarget(framed));
}

bool vtkLaplacianSurfaceRegistration::Fit(vtkPolyData* rest, vtkPolyData* shape)
{
  vtkInternals& internals = *this->Internals;
  lep::EditPipeline& pipeline = internals.Pipeline;
  lep::FitSource& source = internals.Source;
  lep::SolverSettings settings = this->SharedSettings();
  settings.NormalSmoothingRadius = this->NormalSmoothingRadius > 0.0
    ? this->NormalSmoothingRadius
    : AutomaticSmoothingFraction * internals.Diagonal;
  // Below the calibrated spacing, the pull weakens and the bending stiffens (CalibratedSpacing).
  const double spacing = MeanEdgeLength(rest) / internals.Diagonal;
  const double fineness = spacing > 0.0 ? std::min(1.0, spacing / CalibratedSpacing) : 1.0;
  settings.Bending = this->BendingWeight / (fineness * fineness);
  const bool merge = this->MergeCoincidentPoints != 0;
  internals.Guard.Reset(shape->GetNumberOfPoints());
  const int rounds = this->WarpRounds + this->NumberOfStages * this->RoundsPerStage +
    (source.LandmarkSources ? 1 : 0);
  const double share = internals.RoundsShare / rounds;
  auto run = [&](double weight, double splinePrior) {
    pipeline.SetProgressSpan(share * this->NumberOfRounds, share * (this->NumberOfRounds + 1.0));
    source.Weight = weight;
    settings.SplinePrior = splinePrior;
    const bool solved = pipeline.Run(rest, shape, source, settings, merge);
    this->NumberOfRounds += solved;
    return solved;
  };
  if (source.LandmarkSources)
  {
    source.SetMatches({}, {}, true);
    if (!run(LandmarkFitWeight, LandmarkSplinePrior))
    {
      return false;
    }
  }
  // The landmarks' fit (or the pose) put the template near the target: a cloud's normals take
  // their sign from it.
  internals.Matcher.OrientCloud(shape);
  // The smooth warp, from the landmarks' fit; the stages start from that fit too.
  vtkNew<vtkPolyData> warped;
  bool warpStands = false;
  if (this->WarpRounds > 0)
  {
    warped->ShallowCopy(shape);
    if (!this->Warp(rest, warped, share, warpStands))
    {
      return false;
    }
  }
  lep::TargetMatcher::Matches& matches = internals.Matches;
  lep::FoldGuard& guard = internals.Guard;
  std::vector<vtkIdType> trusted;
  // Folds are judged from the stages' start, not each stage's: the cloud's fingers turned over
  // by less than a right angle a stage, 41 triangles in all (RegistrationBenchmark --warp
  // articulated --cases cloud; 0 now). The landmarks' fit or the pose has turned whole parts
  // already.
  guard.Remember(shape);
  for (int stage = 0; stage < this->NumberOfStages; ++stage)
  {
    const double progress = this->NumberOfStages > 1 ? stage / (this->NumberOfStages - 1.0) : 1.0;
    const double weight =
      this->InitialMatchWeight * std::pow(this->FinalMatchWeight / this->InitialMatchWeight, progress);
    bool folded = false;
    for (int round = 0; round < this->RoundsPerStage; ++round)
    {
      internals.Matcher.Match(shape, internals.Criteria, matches);
      // A stage's first round chooses the trusted points, and so does a round after a fold; the
      // others keep them, so that only the targets change and the factor holds.
      const bool choose = round == 0 || folded;
      if (choose)
      {
        trusted.clear();
        for (vtkIdType i = 0; i < static_cast<vtkIdType>(matches.Trusted.size()); ++i)
        {
          if (matches.Trusted[i] && !guard.IsSetAside(i))
          {
            trusted.push_back(i);
          }
        }
      }
      std::vector<std::array<double, 3>> targets;
      targets.reserve(trusted.size());
      for (const vtkIdType i : trusted)
      {
        targets.push_back(matches.Targets[i]);
      }
      source.SetMatches(trusted, std::move(targets), choose);
      if (!run(weight * fineness, 0.0)) // the pull's square scales with the area a vertex holds
      {
        return false;
      }
      folded = guard.Check(shape) > 0;
    }
  }
  // The stages' rigid prior stands unless it keeps the template from the target: a target that
  // is a strained image of the template, which the warp reaches (WarpMisfitMargin).
  this->WarpKept = 0;
  if (warpStands)
  {
    const double stages = this->PlaneMisfit(shape), warp = this->PlaneMisfit(warped);
    if (stages * stages - warp * warp > std::pow(WarpMisfitMargin * internals.Diagonal, 2))
    {
      shape->SetPoints(warped->GetPoints());
      this->WarpKept = 1;
    }
  }
  return true;
}


double vtkLaplacianSurfaceRegistration::PlaneMisfit(vtkPolyData* shape)
{
  vtkInternals& internals = *this->Internals;
  lep::TargetMatcher::Matches& matches = internals.Matches;
  internals.Matcher.Match(shape, internals.Criteria, matches);
  double sum = 0.0;
  vtkIdType trusted = 0;
  for (vtkIdType i = 0; i < static_cast<vtkIdType>(matches.Trusted.size()); ++i)
  {
    if (matches.Trusted[i])
    {
      double p[3];
      shape->GetPoint(i, p);
      sum += vtkMath::Distance2BetweenPoints(p, matches.Targets[i].data());
      ++trusted;
    }
  }
  return trusted > 0 ? std::sqrt(sum / trusted) : std::numeric_limits<double>::infinity();
}

bool vtkLaplacianSurfaceRegistration::Warp(
  vtkPolyData* rest, vtkPolyData* shape, double share, bool& stands)
{
  stands = false;
  namespace le = LaplacianEditing;
  vtkInternals& internals = *this->Internals;
  // The surface's own points (a volume's boundary keeps the interior's, unused).
  std::vector<char> used(rest->GetNumberOfPoints(), 0);
  const vtkIdType* corners = nullptr;
  vtkIdType count = 0;
  auto polygons = vtk::TakeSmartPointer(rest->GetPolys()->NewIterator());
  for (polygons->GoToFirstCell(); !polygons->IsDoneWithTraversal(); polygons->GoToNextCell())
  {
    polygons->GetCurrentCell(count, corners);
    for (vtkIdType k = 0; k < count; ++k)
    {
      used[corners[k]] = 1;
    }
  }
  const le::Positions all = PointRows(rest->GetPoints());
  std::vector<int> surfaceRows;
  for (int i = 0; i < static_cast<int>(used.size()); ++i)
  {
    if (used[i])
    {
      surfaceRows.push_back(i);
    }
  }
  le::Positions surfacePoints(surfaceRows.size(), 3);
  for (std::size_t k = 0; k < surfaceRows.size(); ++k)
  {
    surfacePoints.row(k) = all.row(surfaceRows[k]);
  }
  // The samples spread over the surface; their first WarpCentres are the warp's centres.
  std::vector<vtkIdType> samples;
  for (const int sample : le::SmoothWarp::FarthestPoints(surfacePoints, WarpSamples))
  {
    samples.push_back(surfaceRows[sample]);
  }
  // The landmarks join the samples, point to point, with their targets on every axis.
  vtkPoints* landmarks = internals.Source.LandmarkSources;
  const int pairs = landmarks ? static_cast<int>(landmarks->GetNumberOfPoints()) : 0;
  const int rows = static_cast<int>(samples.size()) + pairs;
  le::Positions points(rows, 3), matches(rows, 3), normals(rows, 3);
  Eigen::VectorXd weights(rows);
  for (std::size_t k = 0; k < samples.size(); ++k)
  {
    points.row(k) = all.row(samples[k]);
  }
  for (int k = 0; k < pairs; ++k)
  {
    double p[3], q[3];
    landmarks->GetPoint(k, p);
    internals.Source.LandmarkTargets->GetPoint(k, q);
    const int row = static_cast<int>(samples.size()) + k;
    points.row(row) << p[0], p[1], p[2];
    matches.row(row) << q[0], q[1], q[2];
    normals.row(row).setZero();
    weights(row) = WarpLandmarkWeight / WarpPointShare;
  }
  const int centres = std::min<int>(WarpCentres, static_cast<int>(samples.size()));
  le::SmoothWarp warp(points.topRows(centres), points);
  lep::TargetMatcher::Matches& found = internals.Matches;
  // A warp that turns a triangle over on its way to the loosest is set aside whole: the target
  // is not a smooth map of the template (parts turned about narrow joints, which a smooth map
  // follows only by shearing them; the articulated Armadillo's folds at its ninth round).
  lep::FoldGuard folds;
  folds.Reset(rest->GetNumberOfPoints());
  folds.Remember(rest);
  for (int round = 0; round < this->WarpRounds; ++round)
  {
    this->UpdateProgress(share * this->NumberOfRounds);
    if (this->GetAbortExecute())
    {
      return false;
    }
    internals.Matcher.Match(shape, internals.Criteria, found, &samples);
    for (std::size_t k = 0; k < samples.size(); ++k)
    {
      const vtkIdType i = samples[k];
      const std::array<double, 3>& m = found.Targets[i];
      const std::array<double, 3>& n = found.Normals[i];
      matches.row(k) << m[0], m[1], m[2];
      normals.row(k) << n[0], n[1], n[2];
      weights(k) = found.Trusted[i] ? 1.0 : 0.0;
    }
    const double progress = this->WarpRounds > 1 ? round / (this->WarpRounds - 1.0) : 1.0;
    const double smoothness =
      WarpFirstSmoothness * std::pow(WarpLastSmoothness / WarpFirstSmoothness, progress);
    if (!warp.Fit(matches, normals, weights, smoothness, WarpPointShare))
    {
      return true; // too few trusted matches to fit: no warp
    }
    const le::Positions displaced = all + warp.Displace(all, lep::SMPFor);
    // New points: the shape's may still be the template's own.
    vtkNew<vtkPoints> moved;
    moved->SetDataTypeToDouble();
    moved->SetNumberOfPoints(all.rows());
    for (vtkIdType i = 0; i < all.rows(); ++i)
    {
      moved->SetPoint(i, displaced(i, 0), displaced(i, 1), displaced(i, 2));
    }
    shape->SetPoints(moved);
    ++this->NumberOfRounds;
    if (folds.Check(shape) > 0)
    {
      return true;
    }
  }
  stands = true;
  return true;
}

void vtkLaplacianSurfaceRegistration::WriteOutput(
  vtkPointSet* rest, vtkPolyData* shape, vtkPointSet* output)
{
  vtkInternals& internals = *this->Internals;
  // The last shape's matches: how far each point ended, and whether its match is trusted.
  lep::TargetMatcher::Matches& matches = internals.Matches;
  internals.Matcher.Match(shape, internals.Criteria, matches);
  // The pose's scale: the cube root of its linear part's determinant.
  const double scale = std::cbrt(internals.Pose->GetMatrix()->Determinant());
  vtkNew<vtkPoints> posed;
  posed->SetDataType(rest->GetPoints()->GetDataType());
  internals.Pose->TransformPoints(output->GetPoints(), posed);
  output->SetPoints(posed);
  if (vtkDataArray* normals = output->GetPointData()->GetNormals())
  {
    vtkSmartPointer<vtkDataArray> turned;
    turned.TakeReference(normals->NewInstance());
    turned->SetName(normals->GetName());
    turned->SetNumberOfComponents(3);
    internals.Pose->TransformNormals(normals, turned);
    output->GetPointData()->SetNormals(turned);
  }
  const vtkIdType n = output->GetNumberOfPoints();
  vtkNew<vtkDoubleArray> distances;
  distances->SetName("DistanceToTarget");
  distances->SetNumberOfTuples(n);
  vtkNew<vtkUnsignedCharArray> trusted;
  trusted->SetName("MatchTrusted");
  trusted->SetNumberOfTuples(n);
  // The surface's points: a volume's interior and points no polygon uses are not fitted.
  std::vector<char> fitted(n, 0);
  vtkIdType count = 0;
  const vtkIdType* ids = nullptr;
  const vtkIdType firstPolygon = shape->GetNumberOfVerts() + shape->GetNumberOfLines();
  for (vtkIdType c = 0; c < shape->GetNumberOfPolys(); ++c)
  {
    shape->GetCellPoints(firstPolygon + c, count, ids);
    for (vtkIdType k = 0; k < count; ++k)
    {
      fitted[ids[k]] = 1;
    }
  }
  double squares = 0.0;
  vtkIdType trustedCount = 0, fittedCount = 0;
  for (vtkIdType i = 0; i < n; ++i)
  {
    const double distance = scale * matches.Distances[i];
    distances->SetValue(i, distance);
    trusted->SetValue(i, fitted[i] && matches.Trusted[i] && !internals.Guard.IsSetAside(i));
    trustedCount += trusted->GetValue(i);
    fittedCount += fitted[i];
    squares += fitted[i] ? distance * distance : 0.0;
  }
  output->GetPointData()->AddArray(distances);
  output->GetPointData()->AddArray(trusted);
  if (this->OutputDisplacement)
  {
    vtkNew<vtkDoubleArray> displacement;
    displacement->SetName("Displacement");
    displacement->SetNumberOfComponents(3);
    displacement->SetNumberOfTuples(n);
    for (vtkIdType i = 0; i < n; ++i)
    {
      double p[3], q[3];
      rest->GetPoint(i, p);
      posed->GetPoint(i, q);
      displacement->SetTuple3(i, q[0] - p[0], q[1] - p[1], q[2] - p[2]);
    }
    output->GetPointData()->AddArray(displacement);
  }
  this->RMSDistanceToTarget = fittedCount > 0 ? std::sqrt(squares / fittedCount) : 0.0;
  this->TrustedFraction = fittedCount > 0 ? static_cast<double>(trustedCount) / fittedCount : 0.0;
  vtkNew<vtkIntArray> rounds;
  rounds->SetName("FitRounds");
  rounds->InsertNextValue(this->NumberOfRounds);
  vtkNew<vtkDoubleArray> rms;
  rms->SetName("RMSDistanceToTarget");
  rms->InsertNextValue(this->RMSDistanceToTarget);
  vtkNew<vtkIntArray> warpKept;
  warpKept->SetName("FitWarpKept");
  warpKept->InsertNextValue(this->WarpKept);
  output->GetFieldData()->AddArray(rounds);
  output->GetFieldData()->AddArray(warpKept);
  output->GetFieldData()->AddArray(rms);
}

void vtkLaplacianSurfaceRegistration::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "PoseMode: " << this->PoseMode << "\n";
  os << indent << "WarpRounds: " << this->WarpRounds << "\n";
  os << indent << "InitialMatchWeight: " << this->InitialMatchWeight << "\n";
  os << indent << "FinalMatchWeight: " << this->FinalMatchWeight << "\n";
  os << indent << "LandmarkWeight: " << this->LandmarkWeight << "\n";
  os << indent << "NumberOfStages: " << this->NumberOfStages << "\n";
  os << indent << "RoundsPerStage: " << this->RoundsPerStage << "\n";
  os << indent << "BendingWeight: " << this->BendingWeight << "\n";
  os << indent << "MaximumMatchDistance: " << this->MaximumMatchDistance << "\n";
  os << indent << "MaximumNormalAngle: " << this->MaximumNormalAngle << "\n";
  os << indent << "MaximumBindingDistance: " << this->MaximumBindingDistance << "\n";
  os << indent << "LandOnTarget: " << (this->LandOnTarget ? "On" : "Off") << "\n";
  os << indent << "NumberOfRounds: " << this->NumberOfRounds << "\n";
  os << indent << "WarpKept: " << (this->WarpKept ? "On" : "Off") << "\n";
  os << indent << "RMSDistanceToTarget: " << this->RMSDistanceToTarget << "\n";
  os << indent << "TrustedFraction: " << this->TrustedFraction << "\n";
  os << indent << "FitTime: " << this->FitTime << "\n";
}
