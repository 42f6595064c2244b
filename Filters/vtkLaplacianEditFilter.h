/**
 * @class   vtkLaplacianEditFilter
 * @brief   abstract base of the Laplacian edit filters: the edit pipeline, the properties of
 *          the Laplacian system, its rotation modes and its solver, and the results they share
 *
 * Every edit filter (vtkLaplacianDeformationFilter, vtkLaplacianLandmarkWarp) moves some points
 * of a surface and reconstructs a region around them from its differential coordinates. They
 * differ in where the moves come from (a handle, landmarks) and share the rest, declared here
 * once: how the differential coordinates follow the edit's rotations, the solver, Dragging, and
 * the results of the last update. The defaults are an interactive edit's; a subclass that solves
 * to convergence at once (the warp) sets its own in its constructor and says so.
 *
 * A subclass owns its inputs and outputs: it checks them, hands the edit pipeline
 * (GetEditPipeline) its rest surface, its source of moves and SharedSettings() completed with
 * its own, and writes what the pipeline solved.
 *
 * @sa vtkLaplacianDeformationFilter vtkLaplacianLandmarkWarp
 */
#ifndef vtkLaplacianEditFilter_h
#define vtkLaplacianEditFilter_h

#include "vtkLaplacianEditingFiltersModule.h" // for export macro
#include "vtkPointSetAlgorithm.h"

#include <memory> // for std::unique_ptr

class vtkPoints;
class vtkPolyData;
class vtkUnstructuredGrid;

namespace LaplacianEditing
{
namespace Pipeline
{
class EditPipeline;
struct OutputEdit;
struct SolverSettings;
class VolumeFollower;
}
}

