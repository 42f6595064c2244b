// A volume mesh's points moved after targets without inverting a cell.
//
// The cells are given as corner tetrahedra (a tetrahedron is its own; a hexahedron has one at
// each corner, formed by the corner and its three edge neighbours), each of positive volume at
// rest. The points are fixed, free, or targeted: a targeted point is pulled towards its target.
// The energy is the symmetric Dirichlet energy of each corner tetrahedron's map from rest,
// sum_c V_c (|J_c|^2 + |J_c^-1|^2 - 6), which is 0 for rigid motions and grows without bound as
// a tetrahedron flattens, plus the penalty sum_t lambda k_t |x_t - target_t|^2 (k_t: the
// point's stiffness). Lowered by the accelerated quadratic proxy of Kovalsky et al.
// ("Accelerated Quadratic Proxy for Geometric Optimization", SIGGRAPH 2016): the stiffness
// matrix of the rest mesh, factored once per zone, is the proxy Hessian, so an iteration costs
// one back-substitution; the first step from rest is the harmonic extension of the targets'
// motion, the displacement Laplacian of mesh motion solvers. Each step is capped where the first
// corner tetrahedron would flatten (the smallest positive root of the cubic det(D + t P), after
// Smith and Schaefer, "Bijective Parameterization with Free Boundaries", SIGGRAPH 2015) and
// shortened until the energy falls enough, so a start without inverted tetrahedra never gets one:
// a target that no valid mesh can reach is left short of it. Two things keep the steps long: the
// pull tightens in stages (lambda from 1 to its final value), and where a step stalls at a
// flattening tetrahedron, the proxy is weighted by the energy's curvature there and factored
// again in the same pattern.
#ifndef LaplacianEditing_InjectiveDeformation_h
#define LaplacianEditing_InjectiveDeformation_h

#include "ParallelFor.h"
#include "SparseCholesky.h"
#include "Types.h"

#include <functional>
#include <string>
#include <vector>

namespace LaplacianEditing
{
/// Four point indices per row: a corner and three neighbours, positively oriented at rest.
using Tetrahedra = Eigen::Matrix<int, Eigen::Dynamic, 4, Eigen::RowMajor>;

enum class PointKind : signed char
{
  Fixed,
  Free,
  Targeted
};

struct InjectiveOptions
{
  /// Iterations at most per solve.
  int MaximumIterations = 300;
  /// Stop when an iteration lowers the energy by less than this fraction of it.
  double Tolerance = 1e-4;
  /// Momentum of the accelerated proxy (false: plain proxy steps).
  bool Accelerate = true;
  /// Tighten the targets' pull in stages, from as stiff as the mesh up to the weight given to
  /// Prepare (a start far from the targets); false: at that weight only (a drag step).
  bool Continuation = true;
  /// Where a step stalls at a flattening cell, weight the proxy by the energy's curvature there
  /// and factor it again (false: a drag step, which must not pay a factorization).
  bool Reweight = true;
  /// Called after each iteration with the share of MaximumIterations done; returning false
  /// stops the solve at that iterate, which inverts no tetrahedron the start did not.
  std::function<bool(double)> Progress;
  /// Go on with the solve that Progress stopped last, where it stopped (its stage, momentum and
  /// iterate before the snap) and as it started (Continuation), as if it had not: the caller
  /// passes the same targets. Without a stopped solve, a new one starts.
  bool Resume = false;
};

struct InjectiveReport
{
  int Iterations = 0;
  /// Factorizations of the proxy (continuation stages and reweighting; none while the weights
  /// are those already factored, as in a drag step).
  int Factorizations = 0;
  /// The symmetric Dirichlet part of the energy over the rest volume (0 at rest or rigid).
  double Distortion = 0.0;
  /// The largest distance of a targeted point from its target.
  double LargestMiss = 0.0;
  /// Corner tetrahedra of non-positive volume in the result (0 when the start had none).
  int Inverted = 0;
  /// Why the solve stopped early (a factorization refused), empty otherwise.
  std::string Error;
  /// Whether Progress stopped the solve.
  bool Stopped = false;
};

class InjectiveDeformation
{
public:
  /// Takes the rest positions, the corner tetrahedra and each point's kind, and assembles the
  /// proxy (Solve factors it, at the weights its stages need). `targetWeight` is lambda: how
  /// much stiffer than the mesh around it a target's pull is. Returns an error (a tetrahedron
  /// not positive at rest, no point to move), empty on success.
  std::string Prepare(const Positions& rest, const Tetrahedra& tetrahedra,
    const std::vector<PointKind>& kinds, double targetWeight = 1e4,
    SolverBackend backend = SolverBackend::Cholmod);

  /// Factors the proxy, unless it is factored: at the weight given to Prepare, as a solve without
  /// a continuation (a drag step, a release from a drag's end) uses it; adds the factorizations
  /// to `factorizations`. Returns an error, empty on success.
  std::string FactorForDrag(int& factorizations);

  /// Moves the free and targeted rows of `points` (a start without inverted tetrahedra: the rest
  /// or an earlier result) towards `targets` (rows of the targeted points are read). Fixed rows
  /// are never written. Targeted points that end within `snap` of their targets are put exactly
  /// on them where no tetrahedron inverts by it.
  InjectiveReport Solve(const Positions& targets, Positions& points, const InjectiveOptions& options,
    double snap = 0.0, const ParallelFor& loop = SerialFor);

