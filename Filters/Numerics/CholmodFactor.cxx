#include "CholmodFactor.h"

#include "SimdClones.h"

#include <cholmod.h>

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <mutex>
#include <numeric>
#include <type_traits>
#include <vector>

#ifdef __linux__
#include <sys/mman.h>
#endif

// The OpenMP runtime CHOLMOD brought in, if any (weak: resolved only where it is loaded).
extern "C"
{
  int omp_get_max_active_levels() __attribute__((weak));
  void omp_set_max_active_levels(int levels) __attribute__((weak));
}

namespace LaplacianEditing
{
namespace
{
// CHOLMOD 3 (SuiteSparse 5) runs the loops of its supernodal factorization that copy, zero and
// scatter a supernode on a fixed team of 4 OpenMP threads (CHOLMOD_OMP_NUM_THREADS, a
// compile-time constant), one team per supernode, beside BLAS's own threads. On surface meshes
// the supernodes are small, so the teams cost more in wake-ups than the loops gain (about half of
// a factorization's time: Documentation/performance.md, "Measured choices"). During a
// factorization the calling thread's OpenMP regions are therefore inactive (its
// max-active-levels ICV is 0); BLAS keeps its threads.
class SerialOpenMPLoops
{
public:
  SerialOpenMPLoops()
    : Available(omp_get_max_active_levels && omp_set_max_active_levels)
  {
    if (this->Available)
    {
      this->Saved = omp_get_max_active_levels();
      omp_set_max_active_levels(0);
    }
  }
  ~SerialOpenMPLoops()
  {
    if (this->Available)
    {
      omp_set_max_active_levels(this->Saved);
    }
  }
  SerialOpenMPLoops(const SerialOpenMPLoops&) = delete;
  SerialOpenMPLoops& operator=(const SerialOpenMPLoops&) = delete;

private:
  const bool Available;
  int Saved = 0;
};

cholmod_sparse ViewUpperTriangle(const Eigen::SparseMatrix<double>& matrix)
{
  cholmod_sparse view{};
  view.nrow = static_cast<size_t>(matrix.rows());
  view.ncol = static_cast<size_t>(matrix.cols());
  view.nzmax = static_cast<size_t>(matrix.nonZeros());
  view.p = const_cast<int*>(matrix.outerIndexPtr());
  view.i = const_cast<int*>(matrix.innerIndexPtr());
  view.x = const_cast<double*>(matrix.valuePtr());
  view.stype = 1; // the upper triangle: CHOLMOD then permutes it with one transpose, not two
  view.itype = CHOLMOD_INT;
  view.xtype = CHOLMOD_REAL;
  view.dtype = CHOLMOD_DOUBLE;
  view.sorted = 1;
  view.packed = 1;
  return view;
}

// A fill-reducing order of the symmetric `pattern` by `method` (a CHOLMOD ordering).
bool OrderPattern(cholmod_sparse& pattern, int method, cholmod_common& common, std::vector<int>& order)
{
  if (method == CHOLMOD_AMD)
  {
    return cholmod_amd(&pattern, nullptr, 0, order.data(), &common);
  }
  if (method == CHOLMOD_METIS)
  {
    return cholmod_metis(&pattern, nullptr, 0, 1, order.data(), &common);
  }
  std::vector<int> parents(order.size()), members(order.size());
  return cholmod_nested_dissection(
           &pattern, nullptr, 0, order.data(), parents.data(), members.data(), &common) >= 0;
}

// Orders the graph of the blocks, one node per group of `blockSize` unknowns (coupled where the
// matrix couples any of their unknowns), and expands the order to the unknowns. A group's
// unknowns stay together, and the graph ordered is blockSize^2 times smaller.
std::vector<int> OrderBlocks(
  const Eigen::SparseMatrix<double>& matrix, int blockSize, int method, cholmod_common& common)
{
  const int blocks = static_cast<int>(matrix.rows()) / blockSize;
  std::vector<int> columnStart(1, 0);
  std::vector<int> rows;
  std::vector<int> seenIn(blocks, -1);
  for (int b = 0; b < blocks; ++b)
  {
    for (int j = b * blockSize; j < (b + 1) * blockSize; ++j)
    {
      for (int p = matrix.outerIndexPtr()[j]; p < matrix.outerIndexPtr()[j + 1]; ++p)
      {
        const int a = matrix.innerIndexPtr()[p] / blockSize;
        if (seenIn[a] != b)
        {
          seenIn[a] = b;
          rows.push_back(a);
        }
      }
    }
    std::sort(rows.begin() + columnStart.back(), rows.end());
    columnStart.push_back(static_cast<int>(rows.size()));
  }
  cholmod_sparse pattern{};
  pattern.nrow = pattern.ncol = static_cast<size_t>(blocks);
  pattern.nzmax = rows.size();
  pattern.p = columnStart.data();
  pattern.i = rows.data();
  pattern.stype = 1;
  pattern.itype = CHOLMOD_INT;
  pattern.xtype = CHOLMOD_PATTERN;
  pattern.dtype = CHOLMOD_DOUBLE;
  pattern.sorted = 1;
  pattern.packed = 1;
  std::vector<int> order(blocks);
  const bool ordered = OrderPattern(pattern, method, common, order);
  if (!ordered)
  {
    return {};
  }
  std::vector<int> expanded(matrix.rows());
  for (int k = 0; k < blocks; ++k)
  {
    for (int c = 0; c < blockSize; ++c)
    {
      expanded[k * blockSize + c] = order[k] * blockSize + c;
    }
  }
  return expanded;
}

#ifdef __linux__
// A factor is written once and streamed by every solve: 300 MB for the implicit system of a
// 30k-vertex region. In 2 MB pages its first touch takes 512 times fewer page faults and its
// solves fewer TLB misses. Linux grants them to regions marked MADV_HUGEPAGE (Debian's default
// "madvise" mode); small blocks stay with malloc.
void* AllocateInHugePages(size_t bytes)
{
  constexpr size_t hugePage = size_t(2) << 20;
  if (bytes < 4 * hugePage)
  {
    return std::malloc(bytes);
  }
  void* memory = nullptr;
  if (posix_memalign(&memory, hugePage, bytes) != 0)
  {
    return nullptr;
  }
  madvise(memory, bytes, MADV_HUGEPAGE);
  return memory;
}

void* ClearedInHugePages(size_t count, size_t size)
{
  if (size != 0 && count > std::numeric_limits<size_t>::max() / size)
  {
    return nullptr;
  }
  void* memory = AllocateInHugePages(count * size);
  if (memory)
  {
    std::memset(memory, 0, count * size);
  }
  return memory;
}
#endif

// SuiteSparse's allocator is process-wide; it is replaced only while it is still the C
// library's, so an application's own allocator is kept. Blocks stay free()-compatible.
void UseHugePagesForLargeBlocks()
{
#ifdef __linux__
  static std::once_flag once;
  std::call_once(once, [] {
    if (SuiteSparse_config.malloc_func == std::malloc &&
      SuiteSparse_config.calloc_func == std::calloc && SuiteSparse_config.free_func == std::free)
    {
      SuiteSparse_config.malloc_func = AllocateInHugePages;
      SuiteSparse_config.calloc_func = ClearedInHugePages;
    }
  });
#endif
}
// The supernodal elimination tree, with each supernode's share of a solve's work (its entries).
struct SupernodeTree
{
  std::vector<int> Parent;
  std::vector<std::vector<int>> Children;
  std::vector<int> Roots;
  std::vector<double> Work;
  std::vector<double> SubtreeWork;
  double TotalWork = 0.0;
  // Whether every supernode's rows are sorted (the schedule needs them so).
  bool Sorted = true;

