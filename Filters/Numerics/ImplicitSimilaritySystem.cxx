#include "ImplicitSimilaritySystem.h"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <utility>
#include <vector>

namespace LaplacianEditing
{
namespace
{
// Flattens n x 3 positions into (x0, y0, z0, x1, ...), the unknowns' order.
Eigen::VectorXd Interleave(const Positions& positions)
{
  const Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor> rows = positions;
  return Eigen::Map<const Eigen::VectorXd>(rows.data(), rows.size());
}

Positions Deinterleave(const Eigen::VectorXd& values)
{
  return Eigen::Map<const Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>>(
    values.data(), values.size() / 3, 3);
}

// [x, y, z] -> the 3 x 7 block of Eq. 11 for unknowns (s, h1, h2, h3, tx, ty, tz).
Eigen::Matrix<double, 3, 7> FitBlock(const Eigen::Vector3d& p)
{
  Eigen::Matrix<double, 3, 7> block;
  block << p.x(), 0.0, p.z(), -p.y(), 1.0, 0.0, 0.0, //
    p.y(), -p.z(), 0.0, p.x(), 0.0, 1.0, 0.0,         //
    p.z(), p.y(), -p.x(), 0.0, 0.0, 0.0, 1.0;
  return block;
}

// T delta = s delta + h x delta, as a 3 x 4 matrix acting on (s, h1, h2, h3).
Eigen::Matrix<double, 3, 4> ApplyToDelta(const Eigen::Vector3d& delta)
{
  Eigen::Matrix<double, 3, 4> g;
  g.col(0) = delta;
  g.col(1) = Eigen::Vector3d::UnitX().cross(delta);
  g.col(2) = Eigen::Vector3d::UnitY().cross(delta);
  g.col(3) = Eigen::Vector3d::UnitZ().cross(delta);
  return g;
}

// The residual rows of one ROI vertex, dense over the ROI vertices they touch.
struct VertexRows
{
  const std::vector<int>* Columns = nullptr; // ROI rows, sorted
  Eigen::MatrixXd Jacobian;                  // equations x 3 Columns->size()
  Eigen::VectorXd Known;

  void Start(const std::vector<int>& columns, int equations)
  {
    this->Columns = &columns;
    this->Jacobian.setZero(equations, 3 * static_cast<Eigen::Index>(columns.size()));
    this->Known.setZero(equations);
  }

  int Column(int roiRow) const
  {
    return static_cast<int>(std::lower_bound(this->Columns->begin(), this->Columns->end(), roiRow) -
      this->Columns->begin());
  }
};

// A^T A (upper triangle) and A^T k of a system given vertex by vertex, in 3 x 3 blocks between
// ROI vertices. The block pattern is known before any value: vertices a and b are coupled when
// some vertex's residual rows act on both.
class BlockNormalEquations
{
public:
  explicit BlockNormalEquations(const std::vector<std::vector<int>>& residualColumns)
    : RightHandSide(Eigen::VectorXd::Zero(3 * static_cast<Eigen::Index>(residualColumns.size())))
  {
    // Block column b holds the blocks (a, b) with a <= b, sorted.
    std::vector<std::vector<int>> coupled(residualColumns.size());
    for (const std::vector<int>& columns : residualColumns)
    {
      for (std::size_t b = 0; b < columns.size(); ++b)
      {
        std::vector<int>& column = coupled[columns[b]];
        column.insert(column.end(), columns.begin(), columns.begin() + b + 1);
      }
    }
    this->ColumnStart.assign(1, 0);
    for (std::vector<int>& column : coupled)
    {
      std::sort(column.begin(), column.end());
      column.erase(std::unique(column.begin(), column.end()), column.end());
      this->BlockRows.insert(this->BlockRows.end(), column.begin(), column.end());
      this->ColumnStart.push_back(static_cast<int>(this->BlockRows.size()));
    }
    this->Blocks.assign(this->BlockRows.size(), Eigen::Matrix3d::Zero());
  }

