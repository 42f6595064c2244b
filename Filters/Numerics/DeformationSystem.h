// The least-squares editing system of Sections 3 and 6, restricted to the region of interest.
//
// Unknowns are the ROI vertices. Each ROI vertex contributes its differential-coordinate row
// D(v') = delta, with neighbours outside the ROI moved to the right-hand side, so the edit
// blends continuously into the fixed mesh. Handle and anchor vertices add soft constraints
// w_i v'_i = w_i u_i. The normal equations (A^T A) v' = A^T b are factored once per region; a
// handle move, or new (rotated) differential coordinates, only change the right-hand side.
#ifndef LaplacianEditing_DeformationSystem_h
#define LaplacianEditing_DeformationSystem_h

#include "EditRegion.h"
#include "LaplacianOperator.h"
#include "SparseCholesky.h"

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include <string>
#include <vector>

namespace LaplacianEditing
{
using AffineMap = Eigen::Matrix<double, 3, 4>;
using Positions = Eigen::Matrix<double, Eigen::Dynamic, 3>;

struct DeformationOptions
{
  LaplacianWeights Weights = LaplacianWeights::Uniform;
  int Order = 1;
  /// Weight of the handle constraints; large enough that handles land on their targets.
  double HandleWeight = 100.0;
  /// Weight of the outermost anchors; an anchor's weight is this times its relative distance
  /// from the handle (Section 6).
  double AnchorWeight = 1.0;
  SolverBackend Backend = SolverBackend::Cholmod;
};

class DeformationSystem
{
public:
  /// Assembles and factors the system. Returns an error message, empty on success.
  std::string Build(const SurfaceMesh& mesh, const EditRegion& region,
    const DeformationOptions& options);

  /// Reconstructs the ROI from its rest differential coordinates, moving each handle group g
  /// by handleMaps[g] (a missing map means identity). Rows follow region.Vertices.
  Positions Solve(const std::vector<AffineMap>& handleMaps) const;

  /// The same with other differential coordinates, for example rotated ones.
  Positions SolveWithDifferentialCoordinates(
    const Positions& differentialCoordinates, const std::vector<AffineMap>& handleMaps) const;

  /// The constraints' share of A^T b: w_i^2 u_i, with u_i the transformed rest position of a
  /// handle vertex and the rest position of an anchor; zero for free vertices.
  Positions ConstraintRightHandSide(const std::vector<AffineMap>& handleMaps) const;

  const Positions& GetRestPositions() const { return this->RestPositions; }
  const Positions& GetRestDifferentialCoordinates() const { return this->RestDelta; }
  /// Differential rows restricted to the ROI columns (the unknowns).
  const Eigen::SparseMatrix<double, Eigen::RowMajor>& GetRegionOperator() const
  {
    return this->RegionOperator;
  }
  /// Contribution of the fixed vertices (outside the ROI) to each differential row.
  const Positions& GetFixedPart() const { return this->FixedPart; }
  /// Squared constraint weight of each ROI vertex (0 for free vertices).
  const Eigen::VectorXd& GetSquaredWeights() const { return this->SquaredWeights; }
  int GetNumberOfUnknowns() const { return static_cast<int>(this->RestPositions.rows()); }
  const SparseCholesky& GetFactor() const { return this->Factor; }

private:
  Eigen::SparseMatrix<double, Eigen::RowMajor> RegionOperator;
  SparseCholesky Factor;
  Positions RestPositions;
  Positions RestDelta;
  Positions FixedPart;
  Eigen::VectorXd SquaredWeights;
  std::vector<int> HandleGroups;
  // L^T (delta - fixed part) for the rest differential coordinates: constant per region.
  Positions RestRightHandSide;
};
}

#endif
