#include "AffineRows.h"

namespace LaplacianEditing
{
Positions AffineRows::Evaluate(const Eigen::VectorXd& parameters) const
{
  Positions positions = this->Offsets;
  if (this->Coupled)
  {
    const Eigen::VectorXd moved = this->Responses * parameters;
    positions += Eigen::Map<const Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>>(
      moved.data(), this->Offsets.rows(), 3);
    return positions;
  }
  for (Eigen::Index g = 0; 12 * g + 12 <= parameters.size(); ++g)
  {
    const Eigen::Map<const Eigen::Matrix<double, 3, 4, Eigen::RowMajor>> map(parameters.data() + 12 * g);
    positions.noalias() += this->Responses.middleCols<4>(4 * g) * map.transpose();
  }
  return positions;
}

Eigen::VectorXd HandleMapParameters(const std::vector<AffineMap>& maps, int groups)
{
  Eigen::VectorXd parameters(12 * groups);
  for (int g = 0; g < groups; ++g)
  {
    const Eigen::Matrix<double, 3, 4, Eigen::RowMajor> map =
      static_cast<std::size_t>(g) < maps.size() ? maps[g] : AffineMap::Identity();
    parameters.segment<12>(12 * g) = Eigen::Map<const Eigen::Matrix<double, 12, 1>>(map.data());
  }
  return parameters;
}
}
