// Unit tests of the VTK-free numerical core: operators, regions, the editing system, solvers.
#include "NumericsTestMeshes.h"

#include "CoincidentPoints.h"
#include "DeformationGraph.h"
#include "DeformationSystem.h"
#include "DistributedSolver.h"
#include "EditRegion.h"
#include "GeodesicDistance.h"
#include "ImplicitSimilaritySystem.h"
#include "InjectiveDeformation.h"
#include "LaplacianOperator.h"
#include "SmoothWarp.h"
#include "SurfaceMesh.h"
#include "ThinPlateSpline.h"

#include <Eigen/Dense>
#include <Eigen/SparseCholesky>
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <utility>
#include <cstdio>
#include <limits>
#include <functional>
#include <thread>

using namespace LaplacianEditing;
using namespace LaplacianEditing::Testing;

namespace
{
double Bumps(double x, double y)
{
  return 0.03 * std::sin(12 * x) * std::sin(12 * y);
}

struct Edit
{
  SurfaceMesh Mesh;
  EditRegion Region;
  DeformationSystem System;
};

void Prepare(Edit& edit, double handleRadius, double roiRadius, const DeformationOptions& options,
  double padding = 0.1)
{
  const int center = edit.Mesh.FindNearestVertex(Vector3(0.5, 0.5, 0.0));
  ASSERT_EQ(SelectGeodesicRegion(edit.Mesh, center, handleRadius, roiRadius, padding, edit.Region), "");
  ASSERT_EQ(edit.System.Build(edit.Mesh, edit.Region, options), "");
}
}

TEST(SurfaceMesh, MergesCoincidentPointsAndSplitsQuads)
{
  // Two quads sharing an edge whose points are duplicated, as at a texture seam.
  const std::vector<Vector3> points = { { 0, 0, 0 }, { 1, 0, 0 }, { 1, 1, 0 }, { 0, 1, 0 },
    { 1, 0, 0 }, { 2, 0, 0 }, { 2, 1, 0 }, { 1, 1, 0 } };
  const std::vector<std::int64_t> offsets = { 0, 4, 8 };
  const std::vector<std::int64_t> connectivity = { 0, 1, 2, 3, 4, 5, 6, 7 };
  const SurfaceMesh merged = SurfaceMesh::FromPolygons(points, offsets, connectivity, true);
  EXPECT_EQ(merged.GetNumberOfVertices(), 6);
  EXPECT_EQ(merged.GetNumberOfTriangles(), 4);
  EXPECT_EQ(merged.GetNumberOfComponents(), 1);
  EXPECT_EQ(merged.GetVertexOfPoint()[1], merged.GetVertexOfPoint()[4]);
  const SurfaceMesh split = SurfaceMesh::FromPolygons(points, offsets, connectivity, false);
  EXPECT_EQ(split.GetNumberOfVertices(), 8);
  EXPECT_EQ(split.GetNumberOfComponents(), 2);
}

TEST(SurfaceMesh, NumbersAnyPartAsTheWholeDoes)
{
  // A bumpy 40 x 40 grid, whole, and the quads of a disc of it scaled into another frame (as
  // the adapter scales each region's part to a unit diagonal), both numbered from the input's
  // own coordinates: required, the part's vertices come in the whole's order.
  std::vector<Vector3> points;
  for (int j = 0; j <= 40; ++j)
  {
    for (int i = 0; i <= 40; ++i)
    {
      points.emplace_back(0.1 * i - 1.3, 0.1 * j + 0.7, 0.05 * std::sin(1.7 * i) * std::cos(2.3 * j));
    }
  }
  std::vector<std::int64_t> offsets(1, 0), connectivity, partOffsets(1, 0), partConnectivity;
  for (int j = 0; j < 40; ++j)
  {
    for (int i = 0; i < 40; ++i)
    {
      const std::int64_t a = j * 41 + i;
      connectivity.insert(connectivity.end(), { a, a + 1, a + 42, a + 41 });
      offsets.push_back(static_cast<std::int64_t>(connectivity.size()));
      if ((i - 25) * (i - 25) + (j - 15) * (j - 15) < 100)
      {
        partConnectivity.insert(partConnectivity.end(), { a, a + 1, a + 42, a + 41 });
        partOffsets.push_back(static_cast<std::int64_t>(partConnectivity.size()));
      }
    }
  }
  // The part keeps its own points only, renumbered, in another frame.
  std::vector<int> partPoint(points.size(), -1);
  std::vector<Vector3> kept, scaled;
  for (std::int64_t& point : partConnectivity)
  {
    if (partPoint[point] < 0)
    {
      partPoint[point] = static_cast<int>(kept.size());
      kept.push_back(points[point]);
      scaled.push_back((points[point] - Vector3(1.1, 1.9, 0.0)) * 0.37);
    }
    point = partPoint[point];
  }
  const SurfaceMesh whole = SurfaceMesh::FromPolygons(points, offsets, connectivity, true);
  const SurfaceMesh part =
    SurfaceMesh::FromPolygons(scaled, partOffsets, partConnectivity, true, &kept);
  std::vector<std::pair<int, int>> order; // per kept point, its vertex in the part and the whole
  for (std::size_t k = 0; k < points.size(); ++k)
  {
    if (partPoint[k] >= 0)
    {
      order.emplace_back(part.GetVertexOfPoint()[partPoint[k]], whole.GetVertexOfPoint()[k]);
    }
  }
  ASSERT_GT(order.size(), 200u);
  std::sort(order.begin(), order.end());
  for (std::size_t k = 1; k < order.size(); ++k)
  {
    EXPECT_LT(order[k - 1].second, order[k].second) << "part vertex " << order[k].first;
  }
}

