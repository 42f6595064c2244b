/**
 * @class   vtkLaplacianDeformationFilter
 * @brief   detail-preserving mesh editing with differential (Laplacian) coordinates
 *
 * vtkLaplacianDeformationFilter moves a handle region of a triangle mesh and reconstructs the
 * surrounding region of interest (ROI) from its differential coordinates, after Lipman,
 * Sorkine, Alexa et al., "Laplacian Framework for Interactive Mesh Editing" (2005).
 *
 * The region is geodesic discs about HandleCenter (the default), the labels of an integer
 * point array (0 fixed, 1 ROI, 2 handle, 3, 4, ... further handle groups), or a vtkSelection on
 * input port 1. The outer AnchorPadding of the ROI holds stationary anchors. Each handle group
 * follows its own vtkLinearTransform, or the handle properties. The system is factored once
 * per region and reused while only the handles move (GetNumberOfFactorizations()).
 *
 * Input: polygons (split into triangle fans for the operator). Points at the same position,
 * up to rounding, are one surface vertex (MergeCoincidentPoints), so seams and soups edit as
 * one surface. Output: the input with the region's points moved, all point and cell data
 * passed through, normals refreshed near the edit, and the EditRole point array. On bad input
 * the filter reports an error, passes the input through and sets GetErrorCode() to
 * vtkErrorCode::UserError until an update succeeds. Documentation/filter.md has the guide.
 *
 * The properties come in groups: the handle, the region, the constraints, large regions,
 * the output, commits, and the results of the last update. The operator (weights, order), the
 * rotation modes and their settings, the solver, Dragging and the results every edit shares are
 * vtkLaplacianEditFilter's; here NormalSmoothingRadius is in RadiusUnits, and its 0 means 0.2
 * times the ROI radius (in array mode, the largest distance of an ROI vertex from the handles).
 *
 * @sa vtkLaplacianEditFilter vtkPLaplacianDeformationFilter vtkDeformationHandleWidget
 * vtkLaplacianDragPreview
 */
#ifndef vtkLaplacianDeformationFilter_h
#define vtkLaplacianDeformationFilter_h

#include "vtkCommand.h"                      // for vtkCommand::UserEvent
#include "vtkLaplacianEditFilter.h"
#include "vtkLaplacianEditingFiltersModule.h" // for export macro
#include "vtkSmartPointer.h" // for vtkSmartPointer

#include <memory> // for std::unique_ptr

class vtkAlgorithmOutput;
class vtkIntArray;
class vtkLinearTransform;
class vtkPolyData;
class vtkSelection;
namespace LaplacianEditing
{
class DistributedSolver;
namespace Pipeline
{
class EditPipeline;
struct OutputEdit;
struct OutputOptions;
struct RegionParameters;
struct SolverSettings;
}
}

class VTKLAPLACIANEDITINGFILTERS_EXPORT vtkLaplacianDeformationFilter : public vtkLaplacianEditFilter
{
public:
  static vtkLaplacianDeformationFilter* New();
  vtkTypeMacro(vtkLaplacianDeformationFilter, vtkLaplacianEditFilter);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /** The output, a vtkPolyData as the input is. */
  vtkPolyData* GetOutput();
  vtkPolyData* GetOutput(int port);

  enum SelectionModes
  {
    SELECTION_GEODESIC = 0,
    SELECTION_ARRAY = 1
  };
  enum RadiusUnitsTypes
  {
    RADIUS_ABSOLUTE = 0,
    RADIUS_DIAGONAL_FRACTION = 1
  };
  enum DistanceMethods
  {
    DISTANCE_FAST_MARCHING = 0,
    DISTANCE_EDGE_PATHS = 1
  };
  enum EditRoles
  {
    ROLE_FIXED = 0,
    ROLE_ANCHOR = 1,
    ROLE_FREE = 2,
    ROLE_HANDLE = 3
  };

  /**
   * @name Handle
   * Where the handle is and how each handle group moves.
   */
  ///@{
  /**
   * Geodesic selection: the point the handle is centred on, in mesh coordinates; the handle
   * sits on the surface vertex nearest it (a warning says when that vertex is farther away than
   * the handle radius). It is also the pivot of HandleRotation. Default (0, 0, 0).
   */
  vtkSetVector3Macro(HandleCenter, double);
  vtkGetVector3Macro(HandleCenter, double);

