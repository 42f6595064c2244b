// The paper's central claim, measured: explicit (Sections 4, 7) and implicit (Section 5)
// rotation of the differential coordinates keeps details in their natural orientation.
#include "FilterTestHelpers.h"

#include "vtkCleanPolyData.h"
#include "vtkIntArray.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkSphereSource.h"
#include "vtkSignedCharArray.h"

#include <Eigen/Dense>
#include <gtest/gtest.h>

#include <array>

#include <cstdio>
#include <vector>

namespace
{
using Filter = vtkLaplacianDeformationFilter;

vtkSmartPointer<vtkPolyData> WithSelection(vtkPolyData* mesh, int (*label)(const double p[3]))
{
  auto labelled = vtkSmartPointer<vtkPolyData>::New();
  labelled->ShallowCopy(mesh);
  vtkNew<vtkIntArray> selection;
  selection->SetName("Selection");
  for (vtkIdType i = 0; i < mesh->GetNumberOfPoints(); ++i)
  {
    selection->InsertNextValue(label(mesh->GetPoint(i)));
  }
  labelled->GetPointData()->AddArray(selection);
  return labelled;
}

vtkSmartPointer<Filter> ArrayEdit(vtkPolyData* labelled, int mode)
{
  auto filter = vtkSmartPointer<Filter>::New();
  filter->SetInputData(labelled);
  filter->SetSelectionModeToArray();
  filter->SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, "Selection");
  filter->SetRotationMode(mode);
  return filter;
}

// A closed sphere, entirely in the ROI, held by two polar caps (handle groups 0 and 1).
vtkSmartPointer<vtkPolyData> CappedSphere()
{
  vtkNew<vtkSphereSource> sphere;
  sphere->SetThetaResolution(60);
  sphere->SetPhiResolution(40);
  vtkNew<vtkCleanPolyData> clean;
  clean->SetInputConnection(sphere->GetOutputPort());
  clean->Update();
  return WithSelection(clean->GetOutput(),
    [](const double p[3]) { return p[2] > 0.4 ? 2 : (p[2] < -0.4 ? 3 : 1); });
}

// Moves both caps by one rotation about the x axis and returns the largest distance of any
// output point from the rotated input, relative to the diagonal.
double RigidError(Filter* filter, vtkPolyData* input, double degrees)
{
  vtkNew<vtkTransform> rotation;
  rotation->RotateX(degrees);
  filter->SetAnchorPadding(0.0);
  filter->SetHandleTransform(0, rotation);
  filter->SetHandleTransform(1, rotation);
  filter->Update();
  double worst = 0.0;
  for (vtkIdType i = 0; i < input->GetNumberOfPoints(); ++i)
  {
    double expected[3], actual[3];
    rotation->TransformPoint(input->GetPoint(i), expected);
    filter->GetOutput()->GetPoint(i, actual);
    worst = std::max(worst, std::sqrt(vtkMath::Distance2BetweenPoints(expected, actual)));
  }
  return worst / Diagonal(input);
}

// Mean distance of the equator band from its centre, relative to the rest: the scale of the
// shape after a rigid rotation of the caps (1 when the shape is kept).
double EquatorScale(vtkPolyData* rest, vtkPolyData* edited)
{
  auto meanRadius = [](vtkPolyData* mesh, vtkPolyData* band) {
    Eigen::Vector3d center = Eigen::Vector3d::Zero();
    std::vector<Eigen::Vector3d> points;
    for (vtkIdType i = 0; i < mesh->GetNumberOfPoints(); ++i)
    {
      if (std::abs(band->GetPoint(i)[2]) < 0.1)
      {
        points.emplace_back(mesh->GetPoint(i));
        center += points.back();
      }
    }
    center /= static_cast<double>(points.size());
    double sum = 0.0;
    for (const auto& p : points)
    {
      sum += (p - center).norm();
    }
    return sum / points.size();
  };
  return meanRadius(edited, rest) / meanRadius(rest, rest);
}
}

class RigidMotion : public ::testing::TestWithParam<double>
{
};

