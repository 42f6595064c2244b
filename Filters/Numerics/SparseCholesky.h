// Factor once, solve many times: the kernel of interactive editing (Section 8).
//
// Backends: CHOLMOD's supernodal Cholesky (CholmodFactor), which uses BLAS threads for the
// dense supernodes, Eigen's own SimplicialLDLT as the dependency-free fallback, a factor
// spread across processes (DistributedSolver) for regions too large for one, and no factor at
// all: conjugate gradients preconditioned by algebraic multigrid (AlgebraicMultigrid), set up
// once in a fraction of a factorization's time, for the regions whose factor would take longer
// to compute than an edit may wait (Documentation/performance.md).
#ifndef LaplacianEditing_SparseCholesky_h
#define LaplacianEditing_SparseCholesky_h

#include "DistributedSolver.h"
#include "ParallelFor.h"

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include <memory>
#include <string>

namespace LaplacianEditing
{
enum class SolverBackend
{
  Cholmod,
  SimplicialLDLT,
  Distributed, // the DistributedSolver handed to Factorize
  Multigrid    // AlgebraicMultigrid: each solve iterates from the last solution
};

/// Fill-reducing orderings (CHOLMOD only; SimplicialLDLT always uses AMD).
enum class FillOrdering
{
  Automatic,       // AMD below 300k unknowns, METIS from there or for block systems (Documentation/performance.md)
  AMD,             // approximate minimum degree
  METIS,           // METIS nested dissection
  NestedDissection // CHOLMOD's own nested dissection (METIS-based, constrained)
};

class SparseCholesky
{
public:
  SparseCholesky();
  ~SparseCholesky();
  SparseCholesky(SparseCholesky&&) noexcept;
  SparseCholesky& operator=(SparseCholesky&&) noexcept;

  /// Whether the backend was compiled in (the distributed one comes from the caller).
  static bool IsAvailable(SolverBackend backend);

  /// Factors a symmetric positive definite matrix (its upper triangle is read).
  /// Returns an error message, empty on success.
  /// With CHOLMOD, the symbolic analysis predicts the factor's size first; a factor larger
  /// than `maximumBytes` (0: no limit) is refused with an error instead of being attempted.
  /// `blockSize` > 1 says the unknowns come in groups of that many with one pattern (x, y, z
  /// coupled); CHOLMOD then orders the much smaller graph of the groups.
  /// With a `distributed` solver, a CHOLMOD factor predicted above `maximumBytes` is factored
  /// across its processes instead of being refused; SolverBackend::Distributed always is.
  std::string Factorize(const Eigen::SparseMatrix<double>& matrix, SolverBackend backend,
    FillOrdering ordering = FillOrdering::Automatic, double maximumBytes = 0.0, int blockSize = 1,
    DistributedSolver* distributed = nullptr);

  /// Factors new values of the matrix last factored, in the same pattern, reusing its analysis
  /// (the ordering and the symbolic factor). Returns an error, empty on success; the factor is
  /// then gone, as it is for a distributed one, which this cannot refactor.
  std::string Refactorize(const Eigen::SparseMatrix<double>& matrix);

  /// Whether the next factors are solved many times each (ARAP's global step every
  /// iteration): CHOLMOD's factors then trade a slower factorization for faster solves
  /// (CholmodFactor::SetManySolves).
  void SetManySolves(bool many) { this->ManySolves = many; }

  /// Multigrid: a solve stops when every column's residual is at most this fraction of its
  /// residual at the start, the last solve's solution (default 1e-8).
  void SetIterativeTolerance(double tolerance);
  /// How the multigrid backend's set-up loops run (serial by default).
  void SetParallelFor(ParallelFor loop) { this->Loop = std::move(loop); }

  /// Solves for every column of `rhs` with the current factor. With CHOLMOD, solves for up to
  /// four columns run independent subtrees of the factor through `loop`. Multigrid solves up
  /// to three columns, from the last solve's solution.
  Eigen::MatrixXd Solve(const Eigen::MatrixXd& rhs, const ParallelFor& loop = SerialFor) const;

  /// Approximately solves for up to three columns, as a preconditioner: the factor's solve,
  /// or one multigrid V-cycle from zero (a fraction of an iterated solve's cost).
  Eigen::MatrixXd Precondition(const Eigen::MatrixXd& rhs, const ParallelFor& loop = SerialFor) const;

  bool IsFactorized() const;

  /// Seconds spent in the symbolic analysis (ordering) and the numeric factorization.
  double GetAnalysisSeconds() const { return this->AnalysisSeconds; }
  double GetFactorizationSeconds() const { return this->FactorizationSeconds; }
  /// Predicted (CHOLMOD) or actual bytes of the factor; 0 if unknown. A distributed factor's
  /// bytes are its processes' together.
  double GetFactorBytes() const { return this->FactorBytes; }
  /// Whether the factor is spread across processes (DistributedSolver).
  bool IsDistributed() const { return this->Distributed; }
  /// Share of a few-column solve's work that runs in independent subtrees, in parallel when
  /// the loop allows it (CHOLMOD; 0 otherwise).
  double GetParallelShare() const { return this->ParallelShare; }

  /// The factor of one backend (defined in the .cxx).
  struct Backend;

private:
  std::unique_ptr<Backend> Impl;
  double AnalysisSeconds = 0.0;
  double FactorizationSeconds = 0.0;
  double FactorBytes = 0.0;
  double ParallelShare = 0.0;
  bool Distributed = false;
  bool ManySolves = false;
  double IterativeTolerance = 1e-8;
  ParallelFor Loop = SerialFor;
};
}

#endif