  /**
   * Handle group 0's translation, in mesh units, applied after HandleRotation: the simplest way
   * to move the handle from scripts, Python, vedo and ParaView. Used when no transform object
   * is set for group 0. Default (0, 0, 0).
   */
  vtkSetVector3Macro(HandleTranslation, double);
  vtkGetVector3Macro(HandleTranslation, double);

  /**
   * Handle group 0's rotation: angles in degrees about x, then y, then z, about HandleCenter,
   * applied before HandleTranslation. Used when no transform object is set for group 0.
   * Default (0, 0, 0).
   */
  vtkSetVector3Macro(HandleRotation, double);
  vtkGetVector3Macro(HandleRotation, double);

  /**
   * The transform of handle group 0, applied to the handle's rest positions. nullptr (the
   * default) means HandleTranslation and HandleRotation. The filter's MTime includes the
   * transforms' MTimes.
   */
  void SetHandleTransform(vtkLinearTransform* transform) { this->SetHandleTransform(0, transform); }
  vtkLinearTransform* GetHandleTransform() { return this->GetHandleTransform(0); }

  /**
   * The transform of handle group `group` (array value 2 + group); nullptr for no motion.
   */
  void SetHandleTransform(int group, vtkLinearTransform* transform);
  vtkLinearTransform* GetHandleTransform(int group);
  /** How many handle transform slots are set (the largest group given plus one). */
  int GetNumberOfHandleTransforms();
  /** Forget every handle transform object. */
  void RemoveAllHandleTransforms();

  /**
   * Handle group `group`'s motion (group 1 and above), as HandleTranslation and HandleRotation
   * move group 0, about the group's rest centroid (GetHandleGroupCenter); a transform object
   * takes precedence. `group` is a vtkIdType because ParaView's client-server layer converts
   * doubles to 64-bit integers (its HandleGroupMotions property calls this).
   */
  void SetHandleGroupMotion(vtkIdType group, double translationX, double translationY,
    double translationZ, double rotationX, double rotationY, double rotationZ);
  /** Group `group`'s motion as (translation, rotation); false if it has none. */
  bool GetHandleGroupMotion(int group, double motion[6]);
  /** How many groups have a motion. */
  int GetNumberOfHandleGroupMotions();
  /** Forget every group's motion. */
  void RemoveAllHandleGroupMotions();

  /**
   * The rest centroid of handle group `group` in the region of the last update, the natural
   * pivot of its handle widget; false, or (0, 0, 0), if the last update had no such group. The
   * second form is for callers that take no output arguments (ParaView's client-server layer).
   */
  bool GetHandleGroupCenter(int group, double center[3]);
  double* GetHandleGroupCenter(int group) VTK_SIZEHINT(3);

  /**
   * How many handle groups the region of the last update has (groups 0, 1, ...): 1 for a
   * handle alone, 0 before the first region.
   */
  int GetNumberOfHandleGroups();
  ///@}

  /**
   * @name Region
   * Which vertices the handle and the region of interest hold, and how distances are measured.
   */
  ///@{
  /**
   * How the handle and the ROI are chosen: geodesic discs around HandleCenter (default) or the
   * integer point array named with SetInputArrayToProcess (0 fixed, 1 ROI, 2+ handle group).
   */
  vtkSetClampMacro(SelectionMode, int, SELECTION_GEODESIC, SELECTION_ARRAY);
  vtkGetMacro(SelectionMode, int);
  /** Select the handle and ROI as geodesic discs around HandleCenter (the default). */
  void SetSelectionModeToGeodesic() { this->SetSelectionMode(SELECTION_GEODESIC); }
  /** Select the handle and ROI from the labelled point array (SetInputArrayToProcess). */
  void SetSelectionModeToArray() { this->SetSelectionMode(SELECTION_ARRAY); }

