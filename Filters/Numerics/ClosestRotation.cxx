#include "ClosestRotation.h"

#include <Eigen/Dense>

#include <cmath>

namespace LaplacianEditing
{
bool RefineClosestRotation(const Eigen::Matrix3d& a, Eigen::Quaterniond& q, int steps)
{
  for (int step = 0; step < steps; ++step)
  {
    // trace((exp([w]) R)^T A), to second order in the angle w: trace(M) + g.w - w^T H w / 2 for
    // M = A R^T, g its skew part, H = trace(M) I - sym(M).
    const Eigen::Matrix3d m = a * q.toRotationMatrix().transpose();
    const Vector3 gradient(m(2, 1) - m(1, 2), m(0, 2) - m(2, 0), m(1, 0) - m(0, 1));
    const double trace = m.trace();
    const double h00 = trace - m(0, 0), h11 = trace - m(1, 1), h22 = trace - m(2, 2);
    const double h01 = -0.5 * (m(0, 1) + m(1, 0)), h02 = -0.5 * (m(0, 2) + m(2, 0)),
                 h12 = -0.5 * (m(1, 2) + m(2, 1));
    // Newton's step where H is safely positive definite (near the maximum); elsewhere Mueller's,
    // which takes trace(M) for all of H: on a flat ring's covariance that step is half as long
    // as it should be, and four of them left 1e-5 of an angle. H's inverse by its cofactors.
    const double c00 = h11 * h22 - h12 * h12, c01 = h02 * h12 - h01 * h22, c02 = h01 * h12 - h02 * h11;
    const double determinant = h00 * c00 + h01 * c01 + h02 * c02;
    const double scale = h00 + h11 + h22;
    const bool concave = h00 > 0.0 && h00 * h11 - h01 * h01 > 0.0 &&
      determinant > 1e-6 * scale * scale * scale;
    Vector3 omega;
    if (concave)
    {
      const double c11 = h00 * h22 - h02 * h02, c12 = h01 * h02 - h00 * h12, c22 = h00 * h11 - h01 * h01;
      omega = Vector3(c00 * gradient.x() + c01 * gradient.y() + c02 * gradient.z(),
                c01 * gradient.x() + c11 * gradient.y() + c12 * gradient.z(),
                c02 * gradient.x() + c12 * gradient.y() + c22 * gradient.z()) /
        determinant;
    }
    else
    {
      omega = gradient / (std::abs(trace) + 1e-12);
    }
    // The rotation by omega, to first order: the error this leaves is of third order.
    q = Eigen::Quaterniond(1.0, 0.5 * omega.x(), 0.5 * omega.y(), 0.5 * omega.z()) * q;
    q.normalize();
    if (concave && omega.squaredNorm() < 1e-14)
    {
      return true; // quadratic convergence: the next step would be of order 1e-14 or less
    }
  }
  return false;
}

Eigen::Quaterniond ClosestRotation(const Eigen::Matrix3d& a)
{
  // The right singular vectors of the two largest singular values, as eigenvectors of A^T A in
  // closed form (a fifth of a Jacobi SVD's time); the left ones follow as A v / |A v|, the
  // third of each as a cross product, which also turns a reflection into the closest rotation.
  // Where A is nearly of rank one, the second direction is undefined: the SVD decides it.
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen;
  eigen.computeDirect(a.transpose() * a);
  const Vector3 v1 = eigen.eigenvectors().col(2);
  const Vector3 v2 = eigen.eigenvectors().col(1);
  Vector3 u1 = a * v1;
  Vector3 u2 = a * v2;
  const double n1 = u1.norm();
  if (n1 > 0.0)
  {
    u2 -= u2.dot(u1) / (n1 * n1) * u1;
  }
  const double n2 = u2.norm();
  if (n1 > 0.0 && n2 > 1e-6 * n1 && std::abs(v1.dot(v2)) < 1e-6)
  {
    u1 /= n1;
    u2 /= n2;
    Eigen::Matrix3d u, v;
    u << u1, u2, u1.cross(u2);
    v << v1, v2, v1.cross(v2);
    return Eigen::Quaterniond(Eigen::Matrix3d(u * v.transpose()));
  }
  const Eigen::JacobiSVD<Eigen::Matrix3d> svd(a, Eigen::ComputeFullU | Eigen::ComputeFullV);
  Eigen::Matrix3d u = svd.matrixU();
  if ((u * svd.matrixV().transpose()).determinant() < 0.0)
  {
    u.col(2) = -u.col(2); // a reflection: flip the direction of least stretch
  }
  return Eigen::Quaterniond(Eigen::Matrix3d(u * svd.matrixV().transpose()));
}
}
