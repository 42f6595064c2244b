// A CHOLMOD supernodal Cholesky factor, with triangular solves made for editing.
//
// An edit's moves solve for three right-hand sides (x, y, z). CHOLMOD's own solve hands each
// supernode to BLAS, whose packing then costs more than the arithmetic, and runs on one core.
// Here a solve with up to four columns streams each supernode once per triangular pass, with
// the columns interleaved, and splits the elimination tree into independent subtrees of about
// equal work that run in parallel; only the separators above them are solved serially. Wider
// solves (the setup's responses) go through CHOLMOD's BLAS-3 path.
#ifndef LaplacianEditing_CholmodFactor_h
#define LaplacianEditing_CholmodFactor_h

#include "ParallelFor.h"
#include "SparseCholesky.h"

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include <memory>
#include <string>

namespace LaplacianEditing
{
class CholmodFactor
{
public:
  CholmodFactor();
  ~CholmodFactor();
  CholmodFactor(const CholmodFactor&) = delete;
  CholmodFactor& operator=(const CholmodFactor&) = delete;

  /// Before Analyze: whether the factor is solved many times per factorization. CHOLMOD then
  /// merges fewer supernodes, which adds fewer explicit zeros for the solves to read: on the
  /// bunny's 30k-vertex ARAP region, 1.64M stored values become 1.27M (1.05M nonzeros), the
  /// factorization takes twice as long and a solve about a third less.
  void SetManySolves(bool many);

  /// Orders and analyses the pattern of a symmetric matrix (its upper triangle is read).
  /// `parts` is how many subtrees the few-column solves may run at once. With `blockSize` > 1,
  /// the unknowns come in groups of that many sharing one pattern, and the ordering works on
  /// the groups.
  std::string Analyze(
    const Eigen::SparseMatrix<double>& matrix, FillOrdering ordering, int parts, int blockSize = 1);
  /// Bytes of the factor the analysis predicts: values and row indices.
  double GetPredictedBytes() const;
  /// Whether the analysis failed because the factor is beyond CHOLMOD's 32-bit indices.
  bool IsTooLarge() const;
  /// Factors the analysed matrix; false if it is not positive definite.
  bool Factorize(const Eigen::SparseMatrix<double>& matrix);

  Eigen::MatrixXd Solve(const Eigen::MatrixXd& rhs, const ParallelFor& loop) const;

  /// Share of the solve's work in the independent subtrees (for tests and tuning).
  double GetParallelShare() const;

private:
  struct Internals;
  std::unique_ptr<Internals> Internal;
};
}

#endif