  /**
   * An optional vtkSelection on input port 1, as vtkExtractSelection takes it (ParaView's
   * "Copy Active Selection"), chooses the handle: the selected points, or the points of the
   * selected cells, are handle group 0, and the ROI is every point within ROIRadius of them on
   * the surface. Any selection vtkExtractSelection reads works (ids, global ids, frustums,
   * locations, thresholds). A connected selection takes precedence over SelectionMode;
   * HandleCenter remains the pivot of HandleRotation. SetSelectionData(nullptr) removes it.
   */
  void SetSelectionConnection(vtkAlgorithmOutput* selection)
  {
    this->SetInputConnection(1, selection);
  }
  /** The handle's selection as a data object (see SetSelectionConnection); nullptr for none. */
  void SetSelectionData(vtkSelection* selection);

  /**
   * Units of HandleRadius, ROIRadius and NormalSmoothingRadius: mesh units (absolute, the
   * default) or fractions of the diagonal of the input's bounding box, so that one setting fits
   * every mesh (for example a handle of 0.03 and an ROI of 0.15).
   */
  vtkSetClampMacro(RadiusUnits, int, RADIUS_ABSOLUTE, RADIUS_DIAGONAL_FRACTION);
  vtkGetMacro(RadiusUnits, int);
  /** Radii in mesh units (the default). */
  void SetRadiusUnitsToAbsolute() { this->SetRadiusUnits(RADIUS_ABSOLUTE); }
  /** Radii as fractions of the input's bounding-box diagonal. */
  void SetRadiusUnitsToDiagonalFraction() { this->SetRadiusUnits(RADIUS_DIAGONAL_FRACTION); }
  /**
   * Mesh units per radius unit: 1 for absolute radii, the input's bounding-box diagonal for
   * fractions of it (1 while there is no input). Widgets that draw the radii use it.
   */
  double GetRadiusScale();

  /**
   * Geodesic selection: the handle holds the vertices within this surface distance of its
   * centre vertex, in RadiusUnits. Must be smaller than ROIRadius. Default 0.05.
   */
  vtkSetMacro(HandleRadius, double);
  vtkGetMacro(HandleRadius, double);

  /**
   * Geodesic selection: the region of interest holds the vertices within this surface distance
   * of the handle's centre vertex, in RadiusUnits; everything farther is untouched. Default 0.5.
   */
  vtkSetMacro(ROIRadius, double);
  vtkGetMacro(ROIRadius, double);

  /**
   * How distances on the surface are measured, for the handle, the ROI, the anchor band and
   * weights and the normal smoothing: fast marching on the triangles (default; discs are round)
   * or shortest paths along edges (the paper's; discs are polygons whose extent varies by 30%
   * with direction on a regular grid).
   */
  vtkSetClampMacro(DistanceMethod, int, DISTANCE_FAST_MARCHING, DISTANCE_EDGE_PATHS);
  vtkGetMacro(DistanceMethod, int);
  /** Distances by fast marching on the triangles (the default): round discs. */
  void SetDistanceMethodToFastMarching() { this->SetDistanceMethod(DISTANCE_FAST_MARCHING); }
  /** Distances along mesh edges (the paper's): polygonal discs. */
  void SetDistanceMethodToEdgePaths() { this->SetDistanceMethod(DISTANCE_EDGE_PATHS); }

  /**
   * The band of the ROI along its border with the fixed part whose vertices become stationary
   * anchors, as a fraction (0 to 1) of the way from the handle to that border. Default 0.1, the
   * paper's choice. Anchor weights rise with the distance from the handle (Section 6).
   */
  vtkSetClampMacro(AnchorPadding, double, 0.0, 1.0);
  vtkGetMacro(AnchorPadding, double);

  ///@}

  /**
   * @name Constraints
   * The handle's and the anchors' soft constraints (Sections 3 and 6).
   */
  ///@{
  /**
   * Soft-constraint weight of the handle vertices (1e-3 to 1e6). Default 100, so that handles
   * land within a small fraction of a percent of their targets.
   */
  vtkSetClampMacro(HandleWeight, double, 1e-3, 1e6);
  vtkGetMacro(HandleWeight, double);

  /**
   * Soft-constraint weight of the anchors at the ROI's outer edge (0 to 1e6), proportional to
   * the distance from the handle inside the padding. Default 1.
   */
  vtkSetClampMacro(AnchorWeight, double, 0.0, 1e6);
  vtkGetMacro(AnchorWeight, double);
  ///@}

