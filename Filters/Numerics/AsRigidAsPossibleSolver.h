// As-rigid-as-possible editing (Sorkine and Alexa, "As-Rigid-As-Possible Surface Modeling",
// SGP 2007), the local-global iteration, accelerated (Peng et al., "Anderson Acceleration for
// Geometry Optimization and Physics Simulation", SIGGRAPH 2018).
//
// Energy: sum_i sum_j w_ij |(v'_i - v'_j) - R_i (v_i - v_j)|^2 over the ROI and the ring of fixed
// vertices around it, with symmetric uniform or clamped cotangent weights.
//  - Local step: each R_i is the rotation closest to the ring's covariance, in parallel through
//    the injected ParallelFor: an exact polar decomposition seeds it, Newton steps from the last
//    iteration's refine it.
//  - Global step: the square system L_ff x_f = b over the free vertices (the ROI without its
//    handles), with the handles at their targets and the vertices outside the ROI at rest as hard
//    values. L_ff is the weighted graph Laplacian, about 7 nonzeros a row against the normal
//    equations' 19, factored once per region.
//  - Anderson acceleration mixes the last few iterates; an accelerated iterate whose energy does
//    not fall is replaced by the plain one, so the energy never rises.
// The anchors of the paper's soft constraints play no part: ARAP is held by the fixed ring.
//
// The spline prior (DeformationOptions::SplinePrior), for regions held by points alone: the
// energy adds 2 mu |x_f - r_f - d_f|^2, a pull of the free vertices towards the rest shape r
// moved by the points' thin-plate spline d (ThinPlateSpline.h); the matrix gains mu I and the
// right-hand side mu d_f. Why: sparse points leave the rigid energy many shapes of nearly equal
// cost, and which one a solve lands in varies from one draw of points to the next (100 random
// landmarks on the bunny's hinge: the part that should stay drifted 1.12 times as far as under
// the spline over twelve draws, 1.61 times at worst). The spline's smooth bend breaks the tie.
// mu = SplinePrior times the mean diagonal times points / unknowns: the rigid energy's hold on a
// bend between points grows with their density (as 1 / spacing^2, so with their number), and
// the pull, a sum over vertices, with the mesh's resolution; so one weight means the same at any
// density and resolution.
//
// Smoothed rotations (DeformationOptions::RotationSmoothing, Levi and Gotsman, "Smooth Rotation
// Enhanced As-Rigid-As-Possible Mesh Animation", 2015; CGAL's SRE_ARAP): the energy adds
// sum over edges beta_ij |R_i - R_j|_F^2, beta_ij = alpha A (1/n_i + 1/n_j) / 2 with A the ROI's
// area and n the valences, which is CGAL's term for alpha on a region that is the whole surface.
// The rotations then vary over a length of about sqrt(alpha A) instead of jumping from ring to
// ring. The local step runs CoupledSweeps Gauss-Seidel sweeps, each rotation fitted exactly
// against its neighbours' latest, a color of a greedy coloring at a time (in parallel within
// a color, since no two of its vertices are neighbours): every fit lowers the energy, so it
// still never rises. Why several sweeps: the couplings spread a rotation a ring per sweep, and
// the global step is the iteration's cost.
//
// A scaled bending resistance (DeformationOptions::BendingLength h), for a coarse proxy of a
// finer mesh (RegionProxy.h): per edge, sum_{i->j} w |e' - R_i e|^2 is
// 2 w |e' - (R_i + R_j) e / 2|^2 + w |(R_i - R_j) e|^2 / 2, a stretching term and a bending
// term that grows with the square of the edge length, so that a coarse mesh is stiffer in
// bending than the fine one it stands for, by the square of their spacings' ratio (a proxy at
// 5 times the spacing, plain, bent so differently that its converged shape carried 4.5 times
// the fine converged energy). With s = min(1, (h / |e|)^2) per edge, the energy subtracts
// (1 - s) w |(R_i - R_j) e|^2 / 2 per edge,
// which keeps the global step and couples the rotations: the local step runs the coupled
// sweeps, with -(1 - s) w R_j e e^T / 2 added to each ring's covariance.
#ifndef LaplacianEditing_AsRigidAsPossibleSolver_h
#define LaplacianEditing_AsRigidAsPossibleSolver_h

#include "ArapBending.h"
#include "DeformationSystem.h"
#include "ParallelFor.h"
#include "ThinPlateSpline.h"

#include <Eigen/Geometry>

#include <array>
#include <functional>

#include <string>
#include <vector>

