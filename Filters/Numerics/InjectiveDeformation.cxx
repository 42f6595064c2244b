#include "InjectiveDeformation.h"

#include <Eigen/Eigenvalues>
#include <Eigen/LU>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <numeric>

namespace LaplacianEditing
{
namespace
{
constexpr double Infinity = std::numeric_limits<double>::infinity();
// A step goes this fraction of the way to the first flat tetrahedron at most.
constexpr double SafeFraction = 0.9;
// Armijo's sufficient decrease.
constexpr double SufficientDecrease = 1e-4;
constexpr int MaximumHalvings = 40;
// AQP's momentum, (1 - sqrt(1/eta)) / (1 + sqrt(1/eta)) with the paper's eta = 100.
constexpr double Momentum = (1.0 - 0.1) / (1.0 + 0.1);
// The continuation's first pull (as stiff as the mesh around a point) and its growth a stage.
constexpr double FirstWeight = 1.0;
constexpr double ContinuationRatio = 100.0;
// Targets missed by at most this many snap distances are near: a stiffer pull meets them.
constexpr double NearMiss = 100.0;
// The earlier stages only bring the points near: they stop at this relative decrease.
constexpr double StageTolerance = 1e-3;
// A step this short says the proxy has lost the energy's shape: it is reweighted.
constexpr double StallStep = 0.05;
// The gradient's blocks of tetrahedra (a fixed number: the sum's order does not follow the
// threads).
constexpr int GradientBlocks = 8;

// The first tetrahedron of a block among m.
int FirstOfBlock(int m, int block)
{
  return static_cast<int>(static_cast<std::int64_t>(m) * block / GradientBlocks);
}

using Matrix3 = Eigen::Matrix3d;

// Points one row each, contiguous: the loops over tetrahedra gather four rows a tetrahedron.
using Rows = Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>;

// The edge matrix [x1 - x0, x2 - x0, x3 - x0] of tetrahedron `row`.
template <typename Points>
Matrix3 Edges(const Points& x, const Tetrahedra& tets, int row)
{
  Matrix3 edges;
  const Vector3 origin = x.row(tets(row, 0)).transpose();
  for (int k = 0; k < 3; ++k)
  {
    edges.col(k) = x.row(tets(row, k + 1)).transpose() - origin;
  }
  return edges;
}

// The passes over tetrahedra below work on plain scalars: Eigen's 3x3 products, on SSE2, store
// single values and load them back in pairs, and those store-forwarding stalls cost the drag
// step's passes more than their arithmetic did (perf; Documentation/volumes.md).
using Edges3 = double[3][3]; // [i][k]: coordinate i of edge k

// The edges x_k+1 - x_0 of the tetrahedron `tet` among row-major points `x`.
inline void LoadEdges(const double* x, const int* tet, Edges3& edges)
{
  const double* origin = x + 3 * tet[0];
  for (int k = 0; k < 3; ++k)
  {
    const double* corner = x + 3 * tet[k + 1];
    for (int i = 0; i < 3; ++i)
    {
      edges[i][k] = corner[i] - origin[i];
    }
  }
}

inline double Determinant(const Edges3& m)
{
  return m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
    m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
    m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
}

// The passes that run at every drag step over every tetrahedron take them a batch at a time,
// each value's lanes side by side in loops without branches, which compile to vector
// instructions (two tetrahedra an instruction on SSE2), where one tetrahedron at a time waited
// on its division and square root (perf, Documentation/volumes.md). A batch short of Lanes
// repeats its last tetrahedron.
constexpr int Lanes = 8;

// V (|J|^2 + |J^-1|^2 - 6) for J = edges B (B column-major; both of positive determinant), and
// if `corners` is given, its gradient at the four corners (column-major 3 x 4).
inline double SymmetricDirichlet(const Edges3& edges, const double* B, double volume, double* corners)
{
  double J[3][3];
  for (int i = 0; i < 3; ++i)
  {
    for (int j = 0; j < 3; ++j)
    {
      J[i][j] = edges[i][0] * B[3 * j] + edges[i][1] * B[3 * j + 1] + edges[i][2] * B[3 * j + 2];
    }
  }
  // G = J^-T: the cofactors over the determinant.
  double G[3][3];
  G[0][0] = J[1][1] * J[2][2] - J[1][2] * J[2][1];
  G[0][1] = J[1][2] * J[2][0] - J[1][0] * J[2][2];
  G[0][2] = J[1][0] * J[2][1] - J[1][1] * J[2][0];
  G[1][0] = J[0][2] * J[2][1] - J[0][1] * J[2][2];
  G[1][1] = J[0][0] * J[2][2] - J[0][2] * J[2][0];
  G[1][2] = J[0][1] * J[2][0] - J[0][0] * J[2][1];
  G[2][0] = J[0][1] * J[1][2] - J[0][2] * J[1][1];
  G[2][1] = J[0][2] * J[1][0] - J[0][0] * J[1][2];
  G[2][2] = J[0][0] * J[1][1] - J[0][1] * J[1][0];
  const double inverseDeterminant = 1.0 / (J[0][0] * G[0][0] + J[0][1] * G[0][1] + J[0][2] * G[0][2]);
  double norms = -6.0;
  for (int i = 0; i < 3; ++i)
  {
    for (int j = 0; j < 3; ++j)
    {
      G[i][j] *= inverseDeterminant;
      norms += J[i][j] * J[i][j] + G[i][j] * G[i][j];
    }
  }
  if (!corners)
  {
    return volume * norms;
  }
  // dE/dJ = 2 V (J - G G^T G), and dE/dedges = dE/dJ B^T.
  double S[3][3]; // G G^T
  for (int i = 0; i < 3; ++i)
  {
    for (int j = 0; j < 3; ++j) // both halves, the same values: a loop of constant length
    {
      S[i][j] = G[i][0] * G[j][0] + G[i][1] * G[j][1] + G[i][2] * G[j][2];
    }
  }
  double dJ[3][3];
  for (int i = 0; i < 3; ++i)
  {
    for (int j = 0; j < 3; ++j)
    {
      dJ[i][j] = 2.0 * volume * (J[i][j] - (S[i][0] * G[0][j] + S[i][1] * G[1][j] + S[i][2] * G[2][j]));
    }
  }
  for (int i = 0; i < 3; ++i)
  {
    corners[i] = 0.0;
    for (int k = 0; k < 3; ++k)
    {
      const double d = dJ[i][0] * B[k] + dJ[i][1] * B[3 + k] + dJ[i][2] * B[6 + k];
      corners[3 * (k + 1) + i] = d;
      corners[i] -= d;
    }
  }
  return volume * norms;
}

// A batch of tetrahedra in lanes (see Lanes): their edges, rest inverses and volumes.
struct TetrahedronLanes
{
  double EdgeLanes[3][3][Lanes], RestInverseLanes[9][Lanes], VolumeLanes[Lanes];
  int Used = 0;

