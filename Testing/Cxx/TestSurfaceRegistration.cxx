// vtkLaplacianSurfaceRegistration: a template fitted to itself stays put; a volume template
// follows its fitted boundary without inverting a cell; on known warps
// (RegistrationCases.h: a remeshed target, a noisy one, one with a hole, a point cloud, a posed
// one) the fit lands on the target in correspondence, well closer to the true shape than the
// landmark warp, with no triangle turned over; the output carries its arrays; progress rises
// to the end and an abort ends the fit at a valid shape; bad inputs are clear errors that pass
// the template through.
#include "FilterTestHelpers.h"
#include "RegistrationCases.h"
#include "VolumeMeshes.h"

#include "vtkLaplacianLandmarkWarp.h"
#include "vtkLaplacianSurfaceRegistration.h"

#include "vtkCallbackCommand.h"
#include "vtkCellData.h"
#include "vtkDataSetSurfaceFilter.h"
#include "vtkDoubleArray.h"
#include "vtkErrorCode.h"
#include "vtkFieldData.h"
#include "vtkIdFilter.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkStringArray.h"
#include "vtkTriangleFilter.h"
#include "vtkUnstructuredGrid.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

using namespace FilterTestHelpers;

namespace
{
// The landmarks as input port 2 takes them: points on the template, their places in "Target".
vtkSmartPointer<vtkPolyData> Landmarks(vtkPoints* sources, vtkPoints* targets)
{
  auto landmarks = vtkSmartPointer<vtkPolyData>::New();
  landmarks->SetPoints(sources);
  vtkNew<vtkDoubleArray> places;
  places->SetName("Target");
  places->SetNumberOfComponents(3);
  for (vtkIdType i = 0; i < targets->GetNumberOfPoints(); ++i)
  {
    places->InsertNextTuple(targets->GetPoint(i));
  }
  landmarks->GetPointData()->AddArray(places);
  return landmarks;
}

vtkSmartPointer<vtkLaplacianSurfaceRegistration> Registration(
  vtkPointSet* mesh, vtkPointSet* target, vtkPointSet* landmarks = nullptr)
{
  auto registration = vtkSmartPointer<vtkLaplacianSurfaceRegistration>::New();
  registration->SetInputData(mesh);
  registration->SetTargetData(target);
  if (landmarks)
  {
    registration->SetLandmarksData(landmarks);
  }
  return registration;
}

// The template with a point and a cell array of its ids, to check that they pass through.
vtkSmartPointer<vtkPolyData> WithIds(vtkPolyData* mesh)
{
  vtkNew<vtkIdFilter> ids;
  ids->SetInputData(mesh);
  ids->SetPointIdsArrayName("PointIds");
  ids->SetCellIdsArrayName("CellIds");
  ids->Update();
  auto labeled = vtkSmartPointer<vtkPolyData>::New();
  labeled->ShallowCopy(ids->GetOutput());
  return labeled;
}

// The landmark warp's fit of a case, from its landmarks alone: the yardstick of a fit.
RegistrationCases::Measures LandmarkWarpMeasures(
  const KnownWarps::Warp& warp, const RegistrationCases::Case& fit)
{
  vtkNew<vtkLaplacianLandmarkWarp> landmarkWarp;
  landmarkWarp->SetInputData(warp.Mesh);
  landmarkWarp->SetSourceLandmarks(fit.Sources);
  landmarkWarp->SetTargetLandmarks(fit.Targets);
  landmarkWarp->Update();
  return RegistrationCases::Measure(
    vtkPolyData::SafeDownCast(landmarkWarp->GetOutput()), fit, warp.Mesh->GetLength());
}
}

TEST(SurfaceRegistration, TemplateOnItselfStaysPut)
{
  // The template is its own target: every match is the vertex itself, so nothing moves, with
  // the pose fixed or found by ICP.
  vtkSmartPointer<vtkPolyData> plane = BumpyPlane(40);
  vtkNew<vtkPolyData> target;
  target->DeepCopy(plane);
  const double diagonal = Diagonal(plane);
  for (const int pose : { vtkLaplacianSurfaceRegistration::POSE_NONE,
         vtkLaplacianSurfaceRegistration::POSE_SIMILARITY })
  {
    auto registration = Registration(plane, target);
    registration->SetPoseMode(pose);
    ErrorCatcher errors(registration);
    registration->Update();
    EXPECT_TRUE(errors.Messages.empty()) << errors.Messages;
    const double tolerance = pose == vtkLaplacianSurfaceRegistration::POSE_NONE ? 1e-9 : 1e-5;
    EXPECT_LT(MaxPointDistance(plane, registration->GetOutput()), tolerance * diagonal)
      << "pose mode " << pose;
    EXPECT_LT(registration->GetRMSDistanceToTarget(), tolerance * diagonal);
    EXPECT_EQ(registration->GetTrustedFraction(), 1.0);
  }
}

