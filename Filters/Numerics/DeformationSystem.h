// The least-squares editing system of Sections 3 and 6, restricted to the region of interest.
//
// Unknowns are the ROI vertices. Each ROI vertex contributes its differential-coordinate row
// D(v') = delta, with neighbours outside the ROI moved to the right-hand side, so the edit
// blends continuously into the fixed mesh. Handle and anchor vertices add soft constraints
// w_i v'_i = w_i u_i. The normal equations (A^T A) v' = A^T b are factored once per region; a
// handle move, or new (rotated) differential coordinates, only change the right-hand side.
//
// With the rest differential coordinates the solution is affine in each handle group's map
// [M | t]: v' = v'_0 + sum_g R_g [M_g | t_g]^T, with R_g = (A^T A)^-1 W_g^2 [v_g | 1]. Build
// solves for v'_0 and the n x 4 responses R_g once, so a handle move is a small dense product
// instead of two sparse triangular solves.
#ifndef LaplacianEditing_DeformationSystem_h
#define LaplacianEditing_DeformationSystem_h

#include "AffineRows.h"
#include "EditRegion.h"
#include "LaplacianOperator.h"
#include "PointConstraints.h"
#include "SparseCholesky.h"
#include "Types.h"

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace LaplacianEditing
{
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
  FillOrdering Ordering = FillOrdering::Automatic;
  /// Whether the paper's soft-constraint least-squares system is built and factored (every
  /// mode but as-rigid-as-possible, which has its own square system).
  bool LeastSquares = true;
  /// Largest factor to attempt, in bytes (0: no limit; CHOLMOD only). A new limit is tried
  /// anew, so it takes part in equality.
  double MaximumFactorBytes = 0.0;
  /// Processes to factor across (SolverBackend::Distributed, or a factor above the limit);
  /// none by default. Not owned.
  DistributedSolver* Distributed = nullptr;
  /// Soft constraints on points of the surface (PointConstraints.h), with their weight relative
  /// to the system's stiffness; PointsVersion changes whenever the points do. None by default.
  std::shared_ptr<const std::vector<SurfacePoint>> Points;
  std::uint64_t PointsVersion = 0;
  double PointWeight = 100.0;
  /// As-rigid-as-possible mode: the weight of its bending term (ArapBending.h), which a region
  /// held by sparse points needs; 0, the default, leaves it out.
  double Bending = 0.0;
  /// As-rigid-as-possible mode with points: the weight, relative to the system's stiffness, of
  /// the pull towards the points' thin-plate spline (AsRigidAsPossibleSolver.h); 0, the
  /// default, leaves it out.
  double SplinePrior = 0.0;
  /// As-rigid-as-possible mode: alpha of smoothed rotations (AsRigidAsPossibleSolver.h, CGAL's
  /// SRE_ARAP); 0, the default, is plain ARAP, as CGAL's default.
  double RotationSmoothing = 0.0;
  /// As-rigid-as-possible mode: the edge length whose resistance to bending the energy keeps.
  /// ARAP resists bending in proportion to the square of its edges' lengths, so a coarse proxy
  /// of a finer mesh bends as that mesh does when its longer edges' resistance is scaled by
  /// (BendingLength / length)^2 (AsRigidAsPossibleSolver.h). 0, the default, is plain ARAP.
  double BendingLength = 0.0;

  bool operator==(const DeformationOptions& other) const
  {
    return this->Weights == other.Weights && this->Order == other.Order &&
      this->HandleWeight == other.HandleWeight && this->AnchorWeight == other.AnchorWeight &&
      this->Backend == other.Backend && this->Ordering == other.Ordering &&
      this->MaximumFactorBytes == other.MaximumFactorBytes &&
      this->Distributed == other.Distributed &&
      this->LeastSquares == other.LeastSquares && (this->Points != nullptr) == (other.Points != nullptr) &&
      this->PointsVersion == other.PointsVersion && this->PointWeight == other.PointWeight &&
      this->Bending == other.Bending && this->SplinePrior == other.SplinePrior &&
      this->RotationSmoothing == other.RotationSmoothing && this->BendingLength == other.BendingLength;
  }
  bool operator!=(const DeformationOptions& other) const { return !(*this == other); }
};

class DeformationSystem
{
public:
  /// Assembles and factors the system. Returns an error message, empty on success.
  std::string Build(const SurfaceMesh& mesh, const EditRegion& region,
    const DeformationOptions& options);

  /// W_g^2 [v_g | 1]: the n x 4 right-hand side of handle group g's response.
  Eigen::MatrixXd HandleBasis(int group) const;

