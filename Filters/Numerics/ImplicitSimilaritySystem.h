// Implicit detail rotation (Section 5). Each ROI vertex i gets a linearized similarity
// T_i = [s, -h3, h2; h3, s, -h1; -h2, h1, s] plus a translation (Eq. 9), fitted by least squares
// to map its rest one-ring onto the deformed one (Eqs. 10-12). The fit is linear in the
// deformed positions V', so the energy sum_i |T_i(V') delta_i - D(V')_i|^2 plus the soft
// constraints is quadratic in V': one coupled 3n x 3n system, factored once per region. Its
// solution is affine in the handle maps too, so Build also precomputes the rest solution and the
// 12 responses of each handle group, and a handle move is a small dense product.
#ifndef LaplacianEditing_ImplicitSimilaritySystem_h
#define LaplacianEditing_ImplicitSimilaritySystem_h

#include "DeformationSystem.h"

namespace LaplacianEditing
{
class ImplicitSimilaritySystem
{
public:
  /// Assembles and factors the coupled system for the region `plain` was built on (it supplies
  /// the differential operator, the fixed part and the constraint weights).
  std::string Build(const SurfaceMesh& mesh, const EditRegion& region,
    const DeformationSystem& plain, const DeformationOptions& options);

  /// The ROI positions minimizing the energy for the given handle maps (precomputed responses).
  Positions Solve(const std::vector<AffineMap>& handleMaps) const;

  /// The same through the factor's triangular solves (the reference for Solve).
  Positions SolveDirect(const DeformationSystem& plain, const std::vector<AffineMap>& handleMaps) const;

  /// T_i(V') delta_i for every ROI vertex, each scaled back to the length of delta_i: the
  /// rotated differential coordinates without the linearization's change of scale.
  Positions RotatedDifferentialCoordinates(const Positions& roiPositions) const;

  const SparseCholesky& GetFactor() const { return this->Factor; }

private:
  // Gathers the one-ring positions of ROI vertex `row` (itself first) into a 3m vector.
  Eigen::VectorXd Ring(int row, const Positions& roiPositions) const;

  int NumberOfVertices = 0;
  // Per ROI vertex: offsets into the ring arrays and into the fit coefficients.
  std::vector<int> RingOffsets;
  std::vector<int> RingRoiRows;   // ROI row of each ring member, -1 if fixed
  Positions RingRest;             // rest position of each ring member
  // The (s, h1, h2, h3) rows of the least-squares fit, (A_i^T A_i)^-1 A_i^T, per vertex.
  std::vector<Eigen::MatrixXd> Fits;
  Positions RestDelta;
  SparseCholesky Factor;
  // A^T b of the known parts (fixed vertices): constant per region.
  Eigen::VectorXd KnownRightHandSide;
  // The solution with every handle map zero, and each group's 3n x 12 response to the entries
  // of its map, row by row.
  Eigen::VectorXd RestSolution;
  std::vector<Eigen::MatrixXd> GroupResponses;
};
}

#endif