  void Load(const double* x, const int* tets, const std::vector<Eigen::Matrix3d>& restInverse,
    const Eigen::VectorXd& volume, int begin, int end)
  {
    this->Used = std::min(Lanes, end - begin);
    for (int j = 0; j < Lanes; ++j)
    {
      const int c = begin + std::min(j, this->Used - 1);
      Edges3 edges;
      LoadEdges(x, tets + 4 * c, edges);
      for (int i = 0; i < 9; ++i)
      {
        this->EdgeLanes[i / 3][i % 3][j] = edges[i / 3][i % 3];
        this->RestInverseLanes[i][j] = restInverse[c].data()[i];
      }
      this->VolumeLanes[j] = volume[c];
    }
  }

  // Lane j's symmetric Dirichlet energy, Infinity if flat or inverted, and its gradient at the
  // corners if `corners` is given (computed for a flat one too, no trap being enabled).
  double Energy(int j, double* corners) const
  {
    const auto& e = this->EdgeLanes;
    const Edges3 edges = { { e[0][0][j], e[0][1][j], e[0][2][j] },
      { e[1][0][j], e[1][1][j], e[1][2][j] }, { e[2][0][j], e[2][1][j], e[2][2][j] } };
    double B[9];
    for (int i = 0; i < 9; ++i)
    {
      B[i] = this->RestInverseLanes[i][j];
    }
    const double energy = SymmetricDirichlet(edges, B, this->VolumeLanes[j], corners);
    return Determinant(edges) > 0.0 ? energy : Infinity;
  }
};

// Appends the solutions of a + b t + c t^2 = 0 (c may be 0) to roots[count].
void QuadraticRoots(double a, double b, double c, double* roots, int& count)
{
  const double scale = std::abs(a) + std::abs(b);
  if (std::abs(c) <= 1e-14 * scale)
  {
    if (b != 0.0)
    {
      roots[count++] = -a / b;
    }
    return;
  }
  const double discriminant = b * b - 4.0 * c * a;
  if (discriminant < 0.0)
  {
    return;
  }
  // The root of larger magnitude without cancellation, the other from the product.
  const double q = -0.5 * (b + std::copysign(std::sqrt(discriminant), b));
  roots[count++] = q / c;
  if (q != 0.0)
  {
    roots[count++] = a / q;
  }
}


// The smallest positive t with a0 + a1 t + a2 t^2 + a3 t^3 = 0, for a0 > 0; infinity if none,
// and (for most tetrahedra, which the bound below clears at once) if none below `below`.
double SmallestPositiveRoot(
  double a0, double a1, double a2, double a3, double below)
{
  // Most tetrahedra cannot flatten this soon: the polynomial stays above a0 - |a1| t - ... > 0.
  if (a0 - below * (std::abs(a1) + below * (std::abs(a2) + below * std::abs(a3))) > 0.0)
  {
    return Infinity;
  }
  double roots[3];
  int count = 0;
  const double scale = std::abs(a0) + std::abs(a1) + std::abs(a2);
  if (std::abs(a3) <= 1e-12 * scale)
  {
    QuadraticRoots(a0, a1, a2, roots, count);
  }
  else
  {
    // t^3 + p t^2 + q t + r = 0 (Numerical Recipes, 5.6).
    const double p = a2 / a3, q = a1 / a3, r = a0 / a3;
    const double Q = (p * p - 3.0 * q) / 9.0;
    const double R = (2.0 * p * p * p - 9.0 * p * q + 27.0 * r) / 54.0;
    if (R * R < Q * Q * Q)
    {
      const double theta = std::acos(std::clamp(R / std::sqrt(Q * Q * Q), -1.0, 1.0));
      const double s = -2.0 * std::sqrt(Q);
      const double third = 2.0 * M_PI / 3.0;
      for (double shift : { 0.0, third, -third })
      {
        roots[count++] = s * std::cos(theta / 3.0 + shift) - p / 3.0;
      }
    }
    else
    {
      const double A = -std::copysign(std::cbrt(std::abs(R) + std::sqrt(R * R - Q * Q * Q)), R);
      roots[count++] = A + (A != 0.0 ? Q / A : 0.0) - p / 3.0;
    }
    // Newton polishes what the closed form lost to cancellation.
    for (int k = 0; k < count; ++k)
    {
      double& t = roots[k];
      for (int step = 0; step < 2; ++step)
      {
        const double f = a0 + t * (a1 + t * (a2 + t * a3));
        const double df = a1 + t * (2.0 * a2 + t * 3.0 * a3);
        if (df != 0.0)
        {
          t -= f / df;
        }
      }
    }
  }
  double smallest = Infinity;
  for (int k = 0; k < count; ++k)
  {
    if (roots[k] > 0.0 && std::isfinite(roots[k]))
    {
      smallest = std::min(smallest, roots[k]);
    }
  }
  return smallest;
}

}

double InjectiveDeformation::CornerScaledJacobian(
  const Vector3& a, const Vector3& b, const Vector3& c, const Vector3& d)
{
  const Vector3 u = b - a, v = c - a, w = d - a;
  const double lengths = u.norm() * v.norm() * w.norm();
  return lengths > 0.0 ? u.dot(v.cross(w)) / lengths : 0.0;
}

double InjectiveDeformation::TetrahedronScaledJacobian(
  const Vector3& a, const Vector3& b, const Vector3& c, const Vector3& d)
{
  return TetrahedronScaledJacobian(a.data(), b.data(), c.data(), d.data());
}

double InjectiveDeformation::TetrahedronScaledJacobian(
  const double* a, const double* b, const double* c, const double* d)
{
  const double* corners[4] = { a, b, c, d };
  double quality;
  TetrahedronScaledJacobians(corners, 1, &quality);
  return quality;
}

void InjectiveDeformation::TetrahedronScaledJacobians(
  const double* const* corners, int count, double* quality)
{
  // In lanes (see Lanes). Every corner sees the same determinant (six times the volume), with
  // its orientation, over the product of its three edges' lengths: the smallest corner is the
  // one of the longest edges (of the shortest, if inverted). Squared, so that one square root is
  // taken.
  for (int first = 0; first < count; first += Lanes)
  {
    const int used = std::min(Lanes, count - first);
    double x[4][3][Lanes];
    for (int j = 0; j < Lanes; ++j)
    {
      const double* const* tet = corners + 4 * (first + std::min(j, used - 1));
      for (int i = 0; i < 4; ++i)
      {
        for (int k = 0; k < 3; ++k)
        {
          x[i][k][j] = tet[i][k];
        }
      }
    }
    double result[Lanes];
    for (int j = 0; j < Lanes; ++j)
    {
      const auto squared = [&](int a, int b) {
        const double dx = x[b][0][j] - x[a][0][j], dy = x[b][1][j] - x[a][1][j],
                     dz = x[b][2][j] - x[a][2][j];
        return dx * dx + dy * dy + dz * dz;
      };
      const double s01 = squared(0, 1), s02 = squared(0, 2), s03 = squared(0, 3),
                   s12 = squared(1, 2), s13 = squared(1, 3), s23 = squared(2, 3);
      const double lengths[4] = { s01 * s02 * s03, s01 * s12 * s13, s02 * s12 * s23, s03 * s13 * s23 };
      const double shortest = std::min(std::min(lengths[0], lengths[1]), std::min(lengths[2], lengths[3]));
      const double longest = std::max(std::max(lengths[0], lengths[1]), std::max(lengths[2], lengths[3]));
      const auto edge = [&](int i, int k) { return x[k + 1][i][j] - x[0][i][j]; };
      const Edges3 edges = { { edge(0, 0), edge(0, 1), edge(0, 2) },
        { edge(1, 0), edge(1, 1), edge(1, 2) }, { edge(2, 0), edge(2, 1), edge(2, 2) } };
      const double determinant = Determinant(edges);
      // Selections, not branches: a flat tetrahedron's lane divides by one and is then zeroed.
      const bool flat = shortest <= 0.0;
      const double denominator = flat ? 1.0 : (determinant > 0.0 ? longest : shortest);
      const double scaled = std::sqrt(2.0) * determinant / std::sqrt(denominator);
      result[j] = flat ? 0.0 : scaled;
    }
    std::copy(result, result + used, quality + first);
  }
}

std::string InjectiveDeformation::Prepare(const Positions& rest, const Tetrahedra& tetrahedra,
  const std::vector<PointKind>& kinds, double targetWeight, SolverBackend backend)
{
  const int n = static_cast<int>(rest.rows());
  const int m = static_cast<int>(tetrahedra.rows());
  if (static_cast<int>(kinds.size()) != n)
  {
    return "Each point needs a kind.";
  }
  if (!(targetWeight > 0.0))
  {
    return "The targets' pull must be positive.";
  }
  this->Rest = rest;
  // The tetrahedra in the order of their first points, so that the loops over them gather and
  // scatter points near the last ones: in a mesh generator's order, the gradient's scatter into
  // points out of cache dominated the drag steps of large zones (Documentation/volumes.md).
  std::vector<int> order(m);
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(),
    [&](int a, int b) { return tetrahedra.row(a).minCoeff() < tetrahedra.row(b).minCoeff(); });
  this->Tets.resize(m, 4);
  for (int c = 0; c < m; ++c)
  {
    this->Tets.row(c) = tetrahedra.row(order[c]);
  }
  const Tetrahedra& tets = this->Tets;
  this->Kinds = kinds;
  this->FinalWeight = targetWeight;
  this->Backend = backend;
  this->RestInverse.resize(m);
  this->Volume.resize(m);
  for (int c = 0; c < m; ++c)
  {
    const Matrix3 edges = Edges(rest, tets, c);
    const double determinant = edges.determinant();
    if (!(determinant > 0.0))
    {
      return "A cell is flat or inverted at rest (corner tetrahedron " + std::to_string(order[c]) + ").";
    }
    this->RestInverse[c] = edges.inverse();
    this->Volume[c] = determinant / 6.0;
  }
  this->TotalVolume = this->Volume.sum();

