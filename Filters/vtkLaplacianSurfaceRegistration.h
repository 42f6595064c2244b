/**
 * @class   vtkLaplacianSurfaceRegistration
 * @brief   fits a template surface onto a target surface or point cloud, keeping the
 *          template's vertices and triangles (non-rigid registration in dense correspondence)
 *
 * vtkLaplacianSurfaceRegistration moves a triangle template (input port 0) onto a target (input
 * port 1: a triangle surface, or points alone, a point cloud), so that each template vertex
 * lands on the target's corresponding place. A volume template (a vtkUnstructuredGrid of linear
 * 3D cells) is fitted through its boundary surface, and its interior follows without inverting
 * a cell, as in vtkLaplacianVolumeDeformationFilter (with its ScaledJacobian and EditFailed
 * cell arrays). Fitted templates share their vertices, so every specimen fitted from one
 * template is in dense correspondence with the others: its vertices are pseudo-landmarks, and
 * shape statistics and mean shapes come from them directly.
 *
 * The method is non-rigid iterative closest points (Amberg et al. 2007) on the project's edit
 * pipeline:
 *
 * - a pose first: the similarity (or rigid) transform that best takes the landmarks to their
 *   targets where three or more landmark pairs are given (input port 2), otherwise VTK's
 *   iterative closest point transform from the template to the target. The fit then runs in the
 *   template's own frame and size, where its as-rigid-as-possible energy knows the template's
 *   details, and the pose is applied to the result;
 * - where landmarks are given, the landmark warp's fit (vtkLaplacianLandmarkWarp) to them;
 * - a smooth warp of space (WarpRounds rounds): each matches the template to the target and fits
 *   a spline of space to the matches, point-to-plane, from stiff to loose. It reaches a large
 *   smooth stretch or shear, which the stages' as-rigid-as-possible energy resists. A warp that
 *   turns a triangle over on the way is set aside;
 * - then stages of rounds: each template vertex is matched to the foot of its perpendicular on
 *   the target's tangent plane at its closest point (point-to-plane); matches unlikely to be the
 *   same place are set aside (far: beyond MaximumMatchDistance; facing away: normals more than
 *   MaximumNormalAngle apart; beyond the rim of a hole); and the template is solved as rigidly
 *   as possible with the trusted vertices pulled to their matches. The pull grows from
 *   InitialMatchWeight to FinalMatchWeight over NumberOfStages (stiff first, so that whole parts
 *   turn and bend before their details are drawn in), RoundsPerStage rounds each; a round that
 *   keeps the trusted set changes only the right-hand side and reuses the factor. Vertices whose
 *   triangles turn over during the stages are set aside for the rest of the fit;
 * - the stages' fit stands unless they stay farther from the target than the warp by more than
 *   0.2% of the diagonal (root-mean-square point-to-plane): the target is then a strained image
 *   of the template, and the warp's fit is kept (GetWarpKept);
 * - last (LandOnTarget), each trusted vertex moves onto the target where no triangle turns over;
 *   and a sliver (height under a twentieth of its longest edge) the fit turned over is turned
 *   back, its apex where the template has it against its base.
 *
 * A target's normals need not point the same way as the template's; a cloud's are estimated
 * from each point's 12 nearest points. Without landmarks the fit relies on ICP's pose: a target
 * turned far from the template's pose needs landmarks.
 *
 * Output: the template (a vtkPolyData, or the vtkUnstructuredGrid) with its points on the
 * target, every point and cell array passed through, normals refreshed, and the point arrays
 * Displacement (output minus input), DistanceToTarget (each point's distance to the target) and
 * MatchTrusted (1 where the point's last match is trusted, 0 where it is set aside), and the
 * field arrays FitRounds, FitWarpKept, RMSDistanceToTarget and FitSeconds. Progress is reported across the
 * rounds, and an abort ends the fit at its last round's shape. On bad input the filter reports an error,
 * passes the template through and sets GetErrorCode() to vtkErrorCode::UserError.
 * Documentation/template-fitting.md has the guide and the measurements.
 *
 * @sa vtkLaplacianLandmarkWarp vtkIterativeClosestPointTransform vtkLaplacianEditFilter
 */
#ifndef vtkLaplacianSurfaceRegistration_h
#define vtkLaplacianSurfaceRegistration_h

#include "vtkLaplacianEditFilter.h"
#include "vtkLaplacianEditingFiltersModule.h" // for export macro

#include <memory> // for std::unique_ptr

class vtkAlgorithmOutput;
class vtkLinearTransform;
class vtkPoints;
class vtkPointSet;
class vtkPolyData;

class VTKLAPLACIANEDITINGFILTERS_EXPORT vtkLaplacianSurfaceRegistration : public vtkLaplacianEditFilter
{
public:
  static vtkLaplacianSurfaceRegistration* New();
  vtkTypeMacro(vtkLaplacianSurfaceRegistration, vtkLaplacianEditFilter);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum PoseModes
  {
    POSE_NONE = 0,
    POSE_RIGID = 1,
    POSE_SIMILARITY = 2
  };