  /**
   * @name Large regions
   * As-rigid-as-possible regions of any size (Documentation/how-it-works.md).
   */
  ///@{
  /**
   * As-rigid-as-possible mode: a region of more vertices than this is dragged on a proxy of
   * about ProxyNodes nodes, at the cost of a small region whatever its size, and settled at
   * full resolution by multigrid, without a factorization (Documentation/how-it-works.md,
   * "Regions of any size"). 0 factors every region, as smaller ones are. Default 60000.
   */
  vtkSetClampMacro(LargeRegionVertices, int, 0, VTK_INT_MAX);
  vtkGetMacro(LargeRegionVertices, int);

  /**
   * As-rigid-as-possible mode: about how many nodes a large region's proxy has (100 to
   * 1000000); more follow the full-resolution shape more closely during a drag, at the cost of
   * a larger region's drag step. Default 10000.
   */
  vtkSetClampMacro(ProxyNodes, int, 100, 1000000);
  vtkGetMacro(ProxyNodes, int);
  ///@}

  /**
   * @name Output
   */
  ///@{
  /**
   * Add the EditRole point array (0 fixed, 1 anchor, 2 free, 3 handle), a vtkSignedCharArray;
   * it becomes the active scalars where the input has none. Default on.
   */
  vtkSetMacro(GenerateEditRoles, vtkTypeBool);
  vtkGetMacro(GenerateEditRoles, vtkTypeBool);
  vtkBooleanMacro(GenerateEditRoles, vtkTypeBool);

  /**
   * Give the EditRole array an indexed lookup table of the paper's Fig. 2 colours, so that a
   * default vtkPolyDataMapper shows the roles; turn it off where the application manages colour
   * maps (the ParaView plugin does). Default on.
   */
  vtkSetMacro(RoleColors, vtkTypeBool);
  vtkGetMacro(RoleColors, vtkTypeBool);
  vtkBooleanMacro(RoleColors, vtkTypeBool);

  /**
   * Whole copies of a rest array (points, normals, EditRole) the output has taken since
   * construction. The output's arrays are kept between updates and a handle move rewrites only
   * the tuples of its region in place, so a move adds none, unless the array the output held
   * is still held elsewhere (a reference or shallow copy kept by the caller, a downstream output
   * not yet updated), which is never written: copy on write. A new input, new input content or
   * a commit copies once.
   */
  vtkIdType GetNumberOfOutputCopies();
  ///@}

  /**
   * @name Commits
   * An edit made the rest shape of the next, without touching the pipeline connection.
   */
  ///@{
  /**
   * Make the current result the rest shape of the next edit: the filter updates, keeps the
   * output's points, sets the handle motions to rest, moves HandleCenter with the handle and
   * fires EditCommittedEvent (paired widgets reset their transforms on it). A new input forgets
   * all commits.
   */
  void CommitEdit();
  /**
   * Restore the rest shape before the last CommitEdit() and fire CommitUndoneEvent; false if
   * there is none.
   */
  bool UndoCommit();
  /** Fired after the rest shape changed by CommitEdit() and UndoCommit(). */
  enum CommitEvents
  {
    EditCommittedEvent = vtkCommand::UserEvent + 2005,
    CommitUndoneEvent
  };
  /** How many commits the current input has. */
  int GetNumberOfCommits();
  /**
   * The rest position of input point `id`: after CommitEdit its committed position, else the
   * input's. Returns false for an id the input does not have.
   */
  bool GetRestPoint(vtkIdType id, double point[3]);
  ///@}