namespace LaplacianEditing
{
/// Iterations the stopping test looks back over.
constexpr int ConvergenceWindow = 3;
/// Gauss-Seidel sweeps of a local step with smoothed rotations.
constexpr int CoupledSweeps = 4;

struct ArapOptions
{
  /// Local-global iterations at most per solve.
  int MaximumIterations = 30;
  /// Stop when the iterations lower the energy by less than this fraction of it per iteration:
  /// on average over the last ConvergenceWindow (fewer at the start), or, in an extrapolated
  /// solve (a drag step), in its last iteration after the first.
  double Tolerance = 1e-3;
  /// Anderson acceleration, and how many past iterates it mixes.
  bool Accelerate = true;
  int History = 5;
  /// A solve that continues the last one with moved handles starts from its result moved on
  /// by the last solve's change, x + (x - x_before): a constant-velocity guess during a drag.
  /// It runs at least 2 iterations (as MaximumIterations allows), since its first decrease,
  /// from the moved-on guess, does not show what is left. At 30k vertices, a smooth drag at the
  /// default settings ends within 4% of the converged energy in 2 iterations every step,
  /// against 11 without. At handles held still, the solve iterates plainly: as a momentum
  /// step, the extrapolation is stable (with the iteration's rate r on a slow mode, its rate is
  /// sqrt(r)) but oscillates along the slow modes, and a held edit would slosh instead of
  /// settling.
  bool Extrapolate = true;
  /// Newton steps instead of local-global iterations, in a solve that does not extrapolate,
  /// on the plain energy (no points, prior, bending or smoothed rotations; the others iterate
  /// plainly). Why: a local-global iteration is a Newton step whose Hessian leaves out how the
  /// rotations turn with the points, and along the region's soft bending modes that is most
  /// of it: a 152k-vertex region stood at 2.0 times the minimum's energy after 30 iterations,
  /// and at 1.7 after 1000 (Documentation/performance.md). Each step here solves with the full
  /// Hessian, L minus the rotations' derivative (the polar decomposition's, through each
  /// ring's stretch), by conjugate gradients preconditioned by L (the global step's own
  /// solver: the factor, or one multigrid cycle) within a trust region, which shrinks where
  /// the energy does not fall (a local-global step after three tries).
  bool Newton = false;
  /// The solve is a drag step: a large region's proxy iterates (ProxyArapSolver), where a
  /// solve that is not one settles the full-resolution shape.
  bool Dragging = false;
  /// The solve continues the last one on this iterate, which a Progress stop cut short (a
  /// settle split across updates): the stopping test keeps its last energies, Anderson its
  /// history and Newton's steps their trust region, so that the iterates are those of one
  /// uncut solve.
  bool Continue = false;
  /// Called after each iteration with the share of MaximumIterations done. Returning false
  /// ends the solve at that iteration's shape (a settle of a large region takes seconds, and
  /// the user may abort it or grab again).
  std::function<bool(double)> Progress;
};

using Quaternions = std::vector<Eigen::Quaterniond, Eigen::aligned_allocator<Eigen::Quaterniond>>;

/// Where the iteration stands: the ROI positions (rows follow region.Vertices) and the rotation
/// of each vertex of the energy. A solve continues from both. Rotations left empty are seeded
/// from exact polar decompositions at the positions: seeding them from the identity instead
/// lets a re-solve of a converged large rotation drift to a worse minimum.
struct ArapIterate
{
  Positions Points;
  Quaternions Rotations;
  /// The points at the start of the last solve, its handle maps and point targets, for
  /// ArapOptions::Extrapolate.
  Positions Before;
  /// The rotations of Before (empty where they did not fit it).
  Quaternions BeforeRotations;
  std::vector<AffineMap> BeforeMaps;
  Positions BeforeTargets;

