// Point constraints (a landmark warp's), without VTK: points inside triangles pulled to their
// own targets, in every rotation mode, softly or exactly, on a region of whole components.
#include "NumericsTestMeshes.h"

#include "LaplacianEditor.h"
#include "ThinPlateSpline.h"

#include <Eigen/Dense>
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <random>

using namespace LaplacianEditing;
using namespace LaplacianEditing::Testing;

namespace
{
const RotationMode Modes[] = { RotationMode::None, RotationMode::Explicit, RotationMode::Implicit,
  RotationMode::AsRigidAsPossible };

// `count` points inside random triangles of `mesh`, at random barycentric weights.
std::vector<SurfacePoint> RandomPoints(const SurfaceMesh& mesh, int count, unsigned seed = 7)
{
  std::mt19937 random(seed);
  std::uniform_int_distribution<int> triangle(0, mesh.GetNumberOfTriangles() - 1);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<SurfacePoint> points(count);
  for (SurfacePoint& point : points)
  {
    const auto& corners = mesh.GetTriangles()[triangle(random)];
    double a = unit(random), b = unit(random);
    if (a + b > 1.0)
    {
      a = 1.0 - a;
      b = 1.0 - b;
    }
    point.Vertices = corners;
    point.Weights = { { a, b, 1.0 - a - b } };
  }
  return points;
}

// An editor of the whole tube held by `points` alone, in `mode`.
struct Warp
{
  std::shared_ptr<const SurfaceMesh> Mesh = std::make_shared<SurfaceMesh>(MakeTube(16, 24));
  std::shared_ptr<const std::vector<SurfacePoint>> Points;
  LaplacianEditor Editor;

  Warp(RotationMode mode, int count, double weight = 100.0, double splinePrior = 0.0)
    : Warp(mode, RandomPoints(MakeTube(16, 24), count), weight, splinePrior)
  {
  }

  Warp(RotationMode mode, std::vector<SurfacePoint> points, double weight, double splinePrior = 0.0)
    : Points(std::make_shared<std::vector<SurfacePoint>>(std::move(points)))
  {
    this->Editor.SetMesh(this->Mesh);
    RegionRequest region;
    region.Selection = RegionRequest::Kind::Components;
    region.Seeds = { this->Points->front().Vertices[0] };
    DeformationOptions system;
    system.Weights = LaplacianWeights::Cotangent;
    system.LeastSquares = mode != RotationMode::AsRigidAsPossible;
    system.Points = this->Points;
    system.PointsVersion = 1;
    system.PointWeight = weight;
    system.SplinePrior = splinePrior;
    EXPECT_TRUE(this->Editor.UpdateRegion(region, nullptr, system).Ok());
    RotationOptions rotation;
    rotation.Mode = mode;
    rotation.NormalSmoothingRadius = 0.1;
    rotation.Arap.MaximumIterations = 300;
    rotation.Arap.Tolerance = 1e-9;
    EXPECT_TRUE(this->Editor.UpdateRotationModel(rotation).Ok());
  }

  // The points where the rest shape has them.
  Positions RestTargets() const
  {
    Positions targets(static_cast<Eigen::Index>(this->Points->size()), 3);
    for (std::size_t p = 0; p < this->Points->size(); ++p)
    {
      const SurfacePoint& point = (*this->Points)[p];
      Vector3 x = Vector3::Zero();
      for (int c = 0; c < 3; ++c)
      {
        x += point.Weights[c] * this->Mesh->GetPositions()[point.Vertices[c]];
      }
      targets.row(static_cast<Eigen::Index>(p)) = x.transpose();
    }
    return targets;
  }

  Positions Rest() const
  {
    const std::vector<int>& vertices = this->Editor.GetRegion().Vertices;
    Positions rest(static_cast<Eigen::Index>(vertices.size()), 3);
    for (std::size_t k = 0; k < vertices.size(); ++k)
    {
      rest.row(static_cast<Eigen::Index>(k)) = this->Mesh->GetPositions()[vertices[k]].transpose();
    }
    return rest;
  }

  Positions Solve(const Positions& targets, bool exact = true)
  {
    PointTargets points;
    points.Targets = targets;
    points.Exact = exact;
    Positions solution;
    EXPECT_TRUE(this->Editor.Solve({}, solution, &points).Ok());
    return solution;
  }
};

// A bend: z turned toward x about the tube's base, by `angle` at the top.
Vector3 Bend(const Vector3& p, double angle)
{
  const double turn = angle * p.z();
  return Vector3(p.x() * std::cos(turn) + p.z() * std::sin(turn), p.y(),
    -p.x() * std::sin(turn) + p.z() * std::cos(turn));
}
}

