// Constraints on points of the surface that need not be vertices: a landmark warp's source
// landmarks. Each point is a barycentric combination of a triangle's corners, (B x)_p =
// sum_c b_pc x_c, pulled to its own target t_p by the soft term w^2 |B x - t|^2. The normal
// equations gain w^2 B^T B, whose entries couple a triangle's corners (already neighbours in
// every operator, so the factor's pattern barely changes), and the right-hand side w^2 B^T t:
// new targets change only the right-hand side, never the factor.
//
// An exact fit solves with corrected targets t + c until B x = t (the method of multipliers on
// the same factor, c = lambda / w^2): each round costs one solve, and the correction carried
// from one solve to the next makes a drag's rounds few.
#ifndef LaplacianEditing_PointConstraints_h
#define LaplacianEditing_PointConstraints_h

#include "Types.h"

#include <Eigen/SparseCore>

#include <array>
#include <functional>
#include <string>
#include <vector>

namespace LaplacianEditing
{
/// A point of the surface: barycentric weights on three mesh vertices (a triangle's corners;
/// a vertex itself has one weight 1).
struct SurfacePoint
{
  std::array<int, 3> Vertices = { { 0, 0, 0 } };
  std::array<double, 3> Weights = { { 1.0, 0.0, 0.0 } };
  /// Its pull's square relative to the other points' (a soft fit's trust in it; an exact fit
  /// meets every point whatever its pull).
  double Pull = 1.0;
};

/// Targets for a region's point constraints, and how closely to meet them.
struct PointTargets
{
  /// One row per point, in the core's frame.
  Positions Targets;
  /// Meet them to Tolerance (core units), or only as the soft weight pulls.
  bool Exact = true;
  double Tolerance = 1e-10;
  int MaximumRounds = 100;
};

class PointConstraints
{
public:
  /// The points on a region's rows (`rowOfVertex`: each mesh vertex's row, -1 outside). Returns
  /// an error message if a point has a corner outside the region.
  std::string Build(const std::vector<SurfacePoint>& points, const std::vector<int>& rowOfVertex);

  /// The pull, relative to a system's stiffness: w^2 = weight^2 times the mean diagonal entry of
  /// `upper`, so that one weight means the same on every mesh, scale and operator.
  void Weigh(double weight, const Eigen::SparseMatrix<double>& upper);

  int GetNumberOfPoints() const { return static_cast<int>(this->Rows.size()); }
  /// Each point's corners, as region rows.
  const std::vector<std::array<int, 3>>& GetRows() const { return this->Rows; }
  bool IsEmpty() const { return this->Rows.empty(); }
  double GetSquaredWeight() const { return this->SquaredWeight; }

  /// B x: the points for region positions.
  Positions Evaluate(const Positions& region) const;

  /// Adds w^2 B^T B to the upper triangle of a matrix over unknowns: `unknownOfRow` gives each
  /// region row's first unknown (-1: none; an error if a point touches one), `blockSize` the
  /// unknowns a row has, interleaved (x, y, z share a pattern).
  std::string AddToMatrix(
    Eigen::SparseMatrix<double>& upper, const std::vector<int>& unknownOfRow, int blockSize) const;

  /// w^2 B^T t, a row per region row (`rows` of them).
  Positions RightHandSide(const Positions& targets, int rows) const;

  /// The sum of the points' squared distances from their targets, each times its pull.
  double PulledSquaredMiss(const Positions& region, const Positions& targets) const;

  /// The largest distance of a point from its target.
  double LargestMiss(const Positions& region, const Positions& targets) const;

  /// Solves until the points meet the targets (PointTargets::Exact) or once. `solve` returns
  /// the region's positions for some targets; `correction` (a row per point) carries the
  /// targets' correction from one call to the next. Returns the rounds, and the last miss in
  /// `miss`.
  int Fit(const std::function<Positions(const Positions&)>& solve, const PointTargets& targets,
    Positions& correction, Positions& solution, double& miss) const;

private:
  std::vector<std::array<int, 3>> Rows;
  std::vector<std::array<double, 3>> Weights;
  std::vector<double> Pulls;
  double SquaredWeight = 0.0;
};
}

#endif
