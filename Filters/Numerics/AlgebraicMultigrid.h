// Solves a large sparse symmetric positive definite system without factoring it: conjugate
// gradients preconditioned by one V-cycle of smoothed-aggregation algebraic multigrid (Vanek,
// Mandel and Brezina, "Algebraic multigrid by smoothed aggregation for second and fourth order
// elliptic problems", 1996).
//
// Why: the direct factor of a 600k-vertex region's Laplacian takes 8 s to order and factor and
// 400 MB to hold, where an edit must answer within a fraction of that. The hierarchy costs a
// few passes over the matrix, and a warm-started solve, as a local-global iteration asks for
// one after another, a handful of cycles.
//
//  - Aggregates: each vertex with its still free neighbours, the stragglers joined to a
//    neighbouring aggregate (the classic three passes), on the strong connections.
//  - Prolongation: the aggregates' indicator functions smoothed by one damped Jacobi step,
//    P = (I - omega D^-1 A) P0, omega = 4 / (3 rho(D^-1 A)); the coarse matrix is P^T A P.
//  - Smoother: a Chebyshev polynomial in D^-1 A over the upper part of its spectrum, the same
//    before and after the coarse correction, so that the cycle is symmetric (a valid
//    preconditioner for conjugate gradients) and runs on every thread.
//  - The coarsest level, a few thousand unknowns, is factored (SparseCholesky).
#ifndef LaplacianEditing_AlgebraicMultigrid_h
#define LaplacianEditing_AlgebraicMultigrid_h

#include "ParallelFor.h"
#include "SparseCholesky.h"

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include <string>
#include <vector>

namespace LaplacianEditing
{
class AlgebraicMultigrid
{
public:
  /// Vectors of the solver: one row per unknown, one column per right-hand side (up to
  /// three), rows contiguous so that a pass over the matrix serves every column.
  using Block = Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>;

  /// Builds the hierarchy of a symmetric positive definite matrix, given by its upper triangle
  /// (the diagonal included). Returns an error message, empty on success.
  std::string Build(const Eigen::SparseMatrix<double>& upper, const ParallelFor& loop = SerialFor);

  struct Result
  {
    int Iterations = 0;
    /// The largest over the columns of |b - A x| / |b - A x_start| at the end.
    double RelativeResidual = 0.0;
  };

  /// Conjugate gradients from `x` (the start, the solution on return) until every column's
  /// residual is at most `tolerance` times its residual at the start (or 1e-14 times its
  /// right-hand side), or `maximumIterations`.
  Result Solve(const Block& rhs, Block& x, double tolerance, int maximumIterations,
    const ParallelFor& loop = SerialFor) const;

  /// z ~ A^-1 r: one V-cycle from zero, a fixed symmetric positive definite operator (the
  /// preconditioner of an outer Krylov iteration on a nearby matrix).
  void Precondition(const Block& r, Block& z, const ParallelFor& loop = SerialFor) const
  {
    this->Cycle(0, r, z, loop);
  }

  /// y = A x on the finest level.
  void Multiply(const Block& x, Block& y, const ParallelFor& loop = SerialFor) const;

  int GetNumberOfLevels() const { return static_cast<int>(this->Levels.size()); }
  int GetNumberOfUnknowns(int level = 0) const { return this->Levels[level].A.Rows; }
  bool IsBuilt() const { return !this->Levels.empty(); }

  /// Compressed sparse rows, every row of a symmetric matrix stored whole.
  struct Rows
  {
    int Rows = 0;
    int Columns = 0;
    std::vector<int> Offsets;
    std::vector<int> Indices;
    std::vector<double> Values;
  };

private:
  struct Level
  {
    Rows A;
    std::vector<double> InverseDiagonal;
    double LargestEigenvalue = 0.0; // of D^-1 A, bounded from above
    Rows P;  // to this level from the next, coarser one
    Rows PT; // its transpose
  };

  void Cycle(std::size_t level, const Block& b, Block& x, const ParallelFor& loop) const;
  // Chebyshev smoothing of A x = b; `zeroStart`: x starts at zero, whatever it holds.
  void Smooth(const Level& level, const Block& b, Block& x, bool zeroStart, const ParallelFor& loop) const;

  std::vector<Level> Levels;
  SparseCholesky Coarsest;
  // Buffers of each level's cycle (residual, coarse right-hand side and correction).
  mutable std::vector<Block> Residuals, CoarseRhs, CoarseX, Scratch, Product;
  // Conjugate gradients' vectors.
  mutable Block SolveR, SolveZ, SolveP, SolveQ;
};
}

#endif