  /// Buffers the iterations reuse, kept with the iterate so that the updates of a drag do not
  /// allocate: on regions of tens of thousands of vertices, the first touch of fresh memory
  /// cost more than the iterations' arithmetic.
  struct Workspace
  {
    std::vector<Vector3> Patch;
    std::vector<Eigen::Matrix3d> Rotations;
    std::vector<Eigen::Matrix3d> CandidateRotations;
    Quaternions CandidateQuaternions;
    // The rings' covariances, for the sweeps of smoothed rotations.
    std::vector<Eigen::Matrix3d> Deformations;
    Positions Candidate;
    std::vector<double> Residuals;
    Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor> RightHandSide;
    // An exact fit's correction of the point targets (PointConstraints::Fit), carried over.
    Positions PointCorrection;
    // Anderson acceleration's history (columns: how many hold differences, and the newest)
    // and last iterate (whether there is one).
    Eigen::MatrixXd GDifferences;
    Eigen::MatrixXd FDifferences;
    Eigen::VectorXd PreviousG;
    Eigen::VectorXd PreviousF;
    Eigen::VectorXd Residual;
    int StoredDifferences = 0;
    int NewestDifference = -1;
    bool HasPrevious = false;
    // The stopping test's iterations since the solve began and their last energies, a ring
    // (ArapOptions::Continue).
    int LoggedIterations = 0;
    std::array<double, ConvergenceWindow + 1> RecentEnergies{};
    // The spline prior's displacements of the free rows, the point targets they are for, and
    // the cardinal functions on the free rows of the points moved last, by point.
    Eigen::MatrixXd Prior;
    Positions PriorTargets;
    std::vector<std::pair<int, Eigen::VectorXd>> PriorCardinals;
    // Newton steps: each energy vertex's (tr(P) I - P)^-1, P its ring's stretch, the rotations'
    // derivatives in a direction, and that direction on the patch.
    std::vector<Eigen::Matrix3d> Twists;
    std::vector<Eigen::Matrix3d> RotationChanges;
    std::vector<Vector3> PatchChange;
    // Their trust region's radius when the last solve ended (ArapOptions::Continue).
    double TrustRadius = 0.0;
    // Whether Rotations, Residuals and the iterate's Rotations are those of its Points: a solve
    // leaves them so, and the next one recomputes only around the handles it moves.
    bool RotationsFitPoints = false;
  } Work;
};

struct ArapResult
{
  int Iterations = 0;
  double Energy = 0.0;
  bool Converged = false;
};

class AsRigidAsPossibleSolver
{
public:
  /// Assembles and factors L_ff, with the points' soft constraints if the options have points
  /// (w^2 B^T B added; a point may not touch a handle). Returns an error message, empty on
  /// success.
  std::string Build(const SurfaceMesh& mesh, const EditRegion& region,
    const DeformationOptions& options, const ParallelFor& loop = SerialFor);

  /// Iterates from `iterate`, whose handle rows are first set to their targets (after the
  /// extrapolation, if any), with the points pulled to `points` (required if the solver has
  /// points): softly, the energy then adds 2 w^2 |B x - t|^2, or exactly, every global step
  /// meeting them. `energies`, if given, receives the energy after each iteration.
  ArapResult Solve(const std::vector<AffineMap>& handleMaps, ArapIterate& iterate,
    const ArapOptions& options, const ParallelFor& loop = SerialFor,
    std::vector<double>* energies = nullptr, const PointTargets* points = nullptr) const;

  /// One global step with every rotation the identity: the start of a first solve (the
  /// reconstruction from the rest edges, as the none mode with hard constraints).
  ArapIterate InitialGuess(
    const std::vector<AffineMap>& handleMaps, const PointTargets* points = nullptr) const;

  /// One local step at `iterate.Points`, then one global step: the rigid correction of another
  /// mode's result, a function of the points and the handle maps alone (the rotations are
  /// refined from the last call's, but to convergence, or decomposed afresh). The handle rows
  /// are set first; `iterate` keeps the buffers and rotations between calls.
  void Straighten(const std::vector<AffineMap>& handleMaps, ArapIterate& iterate,
    const ParallelFor& loop, const PointTargets* points = nullptr) const;

