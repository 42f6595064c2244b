#include "AsRigidAsPossibleSolver.h"

#include "ClosestRotation.h"

#include <Eigen/Dense>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numeric>

namespace LaplacianEditing
{
namespace
{
Vector3 Apply(const AffineMap& map, const Vector3& p)
{
  return map.leftCols<3>() * p + map.col(3);
}

// A solve's iterations, each with its energy: whether the solve stops after it, converged
// (the energy fell by less than the tolerance per iteration over the last `window`, or
// `stalled`) or aborted through the progress callback. The energies and their count are the
// workspace's, so that a continued solve (ArapOptions::Continue) tests as the uncut one.
class IterationLog
{
public:
  IterationLog(double start, const ArapOptions& options, std::vector<double>* energies,
    ArapIterate::Workspace& work)
    : Options(options)
    , Energies(energies)
    , Recent(work.RecentEnergies)
    , Logged(work.LoggedIterations)
  {
    if (!options.Continue)
    {
      this->Logged = 0;
      this->Recent[0] = start;
    }
  }

  /// The number of the iteration the next Stop logs, counted from the uncut solve's start.
  int Next() const { return this->Logged + 1; }

  bool Stop(ArapResult& result, double energy, int window, bool stalled = false)
  {
    result.Energy = energy;
    ++result.Iterations;
    ++this->Logged;
    if (this->Energies)
    {
      this->Energies->push_back(energy);
    }
    const double decrease = this->Recent[(this->Logged - window) % this->Recent.size()] - energy;
    this->Recent[this->Logged % this->Recent.size()] = energy;
    if (stalled || (window > 0 && decrease <= this->Options.Tolerance * window * energy))
    {
      result.Converged = true;
      return true;
    }
    return this->Options.Progress &&
      !this->Options.Progress(static_cast<double>(result.Iterations) / this->Options.MaximumIterations);
  }

private:
  const ArapOptions& Options;
  std::vector<double>* Energies;
  std::array<double, ConvergenceWindow + 1>& Recent;
  int& Logged;
};

// Anderson acceleration's history: the last `size` differences of g and of the residual
// f = g - x, a ring of the workspace's columns, which a continued solve takes up.
class AndersonRing
{
public:
  AndersonRing(int size, Eigen::Index length, ArapIterate::Workspace& work, bool continues)
    : Size(size)
    , Length(length)
    , Stored(work.StoredDifferences)
    , Newest(work.NewestDifference)
    , HasPrevious(work.HasPrevious)
  {
    if (!continues || work.GDifferences.rows() != length || work.GDifferences.cols() != size)
    {
      work.GDifferences.resize(length, size);
      work.FDifferences.resize(length, size);
      this->Restart();
      this->HasPrevious = false;
    }
  }

  // `next` becomes g, mixed with the history when `accelerate` and there is one; returns
  // whether it mixed. Its passes over the iterates run through `loop`, in fixed blocks whose
  // partial sums add up in order, so that a result does not depend on the threads.
  bool Mix(const Eigen::MatrixXd& g, const Eigen::MatrixXd& x, bool accelerate,
    ArapIterate::Workspace& work, Eigen::MatrixXd& next, const ParallelFor& loop)
  {
    const bool accelerated = accelerate && this->HasPrevious;
    if (accelerated)
    {
      this->Newest = (this->Newest + 1) % this->Size;
      this->Stored = std::min(this->Stored + 1, this->Size);
    }
    next.resize(g.rows(), g.cols());
    work.Residual.resize(this->Length);
    work.PreviousG.resize(this->Length);
    work.PreviousF.resize(this->Length);
    constexpr Eigen::Index BlockLength = 4096;
    const int blocks = static_cast<int>((this->Length + BlockLength - 1) / BlockLength);
    auto inBlocks = [&](const std::function<void(int, Eigen::Index, Eigen::Index)>& body) {
      loop(0, blocks, [&](int first, int last) {
        for (int b = first; b < last; ++b)
        {
          const Eigen::Index begin = b * BlockLength;
          body(b, begin, std::min(BlockLength, this->Length - begin));
        }
      });
    };
    const double* gv = g.data();
    const double* xv = x.data();
    double* nextv = next.data();
    const int newest = this->Newest;
    inBlocks([&](int, Eigen::Index begin, Eigen::Index size) {
      for (Eigen::Index e = begin; e < begin + size; ++e)
      {
        const double f = gv[e] - xv[e];
        if (accelerated)
        {
          work.GDifferences(e, newest) = gv[e] - work.PreviousG[e];
          work.FDifferences(e, newest) = f - work.PreviousF[e];
        }
        work.Residual[e] = f;
        work.PreviousG[e] = gv[e];
        work.PreviousF[e] = f;
        nextv[e] = gv[e];
      }
    });
    this->HasPrevious = true;
    if (!accelerated)
    {
      return false;
    }
    // The mixing weights minimize |f - dF theta|: with at most History columns, through the
    // small Gram matrix (a QR of the tall dF costs tens of times more: performance.md); a
    // rank-revealing solve keeps nearly dependent differences harmless.
    const int stored = this->Stored;
    std::vector<Eigen::MatrixXd> grams(blocks);
    std::vector<Eigen::VectorXd> projections(blocks);
    inBlocks([&](int b, Eigen::Index begin, Eigen::Index size) {
      const auto dF = work.FDifferences.block(begin, 0, size, stored);
      grams[b] = dF.transpose() * dF;
      projections[b] = dF.transpose() * work.Residual.segment(begin, size);
    });
    Eigen::MatrixXd gram = Eigen::MatrixXd::Zero(stored, stored);
    Eigen::VectorXd projection = Eigen::VectorXd::Zero(stored);
    for (int b = 0; b < blocks; ++b)
    {
      gram += grams[b];
      projection += projections[b];
    }
    const Eigen::VectorXd theta = gram.completeOrthogonalDecomposition().solve(projection);
    inBlocks([&](int, Eigen::Index begin, Eigen::Index size) {
      Eigen::Map<Eigen::VectorXd>(nextv + begin, size).noalias() -=
        work.GDifferences.block(begin, 0, size, stored) * theta;
    });
    return true;
  }

