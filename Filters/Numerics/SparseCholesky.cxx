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
void SetOrdering(Solver&, FillOrdering)
{
}

#ifdef LAPLACIAN_EDITING_HAS_CHOLMOD
void SetOrdering(Eigen::CholmodSupernodalLLT<SparseMatrix, Eigen::Lower>& solver, FillOrdering ordering)
{
  cholmod_common& common = solver.cholmod();
  common.nmethods = 1;
  common.method[0].ordering = ordering == FillOrdering::AMD ? CHOLMOD_AMD
    : ordering == FillOrdering::METIS                       ? CHOLMOD_METIS
                                                            : CHOLMOD_NESDIS;
  common.postorder = 1;
}
#endif

template <typename Solver>
std::unique_ptr<SparseCholesky::Backend> FactorWith(const SparseMatrix& matrix,
  FillOrdering ordering, std::string& error, double& analysisSeconds, double& factorSeconds)
{
  auto backend = std::make_unique<EigenBackend<Solver>>();
  SetOrdering(backend->Factor, ordering);
  Clock::time_point start = Clock::now();
  backend->Factor.analyzePattern(matrix);
  analysisSeconds = SecondsSince(start);
  start = Clock::now();
  backend->Factor.factorize(matrix);
  factorSeconds = SecondsSince(start);
  if (backend->Factor.info() != Eigen::Success)
  {
    error = "the normal equations are not positive definite: some part of the region is not "
            "held by any constraint";
    return nullptr;
  }
  return backend;
}
}

std::string SparseCholesky::Factorize(
  const SparseMatrix& matrix, SolverBackend backend, FillOrdering ordering)
{
  // AMD orders fast; on large systems METIS's slower analysis pays back in factorization time
  // and memory. CHOLMOD's own default tries METIS far earlier, which costs more than it saves
  // on editing regions (bunny, 28.9k, second order: 0.69 s against 0.38 s with AMD).
  if (ordering == FillOrdering::Automatic)
  {
    ordering = matrix.rows() < 300000 ? FillOrdering::AMD : FillOrdering::METIS;
  }
  this->Impl.reset();
  std::string error;
  if (!IsAvailable(backend))
  {
    return "this build has no CHOLMOD; use the SimplicialLDLT solver";
  }
#ifdef LAPLACIAN_EDITING_HAS_CHOLMOD
  if (backend == SolverBackend::Cholmod)
  {
    this->Impl = FactorWith<Eigen::CholmodSupernodalLLT<SparseMatrix, Eigen::Lower>>(
      matrix, ordering, error, this->AnalysisSeconds, this->FactorizationSeconds);
    return error;
  }
#endif
  this->Impl = FactorWith<Eigen::SimplicialLDLT<SparseMatrix, Eigen::Lower>>(
      matrix, ordering, error, this->AnalysisSeconds, this->FactorizationSeconds);
  return error;
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