  /// Reconstructs the ROI from its rest differential coordinates, moving each handle group g
  /// by handleMaps[g] (a missing map means identity) and pulling the points to `pointTargets`
  /// (a row per point, if there are points). Rows follow region.Vertices. Uses the precomputed
  /// responses, O(n) per handle group, and one solve for the points' pull.
  Positions Solve(const std::vector<AffineMap>& handleMaps, const Positions& pointTargets = Positions()) const;

  /// The same through the factor's triangular solves (the reference for Solve).
  Positions SolveDirect(
    const std::vector<AffineMap>& handleMaps, const Positions& pointTargets = Positions()) const;

  /// Solve's affine form on some rows (indices into region.Vertices).
  AffineRows GetAffineRows(const std::vector<int>& rows) const;

  /// The same with other differential coordinates, for example rotated ones.
  Positions SolveWithDifferentialCoordinates(const Positions& differentialCoordinates,
    const std::vector<AffineMap>& handleMaps, const ParallelFor& loop = SerialFor,
    const Positions& pointTargets = Positions()) const;

  /// The constraints' share of A^T b: w_i^2 u_i, with u_i the transformed rest position of a
  /// handle vertex and the rest position of an anchor; zero for free vertices.
  Positions ConstraintRightHandSide(const std::vector<AffineMap>& handleMaps) const;
  /// The points' pull away from the rest shape, w^2 B^T (t - B x_rest). With points, every
  /// solve is for the displacement from the rest shape, whose right-hand side vanishes at rest:
  /// points at their rest positions give the rest back to rounding of the displacement, not
  /// of the coordinates.
  Positions PointPull(const Positions& pointTargets) const;
  /// The points where the rest shape has them.
  const Positions& GetRestPoints() const { return this->RestPoints; }

  /// Second order: the first-order coordinates of the ROI, and L applied to first-order
  /// coordinates given for the ROI (those outside it stay at rest), which gives second-order
  /// ones. Rotating each first-order coordinate in its own frame and composing keeps the
  /// second-order right-hand side consistent, where rotating L^2 coordinates one by one does
  /// not, and L^-2 amplifies the inconsistency into a blow-up.
  const Positions& GetFirstOrderDifferentialCoordinates() const { return this->FirstOrderDelta; }
  Positions ComposeSecondOrder(const Positions& firstOrder) const;

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
  /// Handle group of each ROI vertex, -1 for others.
  int GetNumberOfHandleGroups() const { return this->NumberOfHandleGroups; }
  int GetNumberOfUnknowns() const { return static_cast<int>(this->RestPositions.rows()); }
  const SparseCholesky& GetFactor() const { return this->Factor; }
  /// The points' constraints, weighed for this system.
  const PointConstraints& GetPoints() const { return this->Points; }

private:
  // Build's steps: the operator's rows over the ROI (and the fixed part), the constraint
  // weights, the normal equations' factor, and the rest solution with the handle responses.
  void AssembleOperator(const SurfaceMesh& mesh, const EditRegion& region,
    const LaplacianOperator& laplacian, const std::vector<int>& local, int order);
  void WeighConstraints(const EditRegion& region, const DeformationOptions& options);
  std::string FactorNormalEquations(const DeformationOptions& options, const std::vector<int>& local);
  void ComputeResponses(int groups);
  void BuildFirstOrder(const SurfaceMesh& mesh, const EditRegion& region,
    const LaplacianOperator& laplacian, const std::vector<int>& local);

  Eigen::SparseMatrix<double, Eigen::RowMajor> RegionOperator;
  // Its transpose, stored by rows so that A^T r is a gather that rows can share out.
  Eigen::SparseMatrix<double, Eigen::RowMajor> RegionOperatorTransposed;
  SparseCholesky Factor;
  Positions RestPositions;
  Positions RestDelta;
  // Second order: first-order coordinates, L over the ROI, and L's terms from outside it.
  Positions FirstOrderDelta;
  Eigen::SparseMatrix<double, Eigen::RowMajor> FirstOrderRegion;
  Positions FirstOrderOutside;
  Positions FixedPart;
  Eigen::VectorXd SquaredWeights;
  std::vector<int> HandleGroups;
  PointConstraints Points;
  Positions RestPoints;
  // L^T (delta - fixed part) for the rest differential coordinates: constant per region.
  Positions RestRightHandSide;
  // The solution with every handle map zero, and each group's n x 4 response (AffineRows.h).
  AffineRows Responses;
  int NumberOfHandleGroups = 0;
};
}

#endif