TEST(SurfaceMesh, MergesSeamCopiesThatDifferByRounding)
{
  // The same seam, its copies a few ulps apart as separately computed pieces give them
  // (sin(2 pi) is -2.4e-16, not 0): one straddles the bin border at 0. A point 1e-6 away, far
  // more than rounding, stays a vertex of its own.
  const double ulps = 2.4e-16;
  const std::vector<Vector3> points = { { 0, 0, 0 }, { 1, 0, 0 }, { 1, 1, 0 }, { 0, 1, 0 },
    { 1 + ulps, -ulps, 0 }, { 2, 0, 0 }, { 2, 1, 0 }, { 1 - ulps, 1, ulps } };
  const std::vector<std::int64_t> offsets = { 0, 4, 8 };
  const std::vector<std::int64_t> connectivity = { 0, 1, 2, 3, 4, 5, 6, 7 };
  const SurfaceMesh merged = SurfaceMesh::FromPolygons(points, offsets, connectivity, true);
  EXPECT_EQ(merged.GetNumberOfVertices(), 6);
  EXPECT_EQ(merged.GetNumberOfComponents(), 1);
  std::vector<Vector3> apart = points;
  apart[4] += Vector3(1e-6, 0, 0);
  EXPECT_EQ(SurfaceMesh::FromPolygons(apart, offsets, connectivity, true).GetNumberOfVertices(), 7);

  CoincidentPoints copies(1e-10, Vector3::Zero());
  copies.Add(Vector3(0, -1e-17, 0), 3);
  copies.Add(Vector3(0, 1e-17, 0), 2);
  EXPECT_EQ(copies.Find(Vector3(1e-11, 0, -1e-11)), 2); // the smallest id of the two
  EXPECT_EQ(copies.Find(Vector3(0, 2e-10, 0)), -1);
}

TEST(GeodesicDistance, FollowsEdgesOnAGrid)
{
  const SurfaceMesh mesh = MakeGrid(10, 10);
  // The grid's points by row (11 a row); the mesh numbers its vertices in its own order.
  const auto vertex = [&mesh](int point) { return mesh.GetVertexOfPoint()[point]; };
  const auto d = ComputeGeodesicDistances(mesh, { vertex(0) }, 10.0);
  EXPECT_NEAR(d[vertex(10)], 1.0, 1e-12);             // along the bottom edge
  EXPECT_NEAR(d[vertex(120)], std::sqrt(2.0), 1e-12); // along the diagonal edges
  const auto limited = ComputeGeodesicDistances(mesh, { vertex(0) }, 0.25);
  EXPECT_TRUE(std::isinf(limited[vertex(10)]));
}

namespace
{
// How far a disc of `radius` about the grid's centre reaches in 16 directions: the largest
// over the smallest extent (1 for a round disc).
double DiscExtentRatio(DistanceMethod method, double* worstError = nullptr, double* meanError = nullptr)
{
  const SurfaceMesh mesh = MakeGrid(100, 100);
  const Vector3 center(0.5, 0.5, 0.0);
  const double radius = 0.3;
  const auto d = ComputeGeodesicDistances(mesh, { mesh.FindNearestVertex(center) }, radius, method);
  const double pi = std::acos(-1.0);
  double smallest = std::numeric_limits<double>::infinity(), largest = 0.0;
  for (int k = 0; k < 16; ++k)
  {
    const double angle = 2.0 * pi * k / 16.0;
    double extent = 0.0;
    for (int v = 0; v < mesh.GetNumberOfVertices(); ++v)
    {
      const Vector3 offset = mesh.GetPositions()[v] - center;
      const double off = std::remainder(std::atan2(offset.y(), offset.x()) - angle, 2.0 * pi);
      if (std::isfinite(d[v]) && std::abs(off) < pi / 32.0)
      {
        extent = std::max(extent, offset.norm());
      }
    }
    smallest = std::min(smallest, extent);
    largest = std::max(largest, extent);
  }
  if (worstError && meanError)
  {
    *worstError = *meanError = 0.0;
    int count = 0;
    for (int v = 0; v < mesh.GetNumberOfVertices(); ++v)
    {
      const double euclidean = (mesh.GetPositions()[v] - center).norm();
      if (std::isfinite(d[v]) && euclidean > 0.05)
      {
        const double error = std::abs(d[v] - euclidean) / euclidean;
        *worstError = std::max(*worstError, error);
        *meanError += error;
        ++count;
      }
    }
    *meanError /= std::max(count, 1);
  }
  return largest / smallest;
}
}

TEST(GeodesicDistance, FastMarchingDiscsAreRound)
{
  // A disc of radius 0.3 on a regular 100 x 100 grid (the quads split along one diagonal).
  // Required: its extent over 16 directions varies by at most 5% with fast marching, where
  // edge paths make a skewed hexagon (measured: 1.026 and 1.397); on this plane, distances
  // beyond 0.05 within 2% of the Euclidean ones on average and 8% at worst (measured 1.6% and
  // 7.4%, where the front runs along the diagonals' 45-degree corners).
  double worstError = 0.0, meanError = 0.0;
  const double marching = DiscExtentRatio(DistanceMethod::FastMarching, &worstError, &meanError);
  const double edgePaths = DiscExtentRatio(DistanceMethod::EdgePaths);
  std::printf("disc extent ratio: fast marching %.3f (relative error mean %.4f, worst %.4f), "
              "edge paths %.3f\n", marching, meanError, worstError, edgePaths);
  EXPECT_LE(marching, 1.05);
  EXPECT_LT(meanError, 0.02);
  EXPECT_LT(worstError, 0.08);
  EXPECT_GT(edgePaths, 1.2);
}

TEST(LaplacianOperator, UniformRankIsVerticesMinusComponents)
{
  // Two separate grids in one mesh: rank(L) = n - 2 (Section 3).
  SurfaceMesh a = MakeGrid(4, 4);
  std::vector<Vector3> points = a.GetPositions();
  std::vector<std::int64_t> offsets(1, 0), connectivity;
  for (int copy = 0; copy < 2; ++copy)
  {
    for (const auto& tri : a.GetTriangles())
    {
      for (int v : tri)
      {
        connectivity.push_back(v + copy * a.GetNumberOfVertices());
      }
      offsets.push_back(static_cast<std::int64_t>(connectivity.size()));
    }
  }
  for (const auto& p : a.GetPositions())
  {
    points.push_back(p + Vector3(5, 0, 0));
  }
  const SurfaceMesh mesh = SurfaceMesh::FromPolygons(points, offsets, connectivity, true);
  ASSERT_EQ(mesh.GetNumberOfComponents(), 2);
  for (auto weights : { LaplacianWeights::Uniform, LaplacianWeights::Cotangent })
  {
    const Eigen::MatrixXd dense = Eigen::MatrixXd(LaplacianOperator(mesh, weights).Matrix());
    Eigen::FullPivLU<Eigen::MatrixXd> lu(dense);
    lu.setThreshold(1e-10);
    EXPECT_EQ(lu.rank(), mesh.GetNumberOfVertices() - 2);
  }
}