class KnownWarpFit : public ::testing::TestWithParam<const char*>
{
};

// The bend's cases, each against a stated tolerance from RegistrationBenchmark's figures (the
// fit's correspondence error is 0.28-0.31 times the landmark warp's there): within the issue's
// 0.35 times the landmark warp's error, within 0.6% of the diagonal of the target (1.5% for the cloud, whose
// points lie up to their spacing from its surface), and no triangle turned over.
TEST_P(KnownWarpFit, LandsInCorrespondence)
{
  const std::string name = GetParam();
  KnownWarps::Warp warp = KnownWarps::Bend(DataDir);
  ASSERT_TRUE(warp.Mesh);
  const RegistrationCases::Case fit = RegistrationCases::MakeCase(name, warp, 8, 3);
  const double diagonal = warp.Mesh->GetLength();
  const RegistrationCases::Measures landmarksOnly = LandmarkWarpMeasures(warp, fit);
  auto registration = Registration(warp.Mesh, fit.Target, Landmarks(fit.Sources, fit.Targets));
  ErrorCatcher errors(registration);
  registration->Update();
  EXPECT_TRUE(errors.Messages.empty()) << errors.Messages;
  const RegistrationCases::Measures fitted =
    RegistrationCases::Measure(vtkPolyData::SafeDownCast(registration->GetOutput()), fit, diagonal);
  EXPECT_LT(fitted.Correspondence, 0.35 * landmarksOnly.Correspondence) << name;
  EXPECT_LT(fitted.ToTarget, name == "cloud" ? 1.5 : 0.6) << name;
  EXPECT_EQ(fitted.TurnedOver, 0) << name;
  EXPECT_FALSE(registration->GetWarpKept()) << name << ": a bend is the stages' (isometric)";
}

INSTANTIATE_TEST_SUITE_P(
  Bend, KnownWarpFit, ::testing::Values("remeshed", "noisy", "hole", "cloud", "posed"));

// Matches pin the template across the target, not along it: on the bend (isometric) the fit's
// error is the template sliding within the surface, which the landmarks' pull holds
// (RegistrationBenchmark: 1.09% of the diagonal at LandmarkWeight 1, 0.87% at its 1000, on the
// remeshed bend). Weighed as one matched vertex each, the landmarks leave at least 10% more.
TEST(SurfaceRegistration, LandmarksHoldTheTemplateFromSliding)
{
  KnownWarps::Warp warp = KnownWarps::Bend(DataDir);
  ASSERT_TRUE(warp.Mesh);
  const RegistrationCases::Case fit = RegistrationCases::MakeCase("remeshed", warp, 8, 3);
  const double diagonal = warp.Mesh->GetLength();
  double errors[2];
  for (int k = 0; k < 2; ++k)
  {
    auto registration = Registration(warp.Mesh, fit.Target, Landmarks(fit.Sources, fit.Targets));
    if (k == 0)
    {
      registration->SetLandmarkWeight(1.0); // the default second
    }
    registration->Update();
    errors[k] = RegistrationCases::Measure(
      vtkPolyData::SafeDownCast(registration->GetOutput()), fit, diagonal).Correspondence;
  }
  std::printf("bend, correspondence: %.3f%% at LandmarkWeight 1, %.3f%% at the default\n", errors[0],
    errors[1]);
  EXPECT_GT(errors[0], 1.1 * errors[1]);
}