  /// Distance of each targeted point from its target after the last Solve (0 for the others).
  const std::vector<double>& GetMisses() const { return this->Misses; }

  /// The rows of the tetrahedra not of positive volume at `points`, in order.
  static std::vector<int> Inverted(const Positions& points, const Tetrahedra& tetrahedra,
    const ParallelFor& loop = SerialFor);

  /// det(b - a, c - a, d - a) / (|b - a| |c - a| |d - a|): 1 for a right corner, 0 flat,
  /// negative inverted.
  static double CornerScaledJacobian(
    const Vector3& a, const Vector3& b, const Vector3& c, const Vector3& d);
  /// The scaled Jacobian of a tetrahedron as Verdict defines it (1 for a regular one): sqrt(2)
  /// times its smallest corner's.
  static double TetrahedronScaledJacobian(
    const Vector3& a, const Vector3& b, const Vector3& c, const Vector3& d);
  /// The same on four points' coordinates, three contiguous values each.
  static double TetrahedronScaledJacobian(
    const double* a, const double* b, const double* c, const double* d);
  /// The same for `count` tetrahedra into `quality`, corner i of tetrahedron j at
  /// `corners[4 * j + i]`: the results of one at a time, faster.
  static void TetrahedronScaledJacobians(const double* const* corners, int count, double* quality);


private:
  // Factors the proxy with the targets' pull at `weight`, unless it is factored at it (counted
  // in `report`).
  std::string FactorAt(double weight, InjectiveReport& report);
  // Weights each tetrahedron's block by the energy's curvature at `points`.
  void Reweight(const Positions& points, const ParallelFor& loop);
  double Energy(const Positions& points, const Positions& targets, const ParallelFor& loop) const;
  // The largest distance of a targeted point from its target.
  double LargestMiss(const Positions& points, const Positions& targets) const;
  // The targets' pull, sum_t lambda k_t |x_t - target_t|^2.
  double Penalty(const Positions& points, const Positions& targets) const;
  // The gradient over the unknowns at `points`; returns the energy there (infinity if a
  // tetrahedron is flat or inverted).
  double Gradient(const Positions& points, const Positions& targets, Eigen::MatrixXd& gradient,
    const ParallelFor& loop) const;
  // The step along `direction` at which the first tetrahedron flattens; infinity if none does
  // before `below`.
  double LargestSafeStep(const Positions& points, const Positions& direction, double below,
    const ParallelFor& loop) const;
  void Snap(const Positions& targets, Positions& points, double snap) const;
  bool AllPositive(const Positions& points, const std::vector<int>& tets) const;

  Positions Rest;
  Tetrahedra Tets;
  std::vector<Eigen::Matrix3d> RestInverse; // B_c: the rest edge matrix's inverse
  Eigen::VectorXd Volume;                   // V_c
  std::vector<PointKind> Kinds;
  std::vector<int> Unknown;  // per point: its unknown, -1 if fixed
  std::vector<int> Unknowns; // per unknown: its point
  Eigen::VectorXd Pull;      // per point: k_t for targeted ones, 0 for the others
  // The proxy over the unknowns: sum_c w_c (each tetrahedron's block) + the pull; Slots say
  // where a block's entries go among the values (-1: a fixed point's), PullSlots the diagonal.
  Eigen::SparseMatrix<double> Proxy;
  Eigen::Matrix<int, Eigen::Dynamic, 16, Eigen::RowMajor> Slots;
  Eigen::Matrix<double, Eigen::Dynamic, 16, Eigen::RowMajor> Blocks;
  std::vector<int> PullSlots;
  std::vector<double> TetWeights;
  // The corners at each point p, from TetOffsets[p] on: 4 c + i for corner i of tetrahedron c.
  std::vector<int> TetOffsets, PointCorners;
  double Lambda = 0.0;        // the pull's weight in the stage being solved
  // Where a solve's loops stand: whether it started with a continuation, its round of stages,
  // the stage, the iterations in it, the stages' weights, and the momentum's last iterate and
  // the energy; with the iterate, where Progress stopped the last solve (Active).
  struct SolveState
  {
    bool Continuation = true;
    int Round = 0;
    std::size_t Stage = 0;
    int StageIterations = 0;
    std::vector<double> Weights;
    bool Stiffened = false;
    Positions Previous;
    double Energy = 0.0;
    Positions Iterate;
    bool Active = false;
  };
  SolveState Cut;
  double FinalWeight = 0.0;   // Prepare's
  double FactoredWeight = 0.0;
  SolverBackend Backend = SolverBackend::Cholmod;
  double TotalVolume = 0.0;
  SparseCholesky Factor;
  std::vector<double> Misses;
  // Gradient's sums over its blocks of tetrahedra (one row an unknown, a block after another),
  // and the per-tetrahedron energies of Gradient and Energy.
  mutable Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor> BlockGradients;
  std::vector<int> BlockUnknowns; // per block: its first unknown and the end of its range
  std::vector<int> BlockRows;     // per block: its first row in BlockGradients; then their count
  mutable std::vector<double> TetEnergies;
};
}

#endif
