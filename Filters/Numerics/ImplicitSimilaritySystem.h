// Implicit detail rotation (Section 5). Each ROI vertex i gets a linearized similarity
// T_i = [s, -h3, h2; h3, s, -h1; -h2, h1, s] plus a translation (Eq. 9), fitted by least squares
// to map its rest one-ring onto the deformed one (Eqs. 10-12).
//
// The paper's energy, sum_i |D(V')_i - T_i(V') delta_i|^2, constrains each one-ring only
// through its sum. Once details may turn, that leaves bending nearly free wherever the
// constraints hold the region weakly: measured on Armadillo's hand, a finger next to the
// handle moved 2.7 times as far as the handle and swelled (2.8 times with the paper's free
// scale s, so the scale is not the cause). By default the residual is therefore taken per
// one-ring edge, sum_ij w_ij |(v'_i - v'_j) - T_i(V') (v_i - v_j)|^2, with the same fitted
// transforms, and s is fixed at 1 (linearized rotations I + h x): a linearized
// as-rigid-as-possible energy, and the smallest change in the paper's own terms that removes
// the freedom. The paper's formulation stays available (ImplicitFormulation).
#ifndef LaplacianEditing_ImplicitSimilaritySystem_h
#define LaplacianEditing_ImplicitSimilaritySystem_h

#include "DeformationSystem.h"
#include "ParallelFor.h"

namespace LaplacianEditing
{
/// Which energy the implicit mode minimizes; both default to the project's fix, both false is
/// the paper's Section 5.
struct ImplicitFormulation
{
  /// One residual per one-ring edge instead of one per vertex.
  bool PerEdge = true;
  /// The paper's similarities (free scale s) instead of linearized rotations.
  bool AllowScaling = false;

  bool operator==(const ImplicitFormulation& other) const
  {
    return this->PerEdge == other.PerEdge && this->AllowScaling == other.AllowScaling;
  }
};

class ImplicitSimilaritySystem
{
public:
  /// Assembles and factors the coupled system for the region `plain` was built on (it supplies
  /// the differential operator, the fixed part and the constraint weights).
  std::string Build(const SurfaceMesh& mesh, const EditRegion& region,
    const DeformationSystem& plain, const DeformationOptions& options,
    const ImplicitFormulation& formulation = ImplicitFormulation(),
    const ParallelFor& loop = SerialFor);

  /// The ROI positions minimizing the energy for the given handle maps (precomputed responses)
  /// and, if `plain` has points, their targets (one solve).
  Positions Solve(const std::vector<AffineMap>& handleMaps, const ParallelFor& loop = SerialFor,
    const Positions& pointTargets = Positions()) const;

  /// The same through the factor's triangular solves (the reference for Solve).
  Positions SolveDirect(const DeformationSystem& plain, const std::vector<AffineMap>& handleMaps,
    const Positions& pointTargets = Positions()) const;

  /// Solve's affine form on some rows (indices into the region's vertices).
  AffineRows GetAffineRows(const std::vector<int>& rows) const;

  const SparseCholesky& GetFactor() const { return this->Factor; }

private:
  // The rest solution and the handle groups' responses, from the factor.
  void ComputeResponses(const DeformationSystem& plain);
  // The points' pull, w^2 B^T t, solved.
  Positions SolvePoints(const Positions& pointTargets, const ParallelFor& loop) const;

  int NumberOfVertices = 0;
  SparseCholesky Factor;
  // The region's points, weighed for this system; with points, the rest shape and the points
  // on it, for solves of the displacement from it.
  PointConstraints Points;
  Positions Rest;
  Positions RestPoints;
  // A^T b of the known parts (fixed vertices): constant per region.
  Eigen::VectorXd KnownRightHandSide;
  // The solution with every handle map zero, and each group's 3n x 12 response to the entries
  // of its map, row by row.
  Eigen::VectorXd RestSolution;
  std::vector<Eigen::MatrixXd> GroupResponses;
};
}

#endif
