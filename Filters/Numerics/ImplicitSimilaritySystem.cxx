#include "ImplicitSimilaritySystem.h"

#include <Eigen/Dense>

#include <cmath>

namespace LaplacianEditing
{
namespace
{
// Flattens n x 3 positions into (x0, y0, z0, x1, ...), the unknowns' order.
Eigen::VectorXd Interleave(const Positions& positions)
{
  const Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor> rows = positions;
  return Eigen::Map<const Eigen::VectorXd>(rows.data(), rows.size());
}

Positions Deinterleave(const Eigen::VectorXd& values)
{
  return Eigen::Map<const Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>>(
    values.data(), values.size() / 3, 3);
}

// [x, y, z] -> the 3 x 7 block of Eq. 11 for unknowns (s, h1, h2, h3, tx, ty, tz).
Eigen::Matrix<double, 3, 7> FitBlock(const Eigen::Vector3d& p)
{
  Eigen::Matrix<double, 3, 7> block;
  block << p.x(), 0.0, p.z(), -p.y(), 1.0, 0.0, 0.0, //
    p.y(), -p.z(), 0.0, p.x(), 0.0, 1.0, 0.0,         //
    p.z(), p.y(), -p.x(), 0.0, 0.0, 0.0, 1.0;
  return block;
}

// T delta = s delta + h x delta, as a 3 x 4 matrix acting on (s, h1, h2, h3).
Eigen::Matrix<double, 3, 4> ApplyToDelta(const Eigen::Vector3d& delta)
{
  Eigen::Matrix<double, 3, 4> g;
  g.col(0) = delta;
  g.col(1) = Eigen::Vector3d::UnitX().cross(delta);
  g.col(2) = Eigen::Vector3d::UnitY().cross(delta);
  g.col(3) = Eigen::Vector3d::UnitZ().cross(delta);
  return g;
}
}

std::string ImplicitSimilaritySystem::Build(const SurfaceMesh& mesh, const EditRegion& region,
  const DeformationSystem& plain, const DeformationOptions& options,
  const ImplicitFormulation& formulation)
{
  const LaplacianOperator edgeWeights(mesh, options.Weights);
  const int n = region.GetNumberOfVertices();
  this->NumberOfVertices = n;
  this->RestDelta = plain.GetRestDifferentialCoordinates();
  const auto& positions = mesh.GetPositions();
  std::vector<int> roiRow(mesh.GetNumberOfVertices(), -1);
  for (int row = 0; row < n; ++row)
  {
    roiRow[region.Vertices[row]] = row;
  }

  // Rings and fits.
  this->RingOffsets.assign(1, 0);
  this->RingRoiRows.clear();
  std::vector<int> ringVertices;
  for (int row = 0; row < n; ++row)
  {
    const int v = region.Vertices[row];
    ringVertices.push_back(v);
    ringVertices.insert(ringVertices.end(), mesh.NeighborsBegin(v), mesh.NeighborsEnd(v));
    this->RingOffsets.push_back(static_cast<int>(ringVertices.size()));
  }
  this->RingRest.resize(static_cast<Eigen::Index>(ringVertices.size()), 3);
  for (std::size_t k = 0; k < ringVertices.size(); ++k)
  {
    this->RingRoiRows.push_back(roiRow[ringVertices[k]]);
    this->RingRest.row(k) = positions[ringVertices[k]].transpose();
  }
  this->Fits.resize(n);
  this->FitOffsets.resize(n);

  // The residual rows: per vertex (the paper's, Eq. 12) or per one-ring edge. Each row is
  // sum_c a_c v'_c - T_i(V') e = k with T_i(V') e = G(e) (Fits ring + offset): `Add` collects
  // the T part, the unknown or known ring members, and the constants.
  std::vector<Eigen::Triplet<double>> triplets;
  std::vector<double> known;
  const auto& laplacian = plain.GetRegionOperator();
  const Positions& fixedPart = plain.GetFixedPart();
  auto addTransformTerm = [&](int equation, int row, const Eigen::Vector3d& e, double scale) {
    const int begin = this->RingOffsets[row];
    const int size = this->RingOffsets[row + 1] - begin;
    const Eigen::Matrix<double, 3, 4> apply = ApplyToDelta(e);
    const Eigen::MatrixXd transform = apply * this->Fits[row];
    const Eigen::Vector3d constant = apply * this->FitOffsets[row];
    for (int a = 0; a < 3; ++a)
    {
      known[equation + a] += scale * constant[a];
    }
    for (int q = 0; q < size; ++q)
    {
      const int member = this->RingRoiRows[begin + q];
      const Eigen::Matrix3d block = scale * transform.middleCols<3>(3 * q);
      if (member < 0)
      {
        const Eigen::Vector3d term = block * this->RingRest.row(begin + q).transpose();
        for (int a = 0; a < 3; ++a)
        {
          known[equation + a] += term[a];
        }
        continue;
      }
      for (int a = 0; a < 3; ++a)
      {
        for (int c = 0; c < 3; ++c)
        {
          triplets.emplace_back(equation + a, 3 * member + c, -block(a, c));
        }
      }
    }
  };
  for (int row = 0; row < n; ++row)
  {
    const int begin = this->RingOffsets[row];
    const int size = this->RingOffsets[row + 1] - begin;
    // Centre on the vertex for conditioning; the translation absorbs the shift.
    Eigen::MatrixXd fitMatrix(3 * size, 7);
    for (int q = 0; q < size; ++q)
    {
      fitMatrix.middleRows<3>(3 * q) =
        FitBlock(this->RingRest.row(begin + q) - this->RingRest.row(begin));
    }
    this->Fits[row].setZero(4, 3 * size);
    this->FitOffsets[row].setZero();
    if (formulation.AllowScaling)
    {
      this->Fits[row] = fitMatrix.completeOrthogonalDecomposition().pseudoInverse().topRows(4);
    }
    else
    {
      // s = 1: fit (h, t) to what the rest ring, unscaled, leaves over.
      const Eigen::MatrixXd fit =
        fitMatrix.rightCols<6>().completeOrthogonalDecomposition().pseudoInverse().topRows(3);
      this->Fits[row].bottomRows<3>() = fit;
      this->FitOffsets[row] << 1.0, -fit * fitMatrix.col(0);
    }

    if (!formulation.PerEdge)
    {
      // D(V')_i - T_i(V') delta_i = -fixed part.
      const int equation = static_cast<int>(known.size());
      known.resize(known.size() + 3, 0.0);
      for (Eigen::SparseMatrix<double, Eigen::RowMajor>::InnerIterator it(laplacian, row); it; ++it)
      {
        for (int c = 0; c < 3; ++c)
        {
          triplets.emplace_back(equation + c, 3 * static_cast<int>(it.col()) + c, it.value());
        }
      }
      for (int c = 0; c < 3; ++c)
      {
        known[equation + c] -= fixedPart(row, c);
      }
      addTransformTerm(equation, row, this->RestDelta.row(row).transpose(), 1.0);
      continue;
    }
    // sqrt(w_ij) ((v'_i - v'_j) - T_i(V') (v_i - v_j)) = 0, with the row's weights.
    const std::vector<double> weights = edgeWeights.EdgeWeights(region.Vertices[row]);
    double total = 0.0;
    for (double w : weights)
    {
      total += w;
    }
    for (int q = 1; q < size; ++q)
    {
      const double scale = std::sqrt(weights[q - 1] / total);
      const int equation = static_cast<int>(known.size());
      known.resize(known.size() + 3, 0.0);
      const int member = this->RingRoiRows[begin + q];
      for (int c = 0; c < 3; ++c)
      {
        triplets.emplace_back(equation + c, 3 * row + c, scale);
        if (member >= 0)
        {
          triplets.emplace_back(equation + c, 3 * member + c, -scale);
        }
        else
        {
          known[equation + c] += scale * this->RingRest(begin + q, c);
        }
      }
      addTransformTerm(equation, row,
        (this->RingRest.row(begin) - this->RingRest.row(begin + q)).transpose(), scale);
    }
  }
  Eigen::SparseMatrix<double> system(static_cast<Eigen::Index>(known.size()), 3 * n);
  system.setFromTriplets(triplets.begin(), triplets.end());
  const Eigen::SparseMatrix<double> transposed = system.transpose();
  Eigen::SparseMatrix<double> normalMatrix = transposed * system;
  const Eigen::VectorXd& squaredWeights = plain.GetSquaredWeights();
  for (int k = 0; k < 3 * n; ++k)
  {
    normalMatrix.coeffRef(k, k) += squaredWeights[k / 3];
  }
  normalMatrix.makeCompressed();
  this->KnownRightHandSide = transposed * Eigen::Map<const Eigen::VectorXd>(known.data(), known.size());
  const std::string error = this->Factor.Factorize(
    normalMatrix, options.Backend, options.Ordering, options.MaximumFactorBytes);
  if (!error.empty())
  {
    return error;
  }

  // The rest solution and the responses, in one multi-column solve. Column 1 + 12 g + 4 c + j
  // holds the constraint term of entry (c, j) of group g's map.
  const int groups = plain.GetNumberOfHandleGroups();
  Eigen::MatrixXd rhs = Eigen::MatrixXd::Zero(3 * n, 1 + 12 * groups);
  rhs.col(0) = this->KnownRightHandSide +
    Interleave(plain.ConstraintRightHandSide(std::vector<AffineMap>(groups, AffineMap::Zero())));
  for (int g = 0; g < groups; ++g)
  {
    const Eigen::MatrixXd basis = plain.HandleBasis(g);
    for (int c = 0; c < 3; ++c)
    {
      for (int j = 0; j < 4; ++j)
      {
        for (int k = 0; k < n; ++k)
        {
          rhs(3 * k + c, 1 + 12 * g + 4 * c + j) = basis(k, j);
        }
      }
    }
  }
  const Eigen::MatrixXd solution = this->Factor.Solve(rhs);
  this->RestSolution = solution.col(0);
  this->GroupResponses.resize(groups);
  for (int g = 0; g < groups; ++g)
  {
    this->GroupResponses[g] = solution.middleCols<12>(1 + 12 * g);
  }
  return {};
}

Positions ImplicitSimilaritySystem::Solve(const std::vector<AffineMap>& handleMaps) const
{
  Eigen::VectorXd solution = this->RestSolution;
  for (std::size_t g = 0; g < this->GroupResponses.size(); ++g)
  {
    const Eigen::Matrix<double, 3, 4, Eigen::RowMajor> map =
      g < handleMaps.size() ? handleMaps[g] : AffineMap::Identity();
    solution.noalias() +=
      this->GroupResponses[g] * Eigen::Map<const Eigen::Matrix<double, 12, 1>>(map.data());
  }
  return Deinterleave(solution);
}

Positions ImplicitSimilaritySystem::SolveDirect(
  const DeformationSystem& plain, const std::vector<AffineMap>& handleMaps) const
{
  const Eigen::VectorXd rhs =
    this->KnownRightHandSide + Interleave(plain.ConstraintRightHandSide(handleMaps));
  return Deinterleave(this->Factor.Solve(rhs));
}

Eigen::VectorXd ImplicitSimilaritySystem::Ring(int row, const Positions& roiPositions) const
{
  const int begin = this->RingOffsets[row];
  const int size = this->RingOffsets[row + 1] - begin;
  Eigen::VectorXd ring(3 * size);
  for (int q = 0; q < size; ++q)
  {
    const int member = this->RingRoiRows[begin + q];
    ring.segment<3>(3 * q) = member >= 0 ? roiPositions.row(member).transpose()
                                         : this->RingRest.row(begin + q).transpose();
  }
  return ring;
}

Positions ImplicitSimilaritySystem::RotatedDifferentialCoordinates(
  const Positions& roiPositions, const ParallelFor& loop) const
{
  Positions rotated(this->NumberOfVertices, 3);
  loop(0, this->NumberOfVertices, [&](int first, int last) {
    for (int row = first; row < last; ++row)
    {
      const Eigen::Vector3d delta = this->RestDelta.row(row).transpose();
      const Eigen::Vector3d transformed = ApplyToDelta(delta) *
        (this->Fits[row] * this->Ring(row, roiPositions) + this->FitOffsets[row]);
      const double length = transformed.norm();
      const Eigen::Vector3d rescaled =
        length > 0.0 ? Eigen::Vector3d(transformed * (delta.norm() / length)) : delta;
      rotated.row(row) = rescaled.transpose();
    }
  });
  return rotated;
}
}