  /**
   * @name Results of the last update
   */
  ///@{
  /** ROI and handle vertices; vertices of the surface graph, the part of the input the edit can
   * reach (the graph and the caches cost in proportion to it). */
  int GetNumberOfROIVertices();
  int GetNumberOfHandleVertices();
  int GetNumberOfSurfaceVertices();
  /** Whether the factors are spread across MPI processes (MUMPS). */
  vtkTypeBool GetFactoredAcrossProcesses();
  ///@}

#ifndef __VTK_WRAP__
  /**
   * A drag preview's step (vtkLaplacianDragPreview): solves the last update's edit again with
   * handle group 0's motion replaced, on that update's region and factors, and leaves the
   * properties and the output as they were; GetSolvedEdit() then gives the new solution. False
   * where anything but that motion changed since the update (a property, a transform, the
   * input's content), or the solve failed.
   */
  bool SolveDragStep(const double translation[3], const double rotation[3]);
  /** The surface the edits solve on: the input with its commits; null without an input. */
  vtkPolyData* GetRestSurface();
#endif

  vtkMTimeType GetMTime() override;

protected:
  vtkLaplacianDeformationFilter();
  ~vtkLaplacianDeformationFilter() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int FillOutputPortInformation(int port, vtkInformation* info) override;
  // The output is always a vtkPolyData, made by the executive from FillOutputPortInformation.
  int RequestDataObject(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override
  {
    return 1;
  }
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  /**
   * The edit of one whole surface: checks it, then runs the edit pipeline on its rest shape and
   * writes `output` (null: not written; the parallel filter's ranks write their own pieces).
   * On bad input: an error, and the output is the input.
   */
  void EditSurface(vtkPolyData* input, vtkPolyData* output);

  /**
   * Writes `edit` (null: nothing moved) into `output`, a shallow copy of `rest`, with EditRole
   * Displacement as GenerateEditRoles, RoleColors and OutputDisplacement say.
   */
  void WriteEdit(vtkPolyData* rest, vtkPolyData* output,
    const LaplacianEditing::Pipeline::OutputEdit* edit);

  /**
   * The labels of the selection on port 1 for the surface being edited
   * (RegionSelector::LabelSelection for piece 0); the parallel filter's gathered surface
   * carries those of its pieces.
   */
  virtual vtkSmartPointer<vtkIntArray> SelectionLabels(vtkPolyData* input, vtkSelection* selection);

  /** The processes a factor may be spread across (the parallel filter's MUMPS); none here. */
  virtual LaplacianEditing::DistributedSolver* GetDistributedSolver() { return nullptr; }

  /** The properties that choose the region, radii in mesh units. */
  LaplacianEditing::Pipeline::RegionParameters RegionParameters() const;

  /** A radius property in mesh units, after RadiusUnits. */
  double AbsoluteRadius(double radius) const;

  /**
   * The whole surface's bounding-box diagonal when the filter edits a part of it (the parallel
   * filter's gathered part); 0: the edited surface's own.
   */
  double WholeDiagonal = 0.0;

  int SelectionMode = SELECTION_GEODESIC;
  int RadiusUnits = RADIUS_ABSOLUTE;
  double HandleCenter[3] = { 0.0, 0.0, 0.0 };
  double HandleTranslation[3] = { 0.0, 0.0, 0.0 };
  double HandleRotation[3] = { 0.0, 0.0, 0.0 };
  double HandleRadius = 0.05;
  double ROIRadius = 0.5;
  double AnchorPadding = 0.1;
  int DistanceMethod = DISTANCE_FAST_MARCHING;
  double HandleWeight = 100.0;
  double AnchorWeight = 1.0;
  int LargeRegionVertices = 60000;
  int ProxyNodes = 10000;
  vtkTypeBool GenerateEditRoles = 1;
  vtkTypeBool RoleColors = 1;

private:
  // The properties that shape the system and the rotation model, and the output's arrays.
  LaplacianEditing::Pipeline::SolverSettings Settings();
  LaplacianEditing::Pipeline::OutputOptions Outputs() const;
  // The input's checks and the region's labels; false, with the error reported, on bad input.
  bool CheckInput(vtkPolyData* input);
  // PrintSelf's parts.
  void PrintRegionProperties(ostream& os, vtkIndent indent);
  void PrintSolverProperties(ostream& os, vtkIndent indent);
  void PrintLastUpdate(ostream& os, vtkIndent indent);

  vtkLaplacianDeformationFilter(const vtkLaplacianDeformationFilter&) = delete;
  void operator=(const vtkLaplacianDeformationFilter&) = delete;

  struct vtkInternals;
  std::unique_ptr<vtkInternals> Internals;
};

#endif