TEST(LaplacianOperator, RowsSumToZeroAndSecondOrderIsTheSquare)
{
  const SurfaceMesh mesh = MakeGrid(8, 8, 1.0, Bumps);
  for (auto weights : { LaplacianWeights::Uniform, LaplacianWeights::Cotangent })
  {
    const LaplacianOperator op(mesh, weights);
    const Eigen::SparseMatrix<double> L = op.Matrix();
    const Eigen::SparseMatrix<double> L2 = L * L;
    for (int v = 0; v < mesh.GetNumberOfVertices(); ++v)
    {
      double sum = 0.0;
      for (const auto& [j, value] : op.Row(v, 1))
      {
        sum += value;
      }
      EXPECT_NEAR(sum, 0.0, 1e-12);
      for (const auto& [j, value] : op.Row(v, 2))
      {
        EXPECT_NEAR(value, L2.coeff(v, j), 1e-12);
      }
    }
  }
}

TEST(LaplacianOperator, CotangentWeightsStayFiniteOnDegenerateTriangles)
{
  // A zero-area sliver (collinear corners) and an obtuse fan.
  const std::vector<Vector3> points = { { 0, 0, 0 }, { 1, 0, 0 }, { 2, 0, 0 }, { 1, 1, 0 },
    { 1, -0.01, 0 } };
  const std::vector<std::int64_t> offsets = { 0, 3, 6, 9 };
  const std::vector<std::int64_t> connectivity = { 0, 1, 3, 1, 2, 3, 0, 4, 2 };
  const SurfaceMesh mesh = SurfaceMesh::FromPolygons(points, offsets, connectivity, true);
  const LaplacianOperator op(mesh, LaplacianWeights::Cotangent);
  for (int v = 0; v < mesh.GetNumberOfVertices(); ++v)
  {
    double sum = 0.0;
    for (const auto& [j, value] : op.Row(v, 1))
    {
      ASSERT_TRUE(std::isfinite(value));
      if (j != v)
      {
        EXPECT_LE(value, 0.0); // clamped: no negative neighbour weight
      }
      sum += value;
    }
    EXPECT_NEAR(sum, 0.0, 1e-12);
  }
}

class DeformationSystemTest
  : public ::testing::TestWithParam<std::tuple<LaplacianWeights, int>>
{
protected:
  DeformationOptions Options() const
  {
    DeformationOptions options;
    options.Weights = std::get<0>(this->GetParam());
    options.Order = std::get<1>(this->GetParam());
    return options;
  }
};

TEST_P(DeformationSystemTest, ReconstructsExactlyWhenNothingMoves)
{
  Edit edit{ MakeGrid(40, 40, 1.0, Bumps) };
  Prepare(edit, 0.05, 0.3, this->Options());
  const Positions result = edit.System.Solve({});
  EXPECT_LT((result - edit.System.GetRestPositions()).cwiseAbs().maxCoeff(), 1e-10);
}

TEST_P(DeformationSystemTest, HandlesMeetTheirTargetsAndTheEditIsLocal)
{
  Edit edit{ MakeGrid(40, 40, 1.0, Bumps) };
  Prepare(edit, 0.05, 0.3, this->Options());
  const Vector3 lift(0.02, -0.03, 0.15);
  const Positions result = edit.System.Solve({ Translation(lift) });
  const Positions& rest = edit.System.GetRestPositions();
  double anchorMotion = 0.0;
  int anchors = 0;
  for (int k = 0; k < edit.Region.GetNumberOfVertices(); ++k)
  {
    const double motion = (result.row(k) - rest.row(k)).norm();
    if (edit.Region.Roles[k] == VertexRole::Handle)
    {
      // Constraint met to 0.1% of the mesh size (the grid's diagonal is about 1.4).
      EXPECT_LT((result.row(k) - rest.row(k) - lift.transpose()).norm(), 1e-3);
    }
    else if (edit.Region.Roles[k] == VertexRole::Anchor)
    {
      anchorMotion += motion;
      ++anchors;
    }
  }
  ASSERT_GT(anchors, 0);
  // Locality: the anchor belt moves on average less than 5% of the handle's motion.
  EXPECT_LT(anchorMotion / anchors, 0.05 * lift.norm());
}

TEST_P(DeformationSystemTest, BackendsAgree)
{
  if (!SparseCholesky::IsAvailable(SolverBackend::Cholmod))
  {
    GTEST_SKIP() << "built without CHOLMOD";
  }
  Edit a{ MakeGrid(30, 30, 1.0, Bumps) };
  Edit b{ MakeGrid(30, 30, 1.0, Bumps) };
  DeformationOptions options = this->Options();
  options.Backend = SolverBackend::Cholmod;
  Prepare(a, 0.05, 0.35, options);
  options.Backend = SolverBackend::SimplicialLDLT;
  Prepare(b, 0.05, 0.35, options);
  const std::vector<AffineMap> maps = { Translation(Vector3(0.1, 0.0, 0.2)) };
  EXPECT_LT((a.System.Solve(maps) - b.System.Solve(maps)).cwiseAbs().maxCoeff(), 1e-8);
}

TEST_P(DeformationSystemTest, PrecomputedResponsesMatchDirectSolves)
{
  // Two handle groups with general affine maps (rotation, scale, shear, translation): the
  // precomputed path must agree with the triangular solves to 1e-10 relative, in the Laplacian
  // system and in the implicit one.
  Edit edit{ MakeGrid(30, 30, 1.0, Bumps) };
  std::vector<int> labels(edit.Mesh.GetNumberOfVertices(), 1);
  for (int v = 0; v < edit.Mesh.GetNumberOfVertices(); ++v)
  {
    const Vector3& p = edit.Mesh.GetPositions()[v];
    labels[v] = p.x() < 0.05 ? 0 : (p.x() > 0.95 ? 2 : (std::abs(p.x() - 0.5) < 0.04 ? 3 : 1));
  }
  ASSERT_EQ(SelectLabeledRegion(edit.Mesh, labels, 0.1, edit.Region), "");
  ASSERT_EQ(edit.System.Build(edit.Mesh, edit.Region, this->Options()), "");
  ImplicitSimilaritySystem implicit;
  ASSERT_EQ(implicit.Build(edit.Mesh, edit.Region, edit.System, this->Options()), "");
  AffineMap first, second;
  first << 0.9, -0.3, 0.1, 0.2, 0.35, 0.95, 0.05, -0.1, -0.1, 0.02, 1.1, 0.3;
  second << 1.0, 0.2, 0.0, -0.05, -0.2, 1.0, 0.1, 0.0, 0.0, -0.1, 0.9, 0.15;
  const std::vector<AffineMap> maps = { first, second };
  auto relative = [](const Positions& fast, const Positions& direct) {
    return (fast - direct).cwiseAbs().maxCoeff() / direct.cwiseAbs().maxCoeff();
  };
  EXPECT_LT(relative(edit.System.Solve(maps), edit.System.SolveDirect(maps)), 1e-10);
  EXPECT_LT(relative(implicit.Solve(maps), implicit.SolveDirect(edit.System, maps)), 1e-10);
}