  /// Adds J^T J and J^T k of one vertex's rows, J acting on the ROI vertices `columns`.
  void Add(const std::vector<int>& columns, const Eigen::MatrixXd& product,
    const Eigen::VectorXd& projected)
  {
    const int size = static_cast<int>(columns.size());
    for (int b = 0; b < size; ++b)
    {
      this->RightHandSide.segment<3>(3 * columns[b]) += projected.segment<3>(3 * b);
      auto block = this->BlockRows.begin() + this->ColumnStart[columns[b]];
      const auto columnEnd = this->BlockRows.begin() + this->ColumnStart[columns[b] + 1];
      for (int a = 0; a <= b; ++a)
      {
        block = std::lower_bound(block, columnEnd, columns[a]);
        this->Blocks[block - this->BlockRows.begin()] += product.block<3, 3>(3 * a, 3 * b);
      }
    }
  }

  /// The upper triangle of the symmetric matrix, with `diagonal[k]` added to the three diagonal
  /// entries of vertex k.
  Eigen::SparseMatrix<double> UpperTriangle(const Eigen::VectorXd& diagonal) const
  {
    const int vertices = static_cast<int>(this->ColumnStart.size()) - 1;
    Eigen::SparseMatrix<double> matrix(3 * vertices, 3 * vertices);
    matrix.resizeNonZeros(9 * static_cast<Eigen::Index>(this->BlockRows.size()) - 3 * vertices);
    Eigen::Index entry = 0;
    // Column 3b + c holds rows 3a + r <= 3b + c.
    for (int b = 0; b < vertices; ++b)
    {
      for (int c = 0; c < 3; ++c)
      {
        matrix.outerIndexPtr()[3 * b + c] = static_cast<int>(entry);
        for (int k = this->ColumnStart[b]; k < this->ColumnStart[b + 1]; ++k)
        {
          const int a = this->BlockRows[k];
          for (int r = 0; r < (a == b ? c + 1 : 3); ++r)
          {
            matrix.innerIndexPtr()[entry] = 3 * a + r;
            matrix.valuePtr()[entry++] =
              this->Blocks[k](r, c) + (a == b && r == c ? diagonal[b] : 0.0);
          }
        }
      }
    }
    matrix.outerIndexPtr()[3 * vertices] = static_cast<int>(entry);
    return matrix;
  }

  const Eigen::VectorXd& GetRightHandSide() const { return this->RightHandSide; }

private:
  std::vector<int> ColumnStart;
  std::vector<int> BlockRows;
  std::vector<Eigen::Matrix3d> Blocks;
  Eigen::VectorXd RightHandSide;
};
// Each ROI vertex's one-ring and the least-squares fit of its transform to it: what the normal
// equations are assembled from, not needed once they are.
struct RingFits
{
  // Per ROI vertex: offsets into the ring arrays and into the fit coefficients.
  std::vector<int> Offsets;
  std::vector<int> RoiRows; // ROI row of each ring member, -1 if fixed
  Positions Rest;           // rest position of each ring member
  // The (s, h1, h2, h3) rows of the least-squares fit, (A_i^T A_i)^-1 A_i^T, per vertex.
  std::vector<Eigen::MatrixXd> Fits;
  // The constant part of each fit: (1, -fit of the rest ring) with s fixed, zero otherwise.
  std::vector<Eigen::Vector4d, Eigen::aligned_allocator<Eigen::Vector4d>> FitOffsets;

