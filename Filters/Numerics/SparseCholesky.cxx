#include "SparseCholesky.h"

#include "AlgebraicMultigrid.h"
#include "Stopwatch.h"

#include <Eigen/SparseCholesky>

#include <algorithm>
#include <thread>
#ifdef LAPLACIAN_EDITING_HAS_CHOLMOD
#include "CholmodFactor.h"
#endif

namespace LaplacianEditing
{
using SparseMatrix = Eigen::SparseMatrix<double>;

struct SparseCholesky::Backend
{
  virtual ~Backend() = default;
  virtual Eigen::MatrixXd Solve(const Eigen::MatrixXd& rhs, const ParallelFor& loop) const = 0;
  // New values in the analysed pattern; false if they are not positive definite or the backend
  // cannot (a distributed factor).
  virtual bool Refactor(const SparseMatrix&) { return false; }
  virtual void SetTolerance(double) {}
  virtual Eigen::MatrixXd Precondition(const Eigen::MatrixXd& rhs, const ParallelFor& loop) const
  {
    return this->Solve(rhs, loop);
  }
};

namespace
{
// Eigen's SimplicialLDLT, which reads the upper triangle as CHOLMOD does.
struct EigenBackend : SparseCholesky::Backend
{
  Eigen::SimplicialLDLT<SparseMatrix, Eigen::Upper> Factor;
  Eigen::MatrixXd Solve(const Eigen::MatrixXd& rhs, const ParallelFor&) const override
  {
    return this->Factor.solve(rhs);
  }
  bool Refactor(const SparseMatrix& matrix) override
  {
    this->Factor.factorize(matrix);
    return this->Factor.info() == Eigen::Success;
  }
};
}

SparseCholesky::SparseCholesky() = default;
SparseCholesky::~SparseCholesky() = default;
SparseCholesky::SparseCholesky(SparseCholesky&&) noexcept = default;
SparseCholesky& SparseCholesky::operator=(SparseCholesky&&) noexcept = default;

bool SparseCholesky::IsAvailable(SolverBackend backend)
{
#ifdef LAPLACIAN_EDITING_HAS_CHOLMOD
  return backend != SolverBackend::Distributed;
#else
  return backend == SolverBackend::SimplicialLDLT || backend == SolverBackend::Multigrid;
#endif
}

namespace
{
struct FactorReport
{
  std::string Error;
  double AnalysisSeconds = 0.0;
  double FactorizationSeconds = 0.0;
  double FactorBytes = 0.0;
  double ParallelShare = 0.0;
  bool TooLarge = false; // the error is the memory limit's, or CHOLMOD's index range
};

const char* const NotPositiveDefinite = "the normal equations are not positive definite: some part "
                                        "of the region is not held by any constraint";

#ifdef LAPLACIAN_EDITING_HAS_CHOLMOD
struct CholmodBackend : SparseCholesky::Backend
{
  CholmodFactor Factor;
  Eigen::MatrixXd Solve(const Eigen::MatrixXd& rhs, const ParallelFor& loop) const override
  {
    return this->Factor.Solve(rhs, loop);
  }
  bool Refactor(const SparseMatrix& matrix) override { return this->Factor.Factorize(matrix); }
};

std::unique_ptr<SparseCholesky::Backend> FactorWithCholmod(const SparseMatrix& matrix,
  FillOrdering ordering, int blockSize, double maximumBytes, bool manySolves, FactorReport& report)
{
  auto backend = std::make_unique<CholmodBackend>();
  backend->Factor.SetManySolves(manySolves);
  Stopwatch watch;
  const int parts = std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
  report.Error = backend->Factor.Analyze(matrix, ordering, parts, blockSize);
  report.AnalysisSeconds = watch.Seconds();
  report.TooLarge = backend->Factor.IsTooLarge();
  report.FactorBytes = backend->Factor.GetPredictedBytes();
  report.ParallelShare = backend->Factor.GetParallelShare();
  if (report.Error.empty() && maximumBytes > 0.0 && report.FactorBytes > maximumBytes)
  {
    report.TooLarge = true;
    report.Error = "the factor would need " + std::to_string(report.FactorBytes / 1048576.0) +
      " MB, more than the " + std::to_string(maximumBytes / 1048576.0) +
      " MB allowed; choose a smaller region of interest or raise the limit";
  }
  if (!report.Error.empty())
  {
    return nullptr;
  }
  watch = Stopwatch();
  const bool factored = backend->Factor.Factorize(matrix);
  report.FactorizationSeconds = watch.Seconds();
  if (!factored)
  {
    report.Error = NotPositiveDefinite;
    return nullptr;
  }
  return backend;
}
#endif

std::unique_ptr<SparseCholesky::Backend> FactorWithEigen(
  const SparseMatrix& matrix, FactorReport& report)
{
  auto backend = std::make_unique<EigenBackend>();
  Stopwatch watch;
  backend->Factor.analyzePattern(matrix);
  report.AnalysisSeconds = watch.Seconds();
  watch = Stopwatch();
  backend->Factor.factorize(matrix);
  report.FactorizationSeconds = watch.Seconds();
  if (backend->Factor.info() != Eigen::Success)
  {
    report.Error = NotPositiveDefinite;
    return nullptr;
  }
  return backend;
}

// No factor: multigrid-preconditioned conjugate gradients, from the last solution (a
// local-global iteration's consecutive solves are near each other).
struct MultigridBackend : SparseCholesky::Backend
{
  AlgebraicMultigrid Hierarchy;
  double Tolerance = 1e-8;
  mutable AlgebraicMultigrid::Block Last;
  Eigen::MatrixXd Solve(const Eigen::MatrixXd& rhs, const ParallelFor& loop) const override
  {
    AlgebraicMultigrid::Block b = AlgebraicMultigrid::Block::Zero(rhs.rows(), 3);
    b.leftCols(rhs.cols()) = rhs;
    if (this->Last.rows() != rhs.rows())
    {
      this->Last.setZero(rhs.rows(), 3);
    }
    constexpr int MaximumIterations = 200;
    this->Hierarchy.Solve(b, this->Last, this->Tolerance, MaximumIterations, loop);
    return this->Last.leftCols(rhs.cols());
  }
  void SetTolerance(double tolerance) override { this->Tolerance = tolerance; }
  Eigen::MatrixXd Precondition(const Eigen::MatrixXd& rhs, const ParallelFor& loop) const override
  {
    AlgebraicMultigrid::Block b = AlgebraicMultigrid::Block::Zero(rhs.rows(), 3);
    b.leftCols(rhs.cols()) = rhs;
    AlgebraicMultigrid::Block z;
    this->Hierarchy.Precondition(b, z, loop);
    return z.leftCols(rhs.cols());
  }
};

std::unique_ptr<SparseCholesky::Backend> SetUpMultigrid(
  const SparseMatrix& matrix, double tolerance, const ParallelFor& loop, FactorReport& report)
{
  auto backend = std::make_unique<MultigridBackend>();
  backend->Tolerance = tolerance;
  const Stopwatch watch;
  report.Error = backend->Hierarchy.Build(matrix, loop);
  report.AnalysisSeconds = watch.Seconds();
  return report.Error.empty() ? std::move(backend) : nullptr;
}

struct DistributedBackend : SparseCholesky::Backend
{
  std::unique_ptr<DistributedFactor> Factor;
  Eigen::MatrixXd Solve(const Eigen::MatrixXd& rhs, const ParallelFor&) const override
  {
    return this->Factor->Solve(rhs);
  }
};

std::unique_ptr<SparseCholesky::Backend> FactorAcrossProcesses(
  const SparseMatrix& matrix, DistributedSolver& solver, FactorReport& report)
{
  auto backend = std::make_unique<DistributedBackend>();
  const Stopwatch watch;
  report.Error.clear();
  backend->Factor = solver.Factorize(matrix, report.Error);
  report.FactorizationSeconds = watch.Seconds();
  if (!backend->Factor)
  {
    return nullptr;
  }
  report.FactorBytes = backend->Factor->GetBytes();
  return backend;
}
}

std::string SparseCholesky::Factorize(const SparseMatrix& matrix, SolverBackend backend,
  FillOrdering ordering, double maximumBytes, int blockSize, DistributedSolver* distributed)
{
  // AMD orders fast; on large systems METIS's slower analysis pays back in factorization time
  // and memory. CHOLMOD's own default tries METIS far earlier, which costs more than it saves
  // on editing regions. A block system costs blockSize^3 times the flops for the same graph, so
  // METIS pays back at once (Documentation/performance.md, "Measured choices").
  if (ordering == FillOrdering::Automatic)
  {
    ordering = matrix.rows() < 300000 && blockSize == 1 ? FillOrdering::AMD : FillOrdering::METIS;
  }
  this->Impl.reset();
  if (backend == SolverBackend::Distributed && !distributed)
  {
    return "the distributed solver runs only across MPI processes";
  }
  if (backend != SolverBackend::Distributed && !IsAvailable(backend))
  {
    return "this build has no CHOLMOD; use the SimplicialLDLT solver";
  }
  FactorReport report;
#ifdef LAPLACIAN_EDITING_HAS_CHOLMOD
  if (backend == SolverBackend::Cholmod)
  {
    this->Impl = FactorWithCholmod(matrix, ordering, blockSize, maximumBytes, this->ManySolves, report);
  }
#endif
  if (backend == SolverBackend::SimplicialLDLT)
  {
    this->Impl = FactorWithEigen(matrix, report);
  }
  if (backend == SolverBackend::Multigrid)
  {
    this->Impl = SetUpMultigrid(matrix, this->IterativeTolerance, this->Loop, report);
  }
  // Too large for this process: its share of a factor across all of them may fit.
  this->Distributed = distributed &&
    (backend == SolverBackend::Distributed ||
      (report.TooLarge && distributed->GetNumberOfProcesses() > 1));
  if (this->Distributed)
  {
    const double analysisSeconds = report.AnalysisSeconds;
    this->Impl = FactorAcrossProcesses(matrix, *distributed, report);
    report.AnalysisSeconds = analysisSeconds;
  }
  this->AnalysisSeconds = report.AnalysisSeconds;
  this->FactorizationSeconds = report.FactorizationSeconds;
  this->FactorBytes = report.FactorBytes;
  this->ParallelShare = report.ParallelShare;
  return report.Error;
}

std::string SparseCholesky::Refactorize(const SparseMatrix& matrix)
{
  const Stopwatch watch;
  const bool factored = this->Impl && !this->Distributed && this->Impl->Refactor(matrix);
  this->FactorizationSeconds = watch.Seconds();
  if (!factored)
  {
    this->Impl.reset();
    return NotPositiveDefinite;
  }
  return {};
}

void SparseCholesky::SetIterativeTolerance(double tolerance)
{
  this->IterativeTolerance = tolerance;
  if (this->Impl)
  {
    this->Impl->SetTolerance(tolerance);
  }
}

Eigen::MatrixXd SparseCholesky::Solve(const Eigen::MatrixXd& rhs, const ParallelFor& loop) const
{
  return this->Impl->Solve(rhs, loop);
}

Eigen::MatrixXd SparseCholesky::Precondition(const Eigen::MatrixXd& rhs, const ParallelFor& loop) const
{
  return this->Impl->Precondition(rhs, loop);
}

bool SparseCholesky::IsFactorized() const
{
  return this->Impl != nullptr;
}
}
