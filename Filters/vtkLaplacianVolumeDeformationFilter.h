/**
 * @class   vtkLaplacianVolumeDeformationFilter
 * @brief   edit a volume mesh through its boundary surface; the interior follows, no cell inverts
 *
 * The input is a vtkUnstructuredGrid of linear 3D cells (tetrahedra, hexahedra, voxels, wedges,
 * pyramids, mixed; 0D to 2D cells may come along and move with their points). The edit is a
 * vtkLaplacianDeformationFilter edit of the grid's boundary surface (GetSurfaceFilter()): the
 * handle, the region and every mode and solver property are that filter's, with the same names
 * and meanings, and the boundary's point ids are the grid's. The commonly set ones are forwarded
 * here. Its RotationMode starts as rigid as possible. The interior near the edited region then follows, without inverting a cell: it minimizes
 * a distortion energy that no inverted or flat cell can have, each step stopped short of the
 * first cell that would flatten (Documentation/volumes.md says why this method). Points farther
 * than the region's radius from the region keep their coordinates exactly.
 *
 * Output: the input with its points moved, every point and cell array passed through, and two
 * cell arrays: ScaledJacobian (1 for an ideal cell, 0 flat, negative inverted; a tetrahedron's as
 * Verdict defines it, the smallest corner's for other cells; NaN for cells that are not 3D) and
 * EditFailed (1 on a cell with a boundary point that could not reach its edited position without
 * inverting a cell; the filter then warns). On bad input (no 3D cells, non-linear cells, cells
 * flat or inverted at rest, a non-manifold boundary, a failed surface edit) the filter reports an
 * error and passes the input through.
 *
 * Interaction: the handle widget pairs with GetSurfaceFilter(). While Dragging is on, each update
 * moves the interior with a coarse deformation graph of the zone (DragGraph), at the cost of its
 * few hundred nodes, and repairs the few cells that this would invert; the update after the drag
 * iterates to convergence (at most VolumeIterations). Progress: the boundary's edit in
 * (0.1, 0.4), its settle's iterations last; the interior's iterations in (0.4, 0.9). An abort
 * (AbortExecuteOn, from a progress observer when a new grab starts) ends either settle at that
 * iterate, every cell still positive; the next release settles in full.
 *
 * @sa vtkLaplacianDeformationFilter vtkDeformationHandleWidget
 */
#ifndef vtkLaplacianVolumeDeformationFilter_h
#define vtkLaplacianVolumeDeformationFilter_h

#include "vtkLaplacianEditingFiltersModule.h" // for export macro
#include "vtkUnstructuredGridAlgorithm.h"

#include <memory> // for std::unique_ptr

class vtkAlgorithmOutput;
class vtkLaplacianDeformationFilter;
class vtkLinearTransform;
class vtkSelection;