INSTANTIATE_TEST_SUITE_P(WeightsAndOrders, DeformationSystemTest,
  ::testing::Combine(::testing::Values(LaplacianWeights::Uniform, LaplacianWeights::Cotangent),
    ::testing::Values(1, 2)));

TEST(DeformationSystem, SecondOrderGivesASmootherTransition)
{
  // The paper's Fig. 3 on a strip: pull the middle up with the same constraints and compare
  // how the edited surface meets the fixed part. The fixed part is flat, so the slope across
  // the edges that join the ROI to it is the jump in tangent there. The first-order operator
  // leaves a crease (the slope of the "tent"); the bi-Laplacian joins tangentially. Required:
  // at least five times smaller with second order.
  double joinSlope[2];
  for (int order = 1; order <= 2; ++order)
  {
    Edit edit{ MakeGrid(120, 4, 3.0, nullptr, -1.0) };
    DeformationOptions options;
    options.Order = order;
    Prepare(edit, 0.05, 1.2, options);
    const Positions result = edit.System.Solve({ Translation(Vector3(0, 0, 0.3)) });
    std::vector<int> local(edit.Mesh.GetNumberOfVertices(), -1);
    for (int k = 0; k < edit.Region.GetNumberOfVertices(); ++k)
    {
      local[edit.Region.Vertices[k]] = k;
    }
    double worst = 0.0;
    for (int k = 0; k < edit.Region.GetNumberOfVertices(); ++k)
    {
      const int v = edit.Region.Vertices[k];
      for (const int* w = edit.Mesh.NeighborsBegin(v); w != edit.Mesh.NeighborsEnd(v); ++w)
      {
        if (local[*w] < 0)
        {
          const Vector3 edge = result.row(k).transpose() - edit.Mesh.GetPositions()[*w];
          worst = std::max(worst, std::abs(edge.z()) / edge.head<2>().norm());
        }
      }
    }
    joinSlope[order - 1] = worst;
  }
  std::cout << "slope where the edit joins the fixed part: first order " << joinSlope[0]
            << ", second order " << joinSlope[1] << " (ratio " << joinSlope[0] / joinSlope[1]
            << ")\n";
  EXPECT_LT(joinSlope[1] * 5.0, joinSlope[0]);
}

// The range cut into four chunks, each on its own thread: the real concurrency the filter's
// vtkSMPTools gives. (A thread per index made a solve that loops over its rows start
// thousands of threads: 3.5 minutes for this file's few-column test.)
void ThreadedFor(int begin, int end, const std::function<void(int, int)>& body)
{
  constexpr int Chunks = 4;
  std::vector<std::thread> threads;
  for (int chunk = 0; chunk < Chunks; ++chunk)
  {
    const int first = begin + static_cast<int>(static_cast<long long>(end - begin) * chunk / Chunks);
    const int last = begin + static_cast<int>(static_cast<long long>(end - begin) * (chunk + 1) / Chunks);
    if (first < last)
    {
      threads.emplace_back(body, first, last);
    }
  }
  for (auto& thread : threads)
  {
    thread.join();
  }
}

// D - A + 0.01 I over the edges of `mesh`, placed at `offset` in an n x n matrix.
void AddShiftedGraphLaplacian(
  const SurfaceMesh& mesh, int offset, std::vector<Eigen::Triplet<double>>& triplets)
{
  const LaplacianOperator laplacian(mesh, LaplacianWeights::Uniform);
  for (int v = 0; v < mesh.GetNumberOfVertices(); ++v)
  {
    double degree = 0.0;
    for (const auto& [j, coefficient] : laplacian.Row(v, 1))
    {
      if (j != v)
      {
        triplets.emplace_back(offset + v, offset + j, -1.0);
        degree += 1.0;
      }
    }
    triplets.emplace_back(offset + v, offset + v, degree + 0.01);
  }
}

TEST(SparseCholesky, FewColumnSolvesMatchTheBlasPathInParallel)
{
  if (!SparseCholesky::IsAvailable(SolverBackend::Cholmod))
  {
    GTEST_SKIP() << "built without CHOLMOD";
  }
  // One connected grid, and two disjoint ones (a forest of elimination trees).
  const SurfaceMesh big = MakeGrid(90, 90, 1.0, Bumps);
  const SurfaceMesh small = MakeGrid(25, 40, 1.0, Bumps);
  for (bool forest : { false, true })
  {
    std::vector<Eigen::Triplet<double>> triplets;
    AddShiftedGraphLaplacian(big, 0, triplets);
    if (forest)
    {
      AddShiftedGraphLaplacian(small, big.GetNumberOfVertices(), triplets);
    }
    const int n = big.GetNumberOfVertices() + (forest ? small.GetNumberOfVertices() : 0);
    Eigen::SparseMatrix<double> matrix(n, n);
    matrix.setFromTriplets(triplets.begin(), triplets.end());
    for (FillOrdering ordering : { FillOrdering::AMD, FillOrdering::METIS })
    {
      SparseCholesky factor;
      ASSERT_EQ(factor.Factorize(matrix, SolverBackend::Cholmod, ordering), "");
      if (std::thread::hardware_concurrency() > 1)
      {
        EXPECT_GT(factor.GetParallelShare(), 0.5) << "the tree should split into parallel parts";
      }
      std::srand(7);
      const Eigen::MatrixXd rhs = Eigen::MatrixXd::Random(n, 6);
      const Eigen::MatrixXd wide = factor.Solve(rhs); // more than four columns: CHOLMOD's BLAS path
      ASSERT_LT((matrix * wide - rhs).norm() / rhs.norm(), 1e-12);
      for (int columns = 1; columns <= 4; ++columns)
      {
        for (const ParallelFor& loop : { ParallelFor(SerialFor), ParallelFor(ThreadedFor) })
        {
          const Eigen::MatrixXd few = factor.Solve(rhs.leftCols(columns), loop);
          EXPECT_LT((few - wide.leftCols(columns)).cwiseAbs().maxCoeff(),
            1e-12 * wide.cwiseAbs().maxCoeff())
            << columns << " columns, forest " << forest;
        }
      }
    }
  }
}

