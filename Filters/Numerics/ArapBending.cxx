#include "ArapBending.h"

namespace LaplacianEditing
{
void ArapBending::Build(double weight, const ArapRings& rings,
  const std::vector<int>& unknownOfPatch, Eigen::SparseMatrix<double>& upper)
{
  *this = ArapBending();
  const int vertices = static_cast<int>(rings.RestEdgeSums.size());
  if (weight <= 0.0 || vertices == 0 || upper.rows() == 0)
  {
    return;
  }
  // Each ring's row c_i on the free unknowns (W_i at i, -w_ij at j), kept for the right-hand
  // sides, and sum_i c_i^T c_i / W_i^2 (mu = 1), the upper triangle.
  std::vector<Eigen::Triplet<double>> triplets;
  this->Coefficients.resize(vertices);
  this->RingWeights.resize(vertices);
  this->RowOffsets.assign(1, 0);
  for (int i = 0; i < vertices; ++i)
  {
    double total = 0.0;
    for (int k = rings.Offsets[i]; k < rings.Offsets[i + 1]; ++k)
    {
      total += rings.Weights[k];
      if (unknownOfPatch[rings.Neighbors[k]] >= 0)
      {
        this->RowUnknowns.push_back(unknownOfPatch[rings.Neighbors[k]]);
        this->RowEntries.push_back(-rings.Weights[k]);
      }
    }
    if (unknownOfPatch[i] >= 0)
    {
      this->RowUnknowns.push_back(unknownOfPatch[i]);
      this->RowEntries.push_back(total);
    }
    this->RowOffsets.push_back(static_cast<int>(this->RowUnknowns.size()));
    this->RingWeights[i] = total;
    this->Coefficients[i] = total > 0.0 ? 1.0 / (total * total) : 0.0;
    for (int a = this->RowOffsets[i]; a < this->RowOffsets[i + 1]; ++a)
    {
      for (int b = this->RowOffsets[i]; b < this->RowOffsets[i + 1]; ++b)
      {
        if (this->RowUnknowns[a] <= this->RowUnknowns[b])
        {
          triplets.emplace_back(this->RowUnknowns[a], this->RowUnknowns[b],
            this->Coefficients[i] * this->RowEntries[a] * this->RowEntries[b]);
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
  const std::vector<Vector3>& rest, Eigen::Ref<Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>> rhs) const
{
  // A scatter of each ring's share into its free unknowns: serial, a pass over the rings.
  auto moved = [&](int row) -> Vector3 { return patch[row] - rest[row]; };
  for (int i = 0; i < static_cast<int>(this->Coefficients.size()); ++i)
  {
    // (R_i - I) s_i less the ring row's known part, c_i u over the known patch rows.
    const Vector3& sum = rings.RestEdgeSums[i];
    Vector3 target = rotations[i] * sum - sum;
    for (int k = rings.Offsets[i]; k < rings.Offsets[i + 1]; ++k)
    {
      if (unknownOfPatch[rings.Neighbors[k]] < 0)
      {
        target += rings.Weights[k] * moved(rings.Neighbors[k]);
      }
    }
    if (unknownOfPatch[i] < 0)
    {
      target -= this->RingWeights[i] * moved(i);
    }
    for (int a = this->RowOffsets[i]; a < this->RowOffsets[i + 1]; ++a)
    {
      rhs.row(this->RowUnknowns[a]) += (this->Coefficients[i] * this->RowEntries[a]) * target.transpose();
    }
  }
}
}