  SupernodeTree(std::size_t count, const int* super, const int* pi, const int* rows)
    : Parent(count, -1)
    , Children(count)
    , Work(count)
    , SubtreeWork(count, 0.0)
  {
    const int supernodes = static_cast<int>(count);
    std::vector<int> supernodeOfColumn(super[supernodes]);
    for (int s = 0; s < supernodes; ++s)
    {
      std::fill(supernodeOfColumn.begin() + super[s], supernodeOfColumn.begin() + super[s + 1], s);
    }
    for (int s = 0; s < supernodes; ++s)
    {
      const double columns = super[s + 1] - super[s];
      const double height = pi[s + 1] - pi[s];
      this->Work[s] = columns * height - columns * (columns - 1.0) / 2.0;
      this->TotalWork += this->Work[s];
      this->SubtreeWork[s] += this->Work[s];
      for (int k = pi[s] + 1; k < pi[s + 1]; ++k)
      {
        this->Sorted = this->Sorted && rows[k - 1] < rows[k];
      }
      if (height > columns)
      {
        // The first row below the diagonal block is the elimination tree's parent; parents come
        // after their children, so subtree sums are complete when they are read.
        this->Parent[s] = supernodeOfColumn[rows[pi[s] + static_cast<int>(columns)]];
        this->SubtreeWork[this->Parent[s]] += this->SubtreeWork[s];
        this->Children[this->Parent[s]].push_back(s);
      }
      else
      {
        this->Roots.push_back(s);
      }
    }
  }