extern "C"
{
  int omp_get_max_active_levels() __attribute__((weak));
  void omp_set_max_active_levels(int levels) __attribute__((weak));
}

TEST(SparseCholesky, FactorizationsLeaveTheOpenMPSettingAsTheyFoundIt)
{
  // CHOLMOD's OpenMP loops run on the calling thread during a factorization (its
  // max-active-levels is 0): afterwards each thread's own value is back, also when
  // factorizations overlap on two threads.
  if (!SparseCholesky::IsAvailable(SolverBackend::Cholmod) || !omp_get_max_active_levels ||
    !omp_set_max_active_levels)
  {
    GTEST_SKIP() << "no CHOLMOD or no OpenMP runtime loaded";
  }
  const SurfaceMesh grid = MakeGrid(60, 60, 1.0, Bumps);
  std::vector<Eigen::Triplet<double>> triplets;
  AddShiftedGraphLaplacian(grid, 0, triplets);
  Eigen::SparseMatrix<double> matrix(grid.GetNumberOfVertices(), grid.GetNumberOfVertices());
  matrix.setFromTriplets(triplets.begin(), triplets.end());
  const int before = omp_get_max_active_levels();
  auto factorize = [&matrix](int levels) {
    omp_set_max_active_levels(levels);
    for (int k = 0; k < 20; ++k)
    {
      SparseCholesky factor;
      EXPECT_EQ(factor.Factorize(matrix, SolverBackend::Cholmod, FillOrdering::AMD), "");
    }
    EXPECT_EQ(omp_get_max_active_levels(), levels);
  };
  std::thread other(factorize, 2);
  factorize(3);
  other.join();
  omp_set_max_active_levels(before);
}

TEST(SparseCholesky, BlockOrderingsSolveTheCoupledSystem)
{
  // A grid Laplacian with x, y, z coupled at every vertex (kron(L, C) + shift), given by its
  // upper triangle only, as the implicit mode's system is. Ordering the graph of the 3 x 3
  // blocks must solve it as well as ordering the unknowns, with any ordering and either solve.
  const SurfaceMesh grid = MakeGrid(40, 30, 1.0, Bumps);
  std::vector<Eigen::Triplet<double>> scalar;
  AddShiftedGraphLaplacian(grid, 0, scalar);
  Eigen::Matrix3d coupling;
  coupling << 2.0, 0.5, -0.3, 0.5, 1.5, 0.2, -0.3, 0.2, 1.0;
  std::vector<Eigen::Triplet<double>> upper;
  for (const auto& t : scalar)
  {
    for (int r = 0; r < 3; ++r)
    {
      for (int c = 0; c < 3; ++c)
      {
        const int row = 3 * t.row() + r;
        const int column = 3 * t.col() + c;
        if (row <= column)
        {
          upper.emplace_back(row, column, t.value() * coupling(r, c));
        }
      }
    }
  }
  const int n = 3 * grid.GetNumberOfVertices();
  Eigen::SparseMatrix<double> matrix(n, n);
  matrix.setFromTriplets(upper.begin(), upper.end());
  const Eigen::SparseMatrix<double> full = matrix.selfadjointView<Eigen::Upper>();
  std::srand(11);
  const Eigen::MatrixXd rhs = Eigen::MatrixXd::Random(n, 6);
  std::vector<SolverBackend> backends = { SolverBackend::SimplicialLDLT };
  if (SparseCholesky::IsAvailable(SolverBackend::Cholmod))
  {
    backends.push_back(SolverBackend::Cholmod);
  }
  for (SolverBackend backend : backends)
  {
    for (FillOrdering ordering : { FillOrdering::Automatic, FillOrdering::AMD, FillOrdering::METIS,
           FillOrdering::NestedDissection })
    {
      for (int blockSize : { 1, 3 })
      {
        SparseCholesky factor;
        ASSERT_EQ(factor.Factorize(matrix, backend, ordering, 0.0, blockSize), "");
        for (int columns : { 3, 6 }) // the few-column kernels and CHOLMOD's BLAS path
        {
          const Eigen::MatrixXd solution = factor.Solve(rhs.leftCols(columns), ThreadedFor);
          EXPECT_LT((full * solution - rhs.leftCols(columns)).norm() / rhs.norm(), 1e-12)
            << "ordering " << static_cast<int>(ordering) << ", block size " << blockSize;
        }
      }
    }
  }
}

namespace
{
// An in-process stand-in for the processes behind a DistributedSolver (the MPI one,
// MumpsSolver, is tested under mpiexec in the ParaView stage): it records what it
// was asked to factor, so the test can check when SparseCholesky hands a factor over.
struct RecordingDistributedSolver : DistributedSolver
{
  struct Factor : DistributedFactor
  {
    Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>, Eigen::Upper> LDLT;
    Eigen::MatrixXd Solve(const Eigen::MatrixXd& rhs) const override
    {
      return this->LDLT.solve(rhs);
    }
    double GetBytes() const override { return 1.0; }
  };
  int Processes = 2;
  int Factorizations = 0;
  std::unique_ptr<DistributedFactor> Factorize(
    const Eigen::SparseMatrix<double>& matrix, std::string&) override
  {
    ++this->Factorizations;
    auto factor = std::make_unique<Factor>();
    factor->LDLT.compute(matrix);
    return factor;
  }
  int GetNumberOfProcesses() const override { return this->Processes; }
};
}

