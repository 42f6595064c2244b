#include "ArapBending.h"

#include <algorithm>
#include <utility>

namespace LaplacianEditing
{
namespace
{
// Vertex i's ring row c_i on the free unknowns: (unknown, coefficient) pairs.
void RingRow(const ArapRings& rings, const std::vector<int>& unknownOfPatch, int i,
  std::vector<std::pair<int, double>>& row)
{
  row.clear();
  double total = 0.0;
  for (int k = rings.Offsets[i]; k < rings.Offsets[i + 1]; ++k)
  {
    total += rings.Weights[k];
    if (unknownOfPatch[rings.Neighbors[k]] >= 0)
    {
      row.emplace_back(unknownOfPatch[rings.Neighbors[k]], -rings.Weights[k]);
    }
  }
  if (unknownOfPatch[i] >= 0)
  {
    row.emplace_back(unknownOfPatch[i], total);
  }
}
}

void ArapBending::Build(double weight, const ArapRings& rings,
  const std::vector<int>& unknownOfPatch, Eigen::SparseMatrix<double>& upper)
{
  this->Coefficients.clear();
  const int vertices = static_cast<int>(rings.RestEdgeSums.size());
  if (weight <= 0.0 || vertices == 0 || upper.rows() == 0)
  {
    return;
  }
  // sum_i c_i^T c_i / W_i^2 (mu = 1), the upper triangle.
  std::vector<Eigen::Triplet<double>> triplets;
  std::vector<std::pair<int, double>> row;
  this->Coefficients.resize(vertices);
  for (int i = 0; i < vertices; ++i)
  {
    double total = 0.0;
    for (int k = rings.Offsets[i]; k < rings.Offsets[i + 1]; ++k)
    {
      total += rings.Weights[k];
    }
    this->Coefficients[i] = total > 0.0 ? 1.0 / (total * total) : 0.0;
    RingRow(rings, unknownOfPatch, i, row);
    for (const auto& [a, ca] : row)
    {
      for (const auto& [b, cb] : row)
      {
        if (a <= b)
        {
          triplets.emplace_back(a, b, this->Coefficients[i] * ca * cb);
        }
      }
    }
  }
  Eigen::SparseMatrix<double> term(upper.rows(), upper.cols());
  term.setFromTriplets(triplets.begin(), triplets.end());
  const double termDiagonal = term.diagonal().mean();
  const double mu = termDiagonal > 0.0 ? weight * upper.diagonal().mean() / termDiagonal : 0.0;
  for (double& coefficient : this->Coefficients)
  {
    coefficient *= mu;
  }
  upper = upper + mu * term;
  upper.makeCompressed();
}

void ArapBending::AddToRightHandSide(const ArapRings& rings, const std::vector<int>& unknownOfPatch,
  const std::vector<Eigen::Matrix3d>& rotations, const std::vector<Vector3>& patch,
  const Positions& rest, Eigen::Ref<Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>> rhs) const
{
  // A scatter of each ring's share into its free unknowns: serial, a pass over the rings.
  auto moved = [&](int row) -> Vector3 { return patch[row] - rest.row(row).transpose(); };
  std::vector<std::pair<int, double>> row;
  for (int i = 0; i < static_cast<int>(this->Coefficients.size()); ++i)
  {
    // (R_i - I) s_i less the ring row's known part, c_i u over the known patch rows.
    const Vector3& sum = rings.RestEdgeSums[i];
    Vector3 target = rotations[i] * sum - sum;
    double total = 0.0;
    for (int k = rings.Offsets[i]; k < rings.Offsets[i + 1]; ++k)
    {
      total += rings.Weights[k];
      if (unknownOfPatch[rings.Neighbors[k]] < 0)
      {
        target += rings.Weights[k] * moved(rings.Neighbors[k]);
      }
    }
    if (unknownOfPatch[i] < 0)
    {
      target -= total * moved(i);
    }
    RingRow(rings, unknownOfPatch, i, row);
    for (const auto& [u, c] : row)
    {
      rhs.row(u) += (this->Coefficients[i] * c) * target.transpose();
    }
  }
}
}