  this->Unknown.assign(n, -1);
  this->Unknowns.clear();
  for (int p = 0; p < n; ++p)
  {
    if (kinds[p] != PointKind::Fixed)
    {
      this->Unknown[p] = static_cast<int>(this->Unknowns.size());
      this->Unknowns.push_back(p);
    }
  }
  if (this->Unknowns.empty())
  {
    return "No point of the volume can move.";
  }

  // The proxy's pattern over the unknowns, and where each tetrahedron's entries go in it.
  std::vector<Eigen::Triplet<double>> triplets;
  triplets.reserve(static_cast<std::size_t>(m) * 16);
  for (int c = 0; c < m; ++c)
  {
    for (int i = 0; i < 4; ++i)
    {
      for (int j = 0; j < 4; ++j)
      {
        const int ui = this->Unknown[tets(c, i)], uj = this->Unknown[tets(c, j)];
        if (ui >= 0 && uj >= 0)
        {
          triplets.emplace_back(ui, uj, 1.0);
        }
      }
    }
  }
  const int unknowns = static_cast<int>(this->Unknowns.size());
  this->Proxy.resize(unknowns, unknowns);
  this->Proxy.setFromTriplets(triplets.begin(), triplets.end());
  this->Proxy.makeCompressed();
  auto slot = [this](int row, int column) {
    const int* begin = this->Proxy.innerIndexPtr() + this->Proxy.outerIndexPtr()[column];
    const int* end = this->Proxy.innerIndexPtr() + this->Proxy.outerIndexPtr()[column + 1];
    return static_cast<int>(std::lower_bound(begin, end, row) - this->Proxy.innerIndexPtr());
  };
  this->Slots.resize(m, 16);
  this->Blocks.resize(m, 16);
  Eigen::VectorXd stiffness = Eigen::VectorXd::Zero(n);
  for (int c = 0; c < m; ++c)
  {
    // The Hessian of 4 V_c |J_c|^2, which bounds the symmetric Dirichlet energy's Hessian at
    // rest (8 on symmetric strains, 0 on rotations) from above, per coordinate.
    const Matrix3& B = this->RestInverse[c];
    Eigen::Matrix<double, 4, 3> gradients; // of the barycentric coordinates
    gradients.row(0) = -B.colwise().sum();
    gradients.bottomRows<3>() = B;
    const Eigen::Matrix4d block = 8.0 * this->Volume[c] * gradients * gradients.transpose();
    for (int i = 0; i < 4; ++i)
    {
      stiffness[tets(c, i)] += block(i, i);
      for (int j = 0; j < 4; ++j)
      {
        const int ui = this->Unknown[tets(c, i)], uj = this->Unknown[tets(c, j)];
        this->Slots(c, 4 * i + j) = ui >= 0 && uj >= 0 ? slot(ui, uj) : -1;
        this->Blocks(c, 4 * i + j) = block(i, j);
      }
    }
  }
  this->Pull = Eigen::VectorXd::Zero(n);
  this->PullSlots.assign(unknowns, -1);
  for (int p = 0; p < n; ++p)
  {
    if (kinds[p] == PointKind::Targeted)
    {
      this->Pull[p] = stiffness[p];
      this->PullSlots[this->Unknown[p]] = slot(this->Unknown[p], this->Unknown[p]);
    }
  }
  this->TetWeights.assign(m, 1.0);

