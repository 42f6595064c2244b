// The types the core's interfaces share: points, point blocks and affine maps, all Eigen.
#ifndef LaplacianEditing_Types_h
#define LaplacianEditing_Types_h

#include <Eigen/Core>
#include <Eigen/Geometry> // cross products

namespace LaplacianEditing
{
using Vector3 = Eigen::Vector3d;
/// One row per vertex.
using Positions = Eigen::Matrix<double, Eigen::Dynamic, 3>;
/// x' = M x + t, stored as [M | t].
using AffineMap = Eigen::Matrix<double, 3, 4>;
}

#endif