// The turned head's target is a smooth shear of the template (up to 83% across the body), which
// the stages' rigid prior resists (0.49 times the landmark warp's error, RegistrationBenchmark)
// and the smooth warp reaches (0.19-0.21 times there): the warp's fit is kept, within the
// issue's 0.35 times, with no triangle turned over; without the warp the stages' fit is the
// output, farther from the truth.
TEST(SurfaceRegistration, SmoothWarpReachesAStrainedTarget)
{
  KnownWarps::Warp warp = KnownWarps::TurnedHead(DataDir);
  ASSERT_TRUE(warp.Mesh);
  const RegistrationCases::Case fit = RegistrationCases::MakeCase("remeshed", warp, 8, 3);
  const double diagonal = warp.Mesh->GetLength();
  const double landmarksOnly = LandmarkWarpMeasures(warp, fit).Correspondence;
  double errors[2];
  for (const int rounds : { 12, 0 })
  {
    auto registration = Registration(warp.Mesh, fit.Target, Landmarks(fit.Sources, fit.Targets));
    registration->SetWarpRounds(rounds);
    registration->Update();
    const RegistrationCases::Measures fitted = RegistrationCases::Measure(
      vtkPolyData::SafeDownCast(registration->GetOutput()), fit, diagonal);
    EXPECT_EQ(registration->GetWarpKept(), rounds > 0) << rounds << " rounds";
    if (rounds > 0)
    {
      EXPECT_EQ(fitted.TurnedOver, 0); // the stages alone turn two over at the muzzle
    }
    errors[rounds > 0 ? 0 : 1] = fitted.Correspondence;
  }
  EXPECT_LT(errors[0], 0.35 * landmarksOnly);
  EXPECT_LT(errors[0], 0.6 * errors[1]) << "the stages alone";
}

TEST(SurfaceRegistration, VolumeTemplateFollowsWithoutInvertingACell)
{
  // A hexahedral beam fitted onto its own boundary bent into an arc (a radian over its length,
  // the sections turned with it), with its ends' corners as landmarks: the boundary lands on
  // the bent surface, the interior follows as the bend moves it, and no cell inverts.
  vtkSmartPointer<vtkUnstructuredGrid> beam = VolumeMeshes::HexBeam(40, 5, 5, 8.0);
  const double radius = 8.0;
  auto bend = [radius](const double* p, double* q) {
    const double angle = p[0] / radius, arm = radius - p[2];
    q[0] = arm * std::sin(angle);
    q[1] = p[1];
    q[2] = radius - arm * std::cos(angle);
  };
  vtkNew<vtkDataSetSurfaceFilter> boundary;
  boundary->SetInputData(beam);
  vtkNew<vtkTriangleFilter> triangles;
  triangles->SetInputConnection(boundary->GetOutputPort());
  triangles->Update();
  vtkNew<vtkPolyData> bent;
  bent->DeepCopy(triangles->GetOutput());
  for (vtkIdType i = 0; i < bent->GetNumberOfPoints(); ++i)
  {
    double q[3];
    bend(bent->GetPoint(i), q);
    bent->GetPoints()->SetPoint(i, q);
  }
  // The corners of the beam's ends as landmarks, as a user would place them.
  vtkNew<vtkPoints> corners, places;
  for (double x : { 0.0, 8.0 })
  {
    for (double y : { 0.0, 1.0 })
    {
      for (double z : { 0.0, 1.0 })
      {
        const double p[3] = { x, y, z };
        double q[3];
        bend(p, q);
        corners->InsertNextPoint(p);
        places->InsertNextPoint(q);
      }
    }
  }
  auto registration = Registration(beam, bent, Landmarks(corners, places));
  ErrorCatcher errors(registration);
  registration->Update();
  EXPECT_TRUE(errors.Messages.empty()) << errors.Messages;
  auto* output = vtkUnstructuredGrid::SafeDownCast(registration->GetOutput());
  ASSERT_NE(output, nullptr);
  EXPECT_EQ(VolumeMeshes::Measure(output).Inverted, 0);
  EXPECT_TRUE(output->GetCellData()->GetArray("ScaledJacobian"));
  EXPECT_GT(ExpectDisplacement(beam, output), 1.0);
  // The boundary on the bent surface: within 0.5% of the diagonal in the root-mean-square, each
  // trusted point within 2% (measured: 0.32% and 1.6%; the beam's inner face is an eighth
  // shorter on the arc, which an as-rigid-as-possible fit meets only where landing may tilt its
  // triangles, so the ends' faces land least); the interior's centre line where the bend puts
  // it.
  vtkDataArray* distances = output->GetPointData()->GetArray("DistanceToTarget");
  vtkDataArray* trusted = output->GetPointData()->GetArray("MatchTrusted");
  ASSERT_TRUE(distances && trusted);
  const double diagonal = beam->GetLength();
  EXPECT_LT(registration->GetRMSDistanceToTarget(), 0.005 * diagonal);
  EXPECT_GT(registration->GetTrustedFraction(), 0.9);
  int interior = 0;
  for (vtkIdType i = 0; i < beam->GetNumberOfPoints(); ++i)
  {
    const double* p = beam->GetPoint(i);
    if (trusted->GetTuple1(i) != 0.0)
    {
      EXPECT_LT(distances->GetTuple1(i), 0.02 * diagonal) << "boundary point " << i;
    }
    if (p[1] == 0.4 && p[2] == 0.4 && p[0] > 0.0 && p[0] < 8.0)
    {
      ++interior;
      double q[3];
      bend(p, q);
      EXPECT_LT(std::sqrt(vtkMath::Distance2BetweenPoints(output->GetPoint(i), q)), 0.02 * diagonal)
        << "interior point " << i;
    }
  }
  EXPECT_EQ(interior, 39);
}