TEST_P(RigidMotion, ExplicitRotationsReproduceIt)
{
  // Tolerance: with 5 iterations the output is within 1e-4 of the diagonal of the rotated
  // sphere at 10, 45 and 90 degrees; one pass (the paper's method) is at least 5 times closer
  // than no rotation.
  const double degrees = GetParam();
  auto sphere = CappedSphere();
  const double none = RigidError(ArrayEdit(sphere, Filter::ROTATION_NONE), sphere, degrees);
  std::printf("rigid %3.0f deg: none %.2e; explicit, iterations 1..10:", degrees, none);
  double byIterations[11];
  for (int k : { 1, 2, 3, 5, 10 })
  {
    auto filter = ArrayEdit(sphere, Filter::ROTATION_EXPLICIT);
    filter->SetNumberOfIterations(k);
    byIterations[k] = RigidError(filter, sphere, degrees);
    std::printf(" %d: %.2e", k, byIterations[k]);
  }
  std::printf("\n");
  EXPECT_LT(byIterations[1] * 5.0, none);
  EXPECT_LT(byIterations[5], 1e-4);
  EXPECT_LT(byIterations[10], byIterations[3]); // the iteration converges
}

namespace
{
// The rigid error of the implicit mode in `formulation`, without and with the rigid step.
std::array<double, 2> ImplicitRigidErrors(int formulation, double degrees)
{
  auto sphere = CappedSphere();
  std::array<double, 2> errors;
  for (int straighten = 0; straighten <= 1; ++straighten)
  {
    auto filter = ArrayEdit(sphere, Filter::ROTATION_IMPLICIT);
    filter->SetImplicitFormulation(formulation);
    filter->SetPreserveDetailScale(straighten);
    errors[straighten] = RigidError(filter, sphere, degrees);
  }
  return errors;
}
}

TEST_P(RigidMotion, ImplicitSimilaritiesReproduceSmallRotations)
{
  // The linearized similarities are exact only to first order in the angle: required within
  // 3e-3 of the diagonal at 10 degrees; the rigid step (PreserveDetailScale) must cut the error
  // by 20% at every angle. Measured: 1.7e-3 -> 1.1e-3, 45 degrees 3.3e-2 -> 2.2e-2, 90 degrees
  // 0.11 -> 0.083. (The earlier rescaling pass, 6.5e-4 at 10 degrees, re-solved the paper's
  // per-vertex system and undid the per-edge energy's gains on real edits.)
  const double degrees = GetParam();
  const auto errors = ImplicitRigidErrors(Filter::IMPLICIT_PAPER, degrees);
  std::printf("rigid %3.0f deg: implicit %.2e, implicit with the rigid step %.2e\n", degrees,
    errors[0], errors[1]);
  if (degrees <= 10.0)
  {
    EXPECT_LT(errors[0], 3e-3);
  }
  EXPECT_LT(errors[1], 0.8 * errors[0]);
}

TEST_P(RigidMotion, ImplicitPerEdgeRotationsReproduceSmallRotations)
{
  // The default implicit energy fixes the scale, so a linearized rotation I + h x lengthens
  // details by about 1 + angle^2 / 2: required within 6e-3 of the diagonal at 10 degrees
  // (measured 4.6e-3); the rigid step, which takes that growth out, must cut the error by 20%
  // at every angle (measured 2.1e-3; 45 degrees 8.9e-2 -> 4.8e-2, 90 degrees 0.31 -> 0.21). A
  // rigid turn of the whole band converges slowly under local-global steps: ARAP mode, which
  // iterates, reproduces it to 2e-10.
  const double degrees = GetParam();
  const auto errors = ImplicitRigidErrors(Filter::IMPLICIT_PER_EDGE, degrees);
  std::printf("rigid %3.0f deg: implicit per edge %.2e, with the rigid step %.2e\n", degrees,
    errors[0], errors[1]);
  if (degrees <= 10.0)
  {
    EXPECT_LT(errors[0], 6e-3);
  }
  EXPECT_LT(errors[1], 0.8 * errors[0]);
}

INSTANTIATE_TEST_SUITE_P(Angles, RigidMotion, ::testing::Values(10.0, 45.0, 90.0));

