#include "SparseCholesky.h"

#include <Eigen/SparseCholesky>

#include <chrono>
#ifdef LAPLACIAN_EDITING_HAS_CHOLMOD
#include <Eigen/CholmodSupport>
#endif

namespace LaplacianEditing
{
using SparseMatrix = Eigen::SparseMatrix<double>;

struct SparseCholesky::Backend
{
  virtual ~Backend() = default;
  virtual Eigen::MatrixXd Solve(const Eigen::MatrixXd& rhs) const = 0;
};

namespace
{
template <typename Solver>
struct EigenBackend : SparseCholesky::Backend
{
  Solver Factor;
  Eigen::MatrixXd Solve(const Eigen::MatrixXd& rhs) const override { return this->Factor.solve(rhs); }
};
}

SparseCholesky::SparseCholesky() = default;
SparseCholesky::~SparseCholesky() = default;
SparseCholesky::SparseCholesky(SparseCholesky&&) noexcept = default;
SparseCholesky& SparseCholesky::operator=(SparseCholesky&&) noexcept = default;

bool SparseCholesky::IsAvailable(SolverBackend backend)
{
#ifdef LAPLACIAN_EDITING_HAS_CHOLMOD
  (void)backend;
  return true;
#else
  return backend == SolverBackend::SimplicialLDLT;
#endif
}

namespace
{
using Clock = std::chrono::steady_clock;

double SecondsSince(Clock::time_point start)
{
  return std::chrono::duration<double>(Clock::now() - start).count();
}

template <typename Solver>
void Configure(Solver&, FillOrdering)
{
}

// Bytes of the factor the analysis predicts: unknown for Eigen's own solvers.
template <typename Solver>
double PredictedFactorBytes(Solver&)
{
  return 0.0;
}

#ifdef LAPLACIAN_EDITING_HAS_CHOLMOD
void Configure(Eigen::CholmodSupernodalLLT<SparseMatrix, Eigen::Lower>& solver, FillOrdering ordering)
{
  cholmod_common& common = solver.cholmod();
  common.print = 0; // failures reach the caller as messages, not as CHOLMOD's own printing
  common.nmethods = 1;
  common.method[0].ordering = ordering == FillOrdering::AMD ? CHOLMOD_AMD
    : ordering == FillOrdering::METIS                       ? CHOLMOD_METIS
                                                            : CHOLMOD_NESDIS;
  common.postorder = 1;
}

double PredictedFactorBytes(Eigen::CholmodSupernodalLLT<SparseMatrix, Eigen::Lower>& solver)
{
  // Values plus row indices of every stored nonzero.
  return solver.cholmod().lnz * (sizeof(double) + sizeof(int));
}
#endif

struct FactorReport
{
  std::string Error;
  double AnalysisSeconds = 0.0;
  double FactorizationSeconds = 0.0;
  double FactorBytes = 0.0;
};

template <typename Solver>
std::unique_ptr<SparseCholesky::Backend> FactorWith(
  const SparseMatrix& matrix, FillOrdering ordering, double maximumBytes, FactorReport& report)
{
  auto backend = std::make_unique<EigenBackend<Solver>>();
  Configure(backend->Factor, ordering);
  Clock::time_point start = Clock::now();
  backend->Factor.analyzePattern(matrix);
  report.AnalysisSeconds = SecondsSince(start);
  report.FactorBytes = PredictedFactorBytes(backend->Factor);
  if (maximumBytes > 0.0 && report.FactorBytes > maximumBytes)
  {
    report.Error = "the factor would need " + std::to_string(report.FactorBytes / 1048576.0) +
      " MB, more than the " + std::to_string(maximumBytes / 1048576.0) +
      " MB allowed; choose a smaller region of interest or raise the limit";
    return nullptr;
  }
  start = Clock::now();
  backend->Factor.factorize(matrix);
  report.FactorizationSeconds = SecondsSince(start);
  if (backend->Factor.info() != Eigen::Success)
  {
    report.Error = "the normal equations are not positive definite: some part of the region is not "
            "held by any constraint";
    return nullptr;
  }
  return backend;
}
}

std::string SparseCholesky::Factorize(
  const SparseMatrix& matrix, SolverBackend backend, FillOrdering ordering, double maximumBytes)
{
  // AMD orders fast; on large systems METIS's slower analysis pays back in factorization time
  // and memory. CHOLMOD's own default tries METIS far earlier, which costs more than it saves
  // on editing regions (bunny, 28.9k, second order: 0.69 s against 0.38 s with AMD).
  if (ordering == FillOrdering::Automatic)
  {
    ordering = matrix.rows() < 300000 ? FillOrdering::AMD : FillOrdering::METIS;
  }
  this->Impl.reset();
  if (!IsAvailable(backend))
  {
    return "this build has no CHOLMOD; use the SimplicialLDLT solver";
  }
  FactorReport report;
#ifdef LAPLACIAN_EDITING_HAS_CHOLMOD
  if (backend == SolverBackend::Cholmod)
  {
    this->Impl = FactorWith<Eigen::CholmodSupernodalLLT<SparseMatrix, Eigen::Lower>>(
      matrix, ordering, maximumBytes, report);
  }
  else
#endif
  {
    this->Impl = FactorWith<Eigen::SimplicialLDLT<SparseMatrix, Eigen::Lower>>(
      matrix, ordering, maximumBytes, report);
  }
  this->AnalysisSeconds = report.AnalysisSeconds;
  this->FactorizationSeconds = report.FactorizationSeconds;
  this->FactorBytes = report.FactorBytes;
  return report.Error;
}

Eigen::MatrixXd SparseCholesky::Solve(const Eigen::MatrixXd& rhs) const
{
  return this->Impl->Solve(rhs);
}

bool SparseCholesky::IsFactorized() const
{
  return this->Impl != nullptr;
}
}