TEST(SurfaceRegistration, OutputCarriesItsArrays)
{
  vtkSmartPointer<vtkPolyData> plane = WithIds(BumpyPlane(30));
  vtkNew<vtkPolyData> target;
  target->DeepCopy(plane);
  vtkNew<vtkPoints> raised;
  for (vtkIdType i = 0; i < plane->GetNumberOfPoints(); ++i)
  {
    const double* p = plane->GetPoint(i);
    raised->InsertNextPoint(p[0], p[1], p[2] + 0.05 * p[0] * p[0]);
  }
  target->SetPoints(raised);
  auto registration = Registration(plane, target);
  registration->SetPoseMode(vtkLaplacianSurfaceRegistration::POSE_NONE);
  registration->Update();
  vtkPointSet* output = registration->GetOutput();
  ASSERT_EQ(output->GetNumberOfPoints(), plane->GetNumberOfPoints());
  EXPECT_TRUE(output->GetPointData()->GetArray("PointIds"));
  EXPECT_TRUE(output->GetCellData()->GetArray("CellIds"));
  EXPECT_GT(ExpectDisplacement(plane, output), 0.0);
  vtkDataArray* distances = output->GetPointData()->GetArray("DistanceToTarget");
  vtkDataArray* trusted = output->GetPointData()->GetArray("MatchTrusted");
  ASSERT_TRUE(distances && trusted);
  double squares = 0.0;
  for (vtkIdType i = 0; i < output->GetNumberOfPoints(); ++i)
  {
    squares += distances->GetTuple1(i) * distances->GetTuple1(i);
  }
  EXPECT_NEAR(std::sqrt(squares / output->GetNumberOfPoints()),
    registration->GetRMSDistanceToTarget(), 1e-12);
  vtkFieldData* field = output->GetFieldData();
  ASSERT_TRUE(field->GetArray("FitRounds") && field->GetArray("RMSDistanceToTarget") &&
    field->GetArray("FitSeconds"));
  EXPECT_EQ(field->GetArray("FitRounds")->GetTuple1(0),
    registration->GetWarpRounds() + registration->GetNumberOfStages() * registration->GetRoundsPerStage());
  EXPECT_LT(registration->GetRMSDistanceToTarget(), 1e-3 * Diagonal(plane));
}

TEST(SurfaceRegistration, ProgressRisesAndAbortEndsAtAShape)
{
  vtkSmartPointer<vtkPolyData> plane = BumpyPlane(30);
  vtkNew<vtkPolyData> target;
  target->DeepCopy(plane);
  auto registration = Registration(plane, target);
  struct Watch
  {
    std::vector<double> Progress;
    double AbortAt = 2.0;
  } watch;
  vtkNew<vtkCallbackCommand> observer;
  observer->SetClientData(&watch);
  observer->SetCallback([](vtkObject* caller, unsigned long, void* data, void* progress) {
    auto* seen = static_cast<Watch*>(data);
    seen->Progress.push_back(*static_cast<double*>(progress));
    if (seen->Progress.back() > seen->AbortAt)
    {
      static_cast<vtkAlgorithm*>(caller)->AbortExecuteOn();
    }
  });
  registration->AddObserver(vtkCommand::ProgressEvent, observer);
  registration->Update();
  ASSERT_FALSE(watch.Progress.empty());
  for (std::size_t k = 1; k < watch.Progress.size(); ++k)
  {
    EXPECT_GE(watch.Progress[k], watch.Progress[k - 1]) << "progress event " << k;
  }
  EXPECT_EQ(watch.Progress.back(), 1.0);
  const int rounds = registration->GetNumberOfRounds();
  // Aborted halfway: fewer rounds, no error, and a shape on the target's side of the template.
  watch.Progress.clear();
  watch.AbortAt = 0.5;
  registration->Modified();
  ErrorCatcher errors(registration);
  registration->Update();
  registration->AbortExecuteOff();
  EXPECT_TRUE(errors.Messages.empty()) << errors.Messages;
  EXPECT_EQ(registration->GetErrorCode(), vtkErrorCode::NoError);
  EXPECT_GT(registration->GetNumberOfRounds(), 0);
  EXPECT_LT(registration->GetNumberOfRounds(), rounds);
  EXPECT_EQ(registration->GetOutput()->GetNumberOfPoints(), plane->GetNumberOfPoints());
  EXPECT_TRUE(registration->GetOutput()->GetPointData()->GetArray("DistanceToTarget"));
}