  this->TetOffsets.assign(n + 1, 0);
  for (int c = 0; c < m; ++c)
  {
    for (int i = 0; i < 4; ++i)
    {
      ++this->TetOffsets[tets(c, i) + 1];
    }
  }
  for (int p = 0; p < n; ++p)
  {
    this->TetOffsets[p + 1] += this->TetOffsets[p];
  }
  this->PointCorners.resize(this->TetOffsets[n]);
  std::vector<int> fill(this->TetOffsets.begin(), this->TetOffsets.end() - 1);
  for (int c = 0; c < m; ++c)
  {
    for (int i = 0; i < 4; ++i)
    {
      this->PointCorners[fill[tets(c, i)]++] = 4 * c + i;
    }
  }
  // Each block of the gradient's tetrahedra adds into the unknowns it reaches, a range of them
  // (sorted by their first points, the blocks reach overlapping ranges, not all the unknowns).
  this->BlockUnknowns.assign(2 * GradientBlocks, 0);
  this->BlockRows.assign(GradientBlocks + 1, 0);
  for (int block = 0; block < GradientBlocks; ++block)
  {
    int first = std::numeric_limits<int>::max(), end = 0;
    for (int c = FirstOfBlock(m, block); c < FirstOfBlock(m, block + 1); ++c)
    {
      for (int i = 0; i < 4; ++i)
      {
        const int u = this->Unknown[tets(c, i)];
        if (u >= 0)
        {
          first = std::min(first, u);
          end = std::max(end, u + 1);
        }
      }
    }
    first = std::min(first, end);
    this->BlockUnknowns[2 * block] = first;
    this->BlockUnknowns[2 * block + 1] = end;
    this->BlockRows[block + 1] = this->BlockRows[block] + end - first;
  }
  this->Factor = SparseCholesky();
  this->Factor.SetManySolves(true);
  this->FactoredWeight = 0.0; // Solve factors at its first stage's weight
  return {};
}

