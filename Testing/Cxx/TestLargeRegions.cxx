// The solvers of regions of any size, without VTK: algebraic multigrid against the direct
// factor, the region's proxy, and the proxy's drag and full-resolution settle against the
// factored as-rigid-as-possible solver.
#include "NumericsTestMeshes.h"

#include "AsRigidAsPossibleSolver.h"
#include "EditRegion.h"
#include "ProxyArapSolver.h"
#include "RegionProxy.h"
#include "SparseCholesky.h"

#include <Eigen/Geometry>
#include <Eigen/SparseCore>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <memory>
#include <random>
#include <vector>

using namespace LaplacianEditing;
using namespace LaplacianEditing::Testing;

namespace
{
constexpr double Pi = 3.14159265358979323846;

// A bumpy 96 x 96 grid (9409 vertices) unless told: the strip x < 0.15 fixed, x > 0.85 the
// handle, the rest the ROI, which a proxy of about 500 nodes stands for.
struct StripEdit
{
  SurfaceMesh Mesh;
  EditRegion Region;
  DeformationOptions Options;

  // The mesh as ProxyArapSolver holds it while its full-resolution system builds.
  std::shared_ptr<const SurfaceMesh> SharedMesh() const { return std::make_shared<const SurfaceMesh>(this->Mesh); }

  explicit StripEdit(bool bothEndsHandles = false, int cells = 96)
    : Mesh(MakeGrid(cells, cells, 1.0,
        [](double x, double y) { return 0.01 * std::sin(12.0 * Pi * x) * std::sin(12.0 * Pi * y); }))
  {
    std::vector<int> labels(this->Mesh.GetNumberOfVertices());
    for (int v = 0; v < this->Mesh.GetNumberOfVertices(); ++v)
    {
      const double x = this->Mesh.GetPositions()[v].x();
      labels[v] = x < 0.15 ? (bothEndsHandles ? 3 : 0) : (x > 0.85 ? 2 : 1);
    }
    EXPECT_EQ(SelectLabeledRegion(this->Mesh, labels, 0.0, this->Region), "");
  }

  Positions Rest() const
  {
    Positions rest(this->Region.GetNumberOfVertices(), 3);
    for (int k = 0; k < rest.rows(); ++k)
    {
      rest.row(k) = this->Mesh.GetPositions()[this->Region.Vertices[k]].transpose();
    }
    return rest;
  }
};

// The handle lifted by `height` and tilted by `degrees` about the y axis through (1, 0, 0).
AffineMap Lift(double height, double degrees)
{
  AffineMap map;
  map.leftCols<3>() = Eigen::AngleAxisd(degrees * Pi / 180.0, Vector3::UnitY()).toRotationMatrix();
  map.col(3) = Vector3(1, 0, 0) - map.leftCols<3>() * Vector3(1, 0, 0) + Vector3(0, 0, height);
  return map;
}

AffineMap RigidMotion()
{
  AffineMap rigid;
  rigid.leftCols<3>() = Eigen::AngleAxisd(0.9, Vector3(1, 2, 3).normalized()).toRotationMatrix();
  rigid.col(3) = Vector3(0.3, -0.2, 0.5);
  return rigid;
}

ArapOptions Iterations(int count, double tolerance = 0.0)
{
  ArapOptions options;
  options.MaximumIterations = count;
  options.Tolerance = tolerance;
  options.Extrapolate = false;
  return options;
}

// The full-resolution ARAP energy of `points` (the local step at those points, no iteration).
double FineEnergy(const StripEdit& edit, const std::vector<AffineMap>& maps, const Positions& points)
{
  AsRigidAsPossibleSolver solver;
  EXPECT_EQ(solver.Build(edit.Mesh, edit.Region, edit.Options), "");
  ArapIterate iterate;
  iterate.Points = points;
  return solver.Solve(maps, iterate, Iterations(0)).Energy;
}
}