  // Deals `subtrees`, heaviest first, to the least loaded of `parts` bins (into `binOf` if
  // given); returns the heaviest bin's load.
  double Assign(std::vector<int>& subtrees, int parts, std::vector<int>* binOf) const
  {
    std::sort(subtrees.begin(), subtrees.end(),
      [&](int a, int b) { return this->SubtreeWork[a] > this->SubtreeWork[b]; });
    std::vector<double> load(parts, 0.0);
    for (int subtree : subtrees)
    {
      const int bin = static_cast<int>(std::min_element(load.begin(), load.end()) - load.begin());
      load[bin] += this->SubtreeWork[subtree];
      if (binOf)
      {
        (*binOf)[subtree] = bin;
      }
    }
    return *std::max_element(load.begin(), load.end());
  }

  // Each supernode's part (-1 for the top) and subtree root, `subtrees` dealt to `parts` bins.
  void Resolve(std::vector<int>& subtrees, const std::vector<int>& top, int parts,
    std::vector<int>& binOf, std::vector<int>& subtreeRoot) const
  {
    const int supernodes = static_cast<int>(this->Parent.size());
    binOf.assign(supernodes, -1);
    subtreeRoot.assign(supernodes, -1);
    this->Assign(subtrees, parts, &binOf);
    std::vector<char> isTop(supernodes, 0);
    for (int s : top)
    {
      isTop[s] = 1;
    }
    for (int s = supernodes - 1; s >= 0; --s)
    {
      if (isTop[s])
      {
        binOf[s] = -1;
      }
      else if (binOf[s] >= 0)
      {
        subtreeRoot[s] = s;
      }
      else
      {
        binOf[s] = binOf[this->Parent[s]];
        subtreeRoot[s] = subtreeRoot[this->Parent[s]];
      }
    }
  }

  // Splits the heaviest subtree until the estimated time, serial top plus the heaviest part,
  // stops improving; each split moves one separator to the top.
  void Split(int parts, std::vector<int>& bestSubtrees, std::vector<int>& bestTop) const
  {
    std::vector<int> candidates = this->Roots, top;
    bestSubtrees = this->Roots;
    bestTop.clear();
    double topWork = 0.0, bestCost = std::numeric_limits<double>::infinity();
    while (!candidates.empty() && candidates.size() <= static_cast<size_t>(64 * parts))
    {
      const double cost = topWork + this->Assign(candidates, parts, nullptr);
      if (cost < bestCost)
      {
        bestCost = cost;
        bestSubtrees = candidates;
        bestTop = top;
      }
      const int heaviest = candidates.front();
      if (this->Children[heaviest].empty())
      {
        break;
      }
      candidates.erase(candidates.begin());
      candidates.insert(
        candidates.end(), this->Children[heaviest].begin(), this->Children[heaviest].end());
      top.push_back(heaviest);
      topWork += this->Work[heaviest];
    }
  }
};
}

struct CholmodFactor::Internals
{
  mutable cholmod_common Common;
  cholmod_factor* Factor = nullptr;

  // The supernodes' schedule for the few-column solves. Each part is a set of whole subtrees of
  // the supernodal elimination tree, listed in increasing order; Top holds the supernodes above
  // them. A part's forward updates to rows of Top go to its own spill rows (TopSlot), so parts
  // never write the same memory; the backward pass only reads ancestors.
  std::vector<std::vector<int>> Parts;
  std::vector<int> Top;
  std::vector<int> TopColumns;
  std::vector<int> TopSlot;
  // Where each supernode's sorted rows leave its own part (the rest are Top's; all of a Top
  // supernode's rows are its own).
  std::vector<int> DirectRowsEnd;
  double ParallelShare = 0.0;
  // Each row's place in the factor's order (the inverse of Perm): the solution's rows are
  // gathered from it, since a scatter through Perm from several threads shares cache lines.
  std::vector<int> PlaceOfRow;

