#include "LaplacianOperator.h"

#include <algorithm>
#include <cmath>

namespace LaplacianEditing
{
namespace
{
// Cotangent of the angle between u and v, with the sine floored (see the header).
double RobustCotangent(const Vector3& u, const Vector3& v)
{
  const double lengths = u.norm() * v.norm();
  const double sine = std::max(u.cross(v).norm(), 1e-6 * lengths);
  return sine > 0.0 ? u.dot(v) / sine : 0.0;
}

// Sorts a row by vertex and sums the coefficients of repeated vertices.
void Compress(SparseRow& row)
{
  std::sort(row.begin(), row.end(),
    [](const auto& a, const auto& b) { return a.first < b.first; });
  std::size_t last = 0;
  for (std::size_t i = 1; i < row.size(); ++i)
  {
    if (row[i].first == row[last].first)
    {
      row[last].second += row[i].second;
    }
    else
    {
      row[++last] = row[i];
    }
  }
  row.resize(row.empty() ? 0 : last + 1);
}
}

LaplacianOperator::LaplacianOperator(const SurfaceMesh& mesh, LaplacianWeights weights)
  : Mesh(mesh)
  , Weights(weights)
{
}

std::vector<double> LaplacianOperator::EdgeWeights(int v) const
{
  const int valence = this->Mesh.GetValence(v);
  const int* neighbors = this->Mesh.NeighborsBegin(v);
  std::vector<double> weights(valence, 1.0);
  if (this->Weights == LaplacianWeights::Uniform || valence == 0)
  {
    return weights;
  }
  std::fill(weights.begin(), weights.end(), 0.0);
  const auto& p = this->Mesh.GetPositions();
  auto slot = [&](int w) { return std::lower_bound(neighbors, neighbors + valence, w) - neighbors; };
  for (const int* t = this->Mesh.TrianglesBegin(v); t != this->Mesh.TrianglesEnd(v); ++t)
  {
    const auto& tri = this->Mesh.GetTriangles()[*t];
    const int corner = tri[0] == v ? 0 : (tri[1] == v ? 1 : 2);
    const int a = tri[(corner + 1) % 3];
    const int b = tri[(corner + 2) % 3];
    // The angle at b faces edge (v, a); the angle at a faces edge (v, b).
    weights[slot(a)] += 0.5 * RobustCotangent(p[v] - p[b], p[a] - p[b]);
    weights[slot(b)] += 0.5 * RobustCotangent(p[v] - p[a], p[b] - p[a]);
  }
  double total = 0.0;
  for (double& w : weights)
  {
    w = std::max(w, 0.0);
    total += w;
  }
  if (!(total > 1e-12) || !std::isfinite(total))
  {
    std::fill(weights.begin(), weights.end(), 1.0);
  }
  return weights;
}

SparseRow LaplacianOperator::FirstOrderRow(int v) const
{
  const int valence = this->Mesh.GetValence(v);
  SparseRow row;
  row.reserve(valence + 1);
  if (valence == 0)
  {
    return row;
  }
  const int* neighbors = this->Mesh.NeighborsBegin(v);
  const std::vector<double> weights = this->EdgeWeights(v);
  double total = 0.0;
  for (double w : weights)
  {
    total += w;
  }
  // Neighbours are sorted; insert the diagonal in order.
  bool diagonalPlaced = false;
  for (int k = 0; k < valence; ++k)
  {
    if (!diagonalPlaced && neighbors[k] > v)
    {
      row.emplace_back(v, 1.0);
      diagonalPlaced = true;
    }
    row.emplace_back(neighbors[k], -weights[k] / total);
  }
  if (!diagonalPlaced)
  {
    row.emplace_back(v, 1.0);
  }
  return row;
}

SparseRow LaplacianOperator::Row(int v, int order) const
{
  SparseRow first = this->FirstOrderRow(v);
  if (order < 2)
  {
    return first;
  }
  SparseRow square;
  for (const auto& [k, coefficient] : first)
  {
    for (const auto& [j, value] : this->FirstOrderRow(k))
    {
      square.emplace_back(j, coefficient * value);
    }
  }
  Compress(square);
  return square;
}

Eigen::SparseMatrix<double> LaplacianOperator::Matrix() const
{
  std::vector<Eigen::Triplet<double>> triplets;
  for (int v = 0; v < this->Mesh.GetNumberOfVertices(); ++v)
  {
    for (const auto& [j, value] : this->FirstOrderRow(v))
    {
      triplets.emplace_back(v, j, value);
    }
  }
  const int n = this->Mesh.GetNumberOfVertices();
  Eigen::SparseMatrix<double> matrix(n, n);
  matrix.setFromTriplets(triplets.begin(), triplets.end());
  return matrix;
}
}