class VTKLAPLACIANEDITINGFILTERS_EXPORT vtkLaplacianEditFilter : public vtkPointSetAlgorithm
{
public:
  vtkAbstractTypeMacro(vtkLaplacianEditFilter, vtkPointSetAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum LaplacianWeightTypes
  {
    WEIGHTS_UNIFORM = 0,
    WEIGHTS_COTANGENT = 1
  };
  enum RotationModes
  {
    ROTATION_NONE = 0,
    ROTATION_EXPLICIT = 1,
    ROTATION_IMPLICIT = 2,
    ROTATION_AS_RIGID_AS_POSSIBLE = 3
  };
  enum ImplicitFormulations
  {
    IMPLICIT_PER_EDGE = 0,
    IMPLICIT_PAPER = 1
  };
  enum Solvers
  {
    SOLVER_CHOLMOD = 0,
    SOLVER_SIMPLICIAL_LDLT = 1,
    SOLVER_MUMPS = 2
  };
  enum Orderings
  {
    ORDERING_AUTOMATIC = 0,
    ORDERING_AMD = 1,
    ORDERING_METIS = 2,
    ORDERING_NESTED_DISSECTION = 3
  };

  /**
   * Treat input points at the same position (to 1e-10 of the region's size) as one surface
   * vertex, so that texture seams and triangle soups edit as one surface. Default on.
   */
  vtkSetMacro(MergeCoincidentPoints, vtkTypeBool);
  vtkGetMacro(MergeCoincidentPoints, vtkTypeBool);
  vtkBooleanMacro(MergeCoincidentPoints, vtkTypeBool);

  /**
   * @name Laplacian system and rotation mode
   * The differential operator, how the differential coordinates follow the edit's local
   * rotations (Sections 2 to 7), and each mode's own settings.
   */
  ///@{
  /**
   * Weights of the Laplacian: uniform (the paper's umbrella operator) or cotangent (clamped for
   * obtuse and degenerate triangles; see LaplacianOperator.h). Default uniform for an edit,
   * cotangent for a warp.
   */
  vtkSetClampMacro(LaplacianWeights, int, WEIGHTS_UNIFORM, WEIGHTS_COTANGENT);
  vtkGetMacro(LaplacianWeights, int);
  /** Uniform (umbrella) Laplacian weights, the paper's. */
  void SetLaplacianWeightsToUniform() { this->SetLaplacianWeights(WEIGHTS_UNIFORM); }
  /** Cotangent Laplacian weights, clamped for obtuse and degenerate triangles. */
  void SetLaplacianWeightsToCotangent() { this->SetLaplacianWeights(WEIGHTS_COTANGENT); }

  /**
   * Order of the differential operator: 1 (Laplacian, default) or 2 (bi-Laplacian, smoother
   * transitions at the anchors). It applies in the None and Explicit modes and in the Paper
   * implicit formulation; the per-edge implicit energy and the as-rigid-as-possible energy
   * compare one-ring edges, a first-order measure, and ignore it (with a warning).
   */
  vtkSetClampMacro(OperatorOrder, int, 1, 2);
  vtkGetMacro(OperatorOrder, int);

  /**
   * - None: they keep their global orientation (Section 3);
   * - Explicit: each turns with a local frame on smooth normals of a reference edit (Sections
   *   4 and 7);
   * - Implicit: linearized transforms solved for with the shape (Section 5; see
   *   ImplicitFormulation and PreserveDetailScale), one coupled system a region;
   * - AsRigidAsPossible: the local-global iteration of Sorkine and Alexa (2007), beyond the
   *   paper; the best quality on large rotations; each update iterates on from the last.
   * Switching among the first three never refactors the Laplacian system. Default None for an
   * edit, AsRigidAsPossible for a warp.
   */
  vtkSetClampMacro(RotationMode, int, ROTATION_NONE, ROTATION_AS_RIGID_AS_POSSIBLE);
  vtkGetMacro(RotationMode, int);
  /** Differential coordinates keep their global orientation. */
  void SetRotationModeToNone() { this->SetRotationMode(ROTATION_NONE); }
  /** Explicit rotations from smoothed normals (Sections 4 and 7). */
  void SetRotationModeToExplicit() { this->SetRotationMode(ROTATION_EXPLICIT); }
  /** Implicit linearized similarity transforms (Section 5). */
  void SetRotationModeToImplicit() { this->SetRotationMode(ROTATION_IMPLICIT); }
  /** As-rigid-as-possible local-global iteration (Sorkine and Alexa 2007). */
  void SetRotationModeToAsRigidAsPossible() { this->SetRotationMode(ROTATION_AS_RIGID_AS_POSSIBLE); }

  /**
   * Explicit mode: support radius of the smooth normals. It should exceed the size of the
   * details, so that the normals are those of the surface under them. 0 (the default) chooses
   * one from the region; the subclass says in which units and how.
   */
  vtkSetClampMacro(NormalSmoothingRadius, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(NormalSmoothingRadius, double);

  /**
   * Explicit mode: how many times (1 to 100) to re-estimate the rotations from the previous
   * result and solve again with the same factor. 1 (default) is the paper's method; more fix
   * the under-rotation of large bends.
   */
  vtkSetClampMacro(NumberOfIterations, int, 1, 100);
  vtkGetMacro(NumberOfIterations, int);

  /**
   * Implicit mode's energy. Per edge (default): the paper's fitted transforms, as linearized
   * rotations, matched against every one-ring edge. Paper: Section 5 as published, one residual
   * per vertex and similarity transforms, which leaves bending nearly free where the region is
   * held weakly (Armadillo's finger next to the handle moved 2.8 times as far as the handle).
   */
  vtkSetClampMacro(ImplicitFormulation, int, IMPLICIT_PER_EDGE, IMPLICIT_PAPER);
  vtkGetMacro(ImplicitFormulation, int);
  /** The implicit energy matched per one-ring edge (the default). */
  void SetImplicitFormulationToPerEdge() { this->SetImplicitFormulation(IMPLICIT_PER_EDGE); }
  /** The implicit energy as the paper publishes it (Section 5); may inflate free parts. */
  void SetImplicitFormulationToPaper() { this->SetImplicitFormulation(IMPLICIT_PAPER); }

  /**
   * Implicit mode: follow the linear solve with one as-rigid-as-possible step, which takes out
   * the growth of details that linearized rotations cause under large turns (the cactus's
   * 70-degree turn: area 1.23 without, 1.02 with). Default on. Off, a move is a small dense
   * product; on, it also costs a local step and the solves of a second, Laplacian factor.
   */
  vtkSetMacro(PreserveDetailScale, vtkTypeBool);
  vtkGetMacro(PreserveDetailScale, vtkTypeBool);
  vtkBooleanMacro(PreserveDetailScale, vtkTypeBool);

  /**
   * As-rigid-as-possible mode: the most local-global iterations per update (0 to 10000), or,
   * where a region above LargeRegionVertices settles, Newton steps. Default 30 for an edit:
   * brings regions of up to 12k vertices within 2% of the converged energy from rest
   * (Documentation/quality.md), but a drag's release after a pull of a tenth of the diagonal
   * only within 7-8% (5k and 30k vertices); a large region's settle needs more (a 152k
   * region: 1.7 times the converged energy after 30 steps, converged after about 70; both in
   * Documentation/performance.md); 100 for a warp.
   */
  vtkSetClampMacro(ARAPIterations, int, 0, 10000);
  vtkGetMacro(ARAPIterations, int);

  /**
   * As-rigid-as-possible mode: smoothed rotations (Levi and Gotsman's SR-ARAP, CGAL's
   * SRE_ARAP), alpha of the penalty alpha A sum |R_i - R_j|^2 on neighbouring rotations, A the
   * region's area; 0 to 1000. Neighbouring rings then turn together over a length of about
   * sqrt(alpha A), which bends a region like an elastic rod rather than at a few kinks; large
   * alphas approach one rotation for the whole region. CGAL's own alpha is relative to the
   * whole surface's area and defaults to 0.02. Default 0: plain ARAP, as CGAL's default
   * (SPOKES_AND_RIMS). Changing it rebuilds the region's system, as the other weights do.
   */
  vtkSetClampMacro(RotationSmoothing, double, 0.0, 1000.0);
  vtkGetMacro(RotationSmoothing, double);

  /**
   * As-rigid-as-possible mode: an update stops early when its iterations lower the energy by
   * less than this fraction of it per iteration, on average over the last three (a drag step:
   * its last iteration); 0 to 1. Default 1e-3 for an edit, 1e-4 for a warp.
   */
  vtkSetClampMacro(Convergence, double, 0.0, 1.0);
  vtkGetMacro(Convergence, double);

  /**
   * As-rigid-as-possible mode: Anderson acceleration mixes the last iterates, with a safeguard
   * that keeps the energy falling; it reaches a given energy in several times fewer iterations.
   * Default on.
   */
  vtkSetMacro(Acceleration, vtkTypeBool);
  vtkGetMacro(Acceleration, vtkTypeBool);
  vtkBooleanMacro(Acceleration, vtkTypeBool);

  /**
   * As-rigid-as-possible mode: an update that continues the last one with moved constraints
   * starts from the last result moved on by the last update's change (a constant-velocity
   * guess during a drag); with the constraints held still, updates iterate plainly, so the
   * shape settles. Default on; off, each update starts from the last result.
   */
  vtkSetMacro(Extrapolation, vtkTypeBool);
  vtkGetMacro(Extrapolation, vtkTypeBool);
  vtkBooleanMacro(Extrapolation, vtkTypeBool);
  ///@}

  /**
   * @name Dragging
   */
  ///@{
  /**
   * As-rigid-as-possible mode: a handle or landmark is being dragged (vtkDeformationHandleWidget
   * and the ParaView panels set it). Meanwhile each update runs at most DragARAPIterations, so
   * every frame costs about the same. Turning it on does not mark the filter modified; turning
   * it off does (unless a previewed drag's motion is applied by the next update anyway), and the
   * next update settles the shape: ARAPIterations in full, without the Convergence test, which
   * the slow tail a drag leaves would pass at once. Default off.
   */
  void SetDragging(vtkTypeBool dragging);
  vtkGetMacro(Dragging, vtkTypeBool);
  vtkBooleanMacro(Dragging, vtkTypeBool);

  /**
   * As-rigid-as-possible mode: the most iterations per update while Dragging (1 to 10000;
   * never more than ARAPIterations). A large region's proxy, whose iterations cost less, runs
   * twice as many (Documentation/how-it-works.md, "Regions of any size"). Default 2.
   */
  vtkSetClampMacro(DragARAPIterations, int, 1, 10000);
  vtkGetMacro(DragARAPIterations, int);

  /**
   * As-rigid-as-possible mode: the most seconds an update outside a drag spends iterating
   * (0 to 3600; 0: no limit), so that a client stays responsive while a large region settles
   * (a 610k-vertex region's settle takes half a minute). An update that reaches it ends after
   * the iteration at hand, its output a valid edit, and GetSettling() is true; each
   * ContinueSettling() and update then runs the iterations left, from there, until none are:
   * the same iterates as one update without a limit. A change of the motions, the region or the
   * rotation model, or a new drag, starts afresh instead. The filter's progress spans the whole
   * settle. vtkDeformationHandleWidget and the ParaView panel continue it between frames.
   * Default 0.
   */
  vtkSetClampMacro(SettleTimeLimit, double, 0.0, 3600.0);
  vtkGetMacro(SettleTimeLimit, double);

  /**
   * Whether the last update reached SettleTimeLimit with iterations left.
   */
  vtkTypeBool GetSettling();

  /**
   * Marks the filter modified while GetSettling(), so that the next update continues the
   * settle; does nothing otherwise.
   */
  void ContinueSettling();
  ///@}

  /**
   * @name Solver
   * The sparse factorization (Section 8).
   */
  ///@{
  /**
   * Sparse Cholesky backend: CHOLMOD supernodal (default where built in), Eigen's
   * SimplicialLDLT, or MUMPS, which factors across the MPI processes (only
   * vtkPLaplacianDeformationFilter under MPI, in a build with MUMPS). Under MPI, a CHOLMOD factor
   * larger than MaximumFactorMemory is factored with MUMPS across the processes as well.
   */
  vtkSetClampMacro(Solver, int, SOLVER_CHOLMOD, SOLVER_MUMPS);
  vtkGetMacro(Solver, int);
  /** CHOLMOD's supernodal Cholesky (the default where built in). */
  void SetSolverToCholmod() { this->SetSolver(SOLVER_CHOLMOD); }
  /** Eigen's SimplicialLDLT. */
  void SetSolverToSimplicialLDLT() { this->SetSolver(SOLVER_SIMPLICIAL_LDLT); }
  /** MUMPS across the MPI processes. */
  void SetSolverToMUMPS() { this->SetSolver(SOLVER_MUMPS); }
  /** Whether this build has CHOLMOD. */
  static bool IsCholmodAvailable();

  /**
   * CHOLMOD's fill-reducing ordering: automatic (default: AMD below 300,000 unknowns, METIS
   * from there and for the implicit mode's 3 x 3 block system), AMD, METIS or CHOLMOD's nested
   * dissection. SimplicialLDLT always uses AMD.
   */
  vtkSetClampMacro(Ordering, int, ORDERING_AUTOMATIC, ORDERING_NESTED_DISSECTION);
  vtkGetMacro(Ordering, int);

  /**
   * Largest factor to attempt, in megabytes: CHOLMOD predicts a factor's size, and a larger one
   * is refused with an error instead of exhausting memory (under MPI with MUMPS, spread across
   * the processes). 0 (the default): 80% of the physical memory available.
   */
  vtkSetClampMacro(MaximumFactorMemory, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(MaximumFactorMemory, double);
  ///@}

  /**
   * Add the Displacement point array, the output's points minus the rest's (three components,
   * of the points' type), written in place like the points: what a grid transform samples.
   * Default off.
   */
  vtkSetMacro(OutputDisplacement, vtkTypeBool);
  vtkGetMacro(OutputDisplacement, vtkTypeBool);
  vtkBooleanMacro(OutputDisplacement, vtkTypeBool);

  /**
   * @name Results of the last update
   */
  ///@{
  /**
   * Seconds building the surface graph (only when the input changed); of the region's setup (0
   * when the cached factor was reused), of its ordering analysis and of its numeric
   * factorization alone; and solving and writing the output.
   */
  double GetTopologyTime();
  double GetSetupTime();
  double GetAnalysisTime();
  double GetFactorizationTime();
  double GetSolveTime();
  /**
   * Numeric factorizations completed since construction, and those attempted, failed ones
   * included: a failed one is not attempted again until something it depends on changes.
   */
  int GetNumberOfFactorizations();
  int GetNumberOfFactorizationAttempts();
  /**
   * As-rigid-as-possible mode: the iterations run and the energy reached (per vertex, the
   * weighted squared residual of its one-ring after its best rotation, over the weighted
   * squared rest edge lengths; 0 for a rigid motion).
   */
  int GetNumberOfARAPIterations();
  double GetARAPEnergy();
  /** Megabytes of the factors held for the current region (0 if unknown). */
  double GetFactorMemory();
  ///@}

#ifndef __VTK_WRAP__
  /**
   * The last update's solved edit, for C++ code that builds on it (the drag preview, the volume
   * filter's interior): its moved points and the solution they index, valid until the next
   * update or drag step. False, with `edit` untouched, where the update solved nothing.
   */
  bool GetSolvedEdit(LaplacianEditing::Pipeline::OutputEdit& edit) const;
#endif

protected:
  vtkLaplacianEditFilter();
  ~vtkLaplacianEditFilter() override;

  /** The pipeline that runs the edits; it reports errors through SetErrorCode. */
  LaplacianEditing::Pipeline::EditPipeline& GetEditPipeline();
  const LaplacianEditing::Pipeline::EditPipeline& GetEditPipeline() const;

  /**
   * The solver's settings from the properties declared here; a subclass adds its own (the
   * smoothing radius in its units, its constraints' weights).
   */
  LaplacianEditing::Pipeline::SolverSettings SharedSettings() const;

  /**
   * The volume path, the same for every filter that takes a volume mesh (a vtkUnstructuredGrid
   * of linear 3D cells) and edits it through its boundary: VolumeBoundary gives the boundary
   * surface to edit (null, with the error reported, if the grid has none); after the pipeline
   * solved its edit, whose points are written in `edited`, FollowBoundary moves the interior
   * without inverting a cell and writes `output`, its settle reported as the filter's progress
   * from `from` to `to` (false, with the error reported and the input passed through, if it
   * cannot).
   */
  vtkPolyData* VolumeBoundary(vtkUnstructuredGrid* grid);
  bool FollowBoundary(vtkPoints* edited, vtkUnstructuredGrid* output, double from, double to);

  vtkTypeBool MergeCoincidentPoints = 1;
  int LaplacianWeights = WEIGHTS_UNIFORM;
  int OperatorOrder = 1;
  int RotationMode = ROTATION_NONE;
  double NormalSmoothingRadius = 0.0;
  int NumberOfIterations = 1;
  int ImplicitFormulation = IMPLICIT_PER_EDGE;
  vtkTypeBool PreserveDetailScale = 1;
  int ARAPIterations = 30;
  double RotationSmoothing = 0.0;
  double Convergence = 1e-3;
  vtkTypeBool Acceleration = 1;
  vtkTypeBool Extrapolation = 1;
  vtkTypeBool Dragging = 0;
  int DragARAPIterations = 2;
  double SettleTimeLimit = 0.0;
  int Solver = SOLVER_CHOLMOD;
  int Ordering = ORDERING_AUTOMATIC;
  double MaximumFactorMemory = 0.0;
  vtkTypeBool OutputDisplacement = 0;

private:
  vtkLaplacianEditFilter(const vtkLaplacianEditFilter&) = delete;
  void operator=(const vtkLaplacianEditFilter&) = delete;

  std::unique_ptr<LaplacianEditing::Pipeline::EditPipeline> Pipeline;
  std::unique_ptr<LaplacianEditing::Pipeline::VolumeFollower> Volume;
};

#endif