TEST(AlgebraicMultigrid, SolvesAsTheDirectFactorDoes)
{
  // The grid's graph Laplacian with its border held (Dirichlet rows), three random right-hand
  // sides: multigrid-preconditioned conjugate gradients at 1e-10 are required to meet the
  // direct solution to 1e-8 of its size, from a cold start in at most 30 iterations (the
  // hierarchy's point: a few cycles whatever the size), and then from that solution again.
  const SurfaceMesh mesh = MakeGrid(120, 120);
  const int n = mesh.GetNumberOfVertices();
  std::vector<Eigen::Triplet<double>> entries;
  for (int v = 0; v < n; ++v)
  {
    const Vector3& p = mesh.GetPositions()[v];
    const bool border = p.x() == 0.0 || p.y() == 0.0 || p.x() == 1.0 || p.y() == 1.0;
    entries.emplace_back(v, v, border ? 1.0 : 0.0);
    for (const int* w = mesh.NeighborsBegin(v); w != mesh.NeighborsEnd(v); ++w)
    {
      entries.emplace_back(v, v, 1.0);
      if (*w > v)
      {
        entries.emplace_back(v, *w, -1.0);
      }
    }
  }
  Eigen::SparseMatrix<double> upper(n, n);
  upper.setFromTriplets(entries.begin(), entries.end());
  std::mt19937 random(7);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  const Eigen::MatrixXd rhs = Eigen::MatrixXd::NullaryExpr(n, 3, [&]() { return uniform(random); });

  SparseCholesky direct, multigrid;
  ASSERT_EQ(direct.Factorize(upper, SolverBackend::SimplicialLDLT), "");
  ASSERT_EQ(multigrid.Factorize(upper, SolverBackend::Multigrid), "");
  multigrid.SetIterativeTolerance(1e-10);
  const Eigen::MatrixXd expected = direct.Solve(rhs);
  const Eigen::MatrixXd cold = multigrid.Solve(rhs);
  const Eigen::MatrixXd warm = multigrid.Solve(rhs);
  const double scale = expected.cwiseAbs().maxCoeff();
  const double coldMiss = (cold - expected).cwiseAbs().maxCoeff() / scale;
  const double warmMiss = (warm - expected).cwiseAbs().maxCoeff() / scale;
  std::printf("multigrid on %d unknowns: %.2e cold, %.2e warm, of the direct solution\n", n,
    coldMiss, warmMiss);
  EXPECT_LT(coldMiss, 1e-8);
  EXPECT_LT(warmMiss, 1e-8);
}

TEST(RegionProxy, WeightsAreAPartitionOfUnity)
{
  // Both ends handles, so that no node is fixed (a fixed node's weight is not stored: it does
  // not move). Required: each free ROI row's weights sum to 1 (to rounding), a handle row's
  // to 0; and the proxy has at least the nodes asked for, and at most 4 times as many (its
  // spacing shrinks towards the handles' borders, here as long as the strip is wide).
  StripEdit edit(true);
  RegionProxy proxy;
  ASSERT_EQ(proxy.Build(edit.Mesh, edit.Region, 500), "");
  const int nodes = proxy.GetMesh().GetNumberOfVertices();
  std::printf("proxy of %d nodes (%d in the ROI) for %d ROI vertices, spacing %.4f\n", nodes,
    proxy.GetRegion().GetNumberOfVertices(), edit.Region.GetNumberOfVertices(), proxy.GetSpacing());
  EXPECT_GE(nodes, 500);
  EXPECT_LE(nodes, 2000);
  Positions sums;
  proxy.Interpolate(Positions::Ones(proxy.GetRegion().GetNumberOfVertices(), 1), sums);
  for (int k = 0; k < edit.Region.GetNumberOfVertices(); ++k)
  {
    EXPECT_NEAR(sums(k, 0), edit.Region.HandleGroups[k] >= 0 ? 0.0 : 1.0, 1e-12) << "row " << k;
  }
}

TEST(ProxyArap, NothingMovedReproducesTheRest)
{
  // Required: a drag with the handle at rest gives the rest, to 1e-12 of the size; a settle
  // there gives it exactly, with no iteration (a 610k region's first update ran 30 Newton steps
  // on rounding), also after a drag away; and a drag after that moves from the rest as a new
  // region's drag does.
  StripEdit edit;
  ProxyArapSolver solver;
  ASSERT_EQ(solver.Build(edit.SharedMesh(), edit.Region, edit.Options, 500), "");
  const std::vector<AffineMap> rest = { AffineMap::Identity() };
  const std::vector<AffineMap> lifted = { Lift(0.2, 20.0) };
  Positions dragged, settled, settledAfterDrag, draggedAgain, draggedFresh;
  solver.Drag(rest, Iterations(4), dragged);
  const ArapResult atRest = solver.Settle(rest, Iterations(4), settled);
  EXPECT_LT((dragged - edit.Rest()).cwiseAbs().maxCoeff(), 1e-12);
  EXPECT_TRUE(settled == edit.Rest());
  EXPECT_EQ(atRest.Iterations, 0);
  EXPECT_EQ(atRest.Energy, 0.0);
  solver.Drag(lifted, Iterations(4), dragged);
  solver.Settle(rest, Iterations(4), settledAfterDrag);
  EXPECT_TRUE(settledAfterDrag == edit.Rest());
  solver.Drag(lifted, Iterations(4), draggedAgain);
  ProxyArapSolver fresh;
  ASSERT_EQ(fresh.Build(edit.SharedMesh(), edit.Region, edit.Options, 500), "");
  fresh.Drag(lifted, Iterations(4), draggedFresh);
  EXPECT_LT((draggedAgain - draggedFresh).cwiseAbs().maxCoeff(), 1e-12);
}

