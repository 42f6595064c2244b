#include "PointConstraints.h"

#include <algorithm>

namespace LaplacianEditing
{
std::string PointConstraints::Build(
  const std::vector<SurfacePoint>& points, const std::vector<int>& rowOfVertex)
{
  this->Rows.resize(points.size());
  this->Weights.resize(points.size());
  this->Pulls.resize(points.size());
  for (std::size_t p = 0; p < points.size(); ++p)
  {
    for (int c = 0; c < 3; ++c)
    {
      const int vertex = points[p].Vertices[c];
      const int row =
        vertex >= 0 && vertex < static_cast<int>(rowOfVertex.size()) ? rowOfVertex[vertex] : -1;
      if (row < 0 && points[p].Weights[c] != 0.0)
      {
        return "point " + std::to_string(p) + " lies outside the region";
      }
      this->Rows[p][c] = std::max(row, 0);
      this->Weights[p][c] = points[p].Weights[c];
    }
    this->Pulls[p] = points[p].Pull;
  }
  return {};
}

void PointConstraints::Weigh(double weight, const Eigen::SparseMatrix<double>& upper)
{
  const double meanDiagonal = upper.rows() > 0 ? upper.diagonal().mean() : 1.0;
  this->SquaredWeight = weight * weight * meanDiagonal;
}

Positions PointConstraints::Evaluate(const Positions& region) const
{
  Positions points(this->GetNumberOfPoints(), 3);
  for (int p = 0; p < this->GetNumberOfPoints(); ++p)
  {
    points.row(p) = this->Weights[p][0] * region.row(this->Rows[p][0]) +
      this->Weights[p][1] * region.row(this->Rows[p][1]) +
      this->Weights[p][2] * region.row(this->Rows[p][2]);
  }
  return points;
}

std::string PointConstraints::AddToMatrix(
  Eigen::SparseMatrix<double>& upper, const std::vector<int>& unknownOfRow, int blockSize) const
{
  for (int p = 0; p < this->GetNumberOfPoints(); ++p)
  {
    for (int a = 0; a < 3; ++a)
    {
      for (int b = 0; b < 3; ++b)
      {
        const double value = this->SquaredWeight * this->Pulls[p] * this->Weights[p][a] * this->Weights[p][b];
        if (value == 0.0)
        {
          continue;
        }
        const int ua = unknownOfRow[this->Rows[p][a]], ub = unknownOfRow[this->Rows[p][b]];
        if (ua < 0 || ub < 0)
        {
          return "point " + std::to_string(p) + " lies on a vertex whose position is given";
        }
        for (int c = 0; c < blockSize && ua <= ub; ++c)
        {
          // Entries between a triangle's corners exist already but for a polygon's diagonal.
          upper.coeffRef(ua * blockSize + c, ub * blockSize + c) += value;
        }
      }
    }
  }
  upper.makeCompressed();
  return {};
}

Positions PointConstraints::RightHandSide(const Positions& targets, int rows) const
{
  Positions rhs = Positions::Zero(rows, 3);
  for (int p = 0; p < this->GetNumberOfPoints(); ++p)
  {
    for (int c = 0; c < 3; ++c)
    {
      rhs.row(this->Rows[p][c]) += (this->SquaredWeight * this->Pulls[p] * this->Weights[p][c]) * targets.row(p);
    }
  }
  return rhs;
}

double PointConstraints::PulledSquaredMiss(const Positions& region, const Positions& targets) const
{
  const Eigen::VectorXd misses = (this->Evaluate(region) - targets).rowwise().squaredNorm();
  return misses.dot(Eigen::Map<const Eigen::VectorXd>(this->Pulls.data(), this->GetNumberOfPoints()));
}

double PointConstraints::LargestMiss(const Positions& region, const Positions& targets) const
{
  return this->IsEmpty() ? 0.0 : (this->Evaluate(region) - targets).rowwise().norm().maxCoeff();
}

// A fit's round that lowers the squared miss by less than this fraction ends it.
constexpr double StallingDecrease = 1e-3;

int PointConstraints::Fit(const std::function<Positions(const Positions&)>& solve,
  const PointTargets& targets, Positions& correction, Positions& solution, double& miss) const
{
  // `solve` is affine in the targets it sees, so the correction c that meets them solves
  // A c = r, with A = B S B^T symmetric positive semidefinite (S: the pull through the factor)
  // and r what the points miss at the carried correction. Conjugate residuals: each round is
  // one solve, the miss never grows, and far fewer rounds than moving the targets by the miss
  // when landmarks are dense. A is singular where more points than corners share triangles;
  // their targets then cannot all be met, and the rounds stop where the miss stops falling.
  const Positions& wanted = targets.Targets;
  if (!targets.Exact || correction.rows() != wanted.rows())
  {
    correction = Positions::Zero(wanted.rows(), 3);
  }
  const Positions effective = wanted + correction;
  const Positions base = solve(effective);
  solution = base;
  int rounds = 1;
  auto largest = [this](const Positions& r) { return this->IsEmpty() ? 0.0 : r.rowwise().norm().maxCoeff(); };
  Positions residual = wanted - this->Evaluate(solution);
  miss = largest(residual);
  if (!targets.Exact || !(miss > targets.Tolerance))
  {
    return rounds;
  }
  // A residual's response (S B^T r), solved at unit size: as a difference of two solves, a
  // tiny one would lose its digits to the solution's.
  auto respond = [&](const Positions& r) -> Positions {
    ++rounds;
    const double size = r.cwiseAbs().maxCoeff(); // not zero: the points still miss
    return (solve(effective + r / size) - base) * size;
  };
  Positions response = respond(residual); // of the residual
  Positions pulled = this->Evaluate(response); // A r
  Positions direction = residual, directionResponse = response, directionPulled = pulled;
  double product = (residual.array() * pulled.array()).sum(); // r . A r
  double squaredMiss = residual.squaredNorm();
  while (rounds < targets.MaximumRounds && product > 0.0)
  {
    const double step = product / directionPulled.squaredNorm();
    correction += step * direction;
    solution += step * directionResponse;
    residual -= step * directionPulled;
    const double before = squaredMiss;
    const Positions missed = wanted - this->Evaluate(solution);
    miss = largest(missed);
    squaredMiss = missed.squaredNorm();
    if (!(miss > targets.Tolerance) || !(squaredMiss < (1.0 - StallingDecrease) * before))
    {
      break; // met, or the miss left is what the points cannot all meet
    }
    response = respond(residual);
    pulled = this->Evaluate(response);
    const double next = (residual.array() * pulled.array()).sum();
    const double ratio = next / product;
    direction = residual + ratio * direction;
    directionResponse = response + ratio * directionResponse;
    directionPulled = pulled + ratio * directionPulled;
    product = next;
  }
  return rounds;
}
}