  // Fits the transform of ROI vertex `row` to its rest one-ring.
  void Fit(int row, bool allowScaling);
};

void RingFits::Fit(int row, bool allowScaling)
{
  const int begin = this->Offsets[row];
  const int size = this->Offsets[row + 1] - begin;
  // Centre on the vertex for conditioning; the translation absorbs the shift.
  Eigen::MatrixXd fitMatrix(3 * size, 7);
  for (int q = 0; q < size; ++q)
  {
    fitMatrix.middleRows<3>(3 * q) =
      FitBlock(this->Rest.row(begin + q) - this->Rest.row(begin));
  }
  this->Fits[row].setZero(4, 3 * size);
  this->FitOffsets[row].setZero();
  if (allowScaling)
  {
    this->Fits[row] = fitMatrix.completeOrthogonalDecomposition().pseudoInverse().topRows(4);
    return;
  }
  // s = 1: fit (h, t) to what the rest ring, unscaled, leaves over.
  const Eigen::MatrixXd fit =
    fitMatrix.rightCols<6>().completeOrthogonalDecomposition().pseudoInverse().topRows(3);
  this->Fits[row].bottomRows<3>() = fit;
  this->FitOffsets[row] << 1.0, -fit * fitMatrix.col(0);
}

// The one-rings of the ROI vertices (each vertex first, then its neighbours) and their fits.
RingFits FitRings(
  const SurfaceMesh& mesh, const EditRegion& region, bool allowScaling, const ParallelFor& loop)
{
  const int n = region.GetNumberOfVertices();
  std::vector<int> roiRow(mesh.GetNumberOfVertices(), -1);
  for (int row = 0; row < n; ++row)
  {
    roiRow[region.Vertices[row]] = row;
  }
  RingFits rings;
  rings.Offsets.assign(1, 0);
  std::vector<int> ringVertices;
  for (int row = 0; row < n; ++row)
  {
    const int v = region.Vertices[row];
    ringVertices.push_back(v);
    ringVertices.insert(ringVertices.end(), mesh.NeighborsBegin(v), mesh.NeighborsEnd(v));
    rings.Offsets.push_back(static_cast<int>(ringVertices.size()));
  }
  rings.Rest.resize(static_cast<Eigen::Index>(ringVertices.size()), 3);
  for (std::size_t k = 0; k < ringVertices.size(); ++k)
  {
    rings.RoiRows.push_back(roiRow[ringVertices[k]]);
    rings.Rest.row(k) = mesh.GetPositions()[ringVertices[k]].transpose();
  }
  rings.Fits.resize(n);
  rings.FitOffsets.resize(n);
  loop(0, n, [&](int first, int last) {
    for (int row = first; row < last; ++row)
    {
      rings.Fit(row, allowScaling);
    }
  });
  return rings;
}

// The residual rows, per vertex (the paper's, Eq. 12) or per one-ring edge. All rows of ROI
// vertex `row` act on its ring (and, in the paper's form, on its operator row), so each vertex
// contributes a small dense block J^T J to the normal matrix, accumulated directly: forming A
// and A^T A as sparse products took half the setup and most of its memory. Each row is
// sum_c a_c v'_c - T_i(V') e = k with T_i(V') e = G(e) (Fits ring + offset).
class ResidualRows
{
public:
  ResidualRows(const SurfaceMesh& mesh, const EditRegion& region, const DeformationSystem& plain,
    const RingFits& rings, const ImplicitFormulation& formulation, LaplacianWeights weights)
    : Region(region)
    , Plain(plain)
    , Rings(rings)
    , PerEdge(formulation.PerEdge)
    , EdgeWeights(mesh, weights)
  {
    this->FindColumns();
  }

  /// Per ROI vertex, the ROI vertices its rows act on, sorted.
  const std::vector<std::vector<int>>& GetColumns() const { return this->Columns; }

