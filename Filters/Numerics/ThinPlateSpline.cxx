#include "ThinPlateSpline.h"

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <limits>

namespace LaplacianEditing
{
namespace
{
// U(r) = r^2 log r = r^2 log(r^2) / 2, elementwise from r^2 (0 at 0).
template <typename Squared>
Eigen::ArrayXXd Kernel(const Squared& squared)
{
  return (squared > 0.0).select(
    0.5 * squared * squared.max(std::numeric_limits<double>::min()).log(), 0.0);
}
}

bool ThinPlateSpline::Fit(const Positions& landmarks)
{
  this->Landmarks.resize(0, 3);
  const Eigen::Index n = landmarks.rows();
  if (n < 4 || n > MaximumLandmarks)
  {
    return false;
  }
  const Vector3 origin = landmarks.colwise().mean().transpose();
  Positions centered = landmarks.rowwise() - origin.transpose();
  // A volume's worth of spread: the smallest principal variance against the largest.
  const Eigen::Vector3d variances =
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(centered.transpose() * centered).eigenvalues();
  if (!(variances(0) > 1e-10 * variances(2)))
  {
    return false;
  }
  const double extent = (centered.colwise().maxCoeff() - centered.colwise().minCoeff()).norm();
  centered /= extent;
  Eigen::MatrixXd system = Eigen::MatrixXd::Zero(n + 4, n + 4);
  for (Eigen::Index i = 0; i < n; ++i)
  {
    system.col(i).head(n) = Kernel((centered.rowwise() - centered.row(i)).rowwise().squaredNorm().array());
  }
  system.block(0, n, n, 1).setOnes();
  system.block(0, n + 1, n, 3) = centered;
  system.block(n, 0, 4, n) = system.block(0, n, n, 4).transpose();
  this->System.compute(system);
  this->Landmarks = centered;
  this->Origin = origin;
  this->Scale = 1.0 / extent;
  return true;
}

Positions ThinPlateSpline::Displace(
  const Positions& displacements, const Positions& points, const ParallelFor& loop) const
{
  Eigen::MatrixXd values = Eigen::MatrixXd::Zero(this->Landmarks.rows() + 4, 3);
  values.topRows(this->Landmarks.rows()) = displacements;
  return this->Evaluate(this->System.solve(values), points, loop);
}

Eigen::VectorXd ThinPlateSpline::Cardinal(int landmark, const Positions& points, const ParallelFor& loop) const
{
  Eigen::VectorXd value = Eigen::VectorXd::Zero(this->Landmarks.rows() + 4);
  value(landmark) = 1.0;
  return this->Evaluate(this->System.solve(value), points, loop);
}

Eigen::MatrixXd ThinPlateSpline::Evaluate(
  const Eigen::MatrixXd& coefficients, const Positions& points, const ParallelFor& loop) const
{
  const Eigen::Index n = this->Landmarks.rows();
  const auto weights = coefficients.topRows(n);
  const auto affine = coefficients.bottomRows(4);
  const Eigen::RowVectorXd landmarkNorms = this->Landmarks.rowwise().squaredNorm().transpose();
  Eigen::MatrixXd result(points.rows(), coefficients.cols());
  loop(0, static_cast<int>(points.rows()), [&](int first, int last) {
    // Blocks of points: their squared distances as one product, the kernel vectorized over them.
    constexpr int Block = 64;
    for (int begin = first; begin < last; begin += Block)
    {
      const int size = std::min(Block, last - begin);
      const Positions local =
        (points.middleRows(begin, size).rowwise() - this->Origin.transpose()) * this->Scale;
      Eigen::MatrixXd squared = -2.0 * local * this->Landmarks.transpose();
      squared.colwise() += local.rowwise().squaredNorm();
      squared.rowwise() += landmarkNorms;
      auto block = result.middleRows(begin, size);
      block.noalias() = Kernel(squared.array().max(0.0)).matrix() * weights;
      block.rowwise() += affine.row(0);
      block.noalias() += local * affine.bottomRows(3);
    }
  });
  return result;
}
}