std::string InjectiveDeformation::FactorAt(double weight, InjectiveReport& report)
{
  if (weight == this->FactoredWeight)
  {
    return {};
  }
  ++report.Factorizations;
  double* values = this->Proxy.valuePtr();
  std::fill(values, values + this->Proxy.nonZeros(), 0.0);
  for (Eigen::Index c = 0; c < this->Slots.rows(); ++c)
  {
    for (int k = 0; k < 16; ++k)
    {
      if (this->Slots(c, k) >= 0)
      {
        values[this->Slots(c, k)] += this->TetWeights[c] * this->Blocks(c, k);
      }
    }
  }
  for (std::size_t u = 0; u < this->Unknowns.size(); ++u)
  {
    if (this->PullSlots[u] >= 0)
    {
      values[this->PullSlots[u]] += 2.0 * weight * this->Pull[this->Unknowns[u]];
    }
  }
  // The pattern stays: after the first, a factorization reuses the analysis.
  const std::string error = this->Factor.IsFactorized()
    ? this->Factor.Refactorize(this->Proxy)
    : this->Factor.Factorize(this->Proxy, this->Backend, FillOrdering::METIS);
  this->FactoredWeight = error.empty() ? weight : 0.0;
  return error;
}

std::string InjectiveDeformation::FactorForDrag(int& factorizations)
{
  if (this->FactoredWeight > 0.0)
  {
    return {};
  }
  InjectiveReport report;
  const std::string error = this->FactorAt(this->FinalWeight, report);
  factorizations += report.Factorizations;
  return error;
}

void InjectiveDeformation::Reweight(const Positions& x, const ParallelFor& loop)
{
  const int m = static_cast<int>(this->Tets.rows());
  loop(0, m, [&](int first, int last) {
    for (int c = first; c < last; ++c)
    {
      const Matrix3 J = Edges(x, this->Tets, c) * this->RestInverse[c];
      const double smallest =
        std::sqrt(std::max(0.0, Eigen::SelfAdjointEigenSolver<Matrix3>()
                                  .computeDirect(J.transpose() * J, Eigen::EigenvaluesOnly)
                                  .eigenvalues()[0]));
      // The energy's curvature along its most compressed direction, 2 + 6 / s^4, against the
      // proxy's 8 at rest.
      this->TetWeights[c] = std::min(1e12, (2.0 + 6.0 / std::pow(smallest, 4.0)) / 8.0);
    }
  });
  this->FactoredWeight = 0.0;
}

double InjectiveDeformation::Energy(
  const Positions& points, const Positions& targets, const ParallelFor& loop) const
{
  const Rows x = points;
  const int m = static_cast<int>(this->Tets.rows());
  std::vector<double>& energies = this->TetEnergies;
  energies.resize(m);
  loop(0, m, [&](int first, int last) {
    TetrahedronLanes lanes;
    for (int begin = first; begin < last; begin += Lanes)
    {
      lanes.Load(x.data(), this->Tets.data(), this->RestInverse, this->Volume, begin, last);
      double batch[Lanes];
      for (int j = 0; j < Lanes; ++j)
      {
        batch[j] = lanes.Energy(j, nullptr);
      }
      std::copy(batch, batch + lanes.Used, energies.begin() + begin);
    }
  });
  double energy = 0.0;
  for (double e : energies)
  {
    energy += e;
  }
  return energy + this->Penalty(points, targets);
}

double InjectiveDeformation::LargestMiss(const Positions& x, const Positions& targets) const
{
  double largest = 0.0;
  for (int p : this->Unknowns)
  {
    if (this->Kinds[p] == PointKind::Targeted)
    {
      largest = std::max(largest, (x.row(p) - targets.row(p)).norm());
    }
  }
  return largest;
}

double InjectiveDeformation::Penalty(const Positions& x, const Positions& targets) const
{
  double penalty = 0.0;
  for (int p : this->Unknowns)
  {
    if (this->Kinds[p] == PointKind::Targeted)
    {
      penalty += this->Lambda * this->Pull[p] * (x.row(p) - targets.row(p)).squaredNorm();
    }
  }
  return penalty;
}