  /**
   * @name Inputs
   * Port 0 is the template (SetInputConnection), port 1 the target, port 2 (optional) the
   * landmarks: a point set whose points lie on the template and whose three-component point
   * array "Target" (SetInputArrayToProcess(0, 2, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS,
   * name) names another) holds their places on the target. Or, with port 3, two sets of
   * landmarks, the template's on port 2 and the target's on port 3 (Slicer markups through
   * vtkLaplacianMarkupsReader), paired by their Label arrays, or in order without them, as
   * vtkLaplacianLandmarkWarp pairs its ports 1 and 2.
   */
  ///@{
  /** The target on input port 1: a triangle surface, or points alone (a point cloud). */
  void SetTargetConnection(vtkAlgorithmOutput* target) { this->SetInputConnection(1, target); }
  /** The target on input port 1, without a pipeline. */
  void SetTargetData(vtkDataObject* target);
  /** The landmarks on input port 2: points on the template, their places in "Target". */
  void SetLandmarksConnection(vtkAlgorithmOutput* landmarks) { this->SetInputConnection(2, landmarks); }
  /** The landmarks on input port 2, without a pipeline. */
  void SetLandmarksData(vtkDataObject* landmarks);
  /** The target's landmarks on input port 3, paired with port 2's by label. */
  void SetTargetLandmarksConnection(vtkAlgorithmOutput* landmarks)
  {
    this->SetInputConnection(3, landmarks);
  }
  /** The target's landmarks on input port 3, without a pipeline. */
  void SetTargetLandmarksData(vtkDataObject* landmarks);
  ///@}

  /**
   * @name Pose
   */
  ///@{
  /**
   * How the template is first placed on the target: a similarity transform (the default), a
   * rigid one, or none (the template already lies in the target's pose and size). From three or
   * more landmarks where they are given, otherwise by iterative closest points.
   */
  vtkSetClampMacro(PoseMode, int, POSE_NONE, POSE_SIMILARITY);
  vtkGetMacro(PoseMode, int);
  /** The pose the last update found (the identity before one). */
  vtkLinearTransform* GetPose();
  ///@}

  /**
   * @name The fit's stages
   */
  ///@{
  /**
   * The rounds of the smooth warp fitted beside the stages (12; 0 for none): each matches the
   * template to the target and fits a smooth map of space to the matches, point-to-plane, from
   * stiff to loose (SmoothWarp.h). A smooth map reaches a large stretch or shear of the surface,
   * which the as-rigid-as-possible stages resist; it is kept instead of the stages' fit where
   * the stages stay farther from the target than it by more than 0.2% of the diagonal.
   */
  vtkSetClampMacro(WarpRounds, int, 0, 100);
  vtkGetMacro(WarpRounds, int);
  /**
   * The pull of the matches, relative to the template's stiffness, at the first stage (0.001)
   * and the last (0.03), growing geometrically over NumberOfStages (6) of RoundsPerStage (4)
   * rounds each. A stiff start turns and bends whole parts before their details are drawn in.
   * A larger final pull lands the template closer on the target (0.3: within 0.01-0.6% of the
   * diagonal on RegistrationBenchmark's cases, against 0.1-0.7%), at the price of the
   * correspondence and of triangles turned over on fine parts where matches disagree.
   * Both weights, and BendingWeight, mean the same on a template of any resolution: where the
   * template's mean edge is shorter than 0.45% of its diagonal, the pull is scaled by the
   * spacing's ratio and the bending by its inverse square.
   */
  vtkSetClampMacro(InitialMatchWeight, double, 1e-6, 1e6);
  vtkGetMacro(InitialMatchWeight, double);
  /** The pull of the matches at the last stage (0.03); see InitialMatchWeight. */
  vtkSetClampMacro(FinalMatchWeight, double, 1e-6, 1e6);
  vtkGetMacro(FinalMatchWeight, double);
  /**
   * Each landmark's pull in the stages, as many matched vertices' (1000): a landmark is a
   * place known on both shapes, a match only the target's nearest point. Matches pin the
   * template across the target, not along it; the landmarks hold it from sliding there (on
   * RegistrationBenchmark's bend, 1.19% of the diagonal at 1 against 0.95% at 1000, with exact
   * landmarks). Lower it for landmarks placed less surely than the target is scanned.
   */
  vtkSetClampMacro(LandmarkWeight, double, 0.0, 1e9);
  vtkGetMacro(LandmarkWeight, double);
  /** The stages from the initial to the final pull (6). */
  vtkSetClampMacro(NumberOfStages, int, 1, 100);
  vtkGetMacro(NumberOfStages, int);
  /** The rounds of matching and solving in each stage (4). */
  vtkSetClampMacro(RoundsPerStage, int, 1, 100);
  vtkGetMacro(RoundsPerStage, int);
  /**
   * As-rigid-as-possible mode: the weight of the second-order bending term (10), which keeps
   * the template smooth where its matches are set aside (as vtkLaplacianLandmarkWarp's).
   */
  vtkSetClampMacro(BendingWeight, double, 0.0, 1e6);
  vtkGetMacro(BendingWeight, double);
  /**
   * After the stages, move each point whose match is trusted onto it (along the target's
   * normal), except where a triangle would turn over (default on). The stages end where the
   * template's stiffness balances the pull, short of the target where the specimen is not a
   * bent copy of the template (stretched, sheared); landing puts the surface on the target with
   * the stages' correspondence. Off, the output is the stages' as-rigid-as-possible shape.
   */
  vtkSetMacro(LandOnTarget, vtkTypeBool);
  vtkGetMacro(LandOnTarget, vtkTypeBool);
  vtkBooleanMacro(LandOnTarget, vtkTypeBool);
  ///@}

