// Some rows of a solution that is affine in the handle maps, for a process that must place
// its own points without solving. With p the maps' entries (HandleMapParameters), row i is
// Offsets.row(i) + (Responses.middleRows(3 i, 3) p)^T. Where each coordinate responds to its
// own row of the maps alike (the None mode, see DeformationSystem.h), Responses holds one row
// per position and four columns per group, x_c = Offsets(i, c) + sum_g R_g(i, :) [M_g | t_g]
// row c: a ninth of the numbers. The implicit mode without the rigid correction couples the
// coordinates.
#ifndef LaplacianEditing_AffineRows_h
#define LaplacianEditing_AffineRows_h

#include "Types.h"

#include <vector>

namespace LaplacianEditing
{
struct AffineRows
{
  Positions Offsets;
  /// Coupled: three rows per position (x, y, z), twelve columns per handle group (its
  /// [M | t] row by row). Otherwise one row per position and four columns per group.
  Eigen::MatrixXd Responses;
  bool Coupled = true;

  /// The rows' positions for the parameters of HandleMapParameters.
  Positions Evaluate(const Eigen::VectorXd& parameters) const;
};

/// The entries of `groups` handle maps, twelve per group ([M | t] row by row); a missing map
/// is the identity.
Eigen::VectorXd HandleMapParameters(const std::vector<AffineMap>& maps, int groups);
}

#endif