class VTKLAPLACIANEDITINGFILTERS_EXPORT vtkLaplacianVolumeDeformationFilter
  : public vtkUnstructuredGridAlgorithm
{
public:
  static vtkLaplacianVolumeDeformationFilter* New();
  vtkTypeMacro(vtkLaplacianVolumeDeformationFilter, vtkUnstructuredGridAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * The editor of the boundary surface, whose properties choose and move the handle and the
   * region; pair handle widgets with it. Its input is the filter's business.
   */
  vtkLaplacianDeformationFilter* GetSurfaceFilter();
  /**
   * Edits the boundary with `surface` instead (ParaView's proxy hands in its own, whose
   * properties its panel shows). Its input, its commit events and its array selection become
   * the volume filter's business.
   */
  void SetSurfaceFilter(vtkLaplacianDeformationFilter* surface);

  /**
   * @name Handle and region
   * The surface filter's properties of the same names (vtkLaplacianDeformationFilter).
   */
  ///@{
  void SetHandleCenter(double x, double y, double z);
  void SetHandleCenter(const double center[3]);
  double* GetHandleCenter() VTK_SIZEHINT(3);
  void SetHandleTranslation(double x, double y, double z);
  void SetHandleTranslation(const double translation[3]);
  double* GetHandleTranslation() VTK_SIZEHINT(3);
  void SetHandleRotation(double x, double y, double z);
  void SetHandleRotation(const double rotation[3]);
  double* GetHandleRotation() VTK_SIZEHINT(3);
  void SetHandleTransform(vtkLinearTransform* transform) { this->SetHandleTransform(0, transform); }
  void SetHandleTransform(int group, vtkLinearTransform* transform);
  vtkLinearTransform* GetHandleTransform(int group = 0);
  void SetHandleGroupMotion(vtkIdType group, double translationX, double translationY,
    double translationZ, double rotationX, double rotationY, double rotationZ);
  void RemoveAllHandleGroupMotions();
  int GetNumberOfHandleGroups();
  void SetHandleRadius(double radius);
  double GetHandleRadius();
  void SetROIRadius(double radius);
  double GetROIRadius();
  void SetRadiusUnits(int units);
  int GetRadiusUnits();
  void SetRadiusUnitsToAbsolute();
  void SetRadiusUnitsToDiagonalFraction();
  void SetSelectionMode(int mode);
  int GetSelectionMode();
  void SetSelectionModeToGeodesic();
  void SetSelectionModeToArray();
  /**
   * A vtkSelection of the handle's points (grid point ids) on input port 1, as the surface
   * filter's. The array of SelectionModeToArray is the one named with SetInputArrayToProcess on
   * this filter.
   */
  void SetSelectionConnection(vtkAlgorithmOutput* selection) { this->SetInputConnection(1, selection); }
  void SetSelectionData(vtkSelection* selection);
  void SetRotationMode(int mode);
  int GetRotationMode();
  void SetRotationModeToNone();
  void SetRotationModeToAsRigidAsPossible();
  ///@}

  /**
   * @name Interaction and commits
   */
  ///@{
  /**
   * A drag is in progress: the surface filter's Dragging, and the interior runs
   * DragVolumeIterations an update.
   */
  void SetDragging(vtkTypeBool dragging);
  vtkTypeBool GetDragging();
  vtkBooleanMacro(Dragging, vtkTypeBool);
  /**
   * The most seconds an update that is not a drag step settles, boundary and interior together
   * (default 0: no limit). The boundary's settle stops at the surface filter's SettleTimeLimit
   * (this one), the interior then following that boundary as in a drag step; or the interior's
   * settle stops after its iteration at hand, every cell positive. GetSettling() is then true,
   * and each ContinueSettling() and update goes on from there until the settle is done. The
   * ParaView handle panel sets half a second, so that a release never holds the GUI for long.
   * Setting it here sets the surface filter's too; a limit set on the surface filter alone (a
   * handle widget paired with it continues only the surface's settle) cuts only the boundary's,
   * the interior following it and then settling in full.
   */
  void SetSettleTimeLimit(double seconds);
  vtkGetMacro(SettleTimeLimit, double);
  /** Whether the last update stopped its settle at SettleTimeLimit with work left. */
  vtkTypeBool GetSettling();
  /** Marks the filter modified while GetSettling(): the next update goes on settling. */
  void ContinueSettling();
  /**
   * Make the current result the rest shape of the next edit, the whole volume's (the surface
   * filter's CommitEdit; committing through the surface filter, as a widget does, commits the
   * volume too).
   */
  void CommitEdit();
  /** Go back one commit (the surface filter's too); false if there is none. */
  bool UndoCommit();
  int GetNumberOfCommits();

  ///@}

  /**
   * @name Interior
   */
  ///@{
  /** Iterations at most of an update that is not a drag step. Default 300. */
  vtkSetClampMacro(VolumeIterations, int, 1, 100000);
  vtkGetMacro(VolumeIterations, int);
  /**
   * Drag steps follow the zone's deformation graph (default on): an embedded deformation
   * (Sumner et al. 2007) of a node per 40 zone points, as rigid as possible, whose motion since
   * the last update moves the interior; the cells it would invert are repaired by a small
   * injective solve around them, and the boundary meets its edit. Its cost follows the nodes
   * and the zone's points, not its factor (Documentation/volumes.md). Off, or where the repair
   * fails, a drag step runs DragVolumeIterations of the interior's solve.
   */
  vtkSetMacro(DragGraph, vtkTypeBool);
  vtkGetMacro(DragGraph, vtkTypeBool);
  vtkBooleanMacro(DragGraph, vtkTypeBool);
  /**
   * Iterations of a drag step that the graph does not take. Default 1: an iteration carries
   * the boundary's motion into the interior (the harmonic extension of its increment, cut short
   * of any flattening cell); the update after the drag iterates to convergence.
   */
  vtkSetClampMacro(DragVolumeIterations, int, 1, 100000);
  vtkGetMacro(DragVolumeIterations, int);
  ///@}

  /**
   * Add the Displacement point array, the output's points minus the rest's, written in place
   * like the points. Default off.
   */
  vtkSetMacro(OutputDisplacement, vtkTypeBool);
  vtkGetMacro(OutputDisplacement, vtkTypeBool);
  vtkBooleanMacro(OutputDisplacement, vtkTypeBool);

  /**
   * @name Results of the last update
   */
  ///@{
  /** Points and corner tetrahedra of the zone the interior moved in. */
  int GetNumberOfZonePoints();
  int GetNumberOfZoneTetrahedra();
  /** Iterations the interior took, its proxy's factorizations (none in a drag step), and how
   * often the zone grew to meet its targets. */
  int GetNumberOfVolumeIterations();
  int GetNumberOfVolumeFactorizations();
  int GetNumberOfZoneGrowths();
  /** The nodes of the deformation graph that the last drag step followed (0: it did not), and
   * the cells it repaired. */
  int GetNumberOfGraphNodes();
  int GetNumberOfRepairedCells();
  /** Cells marked in EditFailed. */
  int GetNumberOfFailedCells();
  /** The largest distance of a boundary point from its edited position. */
  double GetLargestTargetMiss();
  /** Seconds: choosing the zone and factoring, and iterating. */
  double GetVolumeSetupTime();
  double GetVolumeSolveTime();
  ///@}

  vtkMTimeType GetMTime() override;

protected:
  vtkLaplacianVolumeDeformationFilter();
  ~vtkLaplacianVolumeDeformationFilter() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  int VolumeIterations = 300;
  int DragVolumeIterations = 1;
  vtkTypeBool DragGraph = 1;
  vtkTypeBool OutputDisplacement = 0;
  double SettleTimeLimit = 0.0;

private:
  vtkLaplacianVolumeDeformationFilter(const vtkLaplacianVolumeDeformationFilter&) = delete;
  void operator=(const vtkLaplacianVolumeDeformationFilter&) = delete;

  // Runs the boundary's edit and the interior's; false, with the error reported, if either fails.
  bool Edit(vtkUnstructuredGrid* input, vtkUnstructuredGrid* output);
  // The surface filter's commits, taken by the volume.
  void SurfaceCommitted();
  void SurfaceCommitUndone();

  struct vtkInternals;
  std::unique_ptr<vtkInternals> Internals;
};

#endif