  // Forgets the differences (after a step the safeguard rejected).
  void Restart()
  {
    this->Stored = 0;
    this->Newest = -1;
  }

private:
  int Size;
  Eigen::Index Length;
  int& Stored;
  int& Newest;
  bool& HasPrevious;
};
}

std::string AsRigidAsPossibleSolver::Build(const SurfaceMesh& mesh, const EditRegion& region,
  const DeformationOptions& options, const ParallelFor& loop)
{
  this->NumberOfROIVertices = region.GetNumberOfVertices();
  this->HandleGroups = region.HandleGroups;
  std::vector<int> patchRow;
  const std::vector<int> patchVertices = this->GrowPatch(mesh, region, patchRow);
  this->WeighEdges(mesh, patchVertices, patchRow, options.Weights, loop);
  this->FindRotationsAroundHandles();
  this->CoupleRotations(mesh, patchVertices, patchRow, options.RotationSmoothing, options.BendingLength);
  this->Points = PointConstraints();
  std::string error;
  if (options.Points)
  {
    std::vector<int> roiRow = patchRow;
    std::replace_if(roiRow.begin(), roiRow.end(),
      [this](int row) { return row >= this->NumberOfROIVertices; }, -1);
    error = this->Points.Build(*options.Points, roiRow);
  }
  error = error.empty() ? this->ChooseUnknowns(region) : error;
  if (!error.empty() || this->FreeRows.empty())
  {
    return error;
  }
  Eigen::SparseMatrix<double> matrix = this->AssembleFreeLaplacian(loop);
  this->Bending.Build(options.Bending, this->Rings(), this->UnknownOfPatch, matrix);
  this->PriorWeight = 0.0;
  if (!this->Points.IsEmpty())
  {
    this->RestPoints = this->Points.Evaluate(this->RestRows(this->NumberOfROIVertices));
    this->AddPrior(options.SplinePrior, matrix);
    this->Points.Weigh(options.PointWeight, matrix);
    error = this->Points.AddToMatrix(matrix, this->UnknownOfPatch, 1);
    if (!error.empty())
    {
      return error;
    }
  }
  this->Factor.SetManySolves(true); // a solve every iteration
  this->Factor.SetParallelFor(loop);
  return this->Factor.Factorize(matrix, options.Backend, options.Ordering,
    options.MaximumFactorBytes, 1, options.Distributed);
}

void AsRigidAsPossibleSolver::AddPrior(double weight, Eigen::SparseMatrix<double>& matrix)
{
  // Past ThinPlateSpline::MaximumLandmarks points, the spline's cubic cost would dominate, and
  // points that dense hold the surface without it; points that span no volume fix no spline.
  const int points = this->Points.GetNumberOfPoints();
  if (weight <= 0.0 || !this->Spline.Fit(this->RestPoints))
  {
    this->Spline = ThinPlateSpline();
    return;
  }
  this->PriorWeight = weight * matrix.diagonal().mean() * points / static_cast<double>(matrix.rows());
  for (Eigen::Index u = 0; u < matrix.cols(); ++u)
  {
    matrix.coeffRef(u, u) += this->PriorWeight;
  }
  this->FreeRest = this->FreePositions(this->RestRows(this->NumberOfROIVertices));
}

std::vector<int> AsRigidAsPossibleSolver::GrowPatch(
  const SurfaceMesh& mesh, const EditRegion& region, std::vector<int>& patchRow)
{
  // The patch: the ROI, its ring (the rest of the energy vertices), and the ring's ring.
  const int n = region.GetNumberOfVertices();
  std::vector<int> patchVertices = region.Vertices;
  patchRow.assign(mesh.GetNumberOfVertices(), -1);
  for (int k = 0; k < n; ++k)
  {
    patchRow[region.Vertices[k]] = k;
  }
  auto grow = [&](int begin, int end) {
    for (int k = begin; k < end; ++k)
    {
      const int v = patchVertices[k];
      for (const int* w = mesh.NeighborsBegin(v); w != mesh.NeighborsEnd(v); ++w)
      {
        if (patchRow[*w] < 0)
        {
          patchRow[*w] = static_cast<int>(patchVertices.size());
          patchVertices.push_back(*w);
        }
      }
    }
  };
  grow(0, n);
  this->NumberOfEnergyVertices = static_cast<int>(patchVertices.size());
  grow(n, this->NumberOfEnergyVertices);
  const int patchSize = static_cast<int>(patchVertices.size());
  this->RestVertices.resize(patchSize);
  Vector3 low = Vector3::Constant(std::numeric_limits<double>::infinity()), high = -low;
  for (int k = 0; k < patchSize; ++k)
  {
    this->RestVertices[k] = mesh.GetPositions()[patchVertices[k]];
    low = low.cwiseMin(this->RestVertices[k]);
    high = high.cwiseMax(this->RestVertices[k]);
  }
  this->RestExtent = patchSize > 0 ? (high - low).norm() : 0.0;
  return patchVertices;
}

Positions AsRigidAsPossibleSolver::RestRows(int count) const
{
  Positions rows(count, 3);
  for (int k = 0; k < count; ++k)
  {
    rows.row(k) = this->RestVertices[k].transpose();
  }
  return rows;
}

void AsRigidAsPossibleSolver::WeighEdges(const SurfaceMesh& mesh,
  const std::vector<int>& patchVertices, const std::vector<int>& patchRow, LaplacianWeights type,
  const ParallelFor& loop)
{
  // Symmetric weights: each edge's two one-sided weights averaged. The arrays are sized first
  // and filled in parallel: grown piecemeal, they took a third of the setup, mostly in page
  // faults.
  const LaplacianOperator laplacian(mesh, type);
  const int patchSize = static_cast<int>(patchVertices.size());
  std::vector<int> ringStart(patchSize + 1, 0);
  for (int row = 0; row < patchSize; ++row)
  {
    ringStart[row + 1] = ringStart[row] + mesh.GetValence(patchVertices[row]);
  }
  std::vector<double> oneSided(ringStart[patchSize]);
  loop(0, patchSize, [&](int first, int last) {
    for (int row = first; row < last; ++row)
    {
      const std::vector<double> weights = laplacian.EdgeWeights(patchVertices[row]);
      std::copy(weights.begin(), weights.end(), oneSided.begin() + ringStart[row]);
    }
  });
  const int energyVertices = this->NumberOfEnergyVertices;
  const std::size_t edges = ringStart[energyVertices];
  this->Offsets.assign(ringStart.begin(), ringStart.begin() + energyVertices + 1);
  this->Neighbors.resize(edges);
  this->Weights.resize(edges);
  loop(0, energyVertices, [&](int first, int last) {
    for (int i = first; i < last; ++i)
    {
      const int v = patchVertices[i];
      const int* ring = mesh.NeighborsBegin(v);
      for (int k = 0; k < mesh.GetValence(v); ++k)
      {
        const int j = patchRow[ring[k]];
        const int* back = mesh.NeighborsBegin(ring[k]);
        const auto slot = std::lower_bound(back, mesh.NeighborsEnd(ring[k]), v) - back;
        const int edge = ringStart[i] + k;
        this->Neighbors[edge] = j;
        this->Weights[edge] = 0.5 * (oneSided[ringStart[i] + k] + oneSided[ringStart[j] + slot]);
      }
    }
  });
  this->RestScale = 0.0;
  this->RestEdgeSums.assign(energyVertices, Vector3::Zero());
  for (int i = 0; i < energyVertices; ++i)
  {
    for (int edge = this->Offsets[i]; edge < this->Offsets[i + 1]; ++edge)
    {
      this->RestScale += this->Weights[edge] * this->RestEdge(i, edge).squaredNorm();
      this->RestEdgeSums[i] += this->Weights[edge] * this->RestEdge(i, edge);
    }
  }
}

void AsRigidAsPossibleSolver::CoupleRotations(const SurfaceMesh& mesh,
  const std::vector<int>& patchVertices, const std::vector<int>& patchRow, double smoothing,
  double bendingLength)
{
  this->RotationCoupling.clear();
  this->BendingRelief.clear();
  this->ColorOffsets.clear();
  this->ColoredVertices.clear();
  if (smoothing > 0.0)
  {
    this->SmoothRotations(mesh, patchVertices, patchRow, smoothing);
  }
  if (bendingLength > 0.0)
  {
    this->BendingRelief.assign(this->Neighbors.size(), 0.0);
    for (int i = 0; i < this->NumberOfEnergyVertices; ++i)
    {
      for (int k = this->Offsets[i]; k < this->Offsets[i + 1]; ++k)
      {
        const double scale = std::min(1.0, bendingLength * bendingLength / this->RestEdge(i, k).squaredNorm());
        this->BendingRelief[k] =
          this->Neighbors[k] < this->NumberOfEnergyVertices ? 0.5 * (1.0 - scale) * this->Weights[k] : 0.0;
      }
    }
    if (std::all_of(this->BendingRelief.begin(), this->BendingRelief.end(), [](double r) { return r == 0.0; }))
    {
      this->BendingRelief.clear(); // every edge as short as the fine ones: plain ARAP
    }
  }
  if (this->RotationCoupling.empty() && this->BendingRelief.empty())
  {
    return;
  }
  // Greedy colors, each vertex the first its earlier neighbours leave free, then the vertices
  // bucketed by color.
  std::vector<int> colors(this->NumberOfEnergyVertices, 0);
  int numberOfColors = 0;
  for (int i = 0; i < this->NumberOfEnergyVertices; ++i)
  {
    std::vector<char> taken(numberOfColors + 1, 0);
    for (int k = this->Offsets[i]; k < this->Offsets[i + 1]; ++k)
    {
      if (this->Neighbors[k] < i)
      {
        taken[colors[this->Neighbors[k]]] = 1;
      }
    }
    colors[i] = static_cast<int>(std::find(taken.begin(), taken.end(), 0) - taken.begin());
    numberOfColors = std::max(numberOfColors, colors[i] + 1);
  }
  this->ColorOffsets.assign(numberOfColors + 1, 0);
  for (int color : colors)
  {
    ++this->ColorOffsets[color + 1];
  }
  std::partial_sum(this->ColorOffsets.begin(), this->ColorOffsets.end(), this->ColorOffsets.begin());
  std::vector<int> next(this->ColorOffsets.begin(), this->ColorOffsets.end() - 1);
  this->ColoredVertices.resize(this->NumberOfEnergyVertices);
  for (int i = 0; i < this->NumberOfEnergyVertices; ++i)
  {
    this->ColoredVertices[next[colors[i]]++] = i;
  }
}

void AsRigidAsPossibleSolver::SmoothRotations(const SurfaceMesh& mesh,
  const std::vector<int>& patchVertices, const std::vector<int>& patchRow, double smoothing)
{
  // The ROI's area: each triangle with an ROI vertex, counted at the first of them.
  const int n = this->NumberOfROIVertices;
  const std::vector<Vector3>& p = mesh.GetPositions();
  double area = 0.0;
  for (int k = 0; k < n; ++k)
  {
    for (const int* t = mesh.TrianglesBegin(patchVertices[k]); t != mesh.TrianglesEnd(patchVertices[k]); ++t)
    {
      const std::array<int, 3>& triangle = mesh.GetTriangles()[*t];
      const bool first = std::none_of(triangle.begin(), triangle.end(), [&](int v) {
        const int row = patchRow[v];
        return row >= 0 && row < k;
      });
      if (first)
      {
        area += 0.5 * (p[triangle[1]] - p[triangle[0]]).cross(p[triangle[2]] - p[triangle[0]]).norm();
      }
    }
  }
  const double scale = 0.5 * smoothing * area;
  auto valence = [this](int i) { return this->Offsets[i + 1] - this->Offsets[i]; };
  this->RotationCoupling.assign(this->Neighbors.size(), 0.0);
  for (int i = 0; i < this->NumberOfEnergyVertices; ++i)
  {
    for (int k = this->Offsets[i]; k < this->Offsets[i + 1]; ++k)
    {
      const int j = this->Neighbors[k];
      if (j < this->NumberOfEnergyVertices)
      {
        this->RotationCoupling[k] = scale * (1.0 / valence(i) + 1.0 / valence(j));
      }
    }
  }
}

void AsRigidAsPossibleSolver::FindRotationsAroundHandles()
{
  const int n = this->NumberOfROIVertices;
  auto isHandle = [&](int row) { return row < n && this->HandleGroups[row] >= 0; };
  this->AroundHandles.clear();
  for (int i = 0; i < this->NumberOfEnergyVertices; ++i)
  {
    bool touches = isHandle(i);
    for (int k = this->Offsets[i]; k < this->Offsets[i + 1] && !touches; ++k)
    {
      touches = isHandle(this->Neighbors[k]);
    }
    if (touches)
    {
      this->AroundHandles.push_back(i);
    }
  }
}

std::string AsRigidAsPossibleSolver::ChooseUnknowns(const EditRegion& region)
{
  // Unknowns: the ROI without its handles.
  this->FreeRows.clear();
  this->UnknownOfPatch.assign(this->RestVertices.size(), -1);
  for (int k = 0; k < this->NumberOfROIVertices; ++k)
  {
    if (region.Roles[k] != VertexRole::Handle)
    {
      this->UnknownOfPatch[k] = static_cast<int>(this->FreeRows.size());
      this->FreeRows.push_back(k);
    }
  }
  // Every connected part of the unknowns must reach a known value or a point, or nothing
  // holds it.
  std::vector<char> held(this->FreeRows.size(), 0);
  std::vector<int> stack;
  for (const auto& corners : this->Points.GetRows())
  {
    for (const int row : corners)
    {
      const int u = this->UnknownOfPatch[row];
      if (u >= 0 && !held[u])
      {
        held[u] = 1;
        stack.push_back(u);
      }
    }
  }
  for (std::size_t u = 0; u < this->FreeRows.size(); ++u)
  {
    const int i = this->FreeRows[u];
    for (int k = this->Offsets[i]; k < this->Offsets[i + 1] && !held[u]; ++k)
    {
      if (this->UnknownOfPatch[this->Neighbors[k]] < 0)
      {
        held[u] = 1;
        stack.push_back(static_cast<int>(u));
      }
    }
  }
  while (!stack.empty())
  {
    const int i = this->FreeRows[stack.back()];
    stack.pop_back();
    for (int k = this->Offsets[i]; k < this->Offsets[i + 1]; ++k)
    {
      const int u = this->UnknownOfPatch[this->Neighbors[k]];
      if (u >= 0 && !held[u])
      {
        held[u] = 1;
        stack.push_back(u);
      }
    }
  }
  if (std::find(held.begin(), held.end(), 0) != held.end())
  {
    return "in the as-rigid-as-possible mode every connected part of the region of interest must "
           "touch a handle, a landmark or the fixed part: make the ROI smaller than its component";
  }
  return {};
}

Eigen::SparseMatrix<double> AsRigidAsPossibleSolver::AssembleFreeLaplacian(const ParallelFor& loop) const
{
  // The upper triangle, column by column (rows sorted, the diagonal last), assembled in place.
  // Column u holds the unknowns of u's ring that come before u.
  const int free = static_cast<int>(this->FreeRows.size());
  auto aboveOf = [this](int u, int k) {
    const int other = this->UnknownOfPatch[this->Neighbors[k]];
    return other >= 0 && other < u ? other : -1;
  };
  std::vector<int> columnStart(free + 1, 0);
  for (int u = 0; u < free; ++u)
  {
    const int i = this->FreeRows[u];
    int above = 0;
    for (int k = this->Offsets[i]; k < this->Offsets[i + 1]; ++k)
    {
      above += aboveOf(u, k) >= 0 ? 1 : 0;
    }
    columnStart[u + 1] = columnStart[u] + above + 1;
  }
  Eigen::SparseMatrix<double> laplacian(free, free);
  laplacian.resizeNonZeros(columnStart[free]);
  std::copy(columnStart.begin(), columnStart.end(), laplacian.outerIndexPtr());
  loop(0, free, [&](int first, int last) {
    std::vector<std::pair<int, double>> column;
    for (int u = first; u < last; ++u)
    {
      const int i = this->FreeRows[u];
      double diagonal = 0.0;
      column.clear();
      for (int k = this->Offsets[i]; k < this->Offsets[i + 1]; ++k)
      {
        diagonal += this->Weights[k];
        const int other = aboveOf(u, k);
        if (other >= 0)
        {
          column.emplace_back(other, -this->Weights[k]);
        }
      }
      std::sort(column.begin(), column.end());
      column.emplace_back(u, diagonal);
      for (std::size_t e = 0; e < column.size(); ++e)
      {
        laplacian.innerIndexPtr()[columnStart[u] + e] = column[e].first;
        laplacian.valuePtr()[columnStart[u] + e] = column[e].second;
      }
    }
  });
  return laplacian;
}

void AsRigidAsPossibleSolver::Patch(
  const Positions& roiPositions, std::vector<Vector3>& patch, const ParallelFor& loop) const
{
  patch.resize(this->RestVertices.size());
  loop(0, static_cast<int>(this->RestVertices.size()), [&](int first, int last) {
    for (int k = first; k < last; ++k)
    {
      patch[k] = k < this->NumberOfROIVertices ? Vector3(roiPositions.row(k).transpose()) : this->RestVertices[k];
    }
  });
}

double AsRigidAsPossibleSolver::Rotate(const std::vector<Vector3>& patch,
  std::vector<Eigen::Matrix3d>& rotations, Quaternions& quaternions, ArapIterate::Workspace& work,
  const ParallelFor& loop, const std::vector<int>* only) const
{
  rotations.resize(this->NumberOfEnergyVertices);
  const bool seed = static_cast<int>(quaternions.size()) != this->NumberOfEnergyVertices;
  quaternions.resize(this->NumberOfEnergyVertices);
  if (!this->RotationCoupling.empty() || !this->BendingRelief.empty())
  {
    return this->RotateCoupled(patch, rotations, quaternions, work, loop, seed);
  }
  std::vector<double>& residuals = work.Residuals;
  residuals.resize(this->NumberOfEnergyVertices);
  only = seed ? nullptr : only; // rotations with no history are seeded everywhere
  const int count = only ? static_cast<int>(only->size()) : this->NumberOfEnergyVertices;
  loop(0, count, [&](int first, int last) {
    // A block at a time: the rings' covariances, their rotations refined together (vectorized
    // across the block), then the residuals while the rings are still in cache.
    constexpr int Block = 16;
    Eigen::Matrix3d deformations[Block];
    Eigen::Quaterniond blockRotations[Block];
    bool converged[Block];
    for (int begin = first; begin < last; begin += Block)
    {
      const int size = std::min(Block, last - begin);
      for (int b = 0; b < size; ++b)
      {
        const int i = only ? (*only)[begin + b] : begin + b;
        deformations[b] = this->Deformation(patch, i);
        blockRotations[b] = quaternions[i];
      }
      if (!seed)
      {
        RefineClosestRotations(deformations, blockRotations, converged, size);
      }
      for (int b = 0; b < size; ++b)
      {
        const int i = only ? (*only)[begin + b] : begin + b;
        // Exact rotations, so that the iterate is a function of the points alone (to 1e-13).
        if (seed || !converged[b])
        {
          blockRotations[b] = ClosestRotation(deformations[b]);
          RefineClosestRotation(deformations[b], blockRotations[b]);
        }
        quaternions[i] = blockRotations[b];
        rotations[i] = blockRotations[b].toRotationMatrix();
        residuals[i] = this->Residual(patch, i, rotations[i]);
      }
    }
  });
  return this->SumResiduals(residuals);
}

double AsRigidAsPossibleSolver::SumResiduals(const std::vector<double>& residuals) const
{
  double energy = 0.0;
  for (double r : residuals)
  {
    energy += r;
  }
  return this->RestScale > 0.0 ? energy / this->RestScale : 0.0;
}

Eigen::Matrix3d AsRigidAsPossibleSolver::Deformation(const std::vector<Vector3>& patch, int i) const
{
  // The covariance sum w e e'^T is S^T for the deformation S mapping e to e'.
  Eigen::Matrix3d deformation = Eigen::Matrix3d::Zero();
  for (int k = this->Offsets[i]; k < this->Offsets[i + 1]; ++k)
  {
    deformation.noalias() +=
      this->Weights[k] * (patch[i] - patch[this->Neighbors[k]]) * this->RestEdge(i, k).transpose();
  }
  if (!this->Bending.IsEmpty())
  {
    deformation.noalias() += (2.0 * this->Bending.GetCoefficient(i)) * this->DeformedEdgeSum(patch, i) *
      this->RestEdgeSums[i].transpose();
  }
  return deformation;
}

double AsRigidAsPossibleSolver::RotateCoupled(const std::vector<Vector3>& patch,
  std::vector<Eigen::Matrix3d>& rotations, Quaternions& quaternions, ArapIterate::Workspace& work,
  const ParallelFor& loop, bool seed) const
{
  // The rings' covariances once, seeded rotations where there is no history, then Gauss-Seidel
  // sweeps a color at a time: no two vertices of a color are neighbours, so each color's
  // rotations are fitted in parallel, each exactly against its neighbours' latest.
  const int count = this->NumberOfEnergyVertices;
  std::vector<Eigen::Matrix3d>& deformations = work.Deformations;
  deformations.resize(count);
  std::vector<double>& residuals = work.Residuals;
  residuals.resize(count);
  loop(0, count, [&](int first, int last) {
    for (int i = first; i < last; ++i)
    {
      deformations[i] = this->Deformation(patch, i);
      if (seed)
      {
        quaternions[i] = ClosestRotation(deformations[i]);
        RefineClosestRotation(deformations[i], quaternions[i]);
      }
      rotations[i] = quaternions[i].toRotationMatrix();
    }
  });
  // Smoothed rotations spread a turn one ring a sweep; the bending relief alone only corrects
  // each ring's rotation for its neighbours', which one sweep does.
  const int sweeps = this->RotationCoupling.empty() ? 1 : CoupledSweeps;
  for (int sweep = 0; sweep < sweeps; ++sweep)
  {
    for (std::size_t color = 0; color + 1 < this->ColorOffsets.size(); ++color)
    {
      loop(this->ColorOffsets[color], this->ColorOffsets[color + 1], [&](int first, int last) {
        // A block at a time, the rotations refined together (vectorized across the block).
        constexpr int Block = 16;
        Eigen::Matrix3d coupled[Block];
        Eigen::Quaterniond blockRotations[Block];
        bool converged[Block];
        for (int begin = first; begin < last; begin += Block)
        {
          const int size = std::min(Block, last - begin);
          for (int b = 0; b < size; ++b)
          {
            const int i = this->ColoredVertices[begin + b];
            coupled[b] = deformations[i];
            for (int k = this->Offsets[i]; k < this->Offsets[i + 1]; ++k)
            {
              const Eigen::Matrix3d& neighbor = rotations[this->Neighbors[k]];
              if (!this->RotationCoupling.empty() && this->RotationCoupling[k] > 0.0)
              {
                coupled[b] += this->RotationCoupling[k] * neighbor;
              }
              if (!this->BendingRelief.empty() && this->BendingRelief[k] > 0.0)
              {
                const Vector3 edge = this->RestEdge(i, k);
                coupled[b].noalias() -= this->BendingRelief[k] * (neighbor * edge) * edge.transpose();
              }
            }
            blockRotations[b] = quaternions[i];
          }
          RefineClosestRotations(coupled, blockRotations, converged, size);
          for (int b = 0; b < size; ++b)
          {
            const int i = this->ColoredVertices[begin + b];
            if (!converged[b])
            {
              blockRotations[b] = ClosestRotation(coupled[b]);
              RefineClosestRotation(coupled[b], blockRotations[b]);
            }
            quaternions[i] = blockRotations[b];
            rotations[i] = blockRotations[b].toRotationMatrix();
          }
        }
      });
    }
  }
  loop(0, count, [&](int first, int last) {
    for (int i = first; i < last; ++i)
    {
      residuals[i] = this->Residual(patch, i, rotations[i]) + this->CouplingResidual(rotations, i);
    }
  });
  return this->SumResiduals(residuals);
}

double AsRigidAsPossibleSolver::CouplingResidual(const std::vector<Eigen::Matrix3d>& rotations, int i) const
{
  // Each edge's share: half of the coupling, minus half of the relief.
  double residual = 0.0;
  for (int k = this->Offsets[i]; k < this->Offsets[i + 1]; ++k)
  {
    const int j = this->Neighbors[k];
    if (!this->RotationCoupling.empty() && this->RotationCoupling[k] > 0.0)
    {
      residual += 0.5 * this->RotationCoupling[k] * (rotations[i] - rotations[j]).squaredNorm();
    }
    if (!this->BendingRelief.empty() && this->BendingRelief[k] > 0.0)
    {
      residual -= 0.5 * this->BendingRelief[k] * ((rotations[i] - rotations[j]) * this->RestEdge(i, k)).squaredNorm();
    }
  }
  return residual;
}

Vector3 AsRigidAsPossibleSolver::DeformedEdgeSum(const std::vector<Vector3>& patch, int i) const
{
  Vector3 sum = Vector3::Zero();
  for (int k = this->Offsets[i]; k < this->Offsets[i + 1]; ++k)
  {
    sum += this->Weights[k] * (patch[i] - patch[this->Neighbors[k]]);
  }
  return sum;
}

double AsRigidAsPossibleSolver::Residual(
  const std::vector<Vector3>& patch, int i, const Eigen::Matrix3d& rotation) const
{
  double residual = 0.0;
  for (int k = this->Offsets[i]; k < this->Offsets[i + 1]; ++k)
  {
    residual += this->Weights[k] *
      (patch[i] - patch[this->Neighbors[k]] - rotation * this->RestEdge(i, k)).squaredNorm();
  }
  if (!this->Bending.IsEmpty())
  {
    residual += 2.0 * this->Bending.GetCoefficient(i) *
      (this->DeformedEdgeSum(patch, i) - rotation * this->RestEdgeSums[i]).squaredNorm();
  }
  return residual;
}

Eigen::MatrixXd AsRigidAsPossibleSolver::Global(const std::vector<Eigen::Matrix3d>& rotations,
  const std::vector<Vector3>& patch, ArapIterate::Workspace& work, const ParallelFor& loop,
  const PointTargets* points) const
{
  // Solved for the displacement from the rest shape, whose right-hand side vanishes where the
  // rotations are the identity and the known rows at rest: the rest comes back to rounding of
  // the edges' size, not of the coordinates'.
  const int free = static_cast<int>(this->FreeRows.size());
  auto& rhs = work.RightHandSide;
  rhs.resize(free, 3);
  loop(0, free, [&](int first, int last) {
    for (int u = first; u < last; ++u)
    {
      // sum_j w_ij ((R_i + R_j) / 2 - I) e_ij, with R_i's part from the ring's rest sum.
      const int i = this->FreeRows[u];
      const Vector3& sum = this->RestEdgeSums[i];
      Vector3 b = rotations[i] * sum - sum;
      Vector3 turned = Vector3::Zero();
      for (int k = this->Offsets[i]; k < this->Offsets[i + 1]; ++k)
      {
        const int j = this->Neighbors[k];
        turned.noalias() += this->Weights[k] * (rotations[j] * this->RestEdge(i, k));
        if (this->UnknownOfPatch[j] < 0)
        {
          b += (2.0 * this->Weights[k]) * (patch[j] - this->RestVertices[j]);
        }
      }
      rhs.row(u) = 0.5 * (b + (turned - sum)).transpose();
    }
  });
  if (!this->Bending.IsEmpty())
  {
    this->Bending.AddToRightHandSide(
      this->Rings(), this->UnknownOfPatch, rotations, patch, this->RestVertices, rhs);
  }
  if (this->PriorWeight > 0.0)
  {
    rhs += this->PriorWeight * work.Prior;
  }
  if (this->Points.IsEmpty())
  {
    // The free rows straight from the displacements, in parallel: the whole ROI is for Fit.
    const Eigen::MatrixXd displacement = this->Factor.Solve(rhs, loop);
    Eigen::MatrixXd g(free, 3);
    loop(0, free, [&](int first, int last) {
      for (int u = first; u < last; ++u)
      {
        g.row(u) = this->RestVertices[this->FreeRows[u]].transpose() + displacement.row(u);
      }
    });
    return g;
  }
  Positions roi(this->NumberOfROIVertices, 3);
  for (int k = 0; k < this->NumberOfROIVertices; ++k)
  {
    roi.row(k) = patch[k].transpose();
  }
  // The points' pull on the free rows, met exactly or softly (PointConstraints::Fit).
  auto solve = [&](const Positions& targets) {
    Eigen::MatrixXd withPull = rhs;
    const Positions pull =
      this->Points.RightHandSide(targets - this->RestPoints, this->NumberOfROIVertices);
    for (int u = 0; u < free; ++u)
    {
      withPull.row(u) += pull.row(this->FreeRows[u]);
    }
    const Eigen::MatrixXd displacement = this->Factor.Solve(withPull, loop);
    for (int u = 0; u < free; ++u)
    {
      roi.row(this->FreeRows[u]) = this->RestVertices[this->FreeRows[u]].transpose() + displacement.row(u);
    }
    return roi;
  };
  // Without targets, the points stay where the rest shape has them.
  const PointTargets atRest{ this->RestPoints, false };
  Positions solution;
  double miss = 0.0;
  this->Points.Fit(solve, points ? *points : atRest, work.PointCorrection, solution, miss);
  return this->FreePositions(solution);
}

double AsRigidAsPossibleSolver::PullEnergy(const Positions& roiPositions,
  const PointTargets* points, const ArapIterate::Workspace& work) const
{
  if (this->RestScale <= 0.0)
  {
    return 0.0;
  }
  double energy = 0.0;
  if (!this->Points.IsEmpty() && points && !points->Exact)
  {
    energy += 2.0 * this->Points.GetSquaredWeight() *
      this->Points.PulledSquaredMiss(roiPositions, points->Targets);
  }
  if (this->PriorWeight > 0.0)
  {
    const Eigen::MatrixXd displacement = this->FreePositions(roiPositions) - this->FreeRest;
    energy += 2.0 * this->PriorWeight * (displacement - work.Prior).squaredNorm();
  }
  return energy / this->RestScale;
}

void AsRigidAsPossibleSolver::UpdatePrior(
  const PointTargets* points, ArapIterate::Workspace& work, const ParallelFor& loop) const
{
  if (this->PriorWeight <= 0.0)
  {
    return;
  }
  const Positions& targets = points ? points->Targets : this->RestPoints;
  std::vector<int> moved;
  if (work.Prior.rows() == static_cast<Eigen::Index>(this->FreeRows.size()) &&
    work.PriorTargets.rows() == targets.rows())
  {
    for (Eigen::Index p = 0; p < targets.rows(); ++p)
    {
      if (work.PriorTargets.row(p) != targets.row(p))
      {
        moved.push_back(static_cast<int>(p));
      }
    }
    if (moved.empty())
    {
      return;
    }
  }
  // The spline is linear in the displacements: a few points moved (a drag's) move the prior by
  // their cardinal functions. Each costs what a refit costs, once: a drag's later frames then
  // cost O(vertices) instead of a refit's O(landmarks^3).
  constexpr std::size_t RememberedCardinals = 4;
  if (moved.empty() || moved.size() > RememberedCardinals)
  {
    work.Prior = this->Spline.Displace(targets - this->RestPoints, this->FreeRest, loop);
    work.PriorTargets = targets;
    return;
  }
  for (const int p : moved)
  {
    auto& cardinals = work.PriorCardinals;
    auto known = std::find_if(cardinals.begin(), cardinals.end(),
      [p](const std::pair<int, Eigen::VectorXd>& cardinal) { return cardinal.first == p; });
    if (known == cardinals.end())
    {
      if (cardinals.size() == RememberedCardinals)
      {
        cardinals.erase(cardinals.begin());
      }
      cardinals.emplace_back(p, this->Spline.Cardinal(p, this->FreeRest, loop));
      known = cardinals.end() - 1;
    }
    work.Prior += known->second * (targets.row(p) - work.PriorTargets.row(p));
  }
  work.PriorTargets = targets;
}

ArapResult AsRigidAsPossibleSolver::Solve(const std::vector<AffineMap>& handleMaps,
  ArapIterate& iterate, const ArapOptions& options, const ParallelFor& loop,
  std::vector<double>* energies, const PointTargets* points) const
{
  ArapIterate::Workspace& work = iterate.Work;
  // A solve that continues the last one (its rotations still fit the points) with moved
  // handles may extrapolate; otherwise only the handle rows move between solves, and the first
  // local step redoes only the rotations around the handles (the others would come out the same).
  const bool continues = work.RotationsFitPoints;
  const bool extrapolate = this->Extrapolate(handleMaps, points, iterate, options);
  this->UpdatePrior(points, work, loop);
  ArapResult result;
  // An extrapolated start moves its rotations on with its points instead of fitting them: the
  // global step needs only rotations, and no test reads the start's energy (its first
  // iteration is never accelerated and never tested). That saves a third of a drag step's
  // local steps.
  bool rotationsMovedOn = false;
  if (extrapolate && !this->FreeRows.empty())
  {
    this->PlaceHandles(handleMaps, iterate, loop);
    rotationsMovedOn = this->ExtrapolateRotations(iterate, loop);
  }
  if (rotationsMovedOn)
  {
    result.Energy = std::numeric_limits<double>::infinity();
  }
  else
  {
    result.Energy = this->LocalStep(handleMaps, iterate, loop, continues && !extrapolate) +
      this->PullEnergy(iterate.Points, points, work);
  }
  if (this->FreeRows.empty() || options.MaximumIterations <= 0)
  {
    return result;
  }
  if (options.Newton && !extrapolate && this->HasPlainEnergy())
  {
    return this->SolveNewton(iterate, options, loop, energies, result);
  }
  // Anderson acceleration on the fixed point x -> Global(Local(x)), over flattened positions.
  AndersonRing ring(std::max(options.History, 1), 3 * static_cast<Eigen::Index>(this->FreeRows.size()),
    work, options.Continue);
  Eigen::MatrixXd x = this->FreePositions(iterate.Points);
  Eigen::MatrixXd next(this->FreeRows.size(), 3);
  IterationLog log(result.Energy, options, energies, work);
  for (int iteration = 0; iteration < options.MaximumIterations; ++iteration)
  {
    const Eigen::MatrixXd g = this->Global(work.Rotations, work.Patch, work, loop, points);
    const bool accelerated = ring.Mix(g, x, options.Accelerate, work, next, loop);
    double energy = this->Evaluate(next, iterate, loop) + this->PullEnergy(work.Candidate, points, work);
    if (energy > result.Energy && accelerated)
    {
      // The accelerated iterate did not lower the energy: take the plain one, start over.
      next = g;
      energy = this->Evaluate(next, iterate, loop) + this->PullEnergy(work.Candidate, points, work);
      ring.Restart();
    }
    iterate.Points.swap(work.Candidate);
    work.Rotations.swap(work.CandidateRotations);
    iterate.Rotations.swap(work.CandidateQuaternions);
    x.swap(next); // Mix overwrites next
    // An extrapolated solve does not stop on its first iteration: that decrease, from a guess
    // moved on by the last change, does not show what is left, and the next extrapolation
    // would double it (drag steps of 1 iteration were followed by steps of 5 to 11).
    // A solve from afar tests the last iterations together: Anderson's accelerated steps
    // alternate long and short ones, and a short one says little (a 60-degree bend of
    // bumps.obj stopped at 1.7 times the converged energy on its 7th iteration's 5e-4). A drag
    // step, which starts near its result, tests its last iteration, after the first.
    const int done = log.Next();
    if (log.Stop(result, energy, extrapolate ? (done >= 2 ? 1 : 0) : std::min(done, ConvergenceWindow)))
    {
      break;
    }
  }
  return result;
}

bool AsRigidAsPossibleSolver::Extrapolate(const std::vector<AffineMap>& handleMaps,
  const PointTargets* targets, ArapIterate& iterate, const ArapOptions& options) const
{
  // A solve that follows one which barely moved (the first move after a setup) has nothing to
  // extrapolate: it starts from afar, as a jump.
  Positions& points = iterate.Points;
  const Positions noTargets;
  const Positions& pointTargets = targets ? targets->Targets : noTargets;
  const bool targetsMoved = pointTargets.rows() != iterate.BeforeTargets.rows() ||
    (pointTargets.array() != iterate.BeforeTargets.array()).any();
  const bool extrapolate = iterate.Work.RotationsFitPoints && options.Extrapolate &&
    options.MaximumIterations > 0 && iterate.Before.rows() == points.rows() &&
    (handleMaps != iterate.BeforeMaps || targetsMoved) &&
    (points - iterate.Before).cwiseAbs().maxCoeff() > 1e-9 * this->RestExtent;
  iterate.BeforeMaps = handleMaps;
  iterate.BeforeTargets = pointTargets;
  if (extrapolate)
  {
    iterate.Work.Candidate = points;
    points += points - iterate.Before;
    iterate.Before.swap(iterate.Work.Candidate);
    // BeforeRotations move on in ExtrapolateRotations.
  }
  else
  {
    iterate.Before = points;
    iterate.BeforeRotations.clear();
    if (iterate.Work.RotationsFitPoints)
    {
      iterate.BeforeRotations = iterate.Rotations;
    }
  }
  return extrapolate;
}

bool AsRigidAsPossibleSolver::ExtrapolateRotations(ArapIterate& iterate, const ParallelFor& loop) const
{
  Quaternions& rotations = iterate.Rotations;
  Quaternions& before = iterate.BeforeRotations;
  const int count = static_cast<int>(rotations.size());
  if (count != this->NumberOfEnergyVertices || before.size() != rotations.size())
  {
    before = rotations;
    return false;
  }
  std::vector<Eigen::Matrix3d>& matrices = iterate.Work.Rotations;
  matrices.resize(count);
  loop(0, count, [&](int first, int last) {
    for (int i = first; i < last; ++i)
    {
      const Eigen::Quaterniond q = rotations[i];
      // q and -q are one rotation: step from the representative nearer q.
      const double sign = q.dot(before[i]) < 0.0 ? -1.0 : 1.0;
      Eigen::Quaterniond next(2.0 * q.coeffs() - sign * before[i].coeffs());
      next.normalize();
      before[i] = q;
      rotations[i] = next;
      matrices[i] = next.toRotationMatrix();
    }
  });
  return true;
}

Eigen::MatrixXd AsRigidAsPossibleSolver::FreePositions(const Positions& roi) const
{
  Eigen::MatrixXd x(this->FreeRows.size(), 3);
  for (std::size_t u = 0; u < this->FreeRows.size(); ++u)
  {
    x.row(u) = roi.row(this->FreeRows[u]);
  }
  return x;
}

double AsRigidAsPossibleSolver::Evaluate(
  const Eigen::MatrixXd& free, ArapIterate& iterate, const ParallelFor& loop) const
{
  // The copies run through `loop` too: serial, they were 5% of a 30k-vertex drag step.
  ArapIterate::Workspace& work = iterate.Work;
  Positions& candidate = work.Candidate;
  candidate.resize(iterate.Points.rows(), 3);
  work.CandidateQuaternions.resize(iterate.Rotations.size());
  const int rows = static_cast<int>(candidate.rows());
  const int rotations = static_cast<int>(iterate.Rotations.size());
  loop(0, std::max(rows, rotations), [&](int first, int last) {
    for (int k = first; k < last; ++k)
    {
      if (k < rows)
      {
        const int u = this->UnknownOfPatch[k];
        if (u >= 0)
        {
          candidate.row(k) = free.row(u);
        }
        else
        {
          candidate.row(k) = iterate.Points.row(k);
        }
      }
      if (k < rotations)
      {
        work.CandidateQuaternions[k] = iterate.Rotations[k];
      }
    }
  });
  this->Patch(candidate, work.Patch, loop);
  return this->Rotate(work.Patch, work.CandidateRotations, work.CandidateQuaternions, work, loop);
}

ArapIterate AsRigidAsPossibleSolver::InitialGuess(
  const std::vector<AffineMap>& handleMaps, const PointTargets* points) const
{
  ArapIterate guess;
  guess.Points = this->RestRows(this->NumberOfROIVertices);
  this->LocalStep(handleMaps, guess, SerialFor, false);
  this->UpdatePrior(points, guess.Work, SerialFor);
  const std::vector<Eigen::Matrix3d> identities(this->NumberOfEnergyVertices, Eigen::Matrix3d::Identity());
  this->GlobalStep(identities, guess, SerialFor, points);
  guess.Rotations.clear(); // those of the rest positions, not of the guess
  return guess;
}

void AsRigidAsPossibleSolver::Straighten(const std::vector<AffineMap>& handleMaps,
  ArapIterate& iterate, const ParallelFor& loop, const PointTargets* points) const
{
  this->UpdatePrior(points, iterate.Work, loop);
  this->LocalStep(handleMaps, iterate, loop, false);
  this->GlobalStep(iterate.Work.Rotations, iterate, loop, points);
}

void AsRigidAsPossibleSolver::PlaceHandles(
  const std::vector<AffineMap>& handleMaps, ArapIterate& iterate, const ParallelFor& loop) const
{
  for (int k = 0; k < this->NumberOfROIVertices; ++k)
  {
    const int group = this->HandleGroups[k];
    if (group >= 0)
    {
      const Vector3& rest = this->RestVertices[k];
      iterate.Points.row(k) = (group < static_cast<int>(handleMaps.size())
          ? Apply(handleMaps[group], rest) : rest).transpose();
    }
  }
  this->Patch(iterate.Points, iterate.Work.Patch, loop);
}

double AsRigidAsPossibleSolver::LocalStep(const std::vector<AffineMap>& handleMaps,
  ArapIterate& iterate, const ParallelFor& loop, bool aroundHandles) const
{
  this->PlaceHandles(handleMaps, iterate, loop);
  ArapIterate::Workspace& work = iterate.Work;
  const double energy = this->Rotate(work.Patch, work.Rotations, iterate.Rotations, work, loop,
    aroundHandles ? &this->AroundHandles : nullptr);
  work.RotationsFitPoints = true;
  return energy;
}

void AsRigidAsPossibleSolver::GlobalStep(const std::vector<Eigen::Matrix3d>& rotations,
  ArapIterate& iterate, const ParallelFor& loop, const PointTargets* points) const
{
  if (!this->FreeRows.empty())
  {
    const Eigen::MatrixXd free =
      this->Global(rotations, iterate.Work.Patch, iterate.Work, loop, points);
    for (std::size_t u = 0; u < this->FreeRows.size(); ++u)
    {
      iterate.Points.row(this->FreeRows[u]) = free.row(u);
    }
  }
  iterate.Work.RotationsFitPoints = false; // the rotations are those of the points before
}

bool AsRigidAsPossibleSolver::HasPlainEnergy() const
{
  return this->Points.IsEmpty() && this->Bending.IsEmpty() && this->RotationCoupling.empty() &&
    this->BendingRelief.empty() && this->PriorWeight == 0.0;
}

Eigen::MatrixXd AsRigidAsPossibleSolver::EdgeBalance(const std::vector<Vector3>& values,
  const std::vector<Eigen::Matrix3d>& matrices, const ParallelFor& loop) const
{
  const int free = static_cast<int>(this->FreeRows.size());
  Eigen::MatrixXd balance(free, 3);
  loop(0, free, [&](int first, int last) {
    for (int u = first; u < last; ++u)
    {
      const int i = this->FreeRows[u];
      Vector3 sum = -0.5 * (matrices[i] * this->RestEdgeSums[i]);
      for (int k = this->Offsets[i]; k < this->Offsets[i + 1]; ++k)
      {
        const int j = this->Neighbors[k];
        sum.noalias() += this->Weights[k] * (values[i] - values[j] - 0.5 * (matrices[j] * this->RestEdge(i, k)));
      }
      balance.row(u) = sum.transpose();
    }
  });
  return balance;
}

void AsRigidAsPossibleSolver::LinearizeRotations(ArapIterate::Workspace& work, const ParallelFor& loop) const
{
  // R = polar(M) for the ring's M = sum w e' e^T = R P: a change dM turns R by dR = R [w]x with
  // (tr(P) I - P) w = axial(R^T dM - dM^T R) ([w]x P + P [w]x = [(tr(P) I - P) w]x). Where that
  // matrix is nearly singular (a ring folded flat) its twist is left out, as a local-global
  // step leaves out every one: the Hessian stays bounded.
  work.Twists.resize(this->NumberOfEnergyVertices);
  loop(0, this->NumberOfEnergyVertices, [&](int first, int last) {
    for (int i = first; i < last; ++i)
    {
      const Eigen::Matrix3d stretch = work.Rotations[i].transpose() * this->Deformation(work.Patch, i);
      const Eigen::Matrix3d symmetric = 0.5 * (stretch + stretch.transpose());
      const Eigen::Matrix3d twist = symmetric.trace() * Eigen::Matrix3d::Identity() - symmetric;
      Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen;
      eigen.computeDirect(twist);
      const Vector3 values = eigen.eigenvalues();
      if (values(0) > 1e-3 * std::abs(values(2)))
      {
        work.Twists[i] =
          eigen.eigenvectors() * values.cwiseInverse().asDiagonal() * eigen.eigenvectors().transpose();
      }
      else
      {
        work.Twists[i].setZero();
      }
    }
  });
}

Eigen::MatrixXd AsRigidAsPossibleSolver::HessianProduct(
  const Eigen::MatrixXd& change, ArapIterate::Workspace& work, const ParallelFor& loop) const
{
  std::vector<Vector3>& patchChange = work.PatchChange;
  patchChange.assign(this->RestVertices.size(), Vector3::Zero());
  const int free = static_cast<int>(this->FreeRows.size());
  loop(0, free, [&](int first, int last) {
    for (int u = first; u < last; ++u)
    {
      patchChange[this->FreeRows[u]] = change.row(u).transpose();
    }
  });
  std::vector<Eigen::Matrix3d>& turns = work.RotationChanges;
  turns.resize(this->NumberOfEnergyVertices);
  loop(0, this->NumberOfEnergyVertices, [&](int first, int last) {
    for (int i = first; i < last; ++i)
    {
      const Eigen::Matrix3d& rotation = work.Rotations[i];
      const Eigen::Matrix3d a = rotation.transpose() * this->Deformation(patchChange, i);
      const Vector3 axial(a(2, 1) - a(1, 2), a(0, 2) - a(2, 0), a(1, 0) - a(0, 1));
      const Vector3 w = work.Twists[i] * axial;
      Eigen::Matrix3d cross;
      cross << 0.0, -w(2), w(1), w(2), 0.0, -w(0), -w(1), w(0), 0.0;
      turns[i] = rotation * cross;
    }
  });
  return this->EdgeBalance(patchChange, turns, loop);
}

AsRigidAsPossibleSolver::NewtonStep AsRigidAsPossibleSolver::NewtonDirection(
  const Eigen::MatrixXd& g, double& radius, ArapIterate::Workspace& work, const ParallelFor& loop) const
{
  // Steihaug's truncated conjugate gradients on H s = -g within a trust region, preconditioned
  // by L_ff (H is L_ff minus a part that is positive semidefinite where no ring is folded, so
  // L_ff bounds it from above), in L_ff's norm: the first step is a local-global step. Far from
  // the minimum, the region's soft modes make H nearly singular or indefinite, and the plain
  // Newton step overshoots by orders of magnitude; the region holds it, and negative curvature
  // goes to its boundary.
  // At most 20 products a step: near the minimum 60 did not reach the gain either, and a
  // 192k region on the sphere released in 17-20 s instead of 31, at the same energy.
  constexpr double ConjugateGradientGain = 0.05;
  constexpr int ConjugateGradientSteps = 20;
  auto dot = [](const Eigen::MatrixXd& a, const Eigen::MatrixXd& b) { return (a.array() * b.array()).sum(); };
  NewtonStep result;
  Eigen::MatrixXd r = -g;
  Eigen::MatrixXd z = this->Factor.Precondition(r, loop);
  Eigen::MatrixXd p = z;
  Eigen::MatrixXd& s = result.Step;
  s.setZero(g.rows(), 3);
  Eigen::MatrixXd hs = Eigen::MatrixXd::Zero(g.rows(), 3);
  double rz = dot(r, z);
  result.FirstStepNorm = std::sqrt(std::max(rz, 0.0));
  if (radius <= 0.0)
  {
    radius = result.FirstStepNorm;
  }
  // |s|^2, s.p and |p|^2 in the preconditioner's norm, by their recurrences.
  double ss = 0.0, sp = 0.0, pp = rz;
  const double start = r.norm();
  auto toBoundary = [&](const Eigen::MatrixXd& q) {
    const double tau = (-sp + std::sqrt(std::max(0.0, sp * sp + pp * (radius * radius - ss)))) / pp;
    s += tau * p;
    hs += tau * q;
    result.OnBoundary = true;
  };
  for (int k = 0; k < ConjugateGradientSteps && rz > 0.0; ++k)
  {
    const Eigen::MatrixXd q = this->HessianProduct(p, work, loop);
    const double curvature = dot(p, q);
    const double alpha = curvature > 0.0 ? rz / curvature : 0.0;
    if (curvature <= 0.0 || ss + 2.0 * alpha * sp + alpha * alpha * pp >= radius * radius)
    {
      toBoundary(q);
      break;
    }
    s += alpha * p;
    hs += alpha * q;
    ss += 2.0 * alpha * sp + alpha * alpha * pp;
    r -= alpha * q;
    if (r.norm() <= ConjugateGradientGain * start)
    {
      break;
    }
    z = this->Factor.Precondition(r, loop);
    const double rzNext = dot(r, z);
    const double beta = rzNext / rz;
    rz = rzNext;
    sp = beta * (sp + alpha * pp);
    pp = rz + beta * beta * pp;
    p = z + beta * p;
  }
  result.ModelDecrease = dot(g, s) + 0.5 * dot(s, hs);
  return result;
}

ArapResult AsRigidAsPossibleSolver::SolveNewton(ArapIterate& iterate, const ArapOptions& options,
  const ParallelFor& loop, std::vector<double>* energies, ArapResult result) const
{
  ArapIterate::Workspace& work = iterate.Work;
  Eigen::MatrixXd x = this->FreePositions(iterate.Points);
  IterationLog log(result.Energy, options, energies, work);
  // The trust region's radius, in L_ff's norm: at first a local-global step's length, or
  // where the cut solve this one continues left it.
  double& radius = work.TrustRadius;
  if (!options.Continue)
  {
    radius = 0.0;
  }
  constexpr int Retries = 3;
  constexpr double NewtonRemainder = 1e-9;
  for (int iteration = 0; iteration < options.MaximumIterations; ++iteration)
  {
    // The gradient at the iterate (its rotations fit its points: the envelope theorem) and the
    // rotations' linearization there; then steps until one lowers the energy, the region
    // shrinking after each that does not, a local-global step after the last.
    const Eigen::MatrixXd g = this->EdgeBalance(work.Patch, work.Rotations, loop);
    this->LinearizeRotations(work, loop);
    Eigen::MatrixXd next;
    double energy = std::numeric_limits<double>::infinity();
    bool converges = false;
    for (int attempt = 0; attempt <= Retries && !(energy < result.Energy); ++attempt)
    {
      const NewtonStep step = this->NewtonDirection(g, radius, work, loop);
      // Inside the region, the model's decrease is what is left above the minimum (to the
      // conjugate gradients' accuracy): under NewtonRemainder of the energy, this step ends the
      // solve, whatever the tolerance (a release asks for its iterations in full).
      converges = !step.OnBoundary &&
        -step.ModelDecrease * 4.0 / this->RestScale <= NewtonRemainder * result.Energy;
      next = x + step.Step;
      energy = this->Evaluate(next, iterate, loop);
      // The energy's decrease against the model's, in the gradient's units (g is over 4, the
      // energy over RestScale).
      const double actual = (result.Energy - energy) * this->RestScale / 4.0;
      const double ratio = step.ModelDecrease < 0.0 ? actual / -step.ModelDecrease : -1.0;
      if (ratio < 0.25)
      {
        radius *= 0.25;
      }
      else if (ratio > 0.75 && step.OnBoundary)
      {
        radius *= 2.0;
      }
    }
    if (!(energy < result.Energy))
    {
      next = this->Global(work.Rotations, work.Patch, work, loop, nullptr);
      energy = this->Evaluate(next, iterate, loop);
    }
    // Not even a local-global step lowers it: the iterate is the minimum, to rounding. It
    // stays (evaluated again, so that the workspace fits it).
    const bool stalled = !(energy < result.Energy);
    if (stalled)
    {
      next = x;
      energy = std::min(result.Energy, this->Evaluate(next, iterate, loop));
    }
    iterate.Points.swap(work.Candidate);
    work.Rotations.swap(work.CandidateRotations);
    iterate.Rotations.swap(work.CandidateQuaternions);
    x.swap(next);
    if (log.Stop(result, energy, std::min(log.Next(), ConvergenceWindow), stalled || converges))
    {
      break;
    }
  }
  return result;
}
}
