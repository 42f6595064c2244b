// The thin-plate spline of landmark displacements (Bookstein, "Principal Warps", 1989), with
// VTK's default kernel U(r) = r^2 log r: d(x) = sum_i w_i U(|x - c_i|) + A [1 x], interpolating
// the displacements at the landmarks c_i. A smooth map of all space, which a landmark warp's
// as-rigid-as-possible solve takes as its prior (AsRigidAsPossibleSolver.h).
//
// The system [U P; P^T 0] depends on the landmarks alone and is factored once (dense, cubic in
// their number: hence MaximumLandmarks); new displacements cost a solve of it and an
// evaluation, linear in the landmarks per point.
#ifndef LaplacianEditing_ThinPlateSpline_h
#define LaplacianEditing_ThinPlateSpline_h

#include "ParallelFor.h"
#include "Types.h"

#include <Eigen/LU>

namespace LaplacianEditing
{
class ThinPlateSpline
{
public:
  /// The most landmarks a spline is fit to (its factorization takes about 0.1 s at 1,000).
  static constexpr int MaximumLandmarks = 1000;

  /// Factors the spline through `landmarks` (a row each). Returns false, the spline left
  /// empty, where there are more than MaximumLandmarks or they span no volume (fewer than four,
  /// or all on a plane: no affine map of space is fixed by them).
  bool Fit(const Positions& landmarks);
  bool IsEmpty() const { return this->Landmarks.rows() == 0; }

  /// The displacements at `points` of the spline interpolating `displacements` (a row per
  /// landmark), rows in parallel through `loop`.
  Positions Displace(
    const Positions& displacements, const Positions& points, const ParallelFor& loop = SerialFor) const;

  /// Landmark `landmark`'s cardinal function at `points`: the spline through displacement 1 at
  /// it and 0 at the others (a component of each). The spline is their sum weighted by the
  /// displacements.
  Eigen::VectorXd Cardinal(int landmark, const Positions& points, const ParallelFor& loop = SerialFor) const;

private:
  // The spline's values at `points` for its coefficients (kernel weights, then the affine part).
  Eigen::MatrixXd Evaluate(
    const Eigen::MatrixXd& coefficients, const Positions& points, const ParallelFor& loop) const;

  // Landmarks in the spline's frame: centred on their mean and scaled to unit extent, for the
  // system's conditioning. The interpolant does not change: a change of scale adds a quadratic
  // to the kernel, which the side conditions P^T w = 0 annihilate.
  Positions Landmarks;
  Vector3 Origin = Vector3::Zero();
  double Scale = 1.0;
  Eigen::PartialPivLU<Eigen::MatrixXd> System;
};
}

#endif