  const SparseCholesky& GetFactor() const { return this->Factor; }
  /// The global step's relative residual where it iterates (SolverBackend::Multigrid).
  void SetSolveTolerance(double tolerance) { this->Factor.SetIterativeTolerance(tolerance); }
  /// The loop the global step's solver runs through, where it is not the one Build had.
  void SetParallelFor(const ParallelFor& loop) { this->Factor.SetParallelFor(loop); }
  const PointConstraints& GetPoints() const { return this->Points; }

private:
  // Build's steps: the patch (returns its vertices, with each mesh vertex's patch row or -1),
  // the edges' symmetric weights and rest vectors, the rotations a handle move changes, the
  // unknowns (an error if a part of them touches no known value and no point), and L_ff's
  // upper triangle.
  std::vector<int> GrowPatch(const SurfaceMesh& mesh, const EditRegion& region, std::vector<int>& patchRow);
  void WeighEdges(const SurfaceMesh& mesh, const std::vector<int>& patchVertices,
    const std::vector<int>& patchRow, LaplacianWeights type, const ParallelFor& loop);
  void FindRotationsAroundHandles();
  // The couplings beta_ij of smoothed rotations at `smoothing` (alpha), none at 0, and the
  // bending relief (1 - s_ij) w_ij / 2 for `bendingLength` (see above), none at 0.
  void CoupleRotations(const SurfaceMesh& mesh, const std::vector<int>& patchVertices,
    const std::vector<int>& patchRow, double smoothing, double bendingLength);
  void SmoothRotations(const SurfaceMesh& mesh, const std::vector<int>& patchVertices,
    const std::vector<int>& patchRow, double smoothing);
  std::string ChooseUnknowns(const EditRegion& region);
  Eigen::SparseMatrix<double> AssembleFreeLaplacian(const ParallelFor& loop) const;
  // The spline prior's term in the matrix, if `weight` and the points allow one.
  void AddPrior(double weight, Eigen::SparseMatrix<double>& matrix);
  // The soft pulls' terms of the energy over the rest scale: the points', 2 w^2 |B x - t|^2 (0
  // for an exact fit or no points), and the spline prior's.
  double PullEnergy(const Positions& roiPositions, const PointTargets* points,
    const ArapIterate::Workspace& work) const;
  // Brings the workspace's prior up to date with the point targets (the rest points without).
  void UpdatePrior(const PointTargets* points, ArapIterate::Workspace& work, const ParallelFor& loop) const;
  // Solve's steps: the extrapolated start (returns whether it extrapolated), the free rows of
  // ROI positions, and a candidate iterate's local step (the iterate with `free` in its free
  // rows, into the workspace's candidate; returns its energy).
  bool Extrapolate(const std::vector<AffineMap>& handleMaps, const PointTargets* points,
    ArapIterate& iterate, const ArapOptions& options) const;
  // An extrapolated start's rotations, moved on as its points are: q + (q - q_before), where
  // the last two solves' rotations are known; returns whether they were.
  bool ExtrapolateRotations(ArapIterate& iterate, const ParallelFor& loop) const;
  Eigen::MatrixXd FreePositions(const Positions& roi) const;
  double Evaluate(const Eigen::MatrixXd& free, ArapIterate& iterate, const ParallelFor& loop) const;
  // Newton's iteration (ArapOptions::Newton) from `result`, the start's energy.
  ArapResult SolveNewton(ArapIterate& iterate, const ArapOptions& options, const ParallelFor& loop,
    std::vector<double>* energies, ArapResult result) const;
  bool HasPlainEnergy() const;
  // Per free row, sum_j w_ij ((a_i - a_j) - (Q_i + Q_j) e_ij / 2) for patch values a and
  // per-energy-vertex matrices Q: the gradient (over 4) for the points and their rotations,
  // or the Hessian's product for a change of the points and the rotations' change with it.
  Eigen::MatrixXd EdgeBalance(const std::vector<Vector3>& values,
    const std::vector<Eigen::Matrix3d>& matrices, const ParallelFor& loop) const;
  // The workspace's Twists at the patch and its rotations.
  void LinearizeRotations(ArapIterate::Workspace& work, const ParallelFor& loop) const;
  // The Hessian (over 4) times a change of the free rows.
  Eigen::MatrixXd HessianProduct(const Eigen::MatrixXd& change, ArapIterate::Workspace& work,
    const ParallelFor& loop) const;
  // The Newton step for gradient g within `radius` (in L_ff's norm; at most 0: the first
  // step's length, which it is then set to), by truncated preconditioned conjugate gradients:
  // the step, its model's decrease g^T s + s^T H s / 2 (negative), the first (local-global)
  // step's length, and whether it ends on the region's boundary.
  struct NewtonStep
  {
    Eigen::MatrixXd Step;
    double ModelDecrease = 0.0;
    double FirstStepNorm = 0.0;
    bool OnBoundary = false;
  };
  NewtonStep NewtonDirection(const Eigen::MatrixXd& g, double& radius, ArapIterate::Workspace& work,
    const ParallelFor& loop) const;
  // The rings in the form ArapBending takes them.
  ArapRings Rings() const { return { this->Offsets, this->Neighbors, this->Weights, this->RestEdgeSums }; }
  // Positions of the patch (the ROI, its ring and the ring's ring) for given ROI positions.
  void Patch(const Positions& roiPositions, std::vector<Vector3>& patch, const ParallelFor& loop) const;
  // The local step: rotations of the energy vertices, refined from `quaternions` (seeded by
  // exact polar decompositions where empty), or of `only` those, the others' rotations and
  // residuals kept (all are redone when rotations are coupled). Returns the energy.
  double Rotate(const std::vector<Vector3>& patch, std::vector<Eigen::Matrix3d>& rotations,
    Quaternions& quaternions, ArapIterate::Workspace& work, const ParallelFor& loop,
    const std::vector<int>* only = nullptr) const;
  // Vertex i's ring: its deformation (the weighted covariance of its edges, rest against
  // `patch`), and its residual under `rotation`.
  Eigen::Matrix3d Deformation(const std::vector<Vector3>& patch, int i) const;
  // The local step with smoothed rotations (seeded by exact polar decompositions if `seed`),
  // and vertex i's share of their coupling energy (half of each of its edges') under
  // `rotations`.
  double RotateCoupled(const std::vector<Vector3>& patch, std::vector<Eigen::Matrix3d>& rotations,
    Quaternions& quaternions, ArapIterate::Workspace& work, const ParallelFor& loop, bool seed) const;
  double CouplingResidual(const std::vector<Eigen::Matrix3d>& rotations, int i) const;
  // The weighted sum of vertex i's deformed edges (the bending term's s'_i).
  Vector3 DeformedEdgeSum(const std::vector<Vector3>& patch, int i) const;
  double Residual(const std::vector<Vector3>& patch, int i, const Eigen::Matrix3d& rotation) const;
  // The energy of the residuals, over the rest scale.
  double SumResiduals(const std::vector<double>& residuals) const;
  // Sets the handle rows to their targets, then the local step at the iterate's points (only
  // around the handles if `aroundHandles`, the other rotations fitting already). Returns the
  // energy.
  double LocalStep(const std::vector<AffineMap>& handleMaps, ArapIterate& iterate,
    const ParallelFor& loop, bool aroundHandles) const;
  // Sets the handle rows to their targets and the patch to the iterate's points.
  void PlaceHandles(const std::vector<AffineMap>& handleMaps, ArapIterate& iterate,
    const ParallelFor& loop) const;
  // A global step with `rotations` from the iterate's patch, written to its free rows.
  void GlobalStep(const std::vector<Eigen::Matrix3d>& rotations, ArapIterate& iterate,
    const ParallelFor& loop, const PointTargets* points) const;
  // The global step: new free positions for the rotations (and the points' targets).
  Eigen::MatrixXd Global(const std::vector<Eigen::Matrix3d>& rotations,
    const std::vector<Vector3>& patch, ArapIterate::Workspace& work, const ParallelFor& loop,
    const PointTargets* points) const;

