#include "DeformationSystem.h"

#include <numeric>

namespace LaplacianEditing
{
std::string DeformationSystem::Build(
  const SurfaceMesh& mesh, const EditRegion& region, const DeformationOptions& options)
{
  const int n = region.GetNumberOfVertices();
  std::vector<int> local(mesh.GetNumberOfVertices(), -1);
  for (int k = 0; k < n; ++k)
  {
    local[region.Vertices[k]] = k;
  }
  const LaplacianOperator laplacian(mesh, options.Weights);
  this->AssembleOperator(mesh, region, laplacian, local, options.Order);
  if (options.Order >= 2)
  {
    this->BuildFirstOrder(mesh, region, laplacian, local);
  }
  this->WeighConstraints(region, options);
  const std::string error = this->FactorNormalEquations(options, local);
  if (!error.empty())
  {
    return error;
  }
  this->ComputeResponses(region.NumberOfHandleGroups);
  return {};
}

void DeformationSystem::AssembleOperator(const SurfaceMesh& mesh, const EditRegion& region,
  const LaplacianOperator& laplacian, const std::vector<int>& local, int order)
{
  // The operator's rows over the ROI columns; its terms on fixed vertices go to FixedPart.
  const int n = region.GetNumberOfVertices();
  const auto& positions = mesh.GetPositions();
  std::vector<Eigen::Triplet<double>> triplets;
  this->RestPositions.resize(n, 3);
  this->RestDelta.setZero(n, 3);
  this->FixedPart.setZero(n, 3);
  for (int k = 0; k < n; ++k)
  {
    const int v = region.Vertices[k];
    this->RestPositions.row(k) = positions[v].transpose();
    // The bi-Laplacian takes two rings of known values on each side: the fixed part and the
    // handle. Its rows at handle vertices would instead ask a turned handle to keep the rest
    // orientation of its second-order coordinates, which reaches two rings into the free part
    // and inflates it.
    if (order >= 2 && region.Roles[k] == VertexRole::Handle)
    {
      continue;
    }
    for (const auto& [j, coefficient] : laplacian.Row(v, order))
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
}

void DeformationSystem::WeighConstraints(const EditRegion& region, const DeformationOptions& options)
{
  const int n = region.GetNumberOfVertices();
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
}

std::string DeformationSystem::FactorNormalEquations(
  const DeformationOptions& options, const std::vector<int>& local)
{
  const int n = this->GetNumberOfUnknowns();
  Eigen::SparseMatrix<double> normalMatrix =
    Eigen::SparseMatrix<double>(this->RegionOperator.transpose()) *
    Eigen::SparseMatrix<double>(this->RegionOperator);
  for (int k = 0; k < n; ++k)
  {
    normalMatrix.coeffRef(k, k) += this->SquaredWeights[k];
  }
  normalMatrix.makeCompressed();
  this->Points = PointConstraints();
  if (options.Points)
  {
    std::vector<int> unknowns(n);
    std::iota(unknowns.begin(), unknowns.end(), 0);
    std::string error = this->Points.Build(*options.Points, local);
    if (error.empty())
    {
      this->RestPoints = this->Points.Evaluate(this->RestPositions);
      this->Points.Weigh(options.PointWeight, normalMatrix);
      error = this->Points.AddToMatrix(normalMatrix, unknowns, 1);
    }
    if (!error.empty())
    {
      return error;
    }
  }
  this->RegionOperatorTransposed = this->RegionOperator.transpose();
  this->RestRightHandSide = this->RegionOperatorTransposed * (this->RestDelta - this->FixedPart);
  return this->Factor.Factorize(normalMatrix, options.Backend, options.Ordering,
    options.MaximumFactorBytes, 1, options.Distributed);
}

void DeformationSystem::ComputeResponses(int groups)
{
  // The rest solution and the handle responses, in one multi-column solve.
  Eigen::MatrixXd rhs(this->GetNumberOfUnknowns(), 3 + 4 * groups);
  rhs.leftCols<3>() =
    this->RestRightHandSide + this->ConstraintRightHandSide(std::vector<AffineMap>(groups, AffineMap::Zero()));
  for (int g = 0; g < groups; ++g)
  {
    rhs.middleCols<4>(3 + 4 * g) = this->HandleBasis(g);
  }
  const Eigen::MatrixXd solution = this->Factor.Solve(rhs);
  this->Responses.Coupled = false; // each coordinate responds to its own row of a map alike
  this->Responses.Offsets = solution.leftCols<3>();
  this->Responses.Responses = solution.rightCols(4 * groups);
  this->NumberOfHandleGroups = groups;
}

void DeformationSystem::BuildFirstOrder(const SurfaceMesh& mesh, const EditRegion& region,
  const LaplacianOperator& laplacian, const std::vector<int>& local)
{
  const int n = region.GetNumberOfVertices();
  const auto& positions = mesh.GetPositions();
  auto delta = [&](int v) {
    Vector3 d = Vector3::Zero();
    for (const auto& [j, coefficient] : laplacian.Row(v, 1))
    {
      d += coefficient * positions[j];
    }
    return d;
  };
  std::vector<Eigen::Triplet<double>> triplets;
  this->FirstOrderDelta.resize(n, 3);
  this->FirstOrderOutside.setZero(n, 3);
  for (int k = 0; k < n; ++k)
  {
    const int v = region.Vertices[k];
    this->FirstOrderDelta.row(k) = delta(v).transpose();
    for (const auto& [j, coefficient] : laplacian.Row(v, 1))
    {
      if (local[j] >= 0)
      {
        triplets.emplace_back(k, local[j], coefficient);
      }
      else
      {
        this->FirstOrderOutside.row(k) += coefficient * delta(j).transpose();
      }
    }
  }
  this->FirstOrderRegion.resize(n, n);
  this->FirstOrderRegion.setFromTriplets(triplets.begin(), triplets.end());
}

Positions DeformationSystem::ComposeSecondOrder(const Positions& firstOrder) const
{
  return this->FirstOrderRegion * firstOrder + this->FirstOrderOutside;
}

Eigen::MatrixXd DeformationSystem::HandleBasis(int group) const
{
  const int n = this->GetNumberOfUnknowns();
  Eigen::MatrixXd basis = Eigen::MatrixXd::Zero(n, 4);
  for (int k = 0; k < n; ++k)
  {
    if (this->HandleGroups[k] == group)
    {
      basis.row(k) << this->RestPositions.row(k), 1.0;
      basis.row(k) *= this->SquaredWeights[k];
    }
  }
  return basis;
}

Positions DeformationSystem::ConstraintRightHandSide(const std::vector<AffineMap>& handleMaps) const
{
  Positions term = Positions::Zero(this->RestPositions.rows(), 3);
  for (int k = 0; k < term.rows(); ++k)
  {
    if (this->SquaredWeights[k] == 0.0)
    {
      continue;
    }
    const Eigen::Vector3d rest = this->RestPositions.row(k).transpose();
    const int group = this->HandleGroups[k];
    const Eigen::Vector3d target = group >= 0 && group < static_cast<int>(handleMaps.size())
      ? Eigen::Vector3d(handleMaps[group].leftCols<3>() * rest + handleMaps[group].col(3))
      : rest;
    term.row(k) = this->SquaredWeights[k] * target.transpose();
  }
  return term;
}

Positions DeformationSystem::Solve(
  const std::vector<AffineMap>& handleMaps, const Positions& pointTargets) const
{
  const Eigen::VectorXd maps = HandleMapParameters(handleMaps, this->NumberOfHandleGroups);
  if (this->Points.IsEmpty())
  {
    return this->Responses.Evaluate(maps);
  }
  // With points, as a displacement from the rest shape (see PointPull).
  const Eigen::VectorXd identities = HandleMapParameters({}, this->NumberOfHandleGroups);
  return this->RestPositions + (this->Responses.Evaluate(maps) - this->Responses.Evaluate(identities)) +
    Positions(this->Factor.Solve(this->PointPull(pointTargets)));
}

AffineRows DeformationSystem::GetAffineRows(const std::vector<int>& rows) const
{
  AffineRows affine;
  affine.Coupled = false;
  affine.Offsets.resize(static_cast<Eigen::Index>(rows.size()), 3);
  affine.Responses.resize(static_cast<Eigen::Index>(rows.size()), this->Responses.Responses.cols());
  for (std::size_t i = 0; i < rows.size(); ++i)
  {
    affine.Offsets.row(i) = this->Responses.Offsets.row(rows[i]);
    affine.Responses.row(i) = this->Responses.Responses.row(rows[i]);
  }
  return affine;
}

Positions DeformationSystem::SolveDirect(
  const std::vector<AffineMap>& handleMaps, const Positions& pointTargets) const
{
  if (this->Points.IsEmpty())
  {
    return this->Factor.Solve(this->RestRightHandSide + this->ConstraintRightHandSide(handleMaps));
  }
  return this->RestPositions +
    Positions(this->Factor.Solve(this->ConstraintRightHandSide(handleMaps) -
      this->ConstraintRightHandSide({}) + this->PointPull(pointTargets)));
}

Positions DeformationSystem::SolveWithDifferentialCoordinates(
  const Positions& differentialCoordinates, const std::vector<AffineMap>& handleMaps,
  const ParallelFor& loop, const Positions& pointTargets) const
{
  // With points, as a displacement from the rest shape (see PointPull): the rest coordinates'
  // share and the handles' at rest leave the right-hand side.
  const bool displaced = !this->Points.IsEmpty();
  const Positions residual =
    differentialCoordinates - (displaced ? this->RestDelta : this->FixedPart);
  Positions rhs = this->ConstraintRightHandSide(handleMaps);
  if (displaced)
  {
    rhs += this->PointPull(pointTargets) - this->ConstraintRightHandSide({});
  }
  const auto& transposed = this->RegionOperatorTransposed;
  loop(0, this->GetNumberOfUnknowns(), [&](int first, int last) {
    for (int k = first; k < last; ++k)
    {
      for (Eigen::SparseMatrix<double, Eigen::RowMajor>::InnerIterator it(transposed, k); it; ++it)
      {
        rhs.row(k) += it.value() * residual.row(it.col());
      }
    }
  });
  const Positions solution = this->Factor.Solve(rhs, loop);
  return displaced ? Positions(this->RestPositions + solution) : solution;
}

Positions DeformationSystem::PointPull(const Positions& pointTargets) const
{
  return this->Points.RightHandSide(pointTargets - this->RestPoints, this->GetNumberOfUnknowns());
}
}