TEST(SparseCholesky, FactorsTooLargeForOneProcessGoAcrossProcesses)
{
  const SurfaceMesh grid = MakeGrid(30, 30, 1.0, Bumps);
  std::vector<Eigen::Triplet<double>> triplets;
  AddShiftedGraphLaplacian(grid, 0, triplets);
  const int n = grid.GetNumberOfVertices();
  Eigen::SparseMatrix<double> matrix(n, n);
  matrix.setFromTriplets(triplets.begin(), triplets.end());
  const Eigen::MatrixXd rhs = Eigen::MatrixXd::Ones(n, 3);
  RecordingDistributedSolver processes;
  SparseCholesky factor;

  const auto factorize = [&](SolverBackend backend, double maximumBytes) {
    return factor.Factorize(matrix, backend, FillOrdering::AMD, maximumBytes, 1, &processes);
  };
  ASSERT_EQ(factorize(SolverBackend::Cholmod, 0.0), "");
  EXPECT_FALSE(factor.IsDistributed()) << "a factor within the limit stays on this process";
  EXPECT_EQ(processes.Factorizations, 0);

  ASSERT_EQ(factorize(SolverBackend::Cholmod, 1.0), "");
  EXPECT_TRUE(factor.IsDistributed()) << "a factor above the limit goes across the processes";
  EXPECT_EQ(factor.GetFactorBytes(), 1.0);
  EXPECT_LT((matrix * factor.Solve(rhs) - rhs).norm() / rhs.norm(), 1e-12);

  processes.Processes = 1;
  EXPECT_NE(factorize(SolverBackend::Cholmod, 1.0).find("more than the"), std::string::npos)
    << "one process has nowhere to spread the factor: the limit's error stands";
  EXPECT_EQ(factorize(SolverBackend::Distributed, 0.0), "");
  EXPECT_TRUE(factor.IsDistributed()) << "the Distributed backend always factors across";
  EXPECT_EQ(processes.Factorizations, 2);
  EXPECT_NE(factor.Factorize(matrix, SolverBackend::Distributed).find("MPI"), std::string::npos)
    << "without processes, the Distributed backend says why it cannot run";
}

TEST(EditRegion, RejectsBadSelections)
{
  const SurfaceMesh mesh = MakeGrid(10, 10);
  EditRegion region;
  EXPECT_NE(SelectGeodesicRegion(mesh, 0, 0.3, 0.2, 0.1, region), "");  // handle outside ROI
  EXPECT_NE(SelectGeodesicRegion(mesh, 0, 0.0, 0.2, 0.1, region), "");  // zero radius
  EXPECT_NE(SelectGeodesicRegion(mesh, -1, 0.1, 0.2, 0.1, region), ""); // no vertex
  // The whole mesh as ROI and no anchors: nothing pins it.
  EXPECT_NE(SelectGeodesicRegion(mesh, 0, 0.1, 10.0, 0.0, region), "");
  // The same with anchors is well posed: the band is measured from the distance reached.
  EXPECT_EQ(SelectGeodesicRegion(mesh, 0, 0.1, 10.0, 0.1, region), "");
  EXPECT_NEAR(region.Radius, std::sqrt(2.0), 1e-12);

  std::vector<int> labels(mesh.GetNumberOfVertices(), 1);
  EXPECT_NE(SelectLabeledRegion(mesh, labels, 0.1, region), ""); // no handle
  labels[0] = 2;
  labels[5] = 3;
  EXPECT_EQ(SelectLabeledRegion(mesh, labels, 0.1, region), "");
  EXPECT_EQ(region.NumberOfHandleGroups, 2);
}

namespace
{
// Landmarks spread through a unit box (not on a plane), and displacements for them.
Positions BoxLandmarks(int count, unsigned seed)
{
  std::srand(seed);
  return Positions::Random(count, 3);
}
}

TEST(ThinPlateSpline, InterpolatesTheLandmarksAndReproducesAffineMaps)
{
  const Positions landmarks = BoxLandmarks(60, 1);
  ThinPlateSpline spline;
  ASSERT_TRUE(spline.Fit(landmarks));
  // Any displacements are met at the landmarks.
  const Positions displacements = 0.1 * BoxLandmarks(60, 2);
  EXPECT_LE((spline.Displace(displacements, landmarks) - displacements).cwiseAbs().maxCoeff(), 1e-10);
  // An affine displacement is the spline everywhere, not only at the landmarks.
  Eigen::Matrix3d linear;
  linear << 0.2, -0.1, 0.05, 0.3, 0.1, 0.0, -0.2, 0.1, 0.4;
  const Eigen::RowVector3d shift(0.5, -0.3, 0.2);
  auto affine = [&](const Positions& points) {
    Positions moved = points * linear.transpose();
    moved.rowwise() += shift;
    return moved;
  };
  const Positions elsewhere = 2.0 * BoxLandmarks(500, 3);
  EXPECT_LE((spline.Displace(affine(landmarks), elsewhere, ParallelFor(SerialFor)) - affine(elsewhere))
              .cwiseAbs()
              .maxCoeff(),
    1e-10);
}

TEST(ThinPlateSpline, IsTheSumOfItsCardinalFunctions)
{
  // What a drag's prior relies on: moving one landmark moves the spline by its cardinal function
  // times the move.
  const Positions landmarks = BoxLandmarks(40, 4);
  ThinPlateSpline spline;
  ASSERT_TRUE(spline.Fit(landmarks));
  const Positions points = BoxLandmarks(300, 5);
  Positions before = 0.1 * BoxLandmarks(40, 6), after = before;
  after.row(7) += Eigen::RowVector3d(0.02, -0.05, 0.01);
  const Positions moved = spline.Displace(before, points) +
    spline.Cardinal(7, points) * (after.row(7) - before.row(7));
  EXPECT_LE((moved - spline.Displace(after, points)).cwiseAbs().maxCoeff(), 1e-12);
  EXPECT_LE(std::abs(spline.Cardinal(7, landmarks)(7) - 1.0), 1e-10);
  EXPECT_LE(std::abs(spline.Cardinal(7, landmarks)(8)), 1e-10);
}

TEST(ThinPlateSpline, RefusesLandmarksThatFixNoSpline)
{
  ThinPlateSpline spline;
  EXPECT_FALSE(spline.Fit(BoxLandmarks(3, 7))) << "fewer than four";
  Positions flat = BoxLandmarks(50, 8);
  flat.col(2).setConstant(0.25);
  EXPECT_FALSE(spline.Fit(flat)) << "on a plane";
  EXPECT_TRUE(spline.IsEmpty());
  EXPECT_FALSE(spline.Fit(BoxLandmarks(ThinPlateSpline::MaximumLandmarks + 1, 9))) << "too many";
  EXPECT_TRUE(spline.Fit(BoxLandmarks(4, 10)));
}