  /// Adds every vertex's J^T J and J^T k: the products in parallel, a batch at a time; summing
  /// them is serial.
  void Accumulate(BlockNormalEquations& normal, const ParallelFor& loop) const
  {
    const int n = this->Region.GetNumberOfVertices();
    constexpr int batch = 2048;
    std::vector<Eigen::MatrixXd> products(std::min(n, batch));
    std::vector<Eigen::VectorXd> projections(products.size());
    for (int batchBegin = 0; batchBegin < n; batchBegin += batch)
    {
      const int batchEnd = std::min(n, batchBegin + batch);
      loop(batchBegin, batchEnd, [&](int first, int last) {
        VertexRows rows;
        for (int row = first; row < last; ++row)
        {
          this->Fill(row, rows);
          products[row - batchBegin].noalias() = rows.Jacobian.transpose() * rows.Jacobian;
          projections[row - batchBegin].noalias() = rows.Jacobian.transpose() * rows.Known;
        }
      });
      for (int row = batchBegin; row < batchEnd; ++row)
      {
        normal.Add(this->Columns[row], products[row - batchBegin], projections[row - batchBegin]);
      }
    }
  }

private:
  void FindColumns()
  {
    const auto& laplacian = this->Plain.GetRegionOperator();
    this->Columns.resize(this->Region.GetNumberOfVertices());
    for (int row = 0; row < this->Region.GetNumberOfVertices(); ++row)
    {
      std::vector<int>& columns = this->Columns[row];
      for (int k = this->Rings.Offsets[row]; k < this->Rings.Offsets[row + 1]; ++k)
      {
        if (this->Rings.RoiRows[k] >= 0)
        {
          columns.push_back(this->Rings.RoiRows[k]);
        }
      }
      if (!this->PerEdge)
      {
        for (Eigen::SparseMatrix<double, Eigen::RowMajor>::InnerIterator it(laplacian, row); it; ++it)
        {
          columns.push_back(static_cast<int>(it.col()));
        }
      }
      std::sort(columns.begin(), columns.end());
      columns.erase(std::unique(columns.begin(), columns.end()), columns.end());
    }
  }

  void Fill(int row, VertexRows& rows) const
  {
    if (!this->PerEdge)
    {
      // D(V')_i - T_i(V') delta_i = -fixed part.
      rows.Start(this->Columns[row], 3);
      const auto& laplacian = this->Plain.GetRegionOperator();
      for (Eigen::SparseMatrix<double, Eigen::RowMajor>::InnerIterator it(laplacian, row); it; ++it)
      {
        rows.Jacobian.block<3, 3>(0, 3 * rows.Column(static_cast<int>(it.col()))).diagonal().array() +=
          it.value();
      }
      rows.Known.head<3>() -= this->Plain.GetFixedPart().row(row).transpose();
      this->AddTransformTerm(
        row, 0, this->Plain.GetRestDifferentialCoordinates().row(row).transpose(), 1.0, rows);
      return;
    }
    // sqrt(w_ij) ((v'_i - v'_j) - T_i(V') (v_i - v_j)) = 0, with the row's weights.
    const RingFits& rings = this->Rings;
    const int begin = rings.Offsets[row];
    const int size = rings.Offsets[row + 1] - begin;
    rows.Start(this->Columns[row], 3 * (size - 1));
    const std::vector<double> weights = this->EdgeWeights.EdgeWeights(this->Region.Vertices[row]);
    double total = 0.0;
    for (double w : weights)
    {
      total += w;
    }
    for (int q = 1; q < size; ++q)
    {
      const double scale = std::sqrt(weights[q - 1] / total);
      const int equation = 3 * (q - 1);
      const int member = rings.RoiRows[begin + q];
      rows.Jacobian.block<3, 3>(equation, 3 * rows.Column(row)).diagonal().array() += scale;
      if (member >= 0)
      {
        rows.Jacobian.block<3, 3>(equation, 3 * rows.Column(member)).diagonal().array() -= scale;
      }
      else
      {
        rows.Known.segment<3>(equation) += scale * rings.Rest.row(begin + q).transpose();
      }
      this->AddTransformTerm(
        row, equation, (rings.Rest.row(begin) - rings.Rest.row(begin + q)).transpose(), scale, rows);
    }
  }