class RepeatedFit : public ::testing::TestWithParam<const char*>
{
};

TEST_P(RepeatedFit, IsTheSameToTheBit)
{
  // A fit's threads split its loops and sort its locators' cells differently from run to run;
  // the result must not change. Before, a rotation depended on its batch mates in the local
  // step, and of equally near target triangles the locator returned any: the bend's fit varied
  // in the fourth digit of its error, and by up to 1e-4 of the diagonal within one process. Two
  // filters fit the same case, then the first again: the same bits.
  KnownWarps::Warp warp = KnownWarps::Bend(DataDir);
  ASSERT_TRUE(warp.Mesh);
  const RegistrationCases::Case fit = RegistrationCases::MakeCase(GetParam(), warp, 8, 3);
  auto first = Registration(warp.Mesh, fit.Target, Landmarks(fit.Sources, fit.Targets));
  first->Update();
  auto second = Registration(warp.Mesh, fit.Target, Landmarks(fit.Sources, fit.Targets));
  second->Update();
  EXPECT_EQ(MaxPointDistance(first->GetOutput(), second->GetOutput()), 0.0);
  first->Modified();
  first->Update();
  EXPECT_EQ(MaxPointDistance(first->GetOutput(), second->GetOutput()), 0.0);
}

INSTANTIATE_TEST_SUITE_P(Bend, RepeatedFit, ::testing::Values("remeshed", "cloud"));

TEST(SurfaceRegistration, TargetLandmarksPairByLabel)
{
  // The template's landmarks on port 2 and the target's on port 3, labelled and in another
  // order (two Slicer markups files), fit as the same pairs given in a Target array do.
  vtkSmartPointer<vtkPolyData> plane = BumpyPlane(30);
  vtkNew<vtkPolyData> target;
  target->DeepCopy(plane);
  vtkNew<vtkPoints> raised;
  raised->SetDataTypeToDouble();
  for (vtkIdType i = 0; i < plane->GetNumberOfPoints(); ++i)
  {
    const double* p = plane->GetPoint(i);
    raised->InsertNextPoint(p[0], p[1], p[2] + 0.05 * p[0] * p[0]);
  }
  target->SetPoints(raised);
  const std::vector<vtkIdType> ids = { 0, 29, 465, 930, 960 };
  const std::vector<std::string> names = { "a", "b", "c", "d", "e" };
  vtkNew<vtkPoints> sources, targets, reordered;
  sources->SetDataTypeToDouble();
  targets->SetDataTypeToDouble();
  reordered->SetDataTypeToDouble();
  vtkNew<vtkStringArray> labels, reorderedLabels;
  labels->SetName("Label");
  reorderedLabels->SetName("Label");
  for (std::size_t k = 0; k < ids.size(); ++k)
  {
    sources->InsertNextPoint(plane->GetPoint(ids[k]));
    targets->InsertNextPoint(raised->GetPoint(ids[k]));
    labels->InsertNextValue(names[k]);
    const std::size_t back = ids.size() - 1 - k;
    reordered->InsertNextPoint(raised->GetPoint(ids[back]));
    reorderedLabels->InsertNextValue(names[back]);
  }
  auto paired = Registration(plane, target, Landmarks(sources, targets));
  paired->Update();
  vtkNew<vtkPolyData> templateMarkups, targetMarkups;
  templateMarkups->SetPoints(sources);
  templateMarkups->GetPointData()->AddArray(labels);
  targetMarkups->SetPoints(reordered);
  targetMarkups->GetPointData()->AddArray(reorderedLabels);
  auto labelled = Registration(plane, target, templateMarkups);
  labelled->SetTargetLandmarksData(targetMarkups);
  ErrorCatcher errors(labelled);
  labelled->Update();
  EXPECT_TRUE(errors.Messages.empty()) << errors.Messages;
  EXPECT_GT(ExpectDisplacement(plane, labelled->GetOutput()), 0.0);
  // The same pairs give the same fit, to the bit (RepeatedFit); paired in order, the reordered
  // markups pull the template elsewhere.
  const double diagonal = Diagonal(plane);
  EXPECT_EQ(MaxPointDistance(paired->GetOutput(), labelled->GetOutput()), 0.0);
  vtkNew<vtkPolyData> unlabelled;
  unlabelled->SetPoints(reordered);
  auto inOrder = Registration(plane, target, templateMarkups);
  inOrder->SetTargetLandmarksData(unlabelled);
  inOrder->Update();
  EXPECT_GT(MaxPointDistance(paired->GetOutput(), inOrder->GetOutput()), 1e-2 * diagonal);

  // A label on one side only, and the target's landmarks without the template's, are errors.
  reorderedLabels->SetValue(0, "z");
  targetMarkups->Modified();
  ErrorCatcher unpaired(labelled);
  labelled->Update();
  EXPECT_NE(unpaired.Messages.find("2 landmark labels are on one side only: e (sources only), "
                                   "z (targets only)"),
    std::string::npos)
    << unpaired.Messages;
  EXPECT_EQ(MaxPointDistance(plane, labelled->GetOutput()), 0.0);
  auto alone = Registration(plane, target);
  alone->SetTargetLandmarksData(targetMarkups);
  ErrorCatcher missing(alone);
  alone->Update();
  EXPECT_NE(missing.Messages.find("need the template's on input port 2"), std::string::npos)
    << missing.Messages;
}