TEST(PointConstraints, TheRegionIsTheWholeComponentAndFree)
{
  Warp warp(RotationMode::None, 20);
  const EditRegion& region = warp.Editor.GetRegion();
  EXPECT_EQ(region.GetNumberOfVertices(), warp.Mesh->GetNumberOfVertices());
  for (const VertexRole role : region.Roles)
  {
    EXPECT_EQ(role, VertexRole::Free);
  }
}

TEST(PointConstraints, PointsAtTheirSourcesGiveTheRestBack)
{
  for (const RotationMode mode : Modes)
  {
    for (const bool exact : { true, false })
    {
      SCOPED_TRACE(static_cast<int>(mode) * 2 + exact);
      Warp warp(mode, 30);
      const Positions solution = warp.Solve(warp.RestTargets(), exact);
      // Every mode solves for the displacement from the rest, which vanishes here.
      EXPECT_LE((solution - warp.Rest()).cwiseAbs().maxCoeff(), 1e-13);
    }
  }
}

TEST(PointConstraints, AnExactFitMeetsEveryTarget)
{
  for (const RotationMode mode : Modes)
  {
    SCOPED_TRACE(static_cast<int>(mode));
    Warp warp(mode, 40);
    Positions targets = warp.RestTargets();
    for (Eigen::Index p = 0; p < targets.rows(); ++p)
    {
      targets.row(p) = Bend(targets.row(p).transpose(), 0.8).transpose();
    }
    const Positions solution = warp.Solve(targets);
    EXPECT_LE(warp.Editor.GetLargestPointMiss(), 1e-10);
    EXPECT_TRUE(solution.allFinite());
  }
}

TEST(PointConstraints, ARigidMotionOfEveryPointMovesTheSurfaceRigidly)
{
  // As rigid as possible: the rigid motion has zero energy and meets every point.
  Warp warp(RotationMode::AsRigidAsPossible, 40);
  const Eigen::Matrix3d rotation =
    Eigen::AngleAxisd(1.0, Vector3(1.0, 2.0, 0.5).normalized()).toRotationMatrix();
  const Vector3 translation(0.3, -0.2, 0.4);
  Positions targets = warp.RestTargets();
  for (Eigen::Index p = 0; p < targets.rows(); ++p)
  {
    targets.row(p) = (rotation * targets.row(p).transpose() + translation).transpose();
  }
  const Positions solution = warp.Solve(targets);
  const Positions rest = warp.Rest();
  double worst = 0.0;
  for (Eigen::Index k = 0; k < rest.rows(); ++k)
  {
    worst = std::max(worst,
      (solution.row(k).transpose() - (rotation * rest.row(k).transpose() + translation)).norm());
  }
  std::printf("rigid motion: largest distance %.3g (tube length 1)\n", worst);
  EXPECT_LE(worst, 1e-8);
}

TEST(PointConstraints, ASofterPullMissesMore)
{
  double misses[2];
  const double weights[2] = { 0.3, 30.0 };
  for (int k = 0; k < 2; ++k)
  {
    Warp warp(RotationMode::AsRigidAsPossible, 40, weights[k]);
    Positions targets = warp.RestTargets();
    targets.col(0).array() += 0.05 * targets.col(2).array().square();
    warp.Solve(targets, false);
    misses[k] = warp.Editor.GetLargestPointMiss();
  }
  std::printf("soft fit: largest miss %.3g at weight 0.3, %.3g at 30\n", misses[0], misses[1]);
  EXPECT_GT(misses[0], 10.0 * misses[1]);
  EXPECT_GT(misses[1], 0.0);
}

// A point's pull counts as that many points: pulls 1 and 3 on one place, its targets d and -d
// apart, are one point of pull 4 at their weighted mean (the same energy but for a constant).
TEST(PointConstraints, APullCountsAsThatManyPoints)
{
  const std::vector<SurfacePoint> points = RandomPoints(MakeTube(16, 24), 40);
  const Vector3 d(0.05, 0.02, 0.0);
  for (const RotationMode mode : Modes)
  {
    SCOPED_TRACE(static_cast<int>(mode));
    std::vector<SurfacePoint> pair = points, single = points;
    pair.push_back(points.front());
    pair.back().Pull = 3.0;
    single.front().Pull = 4.0;
    Warp paired(mode, pair, 1.0), merged(mode, single, 1.0);
    Positions pairTargets = paired.RestTargets(), singleTargets = merged.RestTargets();
    pairTargets.row(0) += d.transpose();
    pairTargets.row(40) -= d.transpose();
    singleTargets.row(0) -= 0.5 * d.transpose();
    const Positions a = paired.Solve(pairTargets, false), b = merged.Solve(singleTargets, false);
    const double moved = (a - paired.Rest()).rowwise().norm().maxCoeff();
    const double apart = (a - b).rowwise().norm().maxCoeff();
    std::printf("pulls 1 and 3 against one of 4: largest difference %.3g (the point moved %.3g)\n",
      apart, moved);
    EXPECT_GT(moved, 0.1 * d.norm());
    // The linear modes solve once, to round-off; ARAP's local-global iterations stop at their
    // tolerance (1e-9) from two starts.
    EXPECT_LE(apart, (mode == RotationMode::AsRigidAsPossible ? 1e-4 : 1e-12) * moved);
  }
}