TEST(ImplicitScale, TheRigidStepCorrectsTheScaleError)
{
  // Under rotation the linearized rotations change the size of the details. Required: the
  // rigid step leaves at most 40% of the scale error at 45 and 90 degrees (measured: 0.187 ->
  // 0.054 at 45 degrees, 0.453 -> 0.050 at 90).
  auto sphere = CappedSphere();
  for (double degrees : { 45.0, 90.0 })
  {
    double scaleError[2];
    for (int straighten = 0; straighten <= 1; ++straighten)
    {
      auto filter = ArrayEdit(sphere, Filter::ROTATION_IMPLICIT);
      filter->SetPreserveDetailScale(straighten);
      RigidError(filter, sphere, degrees);
      scaleError[straighten] = std::abs(EquatorScale(sphere, filter->GetOutput()) - 1.0);
    }
    std::printf("rigid %3.0f deg: implicit scale error %.3f, with the rigid step %.3f\n", degrees,
      scaleError[0], scaleError[1]);
    EXPECT_LT(scaleError[1], 0.4 * scaleError[0]) << degrees << " degrees";
  }
}

namespace
{
// The paper's Fig. 6 (top): a bumpy plane bent by lifting and tilting its right edge by 60
// degrees, its left edge fixed. Returns the mean angle, in degrees, between each bump's axis
// (base centroid to apex) and the normal of the surface under it (a plane fitted to the ring
// just outside the bump).
double MeanDetailAngle(int mode, int iterations = 1, bool straighten = true, double* worst = nullptr)
{
  BumpyPlaneShape shape;
  shape.Resolution = 80;
  auto plane = WithSelection(shape.Make(),
    [](const double p[3]) { return p[0] < 0.03 ? 0 : (p[0] > 0.97 ? 2 : 1); });
  auto filter = ArrayEdit(plane, mode);
  filter->SetNumberOfIterations(iterations);
  filter->SetPreserveDetailScale(straighten);
  vtkNew<vtkTransform> bend;
  bend->Translate(0.97, 0.5, 0.4);
  bend->RotateY(-60.0);
  bend->Translate(-0.97, -0.5, 0.0);
  filter->SetHandleTransform(bend);
  filter->Update();
  vtkPolyData* edited = filter->GetOutput();

  const double bumpRadius = shape.BumpRadius;
  const int bumps = shape.BumpsPerSide * shape.BumpsPerSide;
  double sum = 0.0;
  double largest = 0.0;
  for (int b = 0; b < bumps; ++b)
  {
    double center[2];
    shape.BumpCenter(b, center);
    vtkIdType apex = 0;
    double apexDistance = VTK_DOUBLE_MAX;
    std::vector<Eigen::Vector3d> base;
    for (vtkIdType i = 0; i < plane->GetNumberOfPoints(); ++i)
    {
      const double* p = plane->GetPoint(i);
      const double d = std::hypot(p[0] - center[0], p[1] - center[1]);
      if (d < apexDistance)
      {
        apexDistance = d;
        apex = i;
      }
      if (d > bumpRadius && d < 1.35 * bumpRadius)
      {
        base.emplace_back(edited->GetPoint(i));
      }
    }
    Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
    for (const auto& p : base)
    {
      centroid += p;
    }
    centroid /= static_cast<double>(base.size());
    Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();
    for (const auto& p : base)
    {
      covariance += (p - centroid) * (p - centroid).transpose();
    }
    const Eigen::Vector3d normal =
      Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(covariance).eigenvectors().col(0);
    const Eigen::Vector3d axis = Eigen::Vector3d(edited->GetPoint(apex)) - centroid;
    const double angle =
      vtkMath::DegreesFromRadians(std::acos(std::abs(axis.normalized().dot(normal))));
    sum += angle;
    largest = std::max(largest, angle);
  }
  if (worst)
  {
    *worst = largest;
  }
  return sum / bumps;
}
}