// The quality pass takes tetrahedra eight at a time in vector lanes (a batch short of eight
// repeats its last): each result is the tetrahedron's own, Verdict's scaled Jacobian.
TEST(InjectiveDeformation, ScaledJacobiansInBatchesAreEachTetrahedronsOwn)
{
  const double s = 1.0 / std::sqrt(2.0);
  std::vector<std::array<double, 3>> points = { { -1, 0, -s }, { 1, 0, -s }, { 0, 1, s },
    { 0, -1, s } };                                          // regular: 1
  points.insert(points.end(), { points[1], points[0], points[2], points[3] }); // inverted: -1
  points.insert(points.end(), { { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 }, { 1, 1, 0 } }); // flat: 0
  points.insert(points.end(), { { 0, 0, 0 }, { 0, 0, 0 }, { 0, 1, 0 }, { 0, 0, 1 } }); // a point twice: 0
  std::srand(7);
  while (points.size() < 4 * 11)
  {
    points.push_back({ std::rand() / double(RAND_MAX), std::rand() / double(RAND_MAX),
      std::rand() / double(RAND_MAX) });
  }
  std::vector<const double*> corners;
  for (const auto& p : points)
  {
    corners.push_back(p.data());
  }
  std::vector<double> batch(11);
  InjectiveDeformation::TetrahedronScaledJacobians(corners.data(), 11, batch.data());
  for (int t = 0; t < 11; ++t)
  {
    const double* const* tet = corners.data() + 4 * t;
    EXPECT_EQ(batch[t], InjectiveDeformation::TetrahedronScaledJacobian(tet[0], tet[1], tet[2], tet[3]))
      << "tetrahedron " << t;
    // Verdict's definition: sqrt(2) times the smallest corner's det / (product of its edges).
    double smallest = std::numeric_limits<double>::infinity();
    for (int c = 0; c < 4 && t >= 4; ++c)
    {
      const Eigen::Vector3d a(tet[c]), b(tet[(c + 1) % 4]), d(tet[(c + 2) % 4]), e(tet[(c + 3) % 4]);
      const double sign = c % 2 ? -1.0 : 1.0; // odd corners see the others in reverse order
      smallest = std::min(smallest, sign * (b - a).dot((d - a).cross(e - a)) /
          ((b - a).norm() * (d - a).norm() * (e - a).norm()));
    }
    if (t >= 4)
    {
      EXPECT_NEAR(batch[t], std::sqrt(2.0) * smallest, 1e-12) << "tetrahedron " << t;
    }
  }
  EXPECT_NEAR(batch[0], 1.0, 1e-12);
  EXPECT_NEAR(batch[1], -1.0, 1e-12);
  EXPECT_EQ(batch[2], 0.0);
  EXPECT_EQ(batch[3], 0.0);
}

TEST(SmoothWarp, ReproducesAnAffineMapAtAnySmoothness)
{
  // An affine map bends nothing: fitted to its own matches, point to point, it is the warp
  // everywhere, however smooth the fit is asked to be.
  const Positions points = BoxLandmarks(400, 11);
  SmoothWarp warp(points.topRows(50), points);
  Eigen::Matrix3d linear;
  linear << 1.1, -0.1, 0.05, 0.2, 0.9, 0.0, -0.1, 0.1, 1.2;
  auto affine = [&](const Positions& p) {
    Positions moved = p * linear.transpose();
    moved.rowwise() += Eigen::RowVector3d(0.3, -0.2, 0.1);
    return moved;
  };
  const Positions normals = Positions::Zero(points.rows(), 3);
  for (const double smoothness : { 1e-6, 1.0, 1e3 })
  {
    ASSERT_TRUE(
      warp.Fit(affine(points), normals, Eigen::VectorXd::Ones(points.rows()), smoothness, 1.0));
    const Positions elsewhere = 1.5 * BoxLandmarks(300, 12);
    EXPECT_LE((elsewhere + warp.Displace(elsewhere) - affine(elsewhere)).cwiseAbs().maxCoeff(), 1e-8)
      << "smoothness " << smoothness;
  }
}

TEST(SmoothWarp, PointToPlaneMatchesAreMetAlongTheirNormals)
{
  // Points on the plane z = 0, matched to the plane 0.1 above at places scattered along it by
  // up to 0.05 (as closest points of another mesh are): the warp meets the plane, and the
  // scatter, which a point-to-plane match does not hold, hardly moves the points along it.
  Positions points = BoxLandmarks(300, 13);
  points.col(2).setZero();
  points.row(0) << 0.0, 0.0, 0.5; // a point off the plane, so that the centres span a volume
  Positions matches = points + 0.05 * BoxLandmarks(300, 15);
  matches.col(2) = points.col(2).array() + 0.1;
  Positions normals = Positions::Zero(points.rows(), 3);
  normals.col(2).setOnes();
  SmoothWarp warp(points.topRows(40), points);
  ASSERT_TRUE(warp.Fit(matches, normals, Eigen::VectorXd::Ones(points.rows()), 1e-3, 0.01));
  const Positions moved = warp.Displace(points);
  EXPECT_LE((moved.col(2).array() - 0.1).abs().maxCoeff(), 1e-3);
  const double scatter = std::sqrt((matches - points).leftCols(2).squaredNorm() / points.rows());
  const double slide = std::sqrt(moved.leftCols(2).squaredNorm() / points.rows());
  EXPECT_LE(slide, 0.2 * scatter);
  // Without weights there is nothing to fit.
  EXPECT_FALSE(warp.Fit(matches, normals, Eigen::VectorXd::Zero(points.rows()), 1e-3, 0.01));
}

TEST(SmoothWarp, FarthestPointsSpreadOverThePoints)
{
  const Positions points = BoxLandmarks(500, 14);
  const std::vector<int> chosen = SmoothWarp::FarthestPoints(points, 30);
  ASSERT_EQ(chosen.size(), 30u);
  EXPECT_EQ(chosen[0], 0);
  std::vector<int> sorted = chosen;
  std::sort(sorted.begin(), sorted.end());
  EXPECT_EQ(std::unique(sorted.begin(), sorted.end()), sorted.end()) << "no point twice";
  // Every point lies nearer a chosen one than the chosen ones lie to each other (at most twice).
  double closestPair = std::numeric_limits<double>::infinity(), farthest = 0.0;
  for (std::size_t a = 0; a < chosen.size(); ++a)
  {
    for (std::size_t b = a + 1; b < chosen.size(); ++b)
    {
      closestPair = std::min(closestPair, (points.row(chosen[a]) - points.row(chosen[b])).norm());
    }
  }
  for (Eigen::Index i = 0; i < points.rows(); ++i)
  {
    double nearest = std::numeric_limits<double>::infinity();
    for (const int c : chosen)
    {
      nearest = std::min(nearest, (points.row(i) - points.row(c)).norm());
    }
    farthest = std::max(farthest, nearest);
  }
  EXPECT_LE(farthest, closestPair + 1e-12);
  EXPECT_EQ(SmoothWarp::FarthestPoints(points.topRows(10), 30).size(), 10u) << "all, where few";
  const std::vector<int> fewer = SmoothWarp::FarthestPoints(points, 12);
  EXPECT_TRUE(std::equal(fewer.begin(), fewer.end(), chosen.begin())) << "a prefix of more";
}