  // -scale T_i(V') e in the three rows from `equation`.
  void AddTransformTerm(
    int row, int equation, const Eigen::Vector3d& e, double scale, VertexRows& rows) const
  {
    const RingFits& rings = this->Rings;
    const int begin = rings.Offsets[row];
    const int size = rings.Offsets[row + 1] - begin;
    const Eigen::Matrix<double, 3, 4> apply = ApplyToDelta(e);
    const Eigen::MatrixXd transform = apply * rings.Fits[row];
    rows.Known.segment<3>(equation) += scale * apply * rings.FitOffsets[row];
    for (int q = 0; q < size; ++q)
    {
      const int member = rings.RoiRows[begin + q];
      const Eigen::Matrix3d block = scale * transform.middleCols<3>(3 * q);
      if (member < 0)
      {
        rows.Known.segment<3>(equation) += block * rings.Rest.row(begin + q).transpose();
        continue;
      }
      rows.Jacobian.block<3, 3>(equation, 3 * rows.Column(member)) -= block;
    }
  }

  const EditRegion& Region;
  const DeformationSystem& Plain;
  const RingFits& Rings;
  bool PerEdge;
  LaplacianOperator EdgeWeights;
  std::vector<std::vector<int>> Columns;
};
}

std::string ImplicitSimilaritySystem::Build(const SurfaceMesh& mesh, const EditRegion& region,
  const DeformationSystem& plain, const DeformationOptions& options,
  const ImplicitFormulation& formulation, const ParallelFor& loop)
{
  this->NumberOfVertices = region.GetNumberOfVertices();
  Eigen::SparseMatrix<double> normalMatrix;
  {
    // The rings and their fits are not needed by the factorization: its peak is lower without.
    const RingFits rings = FitRings(mesh, region, formulation.AllowScaling, loop);
    const ResidualRows residuals(mesh, region, plain, rings, formulation, options.Weights);
    BlockNormalEquations normal(residuals.GetColumns());
    residuals.Accumulate(normal, loop);
    normalMatrix = normal.UpperTriangle(plain.GetSquaredWeights());
    this->KnownRightHandSide = normal.GetRightHandSide();
  }
  this->Points = plain.GetPoints();
  if (!this->Points.IsEmpty())
  {
    this->Rest = plain.GetRestPositions();
    this->RestPoints = plain.GetRestPoints();
    std::vector<int> unknowns(this->NumberOfVertices);
    std::iota(unknowns.begin(), unknowns.end(), 0);
    this->Points.Weigh(options.PointWeight, normalMatrix);
    const std::string error = this->Points.AddToMatrix(normalMatrix, unknowns, 3);
    if (!error.empty())
    {
      return error;
    }
  }
  const std::string error = this->Factor.Factorize(normalMatrix, options.Backend, options.Ordering,
    options.MaximumFactorBytes, /*blockSize=*/3, options.Distributed);
  if (!error.empty())
  {
    return error;
  }
  this->ComputeResponses(plain);
  return {};
}

void ImplicitSimilaritySystem::ComputeResponses(const DeformationSystem& plain)
{
  // The rest solution and the responses, in one multi-column solve. Column 1 + 12 g + 4 c + j
  // holds the constraint term of entry (c, j) of group g's map.
  const int n = this->NumberOfVertices;
  const int groups = plain.GetNumberOfHandleGroups();
  Eigen::MatrixXd rhs = Eigen::MatrixXd::Zero(3 * n, 1 + 12 * groups);
  rhs.col(0) = this->KnownRightHandSide +
    Interleave(plain.ConstraintRightHandSide(std::vector<AffineMap>(groups, AffineMap::Zero())));
  for (int g = 0; g < groups; ++g)
  {
    const Eigen::MatrixXd basis = plain.HandleBasis(g);
    for (int c = 0; c < 3; ++c)
    {
      for (int j = 0; j < 4; ++j)
      {
        for (int k = 0; k < n; ++k)
        {
          rhs(3 * k + c, 1 + 12 * g + 4 * c + j) = basis(k, j);
        }
      }
    }
  }
  const Eigen::MatrixXd solution = this->Factor.Solve(rhs);
  this->RestSolution = solution.col(0);
  this->GroupResponses.resize(groups);
  for (int g = 0; g < groups; ++g)
  {
    this->GroupResponses[g] = solution.middleCols<12>(1 + 12 * g);
  }
}

Positions ImplicitSimilaritySystem::Solve(
  const std::vector<AffineMap>& handleMaps, const ParallelFor& loop, const Positions& pointTargets) const
{
  // Row blocks in parallel: the responses are 3n x 12 per group, too large to stay in cache,
  // so a move is bound by reading them. With points, the displacement from the rest shape:
  // the rest solution and the identity maps' responses give the rest back, and leave out.
  const bool displaced = !this->Points.IsEmpty();
  Positions positions(this->NumberOfVertices, 3);
  loop(0, this->NumberOfVertices, [&](int first, int last) {
    const Eigen::Index rows = 3 * static_cast<Eigen::Index>(last - first);
    Eigen::VectorXd solution = displaced ? Eigen::VectorXd::Zero(rows)
                                         : Eigen::VectorXd(this->RestSolution.segment(3 * first, rows));
    for (std::size_t g = 0; g < this->GroupResponses.size(); ++g)
    {
      Eigen::Matrix<double, 3, 4, Eigen::RowMajor> map =
        g < handleMaps.size() ? handleMaps[g] : AffineMap::Identity();
      if (displaced)
      {
        map -= AffineMap::Identity();
      }
      solution.noalias() += this->GroupResponses[g].middleRows(3 * first, rows) *
        Eigen::Map<const Eigen::Matrix<double, 12, 1>>(map.data());
    }
    positions.middleRows(first, last - first) = Deinterleave(solution);
  });
  if (displaced)
  {
    positions += this->Rest + this->SolvePoints(pointTargets, loop);
  }
  return positions;
}

Positions ImplicitSimilaritySystem::SolvePoints(const Positions& pointTargets, const ParallelFor& loop) const
{
  const Eigen::VectorXd rhs = Interleave(
    this->Points.RightHandSide(pointTargets - this->RestPoints, this->NumberOfVertices));
  return Deinterleave(this->Factor.Solve(rhs, loop));
}

AffineRows ImplicitSimilaritySystem::GetAffineRows(const std::vector<int>& rows) const
{
  // The unknowns are interleaved (x, y, z per vertex), and so are the responses' rows.
  const Eigen::Index groups = static_cast<Eigen::Index>(this->GroupResponses.size());
  AffineRows affine;
  affine.Offsets.resize(static_cast<Eigen::Index>(rows.size()), 3);
  affine.Responses.resize(3 * static_cast<Eigen::Index>(rows.size()), 12 * groups);
  for (std::size_t i = 0; i < rows.size(); ++i)
  {
    affine.Offsets.row(i) = this->RestSolution.segment<3>(3 * rows[i]).transpose();
    for (Eigen::Index g = 0; g < groups; ++g)
    {
      affine.Responses.block<3, 12>(3 * i, 12 * g) = this->GroupResponses[g].middleRows<3>(3 * rows[i]);
    }
  }
  return affine;
}

Positions ImplicitSimilaritySystem::SolveDirect(const DeformationSystem& plain,
  const std::vector<AffineMap>& handleMaps, const Positions& pointTargets) const
{
  if (!this->Points.IsEmpty())
  {
    const Positions pull = plain.ConstraintRightHandSide(handleMaps) -
      plain.ConstraintRightHandSide({}) +
      this->Points.RightHandSide(pointTargets - this->RestPoints, this->NumberOfVertices);
    return this->Rest + Deinterleave(this->Factor.Solve(Interleave(pull)));
  }
  const Eigen::VectorXd rhs =
    this->KnownRightHandSide + Interleave(plain.ConstraintRightHandSide(handleMaps));
  return Deinterleave(this->Factor.Solve(rhs));
}
}