double InjectiveDeformation::Gradient(const Positions& points, const Positions& targets,
  Eigen::MatrixXd& gradient, const ParallelFor& loop) const
{
  const Rows x = points;
  const int m = static_cast<int>(this->Tets.rows());
  const int unknowns = static_cast<int>(this->Unknowns.size());
  // Each block of tetrahedra adds its corners' gradients into its own rows for the unknowns it
  // reaches, which stay in cache, and the blocks are then summed: no two threads write one row,
  // and the sum does not depend on the threads. Kept between calls: allocated anew, a large
  // zone's buffer costs its page faults again.
  Rows& sums = this->BlockGradients;
  sums.resize(this->BlockRows.back(), 3);
  std::vector<double>& energies = this->TetEnergies;
  energies.resize(m);
  loop(0, GradientBlocks, [&](int firstBlock, int lastBlock) {
    for (int block = firstBlock; block < lastBlock; ++block)
    {
      const int firstUnknown = this->BlockUnknowns[2 * block];
      double* sum = sums.data() + 3 * (static_cast<std::ptrdiff_t>(this->BlockRows[block]) - firstUnknown);
      std::fill(sums.data() + 3 * this->BlockRows[block], sums.data() + 3 * this->BlockRows[block + 1], 0.0);
      TetrahedronLanes lanes;
      const int end = FirstOfBlock(m, block + 1);
      for (int begin = FirstOfBlock(m, block); begin < end; begin += Lanes)
      {
        lanes.Load(x.data(), this->Tets.data(), this->RestInverse, this->Volume, begin, end);
        double batch[Lanes], corners[12][Lanes]; // a corner's gradient: rows 3 i to 3 i + 2
        for (int j = 0; j < Lanes; ++j)
        {
          double lane[12];
          batch[j] = lanes.Energy(j, lane);
          for (int k = 0; k < 12; ++k)
          {
            corners[k][j] = lane[k];
          }
        }
        for (int j = 0; j < lanes.Used; ++j)
        {
          const int c = begin + j;
          energies[c] = batch[j];
          if (batch[j] == Infinity)
          {
            continue; // flat or inverted (or overflowed): a start that no step leaves
          }
          const int* tet = this->Tets.data() + 4 * c;
          for (int i = 0; i < 4; ++i)
          {
            const int u = this->Unknown[tet[i]];
            if (u >= 0)
            {
              for (int k = 0; k < 3; ++k)
              {
                sum[3 * u + k] += corners[3 * i + k][j];
              }
            }
          }
        }
      }
    }
  });
  gradient.resize(unknowns, 3);
  loop(0, unknowns, [&](int first, int last) {
    for (int u = first; u < last; ++u)
    {
      const int p = this->Unknowns[u];
      Eigen::RowVector3d sum = Eigen::RowVector3d::Zero();
      for (int block = 0; block < GradientBlocks; ++block)
      {
        const int firstUnknown = this->BlockUnknowns[2 * block];
        if (u >= firstUnknown && u < this->BlockUnknowns[2 * block + 1])
        {
          sum += sums.row(this->BlockRows[block] + u - firstUnknown);
        }
      }
      if (this->Kinds[p] == PointKind::Targeted)
      {
        sum += 2.0 * this->Lambda * this->Pull[p] * (points.row(p) - targets.row(p));
      }
      gradient.row(u) = sum;
    }
  });
  double energy = 0.0;
  for (double e : energies)
  {
    energy += e;
  }
  return energy + this->Penalty(points, targets);
}

double InjectiveDeformation::LargestSafeStep(const Positions& points,
  const Positions& directions, double below, const ParallelFor& loop) const
{
  const Rows x = points, direction = directions;
  const int m = static_cast<int>(this->Tets.rows());
  std::vector<double> steps(m);
  loop(0, m, [&](int first, int last) {
    for (int c = first; c < last; ++c)
    {
      Edges3 D, P;
      LoadEdges(x.data(), this->Tets.data() + 4 * c, D);
      LoadEdges(direction.data(), this->Tets.data() + 4 * c, P);
      // det(D + t P) = det[d0 + t p0, d1 + t p1, d2 + t p2], with a column's cross products.
      const auto column = [](const Edges3& m, int k) { return Vector3(m[0][k], m[1][k], m[2][k]); };
      const Vector3 d0 = column(D, 0), d1 = column(D, 1), d2 = column(D, 2);
      const Vector3 p0 = column(P, 0), p1 = column(P, 1), p2 = column(P, 2);
      const Vector3 d12 = d1.cross(d2), p12 = p1.cross(p2);
      const Vector3 mixed = d1.cross(p2) + p1.cross(d2);
      const double a0 = d0.dot(d12);
      const double a1 = p0.dot(d12) + d0.dot(mixed);
      const double a2 = d0.dot(p12) + p0.dot(mixed);
      const double a3 = p0.dot(p12);
      steps[c] = SmallestPositiveRoot(a0, a1, a2, a3, below);
    }
  });
  double smallest = Infinity;
  for (double s : steps)
  {
    smallest = std::min(smallest, s);
  }
  return smallest;
}