namespace
{
// A block of n^3 unit cubes, six positive tetrahedra each (around the cube's diagonal); the
// block's surface points targeted, the others free.
struct TetBlock
{
  Positions Rest;
  Tetrahedra Tets;
  std::vector<PointKind> Kinds;
};

TetBlock Block(int n)
{
  TetBlock block;
  const int side = n + 1;
  auto id = [side](int i, int j, int k) { return i + side * (j + side * k); };
  block.Rest.resize(side * side * side, 3);
  block.Kinds.assign(side * side * side, PointKind::Free);
  for (int k = 0; k < side; ++k)
  {
    for (int j = 0; j < side; ++j)
    {
      for (int i = 0; i < side; ++i)
      {
        block.Rest.row(id(i, j, k)) << i, j, k;
        const bool surface = i == 0 || j == 0 || k == 0 || i == n || j == n || k == n;
        block.Kinds[id(i, j, k)] = surface ? PointKind::Targeted : PointKind::Free;
      }
    }
  }
  std::vector<std::array<int, 4>> tets;
  const int paths[6][3] = { { 0, 1, 2 }, { 0, 2, 1 }, { 1, 0, 2 }, { 1, 2, 0 }, { 2, 0, 1 }, { 2, 1, 0 } };
  for (int k = 0; k < n; ++k)
  {
    for (int j = 0; j < n; ++j)
    {
      for (int i = 0; i < n; ++i)
      {
        for (const auto& path : paths)
        {
          // From corner (0,0,0) to (1,1,1), one axis at a time.
          int c[3] = { i, j, k };
          std::array<int, 4> tet;
          tet[0] = id(c[0], c[1], c[2]);
          for (int step = 0; step < 3; ++step)
          {
            ++c[path[step]];
            tet[step + 1] = id(c[0], c[1], c[2]);
          }
          Eigen::Matrix3d d;
          for (int e = 0; e < 3; ++e)
          {
            d.col(e) = (block.Rest.row(tet[e + 1]) - block.Rest.row(tet[0])).transpose();
          }
          if (d.determinant() < 0.0)
          {
            std::swap(tet[2], tet[3]);
          }
          tets.push_back(tet);
        }
      }
    }
  }
  block.Tets.resize(static_cast<Eigen::Index>(tets.size()), 4);
  for (std::size_t t = 0; t < tets.size(); ++t)
  {
    for (int c = 0; c < 4; ++c)
    {
      block.Tets(static_cast<Eigen::Index>(t), c) = tets[t][c];
    }
  }
  return block;
}
}

// The volume drag's coarse stand-in reproduces what its weights promise: the rest, and a rigid
// motion of every constrained point, whose local-global iterations it reaches from rest.
TEST(DeformationGraph, ReproducesTheRestAndARigidMotion)
{
  const TetBlock block = Block(6);
  DeformationGraph graph;
  ASSERT_EQ(graph.Build(block.Rest, block.Tets, block.Kinds, 40), "");
  EXPECT_GT(graph.GetNumberOfNodes(), 20);
  EXPECT_LT(graph.GetNumberOfNodes(), 80);
  Positions points = block.Rest;
  graph.Solve(block.Rest, points, 4);
  EXPECT_LT((points - block.Rest).cwiseAbs().maxCoeff(), 1e-12);

  const Eigen::Matrix3d turn =
    Eigen::AngleAxisd(0.7, Eigen::Vector3d(1.0, 2.0, 3.0).normalized()).toRotationMatrix();
  const Eigen::RowVector3d shift(0.5, -2.0, 1.0);
  const Positions moved = (block.Rest * turn.transpose()).rowwise() + shift;
  graph.Solve(moved, points, 60);
  EXPECT_LT((points - moved).cwiseAbs().maxCoeff(), 1e-6);
  EXPECT_TRUE(InjectiveDeformation::Inverted(points, block.Tets).empty());

  graph.ResetToRest();
  graph.Solve(block.Rest, points, 1);
  EXPECT_LT((points - block.Rest).cwiseAbs().maxCoeff(), 1e-12);
}

// A drag of the block's top by a few degrees a step: each step's shape is smooth, inverts no
// tetrahedron, and puts the targeted points on their targets.
TEST(DeformationGraph, FollowsATurnStepByStep)
{
  TetBlock block = Block(8);
  // The bottom stays; the top turns about the x axis through the top's centre; the sides are free.
  for (int p = 0; p < block.Rest.rows(); ++p)
  {
    const double z = block.Rest(p, 2);
    if (block.Kinds[p] == PointKind::Targeted && z > 0.0 && z < 8.0)
    {
      block.Kinds[p] = PointKind::Free;
    }
    if (z == 0.0)
    {
      block.Kinds[p] = PointKind::Fixed;
    }
  }
  DeformationGraph graph;
  ASSERT_EQ(graph.Build(block.Rest, block.Tets, block.Kinds, 60), "");
  Positions points = block.Rest;
  const Eigen::RowVector3d centre(4.0, 4.0, 8.0);
  for (int step = 1; step <= 6; ++step)
  {
    const Eigen::Matrix3d turn =
      Eigen::AngleAxisd(step * 5.0 * 3.14159265358979 / 180.0, Eigen::Vector3d::UnitX()).toRotationMatrix();
    Positions targets = block.Rest;
    for (int p = 0; p < block.Rest.rows(); ++p)
    {
      if (block.Kinds[p] == PointKind::Targeted)
      {
        targets.row(p) = (block.Rest.row(p) - centre) * turn.transpose() + centre;
      }
    }
    graph.Solve(targets, points, 4);
    EXPECT_TRUE(InjectiveDeformation::Inverted(points, block.Tets).empty()) << "step " << step;
    for (int p = 0; p < block.Rest.rows(); ++p)
    {
      if (block.Kinds[p] == PointKind::Targeted)
      {
        EXPECT_EQ(points.row(p), targets.row(p));
      }
      if (block.Kinds[p] == PointKind::Fixed)
      {
        EXPECT_EQ(points.row(p), block.Rest.row(p));
      }
    }
  }
}