TEST(ProxyArap, RigidMotionsAreReproduced)
{
  // Both ends carried by one rigid motion. Required: the proxy's nodes carried by it prolong to
  // its image of the rest exactly (1e-12), and the settle, run to convergence from a drag step,
  // reaches that image to 1e-9. (The proxy's own iteration gets there too, but slowly: its
  // relieved bending is soft, 2000 iterations leave 4e-4.)
  StripEdit edit(true);
  ProxyArapSolver solver;
  ASSERT_EQ(solver.Build(edit.SharedMesh(), edit.Region, edit.Options, 500), "");
  const RegionProxy& proxy = solver.GetProxy();
  const AffineMap rigid = RigidMotion();
  const std::vector<AffineMap> maps = { rigid, rigid };
  Positions expected = edit.Rest() * rigid.leftCols<3>().transpose();
  expected.rowwise() += rigid.col(3).transpose();

  RegionProxy::NodeShape carried = proxy.RestShape();
  carried.Points = carried.Points * rigid.leftCols<3>().transpose();
  carried.Points.rowwise() += rigid.col(3).transpose();
  carried.Turns.assign(carried.Turns.size(), rigid.leftCols<3>());
  Positions prolonged, settled;
  proxy.Prolong(proxy.GetRest(), proxy.RestShape(), carried, maps, prolonged);
  solver.Drag(maps, Iterations(10), settled);
  solver.Settle(maps, Iterations(2000, 1e-14), settled);
  const double prolongMiss = (prolonged - expected).cwiseAbs().maxCoeff();
  const double settleMiss = (settled - expected).cwiseAbs().maxCoeff();
  std::printf("rigid motion reproduced to %.2e prolonged, %.2e settled\n", prolongMiss, settleMiss);
  EXPECT_LT(prolongMiss, 1e-12);
  EXPECT_LT(settleMiss, 1e-9);
}

TEST(ProxyArap, SettlesOnTheFactoredSolversShape)
{
  // The handle lifted by 0.3 and tilted by 30 degrees in 6 drag steps of 3 proxy iterations,
  // then released: every step meets the handle's map exactly (1e-12), the drag's shape carries
  // at most twice the converged energy, and the settle reaches the factored solver's converged
  // shape to 1e-4 (the grid is 1 wide) and its energy to 0.1%.
  StripEdit edit;
  const std::vector<AffineMap> target = { Lift(0.3, 30.0) };

  AsRigidAsPossibleSolver factored;
  ASSERT_EQ(factored.Build(edit.Mesh, edit.Region, edit.Options), "");
  ArapIterate converged = factored.InitialGuess(target);
  const ArapResult reference = factored.Solve(target, converged, Iterations(5000, 1e-12));

  ProxyArapSolver solver;
  ASSERT_EQ(solver.Build(edit.SharedMesh(), edit.Region, edit.Options, 500), "");
  Positions shape;
  for (int step = 1; step <= 6; ++step)
  {
    const std::vector<AffineMap> maps = { Lift(0.05 * step, 5.0 * step) };
    ArapOptions drag = Iterations(3);
    drag.Dragging = true;
    solver.Drag(maps, drag, shape);
    for (int k = 0; k < shape.rows(); ++k)
    {
      if (edit.Region.HandleGroups[k] >= 0)
      {
        const Vector3 rest = edit.Mesh.GetPositions()[edit.Region.Vertices[k]];
        ASSERT_LT((shape.row(k).transpose() - (maps[0].leftCols<3>() * rest + maps[0].col(3))).norm(), 1e-12);
      }
    }
  }
  const double dragEnergy = FineEnergy(edit, target, shape);
  const ArapResult settle = solver.Settle(target, Iterations(5000, 1e-12), shape);
  const double miss = (shape - converged.Points).cwiseAbs().maxCoeff();
  std::printf("converged energy %.6g (%d iterations); dragged %.3fx, settled %.6fx in %d "
              "iterations, %.2e from the factored shape\n",
    reference.Energy, reference.Iterations, dragEnergy / reference.Energy,
    settle.Energy / reference.Energy, settle.Iterations, miss);
  EXPECT_LT(dragEnergy, 2.0 * reference.Energy);
  EXPECT_LT(std::abs(settle.Energy / reference.Energy - 1.0), 1e-3);
  EXPECT_LT(miss, 1e-4);
}

