#include "SmoothWarp.h"

#include <Eigen/LU>

#include <algorithm>
#include <limits>

namespace LaplacianEditing
{
std::vector<int> SmoothWarp::FarthestPoints(const Positions& points, int count)
{
  const int n = static_cast<int>(points.rows());
  std::vector<int> chosen;
  if (n == 0)
  {
    return chosen;
  }
  Eigen::VectorXd nearest = Eigen::VectorXd::Constant(n, std::numeric_limits<double>::infinity());
  int next = 0;
  while (static_cast<int>(chosen.size()) < std::min(count, n))
  {
    chosen.push_back(next);
    nearest = nearest.cwiseMin((points.rowwise() - points.row(next)).rowwise().squaredNorm());
    nearest.maxCoeff(&next);
  }
  return chosen;
}

SmoothWarp::SmoothWarp(const Positions& centres, const Positions& points)
  : Points(points)
{
  this->Origin = centres.colwise().mean().transpose();
  const double extent = (centres.colwise().maxCoeff() - centres.colwise().minCoeff()).norm();
  this->Scale = extent > 0.0 ? 1.0 / extent : 1.0;
  this->Centres = (centres.rowwise() - this->Origin.transpose()) * this->Scale;
  this->Coefficients = Eigen::MatrixXd::Zero(centres.rows() + 4, 3);
  this->Values = this->Basis(points);
  const Eigen::Index k = this->Centres.rows();
  this->Bending.resize(k, k);
  for (Eigen::Index c = 0; c < k; ++c)
  {
    this->Bending.col(c) = (this->Centres.rowwise() - this->Centres.row(c)).rowwise().norm();
  }
}

Eigen::MatrixXd SmoothWarp::Basis(const Positions& points) const
{
  const Eigen::Index k = this->Centres.rows();
  Eigen::MatrixXd basis(points.rows(), k + 4);
  for (Eigen::Index i = 0; i < points.rows(); ++i)
  {
    const Eigen::RowVector3d x = (points.row(i) - this->Origin.transpose()) * this->Scale;
    basis.row(i).head(k) = (this->Centres.rowwise() - x).rowwise().norm().transpose();
    basis(i, k) = 1.0;
    basis.row(i).tail(3) = x;
  }
  return basis;
}

bool SmoothWarp::Fit(const Positions& matches, const Positions& normals,
  const Eigen::VectorXd& weights, double smoothness, double pointShare)
{
  const Eigen::Index k = this->Centres.rows(), m = k + 4, n = this->Points.rows();
  if ((weights.array() > 0.0).count() < 4)
  {
    return false;
  }
  const Eigen::MatrixXd& basis = this->Values;
  // The residuals in the frame: x + d(x) - m, the displacement's frame scale included.
  const Positions gap = (matches - this->Points) * this->Scale;
  // Normal equations of the three axes' coefficients together: the point-to-plane term couples
  // them through n n^T, the point-to-point share adds to each axis alone.
  Eigen::MatrixXd system = Eigen::MatrixXd::Zero(3 * m + 12, 3 * m + 12);
  Eigen::VectorXd rhs = Eigen::VectorXd::Zero(3 * m + 12);
  for (int a = 0; a < 3; ++a)
  {
    for (int b = a; b < 3; ++b)
    {
      Eigen::VectorXd w = weights.cwiseProduct(normals.col(a).cwiseProduct(normals.col(b)));
      if (a == b)
      {
        w += pointShare * weights;
      }
      system.block(a * m, b * m, m, m) = basis.transpose() * w.asDiagonal() * basis;
      system.block(b * m, a * m, m, m) = system.block(a * m, b * m, m, m).transpose();
    }
    const Eigen::VectorXd along = gap.cwiseProduct(normals).rowwise().sum();
    rhs.segment(a * m, m) = basis.transpose() *
      (weights.cwiseProduct(normals.col(a).cwiseProduct(along) + pointShare * gap.col(a)));
  }
  // The bending energy on each axis, and the side conditions P^T a = 0 that make it one.
  Eigen::MatrixXd sides(k, 4);
  sides.col(0).setOnes();
  sides.rightCols(3) = this->Centres;
  for (int a = 0; a < 3; ++a)
  {
    system.block(a * m, a * m, k, k) -= smoothness * static_cast<double>(n) * this->Bending;
    system.block(3 * m + 4 * a, a * m, 4, k) = sides.transpose();
    system.block(a * m, 3 * m + 4 * a, k, 4) = sides;
  }
  const Eigen::PartialPivLU<Eigen::MatrixXd> lu(system);
  const Eigen::VectorXd solution = lu.solve(rhs);
  if (!solution.allFinite() || (system * solution - rhs).norm() > 1e-6 * (rhs.norm() + 1e-300))
  {
    return false;
  }
  for (int a = 0; a < 3; ++a)
  {
    this->Coefficients.col(a) = solution.segment(a * m, m);
  }
  return true;
}

Positions SmoothWarp::Displace(const Positions& points, const ParallelFor& loop) const
{
  Positions displacements(points.rows(), 3);
  loop(0, static_cast<int>(points.rows()), [&](int first, int last) {
    displacements.middleRows(first, last - first) =
      this->Basis(points.middleRows(first, last - first)) * this->Coefficients / this->Scale;
  });
  return displacements;
}
}
