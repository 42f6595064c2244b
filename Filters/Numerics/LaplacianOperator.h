// The differential operator D of the paper (Section 3): rows of L = I - W, where each row of W
// holds non-negative neighbour weights that sum to one, and of its square L^2 (Section 6).
//
// Weights:
//  - Uniform: w_ij = 1 / valence(i), the umbrella operator (Eq. 2), the paper's default.
//  - Cotangent: w_ij proportional to (cot a_ij + cot b_ij) / 2, normalized per row. To stay
//    robust on real scans: each cotangent is computed with the corner's sine floored at
//    1e-6 times the product of its edge lengths (so a zero-area triangle gives a large but finite
//    value); a negative edge weight (an edge opposite two obtuse angles) is clamped to zero; a
//    row whose weights then sum to nothing falls back to uniform weights.
// Normalizing the rows keeps both operators dimensionless, so constraint weights mean the same
// thing for either choice.
#ifndef LaplacianEditing_LaplacianOperator_h
#define LaplacianEditing_LaplacianOperator_h

#include "SurfaceMesh.h"

#include <Eigen/SparseCore>

#include <utility>
#include <vector>

namespace LaplacianEditing
{
enum class LaplacianWeights
{
  Uniform,
  Cotangent
};

/// A sparse row: (vertex, coefficient) pairs sorted by vertex.
using SparseRow = std::vector<std::pair<int, double>>;

class LaplacianOperator
{
public:
  LaplacianOperator(const SurfaceMesh& mesh, LaplacianWeights weights);

  /// The weights of the edges from `v` to each of its neighbours (in the order of
  /// SurfaceMesh::NeighborsBegin), before the row's normalization: 1 (uniform), or the clamped
  /// (cot a + cot b) / 2 with the uniform fallback (cotangent). Symmetric except where one end
  /// falls back.
  std::vector<double> EdgeWeights(int v) const;

  /// Row `v` of L^order, for order 1 or 2.
  SparseRow Row(int v, int order) const;

  /// The whole n x n first-order matrix (used by tests and small meshes).
  Eigen::SparseMatrix<double> Matrix() const;

private:
  SparseRow FirstOrderRow(int v) const;

  const SurfaceMesh& Mesh;
  LaplacianWeights Weights;
};
}

#endif