  int NumberOfROIVertices = 0;
  // Patch vertices: ROI rows first, then the rest; their rest positions and the diagonal of
  // their bounding box.
  std::vector<Vector3> RestVertices;
  double RestExtent = 0.0;
  // The energy vertices (ROI and ring, as patch rows), each with its CSR neighbours (patch
  // rows) and symmetric weights.
  int NumberOfEnergyVertices = 0;
  std::vector<int> Offsets;
  std::vector<int> Neighbors;
  std::vector<double> Weights;
  // The first `count` patch rows' rest positions.
  Positions RestRows(int count) const;
  // Rest edges are differences of RestVertices, not stored: a 600k region's would take 88 MB,
  // and the loops over edges gather the neighbour's current position anyway.
  Vector3 RestEdge(int i, int k) const
  {
    return this->RestVertices[i] - this->RestVertices[this->Neighbors[k]];
  }
  std::vector<Vector3> RestEdgeSums; // per energy vertex, its edges' weighted sum
  std::vector<double> RotationCoupling; // per edge, beta_ij (0 to the ring's ring); empty: none
  std::vector<double> BendingRelief; // per edge, (1 - s_ij) w_ij / 2 (0 to the ring's ring); empty: none
  std::vector<int> ColorOffsets; // the energy vertices by color, for the coupled sweeps
  std::vector<int> ColoredVertices;
  double RestScale = 0.0;
  // Free unknowns: their ROI rows, and the unknown index of each patch row (-1 if known).
  std::vector<int> FreeRows;
  std::vector<int> UnknownOfPatch;
  // Per ROI row: its handle group, -1 for others.
  std::vector<int> HandleGroups;
  // The energy vertices whose ring holds a handle row: the rotations a handle move changes.
  std::vector<int> AroundHandles;
  PointConstraints Points;
  Positions RestPoints; // the points on the rest shape
  // The spline prior: the spline through the rest points, its weight mu (0: none) and the free
  // rows' rest positions.
  ThinPlateSpline Spline;
  double PriorWeight = 0.0;
  Positions FreeRest;
  ArapBending Bending;
  SparseCholesky Factor;
};
}

#endif