TEST(ProxyArap, ADragAfterASettleStartsFromTheSettledShape)
{
  // Dragged, released (settled), grabbed again and moved a little: the new drag step starts
  // from the settled shape, not the proxy's. Required: it lies at most a tenth as far from the
  // settled shape as the first drag's shape did.
  StripEdit edit;
  ProxyArapSolver solver;
  ASSERT_EQ(solver.Build(edit.SharedMesh(), edit.Region, edit.Options, 500), "");
  ArapOptions drag = Iterations(5);
  drag.Dragging = true;
  Positions dragged, settled, again;
  solver.Drag({ Lift(0.2, 20.0) }, drag, dragged);
  solver.Settle({ Lift(0.2, 20.0) }, Iterations(100), settled);
  drag.MaximumIterations = 1;
  solver.Drag({ Lift(0.201, 20.0) }, drag, again);
  const double first = (dragged - settled).cwiseAbs().maxCoeff();
  const double next = (again - settled).cwiseAbs().maxCoeff();
  std::printf("from the settled shape: the first drag %.2e, the next %.2e\n", first, next);
  EXPECT_LT(next, 0.1 * first);
}

TEST(ProxyArap, ASettleStoppedAtOnceResumesToTheUncutSettlesShape)
{
  // A release stopped at its first report (an abort, a time limit or a new grab), then resumed.
  // On a grid of 40k vertices the report comes while the full-resolution system still builds
  // on its thread (its build takes about ten times the drag step), and on a fast machine after
  // the first iteration. Required, either way: the stopped settle leaves a finite shape that
  // meets the handle (1e-12), and the resumed one reaches the shape of a settle never stopped
  // (1e-8).
  StripEdit edit(false, 200);
  const std::vector<AffineMap> maps = { Lift(0.2, 20.0) };
  ArapOptions drag = Iterations(3);
  drag.Dragging = true;

  ProxyArapSolver uncut;
  ASSERT_EQ(uncut.Build(edit.SharedMesh(), edit.Region, edit.Options, 500), "");
  Positions reference;
  uncut.Drag(maps, drag, reference);
  uncut.Settle(maps, Iterations(30, 1e-12), reference);

  ProxyArapSolver solver;
  ASSERT_EQ(solver.Build(edit.SharedMesh(), edit.Region, edit.Options, 500), "");
  Positions shape;
  solver.Drag(maps, drag, shape);
  ArapOptions stopped = Iterations(30, 1e-12);
  double firstReport = -1.0;
  stopped.Progress = [&](double done) {
    firstReport = firstReport < 0.0 ? done : firstReport;
    return false;
  };
  const ArapResult cut = solver.Settle(maps, stopped, shape);
  EXPECT_EQ(solver.GetSettleError(), "");
  EXPECT_LE(cut.Iterations, 1);
  ASSERT_TRUE(shape.allFinite());
  for (int k = 0; k < shape.rows(); ++k)
  {
    if (edit.Region.HandleGroups[k] >= 0)
    {
      const Vector3 rest = edit.Mesh.GetPositions()[edit.Region.Vertices[k]];
      ASSERT_LT((shape.row(k).transpose() - (maps[0].leftCols<3>() * rest + maps[0].col(3))).norm(), 1e-12);
    }
  }
  ArapOptions resumed = Iterations(30, 1e-12);
  resumed.Continue = true;
  solver.Settle(maps, resumed, shape);
  const double miss = (shape - reference).cwiseAbs().maxCoeff();
  std::printf("stopped %s (%d iterations); resumed %.2e from the uncut settle\n",
    cut.Iterations == 0 ? "while the system built" : "after its first iteration", cut.Iterations, miss);
  EXPECT_LT(miss, 1e-8);
}
