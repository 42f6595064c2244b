// A sparse factorization spread across processes, for regions whose factor does not fit one.
//
// The core knows no MPI: an adapter that does (MumpsSolver, over MUMPS) implements
// this interface on the process that solves, and keeps the other processes working alongside
// it in each call. SparseCholesky uses it when asked to (SolverBackend::Distributed), or when
// CHOLMOD predicts a factor above the memory limit.
#ifndef LaplacianEditing_DistributedSolver_h
#define LaplacianEditing_DistributedSolver_h

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include <memory>
#include <string>

namespace LaplacianEditing
{
class DistributedFactor
{
public:
  virtual ~DistributedFactor() = default;
  virtual Eigen::MatrixXd Solve(const Eigen::MatrixXd& rhs) const = 0;
  /// Bytes of the factor on all processes together.
  virtual double GetBytes() const = 0;
};

class DistributedSolver
{
public:
  virtual ~DistributedSolver() = default;
  /// Factors a symmetric positive definite matrix (its upper triangle is read); nullptr and
  /// `error` set when it fails.
  virtual std::unique_ptr<DistributedFactor> Factorize(
    const Eigen::SparseMatrix<double>& matrix, std::string& error) = 0;
  /// How many processes share a factor.
  virtual int GetNumberOfProcesses() const = 0;
};
}

#endif
