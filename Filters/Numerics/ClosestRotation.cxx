#include "ClosestRotation.h"

#include <Eigen/Dense>

#include <cmath>

namespace LaplacianEditing
{
Eigen::Matrix3d RefineClosestRotation(const Eigen::Matrix3d& a, Eigen::Quaterniond& q, int steps)
{
  for (int step = 0; step < steps; ++step)
  {
    const Eigen::Matrix3d r = q.toRotationMatrix();
    const Vector3 omega = (r.col(0).cross(a.col(0)) + r.col(1).cross(a.col(1)) +
                            r.col(2).cross(a.col(2))) /
      (std::abs(r.col(0).dot(a.col(0)) + r.col(1).dot(a.col(1)) + r.col(2).dot(a.col(2))) + 1e-12);
    if (omega.squaredNorm() < 1e-20)
    {
      break;
    }
    // The rotation by omega, to first order: the iteration converges all the same.
    q = Eigen::Quaterniond(1.0, 0.5 * omega.x(), 0.5 * omega.y(), 0.5 * omega.z()) * q;
    q.normalize();
  }
  return q.toRotationMatrix();
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