  /**
   * @name Which matches are trusted
   */
  ///@{
  /**
   * A match farther than MaximumMatchDistance (0.1 of the template's diagonal) is set aside;
   * so is one whose normals are more than MaximumNormalAngle (60 degrees) apart.
   */
  vtkSetClampMacro(MaximumMatchDistance, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(MaximumMatchDistance, double);
  /** Normals farther apart than this many degrees (60) set a match aside. */
  vtkSetClampMacro(MaximumNormalAngle, double, 0.0, 180.0);
  vtkGetMacro(MaximumNormalAngle, double);
  /**
   * A landmark farther than this from the template (0.1 of its diagonal) is an error.
   */
  vtkSetClampMacro(MaximumBindingDistance, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(MaximumBindingDistance, double);
  ///@}

  /**
   * @name Results of the last update
   * The rounds run, the root-mean-square distance of the output's surface points to the target
   * (input units; a volume's interior is not counted), the share of them whose match is trusted
   * at the end, the seconds the fit took, and whether the output is the smooth warp's fit
   * (WarpRounds) rather than the stages'.
   */
  ///@{
  vtkGetMacro(NumberOfRounds, int);
  vtkGetMacro(WarpKept, vtkTypeBool);
  vtkGetMacro(RMSDistanceToTarget, double);
  vtkGetMacro(TrustedFraction, double);
  vtkGetMacro(FitTime, double);
  ///@}

protected:
  vtkLaplacianSurfaceRegistration();
  ~vtkLaplacianSurfaceRegistration() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

private:
  vtkLaplacianSurfaceRegistration(const vtkLaplacianSurfaceRegistration&) = delete;
  void operator=(const vtkLaplacianSurfaceRegistration&) = delete;

  // The landmarks of port 2 with their Target array, or paired with port 3's (none: true with
  // both null); false, with the error reported, if they are not usable.
  bool FindLandmarks(vtkPointSet* landmarks, vtkPointSet* subjectLandmarks, vtkPoints*& sources,
    vtkPoints*& targets);
  // The pose, from the landmarks or by ICP; false, with the error reported, if it cannot be
  // found.
  bool FindPose(vtkPolyData* fitted, vtkPointSet* target, vtkPoints* sources, vtkPoints* targets);
  // The stages' rounds on `shape` (the template in the fit's frame, updated in place); false if
  // a solve failed (reported) or the filter was aborted.
  bool Fit(vtkPolyData* rest, vtkPolyData* shape);
  // The smooth warp's rounds from `shape` (the landmarks' fit, or the posed template), which
  // takes the points of `rest` warped; `stands` is false where the warp folded or found too few
  // matches. False if the filter was aborted. Each round is `share` of the progress.
  bool Warp(vtkPolyData* rest, vtkPolyData* shape, double share, bool& stands);
  // The root-mean-square point-to-plane distance of `shape`'s trusted matches.
  double PlaneMisfit(vtkPolyData* shape);
  // The output (the fitted shape, or the grid that followed it) posed, with its arrays.
  void WriteOutput(vtkPointSet* rest, vtkPolyData* shape, vtkPointSet* output);

  int PoseMode = POSE_SIMILARITY;
  int WarpRounds = 12;
  vtkTypeBool WarpKept = 0;
  double InitialMatchWeight = 0.001;
  double FinalMatchWeight = 0.03;
  double LandmarkWeight = 1000.0;
  int NumberOfStages = 6;
  int RoundsPerStage = 4;
  double BendingWeight = 10.0;
  vtkTypeBool LandOnTarget = 1;
  double MaximumMatchDistance = 0.1;
  double MaximumNormalAngle = 60.0;
  double MaximumBindingDistance = 0.1;
  int NumberOfRounds = 0;
  double RMSDistanceToTarget = 0.0;
  double TrustedFraction = 0.0;
  double FitTime = 0.0;

  struct vtkInternals;
  std::unique_ptr<vtkInternals> Internals;
};

#endif