TEST(DetailOrientation, RotationsKeepBumpsUpright)
{
  // Required: explicit rotations cut the mean bump tilt to under 15% of the value without
  // rotations, implicit ones to under 25%, and three explicit iterations do better than one.
  // Measured: none 24.5 deg, explicit 2.1 (1.1 with 3 iterations), implicit 0.2 (1.3 with the
  // rigid step).
  double worst[5];
  const double none = MeanDetailAngle(Filter::ROTATION_NONE, 1, true, &worst[0]);
  const double explicitOne = MeanDetailAngle(Filter::ROTATION_EXPLICIT, 1, true, &worst[1]);
  const double explicitThree = MeanDetailAngle(Filter::ROTATION_EXPLICIT, 3, true, &worst[2]);
  const double implicitPlain = MeanDetailAngle(Filter::ROTATION_IMPLICIT, 1, false, &worst[3]);
  const double implicitRescaled = MeanDetailAngle(Filter::ROTATION_IMPLICIT, 1, true, &worst[4]);
  std::printf("mean (max) bump tilt, degrees: none %.1f (%.1f), explicit %.1f (%.1f), "
              "explicit x3 %.1f (%.1f), implicit linear %.1f (%.1f), implicit %.1f (%.1f)\n",
    none, worst[0], explicitOne, worst[1], explicitThree, worst[2], implicitPlain, worst[3],
    implicitRescaled, worst[4]);
  std::printf("ratios to none: explicit %.3f, implicit linear %.3f, implicit %.3f\n",
    explicitOne / none, implicitPlain / none, implicitRescaled / none);
  EXPECT_GT(none, 15.0); // the edit really tilts the surface under the bumps
  EXPECT_LT(explicitOne, 0.15 * none);
  EXPECT_LT(explicitThree, explicitOne);
  EXPECT_LT(implicitPlain, 0.25 * none);
  EXPECT_LT(implicitRescaled, 0.25 * none);
}

class EveryMode : public ::testing::TestWithParam<int>
{
};

TEST_P(EveryMode, ReconstructsExactlyKeepsTheOutsideAndReusesTheFactor)
{
  auto input = BumpyPlane();
  auto filter = PlaneEdit(input);
  filter->SetRotationMode(GetParam());
  filter->SetNumberOfIterations(2);
  vtkNew<vtkTransform> handle;
  filter->SetHandleTransform(handle);
  filter->Update();
  EXPECT_LT(MaxPointDistance(input, filter->GetOutput()), 1e-9 * Diagonal(input));
  const int factorizations = filter->GetNumberOfFactorizations();
  // The implicit mode adds its coupled system and its rigid step's Laplacian.
  EXPECT_EQ(factorizations, GetParam() == Filter::ROTATION_IMPLICIT ? 3 : 1);

  for (int move = 1; move <= 4; ++move)
  {
    handle->Identity();
    handle->Translate(0.0, 0.0, 0.05 * move);
    handle->RotateX(5.0 * move);
    filter->Update();
  }
  EXPECT_EQ(filter->GetNumberOfFactorizations(), factorizations);
  vtkPolyData* output = filter->GetOutput();
  auto* roles = vtkSignedCharArray::SafeDownCast(output->GetPointData()->GetArray("EditRole"));
  for (vtkIdType i = 0; i < input->GetNumberOfPoints(); ++i)
  {
    if (roles->GetValue(i) == Filter::ROLE_FIXED)
    {
      double p[3], q[3];
      input->GetPoint(i, p);
      output->GetPoint(i, q);
      ASSERT_TRUE(p[0] == q[0] && p[1] == q[1] && p[2] == q[2]);
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Modes, EveryMode,
  ::testing::Values(Filter::ROTATION_NONE, Filter::ROTATION_EXPLICIT, Filter::ROTATION_IMPLICIT));

TEST(RotationModes, SwitchingModesKeepsTheLaplacianFactor)
{
  auto filter = PlaneEdit(BumpyPlane());
  filter->SetHandleTransform(Translation(0, 0, 0.2));
  filter->Update();
  EXPECT_EQ(filter->GetNumberOfFactorizations(), 1);
  filter->SetRotationModeToExplicit();
  filter->Update();
  EXPECT_EQ(filter->GetNumberOfFactorizations(), 1) << "explicit mode reuses the factor";
  filter->SetNumberOfIterations(3);
  filter->Update();
  EXPECT_EQ(filter->GetNumberOfFactorizations(), 1) << "iterations reuse the factor";
  filter->SetRotationModeToImplicit();
  filter->Update();
  EXPECT_EQ(filter->GetNumberOfFactorizations(), 3)
    << "implicit mode factors its system and its rigid step's Laplacian once";
  filter->PreserveDetailScaleOff();
  filter->SetRotationModeToNone();
  filter->Update();
  filter->SetRotationModeToImplicit();
  filter->Update();
  EXPECT_EQ(filter->GetNumberOfFactorizations(), 3) << "and keeps them";
}
