#include "DisplacementLattice.h"

#include <Eigen/SparseCore>

#include <algorithm>
#include <cmath>
#include <vector>

namespace LaplacianEditing
{
namespace
{
// The cell of `p` and its trilinear weights at the cell's eight corners (their rows); false
// outside the lattice.
bool Corners(const LatticeGeometry& lattice, const Vector3& p, std::array<int, 8>& rows,
  std::array<double, 8>& weights)
{
  int cell[3];
  double t[3];
  for (int a = 0; a < 3; ++a)
  {
    const double x = (p[a] - lattice.Origin[a]) / lattice.Spacing[a];
    const int last = lattice.Dimensions[a] - 1;
    if (!(x >= 0.0 && x <= last))
    {
      return false;
    }
    cell[a] = std::min(static_cast<int>(std::floor(x)), last - 1);
    t[a] = x - cell[a];
  }
  const int nx = lattice.Dimensions[0], ny = lattice.Dimensions[1];
  for (int c = 0; c < 8; ++c)
  {
    const int dx = c & 1, dy = (c >> 1) & 1, dz = (c >> 2) & 1;
    rows[c] = (cell[0] + dx) + nx * ((cell[1] + dy) + ny * (cell[2] + dz));
    weights[c] = (dx ? t[0] : 1.0 - t[0]) * (dy ? t[1] : 1.0 - t[1]) * (dz ? t[2] : 1.0 - t[2]);
  }
  return true;
}
}

std::string FitDisplacementLattice(const LatticeGeometry& lattice, const Positions& points,
  const Positions& displacements, double smoothness, Positions& nodes, SolverBackend backend)
{
  const int nx = lattice.Dimensions[0], ny = lattice.Dimensions[1], nz = lattice.Dimensions[2];
  if (nx < 2 || ny < 2 || nz < 2)
  {
    return "the lattice needs two nodes at least along each axis";
  }
  const int n = nx * ny * nz;
  std::vector<Eigen::Triplet<double>> triplets;
  Eigen::MatrixXd rhs = Eigen::MatrixXd::Zero(n, 3);
  double dataWeight = 0.0;
  std::array<int, 8> rows;
  std::array<double, 8> weights;
  for (Eigen::Index p = 0; p < points.rows(); ++p)
  {
    if (!Corners(lattice, points.row(p).transpose(), rows, weights))
    {
      continue;
    }
    for (int a = 0; a < 8; ++a)
    {
      rhs.row(rows[a]) += weights[a] * displacements.row(p);
      dataWeight += weights[a] * weights[a];
      for (int b = 0; b < 8; ++b)
      {
        triplets.emplace_back(rows[a], rows[b], weights[a] * weights[b]);
      }
    }
  }
  if (dataWeight == 0.0)
  {
    return "no point lies inside the lattice";
  }
  const double mu = smoothness * dataWeight / n;
  auto edge = [&](int a, int b) {
    triplets.emplace_back(a, a, mu);
    triplets.emplace_back(b, b, mu);
    triplets.emplace_back(a, b, -mu);
    triplets.emplace_back(b, a, -mu);
  };
  for (int k = 0; k < nz; ++k)
  {
    for (int j = 0; j < ny; ++j)
    {
      for (int i = 0; i < nx; ++i)
      {
        const int row = i + nx * (j + ny * k);
        if (i + 1 < nx)
        {
          edge(row, row + 1);
        }
        if (j + 1 < ny)
        {
          edge(row, row + nx);
        }
        if (k + 1 < nz)
        {
          edge(row, row + nx * ny);
        }
      }
    }
  }
  Eigen::SparseMatrix<double> matrix(n, n);
  matrix.setFromTriplets(triplets.begin(), triplets.end());
  SparseCholesky factor;
  const std::string error = factor.Factorize(matrix, backend, FillOrdering::METIS);
  if (!error.empty())
  {
    return error;
  }
  nodes = factor.Solve(rhs);
  return {};
}
}
