#include "DeformationSystem.h"

namespace LaplacianEditing
{
std::string DeformationSystem::Build(
  const SurfaceMesh& mesh, const EditRegion& region, const DeformationOptions& options)
{
  const int n = region.GetNumberOfVertices();
  const auto& positions = mesh.GetPositions();
  std::vector<int> local(mesh.GetNumberOfVertices(), -1);
  for (int k = 0; k < n; ++k)
  {
    local[region.Vertices[k]] = k;
  }

  const LaplacianOperator laplacian(mesh, options.Weights);
  std::vector<Eigen::Triplet<double>> triplets;
  this->RestPositions.resize(n, 3);
  this->RestDelta.setZero(n, 3);
  this->FixedPart.setZero(n, 3);
  for (int k = 0; k < n; ++k)
  {
    const int v = region.Vertices[k];
    this->RestPositions.row(k) = positions[v].transpose();
    for (const auto& [j, coefficient] : laplacian.Row(v, options.Order))
    {
      this->RestDelta.row(k) += coefficient * positions[j].transpose();
      if (local[j] >= 0)
      {
        triplets.emplace_back(k, local[j], coefficient);
      }
      else
      {
        this->FixedPart.row(k) += coefficient * positions[j].transpose();
      }
    }
  }
  this->RegionOperator.resize(n, n);
  this->RegionOperator.setFromTriplets(triplets.begin(), triplets.end());

  this->SquaredWeights.setZero(n);
  this->HandleGroups = region.HandleGroups;
  for (int k = 0; k < n; ++k)
  {
    if (region.Roles[k] == VertexRole::Handle)
    {
      this->SquaredWeights[k] = options.HandleWeight * options.HandleWeight;
    }
    else if (region.Roles[k] == VertexRole::Anchor)
    {
      const double weight = options.AnchorWeight * region.RelativeDistances[k];
      this->SquaredWeights[k] = weight * weight;
    }
  }

  this->NormalMatrix = Eigen::SparseMatrix<double>(this->RegionOperator.transpose()) *
    Eigen::SparseMatrix<double>(this->RegionOperator);
  for (int k = 0; k < n; ++k)
  {
    this->NormalMatrix.coeffRef(k, k) += this->SquaredWeights[k];
  }
  this->NormalMatrix.makeCompressed();

  Positions anchorTerm = Positions::Zero(n, 3);
  for (int k = 0; k < n; ++k)
  {
    if (region.Roles[k] == VertexRole::Anchor)
    {
      anchorTerm.row(k) = this->SquaredWeights[k] * this->RestPositions.row(k);
    }
  }
  this->ConstantRightHandSide =
    this->RegionOperator.transpose() * (this->RestDelta - this->FixedPart) + anchorTerm;

  return this->Factor.Factorize(this->NormalMatrix, options.Backend);
}

Positions DeformationSystem::SolveRightHandSide(
  Positions rhs, const std::vector<AffineMap>& handleMaps) const
{
  for (int k = 0; k < rhs.rows(); ++k)
  {
    const int group = this->HandleGroups[k];
    if (group < 0)
    {
      continue;
    }
    const Eigen::Vector3d rest = this->RestPositions.row(k).transpose();
    const Eigen::Vector3d target = group < static_cast<int>(handleMaps.size())
      ? Eigen::Vector3d(handleMaps[group].leftCols<3>() * rest + handleMaps[group].col(3))
      : rest;
    rhs.row(k) += this->SquaredWeights[k] * target.transpose();
  }
  return this->Factor.Solve(rhs);
}

Positions DeformationSystem::Solve(const std::vector<AffineMap>& handleMaps) const
{
  return this->SolveRightHandSide(this->ConstantRightHandSide, handleMaps);
}

Positions DeformationSystem::SolveWithDifferentialCoordinates(
  const Positions& differentialCoordinates, const std::vector<AffineMap>& handleMaps) const
{
  Positions rhs = this->ConstantRightHandSide +
    this->RegionOperator.transpose() * (differentialCoordinates - this->RestDelta);
  return this->SolveRightHandSide(std::move(rhs), handleMaps);
}
}