  Internals() { cholmod_start(&this->Common); }
  ~Internals()
  {
    cholmod_free_factor(&this->Factor, &this->Common);
    cholmod_finish(&this->Common);
  }

  const int* Super() const { return static_cast<const int*>(this->Factor->super); }
  const int* RowPointers() const { return static_cast<const int*>(this->Factor->pi); }
  const int* ValuePointers() const { return static_cast<const int*>(this->Factor->px); }
  const int* Rows() const { return static_cast<const int*>(this->Factor->s); }
  const double* Values() const { return static_cast<const double*>(this->Factor->x); }

  // The parts and the top of the schedule, for `parts` threads.
  void Schedule(int parts);
  void Place(const SupernodeTree& tree, int parts, std::vector<int>& subtrees, const std::vector<int>& top);

  template <int C>
  void Forward(int s, double* y, double* spill) const;
  template <int C>
  void Backward(int s, double* y) const;
  template <int C>
  void SolveInPlace(double* y, const ParallelFor& loop) const;
};

void CholmodFactor::Internals::Schedule(int parts)
{
  const SupernodeTree tree(this->Factor->nsuper, this->Super(), this->RowPointers(), this->Rows());
  std::vector<int> subtrees, top;
  if (tree.Sorted && parts > 1)
  {
    tree.Split(parts, subtrees, top);
  }
  else
  {
    top.resize(tree.Parent.size());
    std::iota(top.begin(), top.end(), 0);
  }
  this->Place(tree, parts, subtrees, top);
}

void CholmodFactor::Internals::Place(
  const SupernodeTree& tree, int parts, std::vector<int>& subtrees, const std::vector<int>& top)
{
  // Each supernode joins its subtree's part, or the top.
  const int supernodes = static_cast<int>(tree.Parent.size());
  const int* super = this->Super();
  const int* pi = this->RowPointers();
  const int* rows = this->Rows();
  this->Parts.assign(std::max(parts, 1), {});
  this->DirectRowsEnd.assign(supernodes, 0);
  this->TopSlot.assign(this->Factor->n, -1);
  this->TopColumns.clear();
  this->Top.clear();
  this->ParallelShare = 0.0;
  std::vector<int> binOf, subtreeRoot;
  tree.Resolve(subtrees, top, parts, binOf, subtreeRoot);
  for (int s = 0; s < supernodes; ++s)
  {
    const int columns = super[s + 1] - super[s];
    int end = pi[s + 1] - pi[s];
    if (binOf[s] < 0)
    {
      this->Top.push_back(s);
      for (int column = super[s]; column < super[s + 1]; ++column)
      {
        this->TopSlot[column] = static_cast<int>(this->TopColumns.size());
        this->TopColumns.push_back(column);
      }
    }
    else
    {
      // Rows are sorted, and the part's own rows are those up to its subtree root's last column.
      const int lastOwnColumn = super[subtreeRoot[s] + 1] - 1;
      end = columns;
      while (end < pi[s + 1] - pi[s] && rows[pi[s] + end] <= lastOwnColumn)
      {
        ++end;
      }
      this->Parts[binOf[s]].push_back(s);
      this->ParallelShare += tree.Work[s] / tree.TotalWork;
    }
    this->DirectRowsEnd[s] = end;
  }
}

namespace
{
// Up to four columns of a supernode at once, so that each row they update is read and written
// once rather than once a column.
constexpr int ColumnBlock = 4;

#if defined(__GNUC__)
// Four right-hand sides side by side fill one vector of doubles (AVX2 where the processor has
// it: GCC builds these twice and the loader picks), so that each factor value updates a row in
// one multiply-add. Three columns are solved as four, the fourth zero.
using Row = double __attribute__((vector_size(32), aligned(8)));

LAPLACIAN_EDITING_SIMD_CLONES
void SubtractRows4(const double* const* columns, int block, const double (&x)[ColumnBlock][4],
  const int* rows, int begin, int end, double* target, const int* slot)
{
  Row xs[ColumnBlock];
  std::memcpy(xs, x, sizeof(xs));
  for (int i = begin; i < end; ++i)
  {
    Row sum = columns[0][i] * xs[0];
    for (int k = 1; k < block; ++k)
    {
      sum += columns[k][i] * xs[k];
    }
    Row* row = reinterpret_cast<Row*>(target + static_cast<size_t>(slot ? slot[rows[i]] : rows[i]) * 4);
    *row -= sum;
  }
}

LAPLACIAN_EDITING_SIMD_CLONES
void GatherRows4(const double* const* columns, int block, const int* rows, int begin, int end,
  const double* y, double (&sums)[ColumnBlock][4])
{
  Row totals[ColumnBlock] = {};
  for (int i = begin; i < end; ++i)
  {
    const Row row = *reinterpret_cast<const Row*>(y + static_cast<size_t>(rows[i]) * 4);
    for (int k = 0; k < block; ++k)
    {
      totals[k] += columns[k][i] * row;
    }
  }
  for (int k = 0; k < block; ++k)
  {
    for (int c = 0; c < 4; ++c)
    {
      sums[k][c] -= totals[k][c];
    }
  }
}
#endif

// target_i -= sum_k L(i, k) x_k over rows [begin, end) of a block of B columns.
template <int C, int B>
void SubtractBlock(const double* const* columns, const double (&x)[ColumnBlock][C], const int* rows,
  int begin, int end, double* target, const int* slot)
{
#if defined(__GNUC__)
  if constexpr (C == 4)
  {
    return SubtractRows4(columns, B, x, rows, begin, end, target, slot);
  }
#endif
  for (int i = begin; i < end; ++i)
  {
    double* row = target + static_cast<size_t>(slot ? slot[rows[i]] : rows[i]) * C;
    for (int c = 0; c < C; ++c)
    {
      double sum = 0.0;
      for (int k = 0; k < B; ++k)
      {
        sum += columns[k][i] * x[k][c];
      }
      row[c] -= sum;
    }
  }
}

// sums_k -= sum_i L(i, k) y_i over rows [begin, end) of a block of B columns.
template <int C, int B>
void GatherBlock(const double* const* columns, const int* rows, int begin, int end,
  const double* y, double (&sums)[ColumnBlock][C])
{
#if defined(__GNUC__)
  if constexpr (C == 4)
  {
    return GatherRows4(columns, B, rows, begin, end, y, sums);
  }
#endif
  for (int i = begin; i < end; ++i)
  {
    const double* row = y + static_cast<size_t>(rows[i]) * C;
    for (int k = 0; k < B; ++k)
    {
      for (int c = 0; c < C; ++c)
      {
        sums[k][c] -= columns[k][i] * row[c];
      }
    }
  }
}

template <int C, typename Function>
void WithBlockWidth(int width, Function&& function)
{
  switch (width)
  {
    case 1: function(std::integral_constant<int, 1>()); break;
    case 2: function(std::integral_constant<int, 2>()); break;
    case 3: function(std::integral_constant<int, 3>()); break;
    default: function(std::integral_constant<int, 4>()); break;
  }
}
}

template <int C>
void CholmodFactor::Internals::Forward(int s, double* y, double* spill) const
{
  const int first = this->Super()[s];
  const int width = this->Super()[s + 1] - first;
  const int height = this->RowPointers()[s + 1] - this->RowPointers()[s];
  const int* rows = this->Rows() + this->RowPointers()[s];
  const double* values = this->Values() + this->ValuePointers()[s];
  const int directEnd = this->DirectRowsEnd[s];
  for (int j0 = 0; j0 < width; j0 += ColumnBlock)
  {
    const int block = std::min(ColumnBlock, width - j0);
    const double* columns[ColumnBlock];
    double x[ColumnBlock][C];
    for (int k = 0; k < block; ++k)
    {
      const int j = j0 + k;
      columns[k] = values + static_cast<size_t>(j) * height;
      double* yj = y + static_cast<size_t>(first + j) * C;
      for (int c = 0; c < C; ++c)
      {
        x[k][c] = yj[c] /= columns[k][j];
      }
      for (int i = j + 1; i < j0 + block; ++i)
      {
        for (int c = 0; c < C; ++c)
        {
          y[static_cast<size_t>(first + i) * C + c] -= columns[k][i] * x[k][c];
        }
      }
    }
    WithBlockWidth<C>(block, [&](auto b) {
      SubtractBlock<C, b()>(columns, x, rows, j0 + block, directEnd, y, nullptr);
      SubtractBlock<C, b()>(columns, x, rows, directEnd, height, spill, this->TopSlot.data());
    });
  }
}

template <int C>
void CholmodFactor::Internals::Backward(int s, double* y) const
{
  const int first = this->Super()[s];
  const int width = this->Super()[s + 1] - first;
  const int height = this->RowPointers()[s + 1] - this->RowPointers()[s];
  const int* rows = this->Rows() + this->RowPointers()[s];
  const double* values = this->Values() + this->ValuePointers()[s];
  for (int end = width; end > 0; end -= ColumnBlock)
  {
    const int j0 = std::max(0, end - ColumnBlock);
    const int block = end - j0;
    const double* columns[ColumnBlock];
    double sums[ColumnBlock][C];
    for (int k = 0; k < block; ++k)
    {
      columns[k] = values + static_cast<size_t>(j0 + k) * height;
      for (int c = 0; c < C; ++c)
      {
        sums[k][c] = y[static_cast<size_t>(first + j0 + k) * C + c];
      }
    }
    WithBlockWidth<C>(
      block, [&](auto b) { GatherBlock<C, b()>(columns, rows, end, height, y, sums); });
    for (int k = block - 1; k >= 0; --k)
    {
      double* yj = y + static_cast<size_t>(first + j0 + k) * C;
      for (int c = 0; c < C; ++c)
      {
        for (int i = k + 1; i < block; ++i)
        {
          sums[k][c] -= columns[k][j0 + i] * y[static_cast<size_t>(first + j0 + i) * C + c];
        }
        yj[c] = sums[k][c] / columns[k][j0 + k];
      }
    }
  }
}

template <int C>
void CholmodFactor::Internals::SolveInPlace(double* y, const ParallelFor& loop) const
{
  const int parts = static_cast<int>(this->Parts.size());
  const size_t spillSize = this->TopColumns.size() * C;
  std::vector<double> spill(spillSize * parts, 0.0);
  loop(0, parts, [&](int firstPart, int lastPart) {
    for (int part = firstPart; part < lastPart; ++part)
    {
      for (int s : this->Parts[part])
      {
        this->Forward<C>(s, y, spill.data() + spillSize * part);
      }
    }
  });
  for (int part = 0; part < parts; ++part)
  {
    for (size_t k = 0; k < this->TopColumns.size(); ++k)
    {
      for (int c = 0; c < C; ++c)
      {
        y[static_cast<size_t>(this->TopColumns[k]) * C + c] += spill[spillSize * part + k * C + c];
      }
    }
  }
  for (int s : this->Top)
  {
    this->Forward<C>(s, y, nullptr);
  }
  for (auto s = this->Top.rbegin(); s != this->Top.rend(); ++s)
  {
    this->Backward<C>(*s, y);
  }
  loop(0, parts, [&](int firstPart, int lastPart) {
    for (int part = firstPart; part < lastPart; ++part)
    {
      for (auto s = this->Parts[part].rbegin(); s != this->Parts[part].rend(); ++s)
      {
        this->Backward<C>(*s, y);
      }
    }
  });
}

CholmodFactor::CholmodFactor()
  : Internal(new Internals)
{
  UseHugePagesForLargeBlocks();
  cholmod_common& common = this->Internal->Common;
  common.print = 0; // failures reach the caller as messages, not as CHOLMOD's own printing
  common.supernodal = CHOLMOD_SUPERNODAL;
  common.nmethods = 1;
  common.postorder = 1;
}

CholmodFactor::~CholmodFactor() = default;

std::string CholmodFactor::Analyze(
  const Eigen::SparseMatrix<double>& matrix, FillOrdering ordering, int parts, int blockSize)
{
  cholmod_common& common = this->Internal->Common;
  const int method = ordering == FillOrdering::AMD ? CHOLMOD_AMD
    : ordering == FillOrdering::METIS              ? CHOLMOD_METIS
                                                   : CHOLMOD_NESDIS;
  cholmod_free_factor(&this->Internal->Factor, &common);
  cholmod_sparse view = ViewUpperTriangle(matrix);
  if (blockSize > 1 && matrix.rows() % blockSize == 0)
  {
    const std::vector<int> permutation = OrderBlocks(matrix, blockSize, method, common);
    if (permutation.empty())
    {
      return "the fill-reducing ordering failed (CHOLMOD status " +
        std::to_string(common.status) + ")";
    }
    common.method[0].ordering = CHOLMOD_GIVEN;
    this->Internal->Factor =
      cholmod_analyze_p(&view, const_cast<int*>(permutation.data()), nullptr, 0, &common);
  }
  else
  {
    common.method[0].ordering = method;
    this->Internal->Factor = cholmod_analyze(&view, &common);
  }
  if (common.status == CHOLMOD_TOO_LARGE)
  {
    return "the factor would have more than 2^31 entries, CHOLMOD's limit; choose a smaller "
           "region of interest";
  }
  if (!this->Internal->Factor || !this->Internal->Factor->is_super)
  {
    return "the symbolic analysis failed (CHOLMOD status " + std::to_string(common.status) + ")";
  }
  this->Internal->Schedule(parts);
  const int* permutation = static_cast<const int*>(this->Internal->Factor->Perm);
  this->Internal->PlaceOfRow.resize(this->Internal->Factor->n);
  for (int k = 0; k < static_cast<int>(this->Internal->Factor->n); ++k)
  {
    this->Internal->PlaceOfRow[permutation[k]] = k;
  }
  return {};
}

void CholmodFactor::SetManySolves(bool many)
{
  // CHOLMOD's default zrelax is {0.8, 0.1, 0.05}: supernodes of up to 4, 16 and 48 columns may
  // be up to 80%, 10% and 5% zeros.
  cholmod_common& common = this->Internal->Common;
  const double relax[3] = { 0.8, 0.1, 0.05 };
  for (int k = 0; k < 3; ++k)
  {
    common.zrelax[k] = many ? relax[k] / 8.0 : relax[k];
  }
}

bool CholmodFactor::IsTooLarge() const
{
  return this->Internal->Common.status == CHOLMOD_TOO_LARGE;
}

double CholmodFactor::GetPredictedBytes() const
{
  return this->Internal->Common.lnz * (sizeof(double) + sizeof(int));
}

bool CholmodFactor::Factorize(const Eigen::SparseMatrix<double>& matrix)
{
  cholmod_sparse view = ViewUpperTriangle(matrix);
  cholmod_factor* factor = this->Internal->Factor;
  const SerialOpenMPLoops serialLoops;
  cholmod_factorize(&view, factor, &this->Internal->Common);
  return this->Internal->Common.status == CHOLMOD_OK && factor->minor == factor->n;
}

Eigen::MatrixXd CholmodFactor::Solve(const Eigen::MatrixXd& rhs, const ParallelFor& loop) const
{
  const cholmod_factor* factor = this->Internal->Factor;
  const int n = static_cast<int>(rhs.rows());
  const int columns = static_cast<int>(rhs.cols());
  Eigen::MatrixXd solution(n, columns);
  if (columns > 4)
  {
    cholmod_dense view{};
    view.nrow = view.d = static_cast<size_t>(n);
    view.ncol = static_cast<size_t>(columns);
    view.nzmax = view.nrow * view.ncol;
    view.x = const_cast<double*>(rhs.data());
    view.xtype = CHOLMOD_REAL;
    view.dtype = CHOLMOD_DOUBLE;
    cholmod_dense* x = cholmod_solve(
      CHOLMOD_A, const_cast<cholmod_factor*>(factor), &view, &this->Internal->Common);
    std::copy_n(static_cast<const double*>(x->x), view.nzmax, solution.data());
    cholmod_free_dense(&x, &this->Internal->Common);
    return solution;
  }
  // Permuted, with each row's columns side by side; three columns as four (one vector a row).
  const int* permutation = static_cast<const int*>(factor->Perm);
  const int stride = columns == 3 ? 4 : columns;
  // The permutations run through `loop` too: serial, they were a seventh of a 30k-vertex solve.
  std::vector<double> y(static_cast<size_t>(n) * stride);
  loop(0, n, [&](int first, int last) {
    for (int k = first; k < last; ++k)
    {
      for (int c = 0; c < stride; ++c)
      {
        y[static_cast<size_t>(k) * stride + c] = c < columns ? rhs(permutation[k], c) : 0.0;
      }
    }
  });
  switch (stride)
  {
    case 1: this->Internal->SolveInPlace<1>(y.data(), loop); break;
    case 2: this->Internal->SolveInPlace<2>(y.data(), loop); break;
    case 4: this->Internal->SolveInPlace<4>(y.data(), loop); break;
    default: break;
  }
  const int* place = this->Internal->PlaceOfRow.data();
  loop(0, n, [&](int first, int last) {
    for (int row = first; row < last; ++row)
    {
      for (int c = 0; c < columns; ++c)
      {
        solution(row, c) = y[static_cast<size_t>(place[row]) * stride + c];
      }
    }
  });
  return solution;
}

double CholmodFactor::GetParallelShare() const
{
  return this->Internal->ParallelShare;
}
}
