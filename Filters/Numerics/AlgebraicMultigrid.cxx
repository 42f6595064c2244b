#include "AlgebraicMultigrid.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace LaplacianEditing
{
namespace
{
using Rows = AlgebraicMultigrid::Rows;
using Block = AlgebraicMultigrid::Block;

// Levels stop coarsening at this many unknowns, which are factored.
constexpr int CoarsestUnknowns = 3000;
// Chebyshev smoothing: the polynomial's degree, and the part of D^-1 A's spectrum it damps,
// [largest / EigenvalueRatio, 1.1 largest].
constexpr int ChebyshevDegree = 2;
constexpr double EigenvalueRatio = 20.0;
// Connections weaker than this (relative to the diagonals) do not bind aggregates.
constexpr double StrongConnection = 0.08;

// Sums of `term(first, last)` over fixed blocks, added in order: the same on any threads.
template <typename Sum, typename Term>
Sum BlockedSum(int count, const ParallelFor& loop, const Term& term)
{
  constexpr int BlockSize = 8192;
  const int blocks = (count + BlockSize - 1) / BlockSize;
  std::vector<Sum> partial(blocks, Sum::Zero());
  loop(0, blocks, [&](int first, int last) {
    for (int b = first; b < last; ++b)
    {
      partial[b] = term(b * BlockSize, std::min(count, (b + 1) * BlockSize));
    }
  });
  Sum total = Sum::Zero();
  for (const Sum& s : partial)
  {
    total += s;
  }
  return total;
}

using Column3 = Eigen::Array3d;

Column3 Dots(const Block& a, const Block& b, const ParallelFor& loop)
{
  return BlockedSum<Column3>(static_cast<int>(a.rows()), loop, [&](int first, int last) {
    Column3 sum = Column3::Zero();
    for (int i = first; i < last; ++i)
    {
      sum += a.row(i).array().transpose() * b.row(i).array().transpose();
    }
    return sum;
  });
}

// y = M x, or y += M x.
void Apply(const Rows& m, const Block& x, Block& y, const ParallelFor& loop, bool add = false)
{
  if (!add)
  {
    y.resize(m.Rows, 3);
  }
  loop(0, m.Rows, [&](int first, int last) {
    for (int i = first; i < last; ++i)
    {
      Eigen::RowVector3d sum = Eigen::RowVector3d::Zero();
      for (int k = m.Offsets[i]; k < m.Offsets[i + 1]; ++k)
      {
        sum.noalias() += m.Values[k] * x.row(m.Indices[k]);
      }
      y.row(i) = add ? Eigen::RowVector3d(y.row(i) + sum) : sum;
    }
  });
}

Rows FromUpper(const Eigen::SparseMatrix<double>& upper)
{
  // Column j of the upper triangle holds a_ij for i <= j: row i gets it, and row j too if i < j.
  Rows m;
  m.Rows = m.Columns = static_cast<int>(upper.rows());
  m.Offsets.assign(m.Rows + 1, 0);
  for (int j = 0; j < upper.outerSize(); ++j)
  {
    for (Eigen::SparseMatrix<double>::InnerIterator it(upper, j); it; ++it)
    {
      ++m.Offsets[it.row() + 1];
      m.Offsets[j + 1] += it.row() < j ? 1 : 0;
    }
  }
  std::partial_sum(m.Offsets.begin(), m.Offsets.end(), m.Offsets.begin());
  m.Indices.resize(m.Offsets.back());
  m.Values.resize(m.Offsets.back());
  std::vector<int> next(m.Offsets.begin(), m.Offsets.end() - 1);
  // Columns in increasing order fill each row r sorted: column r gives it its entries left of
  // the diagonal and the diagonal, in order, and each later column one entry right of it.
  for (int j = 0; j < upper.outerSize(); ++j)
  {
    for (Eigen::SparseMatrix<double>::InnerIterator it(upper, j); it; ++it)
    {
      const int i = static_cast<int>(it.row());
      m.Indices[next[i]] = j;
      m.Values[next[i]++] = it.value();
      if (i < j)
      {
        m.Indices[next[j]] = i;
        m.Values[next[j]++] = it.value();
      }
    }
  }
  return m;
}

Rows Transpose(const Rows& m)
{
  Rows t;
  t.Rows = m.Columns;
  t.Columns = m.Rows;
  t.Offsets.assign(t.Rows + 1, 0);
  for (int c : m.Indices)
  {
    ++t.Offsets[c + 1];
  }
  std::partial_sum(t.Offsets.begin(), t.Offsets.end(), t.Offsets.begin());
  t.Indices.resize(m.Indices.size());
  t.Values.resize(m.Values.size());
  std::vector<int> next(t.Offsets.begin(), t.Offsets.end() - 1);
  for (int i = 0; i < m.Rows; ++i)
  {
    for (int k = m.Offsets[i]; k < m.Offsets[i + 1]; ++k)
    {
      const int slot = next[m.Indices[k]]++;
      t.Indices[slot] = i;
      t.Values[slot] = m.Values[k];
    }
  }
  return t;
}

// The Galerkin product P^T A P, a coarse row at a time (each thread accumulating into a dense
// row of its own): no intermediate A P, whose rows cost more to store than to compute.
Rows GalerkinProduct(const Rows& pt, const Rows& a, const Rows& p, const ParallelFor& loop)
{
  const int coarse = pt.Rows;
  std::vector<std::vector<int>> indices(coarse);
  std::vector<std::vector<double>> values(coarse);
  loop(0, coarse, [&](int first, int last) {
    std::vector<double> dense(p.Columns, 0.0);
    std::vector<int> seen(p.Columns, -1), pattern;
    for (int row = first; row < last; ++row)
    {
      pattern.clear();
      for (int e = pt.Offsets[row]; e < pt.Offsets[row + 1]; ++e)
      {
        const int i = pt.Indices[e];
        for (int k = a.Offsets[i]; k < a.Offsets[i + 1]; ++k)
        {
          const double weight = pt.Values[e] * a.Values[k];
          const int j = a.Indices[k];
          for (int l = p.Offsets[j]; l < p.Offsets[j + 1]; ++l)
          {
            const int column = p.Indices[l];
            if (seen[column] != row)
            {
              seen[column] = row;
              dense[column] = 0.0;
              pattern.push_back(column);
            }
            dense[column] += weight * p.Values[l];
          }
        }
      }
      std::sort(pattern.begin(), pattern.end());
      indices[row] = pattern;
      values[row].resize(pattern.size());
      for (std::size_t e = 0; e < pattern.size(); ++e)
      {
        values[row][e] = dense[pattern[e]];
      }
    }
  });
  Rows c;
  c.Rows = c.Columns = coarse;
  c.Offsets.assign(coarse + 1, 0);
  for (int row = 0; row < coarse; ++row)
  {
    c.Offsets[row + 1] = c.Offsets[row] + static_cast<int>(indices[row].size());
  }
  c.Indices.resize(c.Offsets.back());
  c.Values.resize(c.Offsets.back());
  loop(0, coarse, [&](int first, int last) {
    for (int row = first; row < last; ++row)
    {
      std::copy(indices[row].begin(), indices[row].end(), c.Indices.begin() + c.Offsets[row]);
      std::copy(values[row].begin(), values[row].end(), c.Values.begin() + c.Offsets[row]);
    }
  });
  return c;
}

// P = (I - omega D^-1 A) P0, P0 the aggregates' indicators: row i holds, for its own aggregate
// and each neighbour's, 1 (its own) minus omega a_ij / a_ii summed over the row's unknowns j in
// that aggregate. Two passes over the rows: their lengths, then their entries.
Rows SmoothedProlongation(const Rows& a, const std::vector<double>& inverseDiagonal,
  const std::vector<int>& aggregate, int count, double omega, const ParallelFor& loop)
{
  Rows p;
  p.Rows = a.Rows;
  p.Columns = count;
  p.Offsets.assign(a.Rows + 1, 0);
  // Row i's aggregates are those of A's row i (the diagonal gives its own), sorted, unique.
  auto collect = [&](int i, int* ids, double* weights) {
    int size = 0;
    for (int k = a.Offsets[i]; k < a.Offsets[i + 1]; ++k)
    {
      const int g = aggregate[a.Indices[k]];
      const double w = (a.Indices[k] == i ? 1.0 : 0.0) - omega * a.Values[k] * inverseDiagonal[i];
      int slot = 0;
      while (slot < size && ids[slot] != g)
      {
        ++slot;
      }
      if (slot == size)
      {
        ids[size] = g;
        weights[size++] = 0.0;
      }
      weights[slot] += w;
    }
    // Insertion sort: rows are short.
    for (int x = 1; x < size; ++x)
    {
      for (int y = x; y > 0 && ids[y - 1] > ids[y]; --y)
      {
        std::swap(ids[y - 1], ids[y]);
        std::swap(weights[y - 1], weights[y]);
      }
    }
    return size;
  };
  int longest = 0;
  for (int i = 0; i < a.Rows; ++i)
  {
    longest = std::max(longest, a.Offsets[i + 1] - a.Offsets[i]);
  }
  loop(0, a.Rows, [&](int first, int last) {
    std::vector<int> ids(longest);
    std::vector<double> weights(longest);
    for (int i = first; i < last; ++i)
    {
      p.Offsets[i + 1] = collect(i, ids.data(), weights.data());
    }
  });
  std::partial_sum(p.Offsets.begin(), p.Offsets.end(), p.Offsets.begin());
  p.Indices.resize(p.Offsets.back());
  p.Values.resize(p.Offsets.back());
  loop(0, a.Rows, [&](int first, int last) {
    for (int i = first; i < last; ++i)
    {
      collect(i, p.Indices.data() + p.Offsets[i], p.Values.data() + p.Offsets[i]);
    }
  });
  return p;
}

// The aggregate of each unknown, and how many there are.
std::vector<int> Aggregate(const Rows& a, const std::vector<double>& diagonal, int& count)
{
  const int n = a.Rows;
  auto strong = [&](int i, int k) {
    const int j = a.Indices[k];
    return j != i &&
      std::abs(a.Values[k]) > StrongConnection * std::sqrt(std::abs(diagonal[i] * diagonal[j]));
  };
  std::vector<int> aggregate(n, -1);
  count = 0;
  // 1. Each unknown whose strong neighbours are all free roots an aggregate of them.
  for (int i = 0; i < n; ++i)
  {
    bool free = aggregate[i] < 0;
    for (int k = a.Offsets[i]; k < a.Offsets[i + 1] && free; ++k)
    {
      free = !strong(i, k) || aggregate[a.Indices[k]] < 0;
    }
    if (!free)
    {
      continue;
    }
    aggregate[i] = count;
    for (int k = a.Offsets[i]; k < a.Offsets[i + 1]; ++k)
    {
      if (strong(i, k))
      {
        aggregate[a.Indices[k]] = count;
      }
    }
    ++count;
  }
  // 2. The others join the aggregate of their strongest aggregated neighbour, as pass 1 left them.
  std::vector<int> joined = aggregate;
  for (int i = 0; i < n; ++i)
  {
    if (aggregate[i] >= 0)
    {
      continue;
    }
    double strongest = 0.0;
    for (int k = a.Offsets[i]; k < a.Offsets[i + 1]; ++k)
    {
      if (strong(i, k) && aggregate[a.Indices[k]] >= 0 && std::abs(a.Values[k]) > strongest)
      {
        strongest = std::abs(a.Values[k]);
        joined[i] = aggregate[a.Indices[k]];
      }
    }
  }
  // 3. What is left (no strong neighbour aggregated) forms aggregates with its free neighbours.
  for (int i = 0; i < n; ++i)
  {
    if (joined[i] >= 0)
    {
      continue;
    }
    joined[i] = count;
    for (int k = a.Offsets[i]; k < a.Offsets[i + 1]; ++k)
    {
      if (strong(i, k) && joined[a.Indices[k]] < 0)
      {
        joined[a.Indices[k]] = count;
      }
    }
    ++count;
  }
  return joined;
}

// An upper bound of D^-1 A's spectrum: Gershgorin's, the largest row sum of |D^-1 A|. Why not
// a power iteration's estimate: it converges from below, and a Chebyshev smoother tuned below
// the top of the spectrum amplifies what lies above; on a grid numbered row by row, ten steps
// fell short and conjugate gradients stalled at 0.2 of the residual. For the Laplacians here
// (diagonally dominant) the bound is at most 2, near the true top.
double LargestEigenvalue(const Rows& a, const std::vector<double>& inverseDiagonal)
{
  double bound = 0.0;
  for (int i = 0; i < a.Rows; ++i)
  {
    double sum = 0.0;
    for (int k = a.Offsets[i]; k < a.Offsets[i + 1]; ++k)
    {
      sum += std::abs(a.Values[k]);
    }
    bound = std::max(bound, sum * inverseDiagonal[i]);
  }
  return bound;
}
}

std::string AlgebraicMultigrid::Build(const Eigen::SparseMatrix<double>& upper, const ParallelFor& loop)
{
  this->Levels.clear();
  Level fine;
  fine.A = FromUpper(upper);
  this->Levels.push_back(std::move(fine));
  while (true)
  {
    Level& level = this->Levels.back();
    const Rows& a = level.A;
    std::vector<double> diagonal(a.Rows, 0.0);
    for (int i = 0; i < a.Rows; ++i)
    {
      for (int k = a.Offsets[i]; k < a.Offsets[i + 1]; ++k)
      {
        diagonal[i] += a.Indices[k] == i ? a.Values[k] : 0.0;
      }
      if (!(diagonal[i] > 0.0))
      {
        return "the matrix is not positive definite (a diagonal entry is not positive)";
      }
    }
    level.InverseDiagonal.resize(a.Rows);
    std::transform(diagonal.begin(), diagonal.end(), level.InverseDiagonal.begin(),
      [](double d) { return 1.0 / d; });
    level.LargestEigenvalue = LargestEigenvalue(a, level.InverseDiagonal);
    if (a.Rows <= CoarsestUnknowns)
    {
      break;
    }
    int count = 0;
    const std::vector<int> aggregate = Aggregate(a, diagonal, count);
    if (count > 0.8 * a.Rows)
    {
      break; // coarsening stalls: factor this level
    }
    const double omega = 4.0 / (3.0 * level.LargestEigenvalue);
    Rows p = SmoothedProlongation(a, level.InverseDiagonal, aggregate, count, omega, loop);
    Level coarse;
    level.PT = Transpose(p);
    coarse.A = GalerkinProduct(level.PT, a, p, loop);
    level.P = std::move(p);
    this->Levels.push_back(std::move(coarse));
  }
  // The coarsest level, factored from its upper triangle.
  const Rows& a = this->Levels.back().A;
  std::vector<Eigen::Triplet<double>> triplets;
  for (int i = 0; i < a.Rows; ++i)
  {
    for (int k = a.Offsets[i]; k < a.Offsets[i + 1]; ++k)
    {
      if (a.Indices[k] >= i)
      {
        triplets.emplace_back(i, a.Indices[k], a.Values[k]);
      }
    }
  }
  Eigen::SparseMatrix<double> coarsest(a.Rows, a.Rows);
  coarsest.setFromTriplets(triplets.begin(), triplets.end());
  const SolverBackend backend = SparseCholesky::IsAvailable(SolverBackend::Cholmod)
    ? SolverBackend::Cholmod
    : SolverBackend::SimplicialLDLT;
  const std::string error = this->Coarsest.Factorize(coarsest, backend);
  const std::size_t levels = this->Levels.size();
  this->Residuals.assign(levels, Block());
  this->CoarseRhs.assign(levels, Block());
  this->CoarseX.assign(levels, Block());
  this->Scratch.assign(levels, Block());
  this->Product.assign(levels, Block());
  if (!error.empty())
  {
    this->Levels.clear();
  }
  return error;
}

void AlgebraicMultigrid::Multiply(const Block& x, Block& y, const ParallelFor& loop) const
{
  Apply(this->Levels[0].A, x, y, loop);
}

void AlgebraicMultigrid::Smooth(
  const Level& level, const Block& b, Block& x, bool zeroStart, const ParallelFor& loop) const
{
  // Chebyshev iteration on D^-1 A x = D^-1 b over [lower, upper] (Saad, Iterative Methods for
  // Sparse Linear Systems, Algorithm 12.1): ChebyshevDegree products with A, one fewer from a
  // zero start.
  const Rows& a = level.A;
  const double upper = level.LargestEigenvalue;
  const double lower = upper / EigenvalueRatio;
  const double theta = 0.5 * (upper + lower);
  const double delta = 0.5 * (upper - lower);
  const double sigma = theta / delta;
  const std::size_t index = &level - this->Levels.data();
  Block& r = this->Residuals[index];
  Block& d = this->Scratch[index];
  Block& product = this->Product[index];
  r.resize(a.Rows, 3);
  d.resize(a.Rows, 3);
  product.resize(a.Rows, 3);
  // r = D^-1 (b - A x), d = r / theta.
  loop(0, a.Rows, [&](int first, int last) {
    for (int i = first; i < last; ++i)
    {
      Eigen::RowVector3d ax = Eigen::RowVector3d::Zero();
      for (int k = a.Offsets[i]; k < a.Offsets[i + 1] && !zeroStart; ++k)
      {
        ax.noalias() += a.Values[k] * x.row(a.Indices[k]);
      }
      r.row(i) = level.InverseDiagonal[i] * (b.row(i) - ax);
      d.row(i) = r.row(i) / theta;
    }
  });
  double rho = 1.0 / sigma;
  for (int degree = 1; degree < ChebyshevDegree; ++degree)
  {
    Apply(a, d, product, loop);
    const double next = 1.0 / (2.0 * sigma - rho);
    const double keep = next * rho, step = 2.0 * next / delta;
    const bool assign = zeroStart && degree == 1;
    loop(0, a.Rows, [&](int first, int last) {
      for (int i = first; i < last; ++i)
      {
        x.row(i) = assign ? Eigen::RowVector3d(d.row(i)) : Eigen::RowVector3d(x.row(i) + d.row(i));
        r.row(i) -= level.InverseDiagonal[i] * product.row(i);
        d.row(i) = keep * d.row(i) + step * r.row(i);
      }
    });
    rho = next;
  }
  if (zeroStart && ChebyshevDegree == 1)
  {
    x = d;
  }
  else
  {
    loop(0, a.Rows, [&](int first, int last) {
      for (int i = first; i < last; ++i)
      {
        x.row(i) += d.row(i);
      }
    });
  }
}

void AlgebraicMultigrid::Cycle(std::size_t index, const Block& b, Block& x, const ParallelFor& loop) const
{
  const Level& level = this->Levels[index];
  if (index + 1 == this->Levels.size())
  {
    x = this->Coarsest.Solve(Eigen::MatrixXd(b), loop);
    return;
  }
  const Rows& a = level.A;
  x.resize(a.Rows, 3);
  this->Smooth(level, b, x, true, loop);
  Block& r = this->Residuals[index];
  loop(0, a.Rows, [&](int first, int last) {
    for (int i = first; i < last; ++i)
    {
      Eigen::RowVector3d ax = Eigen::RowVector3d::Zero();
      for (int k = a.Offsets[i]; k < a.Offsets[i + 1]; ++k)
      {
        ax.noalias() += a.Values[k] * x.row(a.Indices[k]);
      }
      r.row(i) = b.row(i) - ax;
    }
  });
  Block& coarseB = this->CoarseRhs[index];
  Block& coarseX = this->CoarseX[index];
  Apply(level.PT, r, coarseB, loop);
  this->Cycle(index + 1, coarseB, coarseX, loop);
  Apply(level.P, coarseX, x, loop, true);
  this->Smooth(level, b, x, false, loop);
}

AlgebraicMultigrid::Result AlgebraicMultigrid::Solve(const Block& rhs, Block& x,
  double tolerance, int maximumIterations, const ParallelFor& loop) const
{
  Result result;
  const int n = this->Levels[0].A.Rows;
  if (x.rows() != n)
  {
    x.setZero(n, 3);
  }
  // Kept between solves: fresh pages cost more than the arithmetic at this size.
  Block& r = this->SolveR;
  Block& z = this->SolveZ;
  Block& p = this->SolveP;
  Block& q = this->SolveQ;
  this->Multiply(x, r, loop);
  loop(0, n, [&](int first, int last) {
    r.middleRows(first, last - first) = rhs.middleRows(first, last - first) - r.middleRows(first, last - first);
  });
  Column3 rr = Dots(r, r, loop);
  // Relative to the start's residual: a warm start near the solution (a local-global
  // iteration's next global step) then still gains `tolerance` on its error, where a test
  // against the right-hand side would stop at once, the error left a condition number above
  // the residual. A residual at rounding's level of the right-hand side is done.
  const Column3 bb = Dots(rhs, rhs, loop);
  const Column3 start = rr.sqrt().max(1e-300);
  auto relative = [&](const Column3& squared) { return (squared.sqrt() / start).maxCoeff(); };
  auto done = [&](const Column3& squared) {
    return (squared.sqrt() <= (tolerance * start).max(1e-14 * bb.sqrt())).all();
  };
  result.RelativeResidual = 1.0;
  if (done(rr))
  {
    result.RelativeResidual = 0.0;
    return result;
  }
  this->Cycle(0, r, z, loop);
  p.resize(n, 3);
  loop(0, n, [&](int first, int last) { p.middleRows(first, last - first) = z.middleRows(first, last - first); });
  Column3 rz = Dots(r, z, loop);
  for (int iteration = 0; iteration < maximumIterations; ++iteration)
  {
    this->Multiply(p, q, loop);
    const Column3 pq = Dots(p, q, loop);
    const Column3 alpha = (pq > 0.0).select(rz / pq, 0.0);
    loop(0, n, [&](int first, int last) {
      for (int i = first; i < last; ++i)
      {
        x.row(i) += (alpha.transpose() * p.row(i).array()).matrix();
        r.row(i) -= (alpha.transpose() * q.row(i).array()).matrix();
      }
    });
    ++result.Iterations;
    rr = Dots(r, r, loop);
    result.RelativeResidual = relative(rr);
    if (done(rr))
    {
      break;
    }
    this->Cycle(0, r, z, loop);
    const Column3 rzNext = Dots(r, z, loop);
    const Column3 beta = (rz > 0.0).select(rzNext / rz, 0.0);
    rz = rzNext;
    loop(0, n, [&](int first, int last) {
      for (int i = first; i < last; ++i)
      {
        p.row(i) = z.row(i) + (beta.transpose() * p.row(i).array()).matrix();
      }
    });
  }
  return result;
}
}
