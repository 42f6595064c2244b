// The rotation closest to a 3 x 3 matrix A in the Frobenius norm: the rotation factor of A's
// polar decomposition, with a reflection turned into the nearest proper rotation. The
// as-rigid-as-possible local step needs one per vertex and per iteration.
#ifndef LaplacianEditing_ClosestRotation_h
#define LaplacianEditing_ClosestRotation_h

#include "Types.h"

#include <Eigen/Geometry>

namespace LaplacianEditing
{
/// Refines `q` in place towards the rotation closest to `a` by at most `steps` steps; returns
/// whether it converged (to about 1e-14 of an angle). Newton's steps on the rotation angle,
/// quadratically convergent: a rotation warm-started from the last iteration's converges in two
/// or three. Where the Hessian is not safely positive definite (far from the maximum), the step
/// is Mueller, Bender, Chentanez and Macklin's ("A Robust Method to Extract the Rotational Part
/// of Deformations", MIG 2016), which lowers |a - R| from anywhere.
bool RefineClosestRotation(const Eigen::Matrix3d& a, Eigen::Quaterniond& q, int steps = 4);

/// RefineClosestRotation on `count` matrices at once, vectorized across them (the local step
/// refines one rotation per vertex); converged[i] receives rotation i's result. Every rotation
/// takes the same steps as alone, to rounding, and its result does not depend on the others in
/// its batch, to the bit (so not on how threads split a loop).
void RefineClosestRotations(
  const Eigen::Matrix3d* a, Eigen::Quaterniond* q, bool* converged, int count, int steps = 4);

/// The closest rotation, exactly: the seed of a rotation with no history, and the fallback of
/// a refinement that does not converge.
Eigen::Quaterniond ClosestRotation(const Eigen::Matrix3d& a);
}

#endif
