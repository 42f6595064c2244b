#include "ClosestRotation.h"

#include "SimdClones.h"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <cstring>

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

#if defined(__GNUC__) // GCC and Clang: vector extensions
namespace
{
// Four rotations refined together, one per lane of a vector of doubles: AVX2 where the
// processor has it (GCC builds the function for both and the loader picks), two SSE2 halves
// otherwise.
using Lanes = double __attribute__((vector_size(32)));

// Four refinements, as plain arrays (vectors are not passed across the two builds).
struct Batch
{
  double A[9][4]; // row-major
  double Q[4][4]; // w, x, y, z
  double Done[4]; // 1 where converged
};

// The steps of RefineClosestRotation in every lane, without branches: R from q (as
// Quaterniond::toRotationMatrix), M = A R^T, Newton's step where H is safely positive definite
// and Mueller's elsewhere; a lane done keeps its rotation.
LAPLACIAN_EDITING_SIMD_CLONES
void RefineBatch(Batch& batch, int steps)
{
  Lanes a[9], q[4], done;
  std::memcpy(a, batch.A, sizeof(a));
  std::memcpy(q, batch.Q, sizeof(q));
  std::memcpy(&done, batch.Done, sizeof(done));
  const Lanes zero = {}, one = zero + 1.0;
  for (int step = 0; step < steps && !(done[0] && done[1] && done[2] && done[3]); ++step)
  {
    const Lanes w = q[0], x = q[1], y = q[2], z = q[3];
    const Lanes tx = 2 * x, ty = 2 * y, tz = 2 * z;
    const Lanes twx = tx * w, twy = ty * w, twz = tz * w, txx = tx * x, txy = ty * x,
                txz = tz * x, tyy = ty * y, tyz = tz * y, tzz = tz * z;
    const Lanes r[9] = { 1 - (tyy + tzz), txy - twz, txz + twy, txy + twz, 1 - (txx + tzz),
      tyz - twx, txz - twy, tyz + twx, 1 - (txx + tyy) };
    Lanes m[9];
    for (int row = 0; row < 3; ++row)
    {
      for (int column = 0; column < 3; ++column)
      {
        m[3 * row + column] = a[3 * row] * r[3 * column] + a[3 * row + 1] * r[3 * column + 1] +
          a[3 * row + 2] * r[3 * column + 2];
      }
    }
    const Lanes g0 = m[7] - m[5], g1 = m[2] - m[6], g2 = m[3] - m[1];
    const Lanes trace = m[0] + m[4] + m[8];
    const Lanes h00 = trace - m[0], h11 = trace - m[4], h22 = trace - m[8];
    const Lanes h01 = -0.5 * (m[1] + m[3]), h02 = -0.5 * (m[2] + m[6]),
                h12 = -0.5 * (m[5] + m[7]);
    const Lanes c00 = h11 * h22 - h12 * h12, c01 = h02 * h12 - h01 * h22,
                c02 = h01 * h12 - h02 * h11, c11 = h00 * h22 - h02 * h02,
                c12 = h01 * h02 - h00 * h12, c22 = h00 * h11 - h01 * h01;
    const Lanes determinant = h00 * c00 + h01 * c01 + h02 * c02;
    const Lanes scale = h00 + h11 + h22;
    const Lanes concave =
      ((h00 > 0.0) & (c22 > 0.0) & (determinant > 1e-6 * scale * scale * scale)) ? one : zero;
    const Lanes absTrace = trace < 0.0 ? -trace : trace;
    const Lanes newton = concave / (concave * determinant + (one - concave));
    const Lanes mueller = (one - concave) / (absTrace + 1e-12);
    const Lanes o0 = newton * (c00 * g0 + c01 * g1 + c02 * g2) + mueller * g0;
    const Lanes o1 = newton * (c01 * g0 + c11 * g1 + c12 * g2) + mueller * g1;
    const Lanes o2 = newton * (c02 * g0 + c12 * g1 + c22 * g2) + mueller * g2;
    // q = (1, omega / 2) q, normalized.
    const Lanes move = (one - done) * 0.5;
    const Lanes hx = move * o0, hy = move * o1, hz = move * o2;
    const Lanes nw = w - hx * x - hy * y - hz * z;
    const Lanes nx = x + hx * w + hy * z - hz * y;
    const Lanes ny = y - hx * z + hy * w + hz * x;
    const Lanes nz = z + hx * y - hy * x + hz * w;
    const Lanes squared = nw * nw + nx * nx + ny * ny + nz * nz;
    Lanes norm;
    for (int l = 0; l < 4; ++l)
    {
      norm[l] = std::sqrt(squared[l]);
    }
    // A lane done keeps its quaternion to the bit: normalizing it again would make a rotation
    // depend on how long its batch's other lanes took, and so on how threads split the loop.
    const Lanes keep = done, take = one - done;
    q[0] = keep * w + take * (nw / norm);
    q[1] = keep * x + take * (nx / norm);
    q[2] = keep * y + take * (ny / norm);
    q[3] = keep * z + take * (nz / norm);
    const Lanes converged = (o0 * o0 + o1 * o1 + o2 * o2 < 1e-14) ? concave : zero;
    done = done > converged ? done : converged;
  }
  std::memcpy(batch.Q, q, sizeof(q));
  std::memcpy(batch.Done, &done, sizeof(done));
}
}
#endif

void RefineClosestRotations(
  const Eigen::Matrix3d* a, Eigen::Quaterniond* q, bool* converged, int count, int steps)
{
#if defined(__GNUC__)
  for (int first = 0; first < count; first += 4)
  {
    const int lanes = std::min(4, count - first);
    Batch batch;
    for (int l = 0; l < 4; ++l)
    {
      const int i = first + std::min(l, lanes - 1); // spare lanes repeat the last rotation
      for (int e = 0; e < 9; ++e)
      {
        batch.A[e][l] = a[i](e / 3, e % 3);
      }
      batch.Q[0][l] = q[i].w();
      batch.Q[1][l] = q[i].x();
      batch.Q[2][l] = q[i].y();
      batch.Q[3][l] = q[i].z();
      batch.Done[l] = 0.0;
    }
    RefineBatch(batch, steps);
    for (int l = 0; l < lanes; ++l)
    {
      q[first + l] = Eigen::Quaterniond(batch.Q[0][l], batch.Q[1][l], batch.Q[2][l], batch.Q[3][l]);
      converged[first + l] = batch.Done[l] != 0.0;
    }
  }
#else
  for (int i = 0; i < count; ++i)
  {
    converged[i] = RefineClosestRotation(a[i], q[i], steps);
  }
#endif
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
