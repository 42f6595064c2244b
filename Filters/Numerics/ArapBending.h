// A second-order term for the as-rigid-as-possible energy: the bending of each ring,
// sum_i mu_i |s'_i - R_i s_i|^2 with s_i = sum_j w_ij (v_i - v_j) the weighted sum of the ring's
// rest edges, s'_i the same of the deformed ones, R_i the vertex's rotation and
// mu_i = mu / W_i^2 (W_i the ring's weight): mu |(L x)_i - R_i delta_i|^2 with L the
// row-normalized Laplacian and delta the rest Laplacian coordinates, the paper's energy with
// the rotations of the local step.
//
// Why: the as-rigid-as-possible energy is first order. Held by sparse points (a landmark warp's
// landmarks) rather than by handle regions and a fixed part, its minimizers grow a cone at each
// point, and the parts between the points flop. With 100 random landmarks
// (`LandmarkWarpBenchmark ../shared/data --landmarks 100 --bending 0|100`), the RMS distance
// from the known shape goes from 0.49% to 0.38% of the diagonal on the articulated warp and
// from 1.38% to 1.14% on the hinge (whose fixed part drifts more with it, 8.7% against 5.7%).
// A second-order term makes point constraints well posed, and a rigid motion still costs
// nothing (every R_i the motion's rotation).
//
// In the energy's units (the local-global form of ARAPSolver), the term adds sum_i mu_i c_i^T
// c_i to the matrix (c_i: the ring's row, W_i at i, -w_ij at j), sum_i mu_i c_i^T R_i s_i to the
// right-hand side, 2 mu_i s'_i s_i^T to vertex i's covariance and 2 mu_i |s'_i - R_i s_i|^2 to
// its residual.
#ifndef LaplacianEditing_ArapBending_h
#define LaplacianEditing_ArapBending_h

#include "Types.h"

#include <Eigen/SparseCore>

#include <vector>

namespace LaplacianEditing
{
/// The rings of an as-rigid-as-possible energy, as its solver stores them: per energy vertex, its
/// neighbours (patch rows) and symmetric weights in CSR form, and its rest edges' weighted sum.
struct ArapRings
{
  const std::vector<int>& Offsets;
  const std::vector<int>& Neighbors;
  const std::vector<double>& Weights;
  const std::vector<Vector3>& RestEdgeSums;
};

class ArapBending
{
public:
  /// Adds the term at relative `weight` to `upper` (the free unknowns' matrix, upper triangle;
  /// `unknownOfPatch`: each patch row's unknown, -1 where known): mu is `weight` times the
  /// ratio of the matrix's mean diagonal to the term's own, so that one weight means the same
  /// on every mesh and scale. A weight of 0 leaves the term out.
  void Build(double weight, const ArapRings& rings, const std::vector<int>& unknownOfPatch,
    Eigen::SparseMatrix<double>& upper);

  bool IsEmpty() const { return this->Coefficients.empty(); }

  /// Vertex i's weight mu_i.
  double GetCoefficient(int i) const { return this->Coefficients[i]; }

  /// Adds the term's share of the right-hand side for the displacement from the rest shape,
  /// sum_i mu_i c_i^T ((R_i - I) s_i - c_i's known displacements), to the free unknowns' rows
  /// of `rhs`, for the rotations and the patch's positions (`rest`: its rest positions).
  void AddToRightHandSide(const ArapRings& rings, const std::vector<int>& unknownOfPatch,
    const std::vector<Eigen::Matrix3d>& rotations, const std::vector<Vector3>& patch,
    const std::vector<Vector3>& rest, Eigen::Ref<Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>> rhs) const;

private:
  std::vector<double> Coefficients; // mu_i
  std::vector<double> RingWeights; // W_i
  // The rings' rows c_i on the free unknowns, in CSR form: built once, read every iteration.
  std::vector<int> RowOffsets;
  std::vector<int> RowUnknowns;
  std::vector<double> RowEntries;
};
}

#endif