std::vector<int> InjectiveDeformation::Inverted(
  const Positions& points, const Tetrahedra& tetrahedra, const ParallelFor& loop)
{
  const Rows x = points;
  const int m = static_cast<int>(tetrahedra.rows());
  std::vector<std::vector<int>> inverted(GradientBlocks);
  loop(0, GradientBlocks, [&](int firstBlock, int lastBlock) {
    for (int block = firstBlock; block < lastBlock; ++block)
    {
      for (int c = FirstOfBlock(m, block); c < FirstOfBlock(m, block + 1); ++c)
      {
        Edges3 d;
        LoadEdges(x.data(), tetrahedra.data() + 4 * c, d);
        const double det = d[0][0] * (d[1][1] * d[2][2] - d[2][1] * d[1][2]) -
          d[0][1] * (d[1][0] * d[2][2] - d[2][0] * d[1][2]) +
          d[0][2] * (d[1][0] * d[2][1] - d[2][0] * d[1][1]);
        if (!(det > 0.0))
        {
          inverted[block].push_back(c);
        }
      }
    }
  });
  std::vector<int> all;
  for (const std::vector<int>& block : inverted)
  {
    all.insert(all.end(), block.begin(), block.end());
  }
  return all;
}

bool InjectiveDeformation::AllPositive(const Positions& x, const std::vector<int>& tets) const
{
  return std::all_of(tets.begin(), tets.end(),
    [&](int c) { return Edges(x, this->Tets, c).determinant() > 0.0; });
}

void InjectiveDeformation::Snap(const Positions& targets, Positions& x, double snap) const
{
  std::vector<int> around;
  for (int p : this->Unknowns)
  {
    if (this->Kinds[p] != PointKind::Targeted)
    {
      continue;
    }
    const Eigen::RowVector3d before = x.row(p);
    if ((before - targets.row(p)).norm() > snap)
    {
      continue;
    }
    x.row(p) = targets.row(p);
    around.clear();
    for (int k = this->TetOffsets[p]; k < this->TetOffsets[p + 1]; ++k)
    {
      around.push_back(this->PointCorners[k] / 4);
    }
    if (!this->AllPositive(x, around))
    {
      x.row(p) = before;
    }
  }
}