TEST(SurfaceRegistration, BadInputsAreClearErrors)
{
  vtkSmartPointer<vtkPolyData> plane = BumpyPlane(20);
  const double* corner = plane->GetPoint(0);
  vtkNew<vtkPolyData> target;
  target->DeepCopy(plane);
  auto expectError = [&plane](vtkLaplacianSurfaceRegistration* registration,
                       vtkPolyData* input, const std::string& phrase) {
    ErrorCatcher errors(registration);
    registration->Update();
    EXPECT_NE(errors.Messages.find(phrase), std::string::npos)
      << "wanted \"" << phrase << "\", got: " << errors.Messages;
    EXPECT_EQ(registration->GetErrorCode(), vtkErrorCode::UserError) << phrase;
    vtkPointSet* output = registration->GetOutput();
    ASSERT_EQ(output->GetNumberOfPoints(), input->GetNumberOfPoints()) << phrase;
    EXPECT_EQ(MaxPointDistance(input, output), 0.0) << phrase;
    (void)plane;
  };
  {
    vtkNew<vtkPolyData> empty;
    auto registration = Registration(empty, target);
    expectError(registration, empty, "The input mesh is empty");
  }
  {
    vtkNew<vtkPolyData> nowhere;
    auto registration = Registration(plane, nowhere);
    expectError(registration, plane, "The target (input port 1) has no points");
  }
  {
    vtkNew<vtkPolyData> broken;
    broken->DeepCopy(target);
    broken->GetPoints()->SetPoint(7, std::numeric_limits<double>::quiet_NaN(), 0.0, 0.0);
    auto registration = Registration(plane, broken);
    expectError(registration, plane, "Target point 7 has a NaN");
  }
  {
    vtkNew<vtkPoints> sources, targets;
    sources->InsertNextPoint(corner);
    targets->InsertNextPoint(corner);
    sources->InsertNextPoint(plane->GetPoint(5));
    targets->InsertNextPoint(plane->GetPoint(5));
    auto registration = Registration(plane, target, Landmarks(sources, targets));
    expectError(registration, plane, "at least three landmark pairs");
  }
  {
    vtkNew<vtkPoints> sources, targets;
    for (vtkIdType i : { 0, 10, 20 })
    {
      sources->InsertNextPoint(plane->GetPoint(i));
      targets->InsertNextPoint(plane->GetPoint(i));
    }
    sources->SetPoint(1, 100.0, 100.0, 100.0);
    auto registration = Registration(plane, target, Landmarks(sources, targets));
    registration->SetPoseMode(vtkLaplacianSurfaceRegistration::POSE_NONE);
    expectError(registration, plane, "lies on no component");
  }
  {
    vtkNew<vtkPolyData> landmarks;
    landmarks->SetPoints(plane->GetPoints());
    auto registration = Registration(plane, target, landmarks);
    expectError(registration, plane, "\"Target\"");
  }
}