TEST(PointConstraints, NewTargetsOnlySolve)
{
  for (const RotationMode mode : Modes)
  {
    SCOPED_TRACE(static_cast<int>(mode));
    Warp warp(mode, 40);
    const int factorizations = warp.Editor.GetNumberOfFactorizations();
    Positions targets = warp.RestTargets();
    for (int move = 1; move <= 3; ++move)
    {
      targets(0, 0) += 0.02;
      warp.Solve(targets);
      EXPECT_LE(warp.Editor.GetLargestPointMiss(), 1e-10);
    }
    EXPECT_EQ(warp.Editor.GetNumberOfFactorizations(), factorizations);
  }
}

TEST(PointConstraints, TargetsAreRequired)
{
  Warp warp(RotationMode::None, 5);
  Positions solution;
  const EditStatus status = warp.Editor.Solve({}, solution);
  EXPECT_FALSE(status.Ok());
  EXPECT_NE(status.Error.find("target"), std::string::npos);
}

TEST(PointConstraints, TheSplinePriorKeepsTheRestAndRigidMotions)
{
  // The spline reproduces affine maps, so the prior pulls towards the rest shape or its rigid
  // motion exactly where the rigid energy has its minimum.
  Warp warp(RotationMode::AsRigidAsPossible, 40, 100.0, 1.0);
  const Positions rest = warp.Rest();
  EXPECT_LE((warp.Solve(warp.RestTargets()) - rest).cwiseAbs().maxCoeff(), 1e-12);
  const Eigen::Matrix3d rotation =
    Eigen::AngleAxisd(1.0, Vector3(1.0, 2.0, 0.5).normalized()).toRotationMatrix();
  const Vector3 translation(0.3, -0.2, 0.4);
  auto rigid = [&](const Positions& points) {
    Positions moved = points * rotation.transpose();
    moved.rowwise() += translation.transpose();
    return moved;
  };
  EXPECT_LE((warp.Solve(rigid(warp.RestTargets())) - rigid(rest)).cwiseAbs().maxCoeff(), 1e-8);
}

TEST(PointConstraints, TheSplinePriorBendsSparsePointsAsTheSplineDoes)
{
  // Eight points bend the tube: without the prior, the rigid energy's own bend; with it, the
  // shape nears the spline's bend of the rest shape (measured: 0.111 without, 0.051 with).
  Positions spline;
  double distances[2];
  for (const double prior : { 0.0, 1.0 })
  {
    Warp warp(RotationMode::AsRigidAsPossible, 8, 100.0, prior);
    Positions targets = warp.RestTargets();
    for (Eigen::Index p = 0; p < targets.rows(); ++p)
    {
      targets.row(p) = Bend(targets.row(p).transpose(), 0.8).transpose();
    }
    ThinPlateSpline reference;
    ASSERT_TRUE(reference.Fit(warp.RestTargets()));
    spline = warp.Rest() + reference.Displace(targets - warp.RestTargets(), warp.Rest());
    distances[prior > 0.0] = (warp.Solve(targets) - spline).rowwise().norm().maxCoeff();
  }
  std::printf("largest distance from the spline's bend: %.3g without the prior, %.3g with\n",
    distances[0], distances[1]);
  EXPECT_LT(distances[1], 0.6 * distances[0]);
}

TEST(PointConstraints, ADraggedPointEndsWhereAFreshSolveDoes)
{
  // A drag moves the prior by the dragged point's cardinal function, not by a refit: converged,
  // it ends where a solve of the last targets from scratch does.
  Warp dragged(RotationMode::AsRigidAsPossible, 40, 100.0, 1.0);
  Positions targets = dragged.RestTargets();
  for (int frame = 1; frame <= 5; ++frame)
  {
    targets.row(3) += Eigen::RowVector3d(0.01, 0.02, -0.01);
    dragged.Solve(targets);
  }
  Warp fresh(RotationMode::AsRigidAsPossible, 40, 100.0, 1.0);
  const double difference = (dragged.Solve(targets) - fresh.Solve(targets)).cwiseAbs().maxCoeff();
  std::printf("dragged against fresh: largest difference %.3g (tube length 1)\n", difference);
  EXPECT_LE(difference, 1e-6);
}