InjectiveReport InjectiveDeformation::Solve(const Positions& targets, Positions& points,
  const InjectiveOptions& options, double snap, const ParallelFor& loop)
{
  InjectiveReport report;
  const int n = static_cast<int>(this->Kinds.size());
  this->Misses.assign(n, 0.0);
  // Nothing asked of a mesh at rest: the rest, exactly (rounding would move it by 1e-16).
  bool still = points == this->Rest;
  for (int p : this->Unknowns)
  {
    still = still && (this->Kinds[p] != PointKind::Targeted || targets.row(p) == this->Rest.row(p));
  }
  // A solve that goes on where Progress stopped the last one goes on as that one started.
  const bool resuming = options.Resume && this->Cut.Active;
  const bool continuation = resuming ? this->Cut.Continuation : options.Continuation;
  if (continuation && !resuming &&
    std::any_of(this->TetWeights.begin(), this->TetWeights.end(), [](double w) { return w != 1.0; }))
  {
    // A settle starts from the rest stiffness, not from an earlier shape's reweighting.
    std::fill(this->TetWeights.begin(), this->TetWeights.end(), 1.0);
    this->FactoredWeight = 0.0;
  }
  Eigen::MatrixXd gradient;
  double lastAlpha = 0.0;
  Positions direction = Positions::Zero(n, 3);
  Positions trial(n, 3);

  // One proxy step from `from`: its energy, the trial point and its energy; false if `from` has
  // a flat tetrahedron or the energy does not fall enough along the step.
  auto step = [&](const Positions& from, double& fromEnergy, double& trialEnergy) {
    trialEnergy = Infinity;
    fromEnergy = this->Gradient(from, targets, gradient, loop);
    if (!std::isfinite(fromEnergy))
    {
      return false;
    }
    const Eigen::MatrixXd solved = -this->Factor.Solve(gradient, loop);
    for (std::size_t u = 0; u < this->Unknowns.size(); ++u)
    {
      direction.row(this->Unknowns[u]) = solved.row(u);
    }
    const double slope = (gradient.array() * solved.array()).sum();
    if (!(slope < 0.0))
    {
      return false;
    }
    double alpha = std::min(
      1.0, SafeFraction * this->LargestSafeStep(from, direction, 1.0 / SafeFraction, loop));
    lastAlpha = alpha;
    for (int k = 0; k < MaximumHalvings; ++k, alpha *= 0.5)
    {
      trial = from + alpha * direction;
      trialEnergy = this->Energy(trial, targets, loop);
      if (trialEnergy <= fromEnergy + SufficientDecrease * alpha * slope)
      {
        return true;
      }
    }
    return false;
  };

  // The targets' pull tightens stage by stage (a penalty continuation): a loose pull lets the
  // whole zone turn and shear towards the targets before a stiff one puts the boundary on them,
  // where a stiff pull from the start drags the boundary ahead of the interior and the steps
  // stall at the first flattened cell.
  std::vector<double> stages{ this->FinalWeight };
  while (stages.back() / ContinuationRatio >= FirstWeight)
  {
    stages.push_back(stages.back() / ContinuationRatio);
  }
  std::reverse(stages.begin(), stages.end());
  // Where targets are left short, the solve goes on from where it ended. Without a continuation
  // (a release from a drag's end), targets a little short are first taken for where the pull
  // balances the mesh, a shortfall that falls as the pull stiffens: one stiffer stage. Otherwise
  // (a stall at a flattening cell) the stages run from a loose pull: the stall that left the
  // targets is rarely met twice.
  const int rounds = continuation ? 2 : 3;
  // Where the loops stand: a new solve's start, or where Progress stopped the last one.
  SolveState state;
  if (resuming)
  {
    state = std::move(this->Cut);
    points = state.Iterate; // the iterate before its snap
  }
  else
  {
    // Without a continuation, the final pull; a solve that may not factor (a drag step) pulls
    // as stiffly as the factor it finds.
    const bool keepFactor = !options.Reweight && this->FactoredWeight > 0.0;
    state.Weights = continuation
      ? stages
      : std::vector<double>{ keepFactor ? this->FactoredWeight : this->FinalWeight };
    state.Energy = still ? 0.0 : Infinity;
    state.Continuation = continuation;
  }
  this->Cut.Active = false;
  double& energy = state.Energy;
  for (; state.Round < rounds && report.Iterations < options.MaximumIterations && !still &&
       !report.Stopped;
       ++state.Round, state.Stage = 0)
  {
    if (state.Round > 0 && state.Stage == 0 && state.StageIterations == 0)
    {
      const double miss = this->LargestMiss(points, targets);
      if (snap <= 0.0 || miss <= snap)
      {
        break;
      }
      const bool stiffen = !continuation && !state.Stiffened && miss <= NearMiss * snap;
      state.Weights = stiffen ? std::vector<double>{ state.Weights.back() * ContinuationRatio } : stages;
      state.Stiffened = state.Stiffened || stiffen;
      if (!stiffen)
      {
        // From a loose pull, from the rest stiffness, as any continuation starts.
        std::fill(this->TetWeights.begin(), this->TetWeights.end(), 1.0);
        this->FactoredWeight = 0.0;
      }
    }
    for (; state.Stage < state.Weights.size(); ++state.Stage, state.StageIterations = 0)
    {
      if (report.Iterations >= options.MaximumIterations || report.Stopped)
      {
        break;
      }
      const double weight = state.Weights[state.Stage];
      report.Error = this->FactorAt(weight, report);
      if (!report.Error.empty())
      {
        break;
      }
      this->Lambda = weight;
      if (state.StageIterations == 0)
      {
        state.Previous = points;
      }
      Positions& previous = state.Previous;
      for (; report.Iterations < options.MaximumIterations; ++state.StageIterations)
      {
        ++report.Iterations;
        // AQP: the step starts from x + theta (x - x_before), theta short of any flat tetrahedron.
        bool accepted = false;
        double trialEnergy = Infinity;
        if (options.Accelerate && state.StageIterations > 0)
        {
          const Positions momentum = points - previous;
          const double theta = std::min(Momentum,
            SafeFraction * this->LargestSafeStep(points, momentum, Momentum / SafeFraction, loop));
          const Positions start = points + theta * momentum;
          double startEnergy = Infinity;
          accepted = step(start, startEnergy, trialEnergy) && trialEnergy < energy;
        }
        // Without momentum where it did not lower the energy: the energy never rises.
        if (!accepted && !step(points, energy, trialEnergy))
        {
          break;
        }
        previous = points;
        points = trial;
        if (options.Reweight && lastAlpha < StallStep)
        {
          // A cell about to flatten stopped the step: the proxy stiffens the cells as the
          // energy's curvature has, and is factored again.
          this->Reweight(points, loop);
          report.Error = this->FactorAt(weight, report);
          if (!report.Error.empty())
          {
            break;
          }
          previous = points;
        }
        const double decrease = energy - trialEnergy;
        energy = trialEnergy;
        const bool proceed = !options.Progress ||
          options.Progress(static_cast<double>(report.Iterations) / options.MaximumIterations);
        // An iterate that converged at the final pull is the result, stopped or not: a solve
        // stopped after each iteration (a settle split by a time limit) still ends.
        const double tolerance = weight < this->FinalWeight ? StageTolerance : options.Tolerance;
        const bool converged = decrease <= tolerance * energy;
        if (!proceed && !(converged && weight >= this->FinalWeight))
        {
          // Where a resumed solve goes on: the next iteration of this stage, or the next stage.
          report.Stopped = true;
          this->Cut = state;
          this->Cut.Active = true;
          this->Cut.Iterate = points;
          if (converged)
          {
            ++this->Cut.Stage;
            this->Cut.StageIterations = 0;
          }
          else
          {
            ++this->Cut.StageIterations;
          }
          break;
        }
        if (converged)
        {
          break;
        }
      }
    }
  }
  // The distortion before the snap, which moves targeted points by less than `snap`.
  const double penalty = this->Penalty(points, targets);
  if (snap > 0.0)
  {
    this->Snap(targets, points, snap);
  }
  for (int p : this->Unknowns)
  {
    if (this->Kinds[p] == PointKind::Targeted)
    {
      this->Misses[p] = (points.row(p) - targets.row(p)).norm();
      report.LargestMiss = std::max(report.LargestMiss, this->Misses[p]);
    }
  }
  if (!std::isfinite(energy))
  {
    // A start with inverted tetrahedra was not moved.
    for (int c = 0; c < this->Tets.rows(); ++c)
    {
      report.Inverted += !(Edges(points, this->Tets, c).determinant() > 0.0);
    }
  }
  report.Distortion = report.Inverted > 0 ? Infinity : (energy - penalty) / this->TotalVolume;
  return report;
}
}
