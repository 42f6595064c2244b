// SmoothWarp: a smooth map of space fitted to a template's matches on a target, the first stage
// of template fitting (vtkLaplacianSurfaceRegistration). The displacement is a spline of the
// 3D biharmonic kernel U(r) = r on a few hundred centres, with an affine part:
//   d(x) = sum_c a_c |x - c| + A [1 x],   P^T a = 0 (P the centres' [1 c] rows),
// whose bending energy is -a^T K a (K_cd = |c - d|). A fit lowers
//   sum_i w_i ((n_i . (x_i + d(x_i) - m_i))^2 + pointShare |x_i + d(x_i) - m_i|^2)
//     + smoothness * count * (-a^T K a)
// over the points x_i with matches m_i and the target's normals n_i there: point-to-plane, so
// that the template slides along the target, which a point-to-point match holds back (its
// small share keeps the slide bounded where the target is flat). Unlike an as-rigid-as-possible
// fit, a spline's energy does not grow with a smooth stretch or shear of the surface: the
// target's own large strains are reached (Documentation/template-fitting.md).
//
// All of it runs in a frame centred on the centres and scaled to their extent, in which the
// smoothness does not depend on the template's size or place.
#ifndef LaplacianEditing_SmoothWarp_h
#define LaplacianEditing_SmoothWarp_h

#include "ParallelFor.h"
#include "Types.h"

#include <vector>

namespace LaplacianEditing
{
class SmoothWarp
{
public:
  /// `count` rows of `points` spread over them: each the farthest from those chosen before,
  /// starting at row 0 (all rows where there are no more than `count`). The first k of them are
  /// the k a smaller count chooses.
  static std::vector<int> FarthestPoints(const Positions& points, int count);

  /// The warp's kernel centres (a row each, at least 4 spanning a volume) and the points it is
  /// fitted at (a row each): their kernel values are computed once, for every fit. The warp is
  /// the identity until a fit.
  SmoothWarp(const Positions& centres, const Positions& points);

  /// Fits the warp to the matches of the points (a row each of `matches` and `normals`; a
  /// weight of 0 ignores a point). Returns false, the warp unchanged, where fewer than four
  /// points have a weight or the system is singular.
  bool Fit(const Positions& matches, const Positions& normals, const Eigen::VectorXd& weights,
    double smoothness, double pointShare);

  /// The displacements at `points`, rows in parallel through `loop`.
  Positions Displace(const Positions& points, const ParallelFor& loop = SerialFor) const;

private:
  // The kernel and affine columns of `points` (in the warp's frame), a row each.
  Eigen::MatrixXd Basis(const Positions& points) const;

  Positions Centres; // in the frame
  Vector3 Origin = Vector3::Zero();
  double Scale = 1.0;
  Positions Points;       // the fitted points
  Eigen::MatrixXd Values; // their basis rows
  Eigen::MatrixXd Bending; // the centres' kernel, K_cd = |c - d|
  Eigen::MatrixXd Coefficients; // kernel weights, then the affine part; a column per axis
};
}

#endif
