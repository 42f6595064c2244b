/**
 * @class   vtkLaplacianLandmarkWarp
 * @brief   warps a surface so that source landmarks reach target landmarks, keeping its details
 *
 * vtkLaplacianLandmarkWarp deforms a triangle surface so that each source landmark moves to its
 * target, the rest of the surface following as rigidly as it can (as-rigid-as-possible, the
 * default) or as the other rotation modes of vtkLaplacianDeformationFilter keep its details.
 * Its interface follows vtkThinPlateSplineTransform where it can: SetSourceLandmarks and
 * SetTargetLandmarks, the same number of points in each. Unlike a thin-plate spline, which
 * bends space and solves a dense system of the landmarks' size, the warp works on the surface:
 * one sparse factorization of the surface's size, whatever the number of landmarks, reused
 * while only the targets change.
 *
 * A source landmark need not be a vertex: it is bound to the nearest point of the surface
 * (barycentric in its triangle), and that point moves by the landmark's displacement. A
 * landmark farther than BindingTolerance from the surface warns; farther than
 * MaximumBindingDistance, it lies on no component and is an error. Every connected component
 * that holds a landmark is warped; the others stay where they are.
 *
 * The landmarks come either as two vtkPoints, or as a point set on input port 1
 * (SetLandmarksConnection): its points are the sources and a three-component point array, by
 * default "Target" (SetInputArrayToProcess(0, 1, 0, POINTS, name)), the targets. The port takes
 * precedence. Or the targets come as a point set of their own on port 2, paired with port 1's
 * points by label (SetTargetLandmarksConnection): 3D Slicer's files, read by
 * vtkLaplacianMarkupsReader. ParaView's "Laplacian Landmark Warp" filter uses the ports.
 *
 * A volume mesh (a vtkUnstructuredGrid of linear 3D cells) warps the same way: the landmarks
 * are bound to its boundary surface, and the interior near the warped part follows without
 * inverting a cell, as in vtkLaplacianVolumeDeformationFilter (with its ScaledJacobian and
 * EditFailed cell arrays).
 *
 * The rotation modes, the solver, Dragging and the shared results are vtkLaplacianEditFilter's,
 * with the defaults of a warp, which solves to convergence at once where an edit is dragged:
 * AsRigidAsPossible, cotangent weights, 100 ARAPIterations and a Convergence of 1e-4. Here
 * NormalSmoothingRadius is in mesh units, and its 0 means 0.05 of the input's diagonal.
 *
 * Output: the input (a vtkPolyData or a vtkUnstructuredGrid) with the warped components' points
 * moved, all point and cell data passed through, normals refreshed, and a "LandmarkDistance"
 * field array, how far each landmark ended from its target (0 up to rounding with ExactFit). On bad input the filter reports an
 * error, passes the input through and sets GetErrorCode() to vtkErrorCode::UserError.
 * Documentation/landmark-warps.md has the guide.
 *
 * @sa vtkLaplacianEditFilter vtkLaplacianDeformationFilter vtkThinPlateSplineTransform
 */
#ifndef vtkLaplacianLandmarkWarp_h
#define vtkLaplacianLandmarkWarp_h

#include "vtkLaplacianEditFilter.h"
#include "vtkLaplacianEditingFiltersModule.h" // for export macro

#include <memory> // for std::unique_ptr

class vtkAlgorithmOutput;
class vtkDoubleArray;
class vtkPoints;
class vtkPointSet;
class vtkPolyData;
namespace LaplacianEditing
{
namespace Pipeline
{
struct SolverSettings;
}
}

class VTKLAPLACIANEDITINGFILTERS_EXPORT vtkLaplacianLandmarkWarp : public vtkLaplacianEditFilter
{
public:
  static vtkLaplacianLandmarkWarp* New();
  vtkTypeMacro(vtkLaplacianLandmarkWarp, vtkLaplacianEditFilter);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * @name Landmarks
   * The pairs, and how the sources are bound to the surface.
   */
  ///@{
  /**
   * The landmarks, as vtkThinPlateSplineTransform takes them: the same number of points in
   * each, in the input's coordinates. Changing only the targets reuses the factorization.
   */
  virtual void SetSourceLandmarks(vtkPoints* sources);
  vtkGetObjectMacro(SourceLandmarks, vtkPoints);
  /** The targets, one per source landmark. */
  virtual void SetTargetLandmarks(vtkPoints* targets);
  vtkGetObjectMacro(TargetLandmarks, vtkPoints);

  /**
   * The landmarks as a point set on input port 1, which takes precedence over the vtkPoints:
   * its points are the sources, and the three-component point array that
   * SetInputArrayToProcess(0, 1, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, name) names,
   * "Target" by default, holds the targets.
   */
  void SetLandmarksConnection(vtkAlgorithmOutput* landmarks) { this->SetInputConnection(1, landmarks); }
  /** The landmarks' point set on input port 1, without a pipeline. */
  void SetLandmarksData(vtkDataObject* landmarks);

  /**
   * The targets as a point set of their own on input port 2 (a template's landmarks on port 1,
   * a subject's here, both read from Slicer's files by vtkLaplacianMarkupsReader): port 1's
   * points are then the sources. Where both point sets have a "Label" point array, landmarks
   * are paired by label, and a label on one side only or twice on one side is an error;
   * otherwise they are paired in order, the same number on each side.
   */
  void SetTargetLandmarksConnection(vtkAlgorithmOutput* targets) { this->SetInputConnection(2, targets); }
  /** The targets' point set on input port 2, without a pipeline. */
  void SetTargetLandmarksData(vtkDataObject* targets);

  /**
   * Targets moved in place of the given ones, as ParaView's landmark dragger moves them:
   * landmark `landmark` (in the order the landmarks pair) goes to (x, y, z), whatever its
   * target input says, until RemoveAllMovedTargets. `landmark` is a vtkIdType because
   * ParaView's client-server layer converts doubles to 64-bit integers (its MovedTargets
   * property calls this). A landmark past the last warns and is left out.
   */
  void SetMovedTarget(vtkIdType landmark, double x, double y, double z);
  int GetNumberOfMovedTargets();
  void RemoveAllMovedTargets();

  /**
   * Binding, in fractions of the input's diagonal: a landmark farther than BindingTolerance
   * (0.01) from the surface warns, one farther than MaximumBindingDistance (0.1) is an error.
   */
  vtkSetClampMacro(BindingTolerance, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(BindingTolerance, double);
  /** Farther than this fraction of the diagonal from the surface, a landmark is an error. */
  vtkSetClampMacro(MaximumBindingDistance, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(MaximumBindingDistance, double);

  /**
   * An exact fit (the default) moves every landmark onto its target, to 1e-10 of the
   * diagonal; off, each landmark is pulled by LandmarkWeight (relative to the surface's
   * stiffness, default 1) and may end short of its target, as noisy landmarks should. Where
   * more landmarks than corners share triangles, no surface meets them all: an exact fit then
   * warns and fits them in the least-squares sense.
   */
  vtkSetMacro(ExactFit, vtkTypeBool);
  vtkGetMacro(ExactFit, vtkTypeBool);
  vtkBooleanMacro(ExactFit, vtkTypeBool);
  /** A soft fit's pull on each landmark, relative to the surface's stiffness. */
  vtkSetClampMacro(LandmarkWeight, double, 1e-6, 1e6);
  vtkGetMacro(LandmarkWeight, double);
  ///@}

  /**
   * @name As-rigid-as-possible terms
   * A warp's own terms beside vtkLaplacianEditFilter's rotation modes.
   */
  ///@{
  /**
   * As-rigid-as-possible mode: the weight of its bending term (100), a second-order term that
   * keeps the surface smooth between sparse landmarks. Without it (0), the first-order energy
   * grows a cone at each landmark and lets the parts between landmarks flop.
   */
  vtkSetClampMacro(BendingWeight, double, 0.0, 1e6);
  vtkGetMacro(BendingWeight, double);

  /**
   * As-rigid-as-possible mode: the pull towards the landmarks' thin-plate spline, relative to
   * the surface's stiffness at the landmarks' spacing (1; 0 turns it off). Sparse landmarks
   * leave the rigid energy many shapes of nearly equal cost, and which one a warp lands in
   * varies with the draw of landmarks; the pull makes it the spline's smooth bend, with the
   * details kept. Off, sparse landmarks on a motion of rigid parts are followed more closely
   * (see Documentation/landmark-warps.md). The spline is fit up to 1,000 landmarks; more hold
   * the surface without it, and landmarks on one plane fix none.
   */
  vtkSetClampMacro(SplinePriorWeight, double, 0.0, 1e3);
  vtkGetMacro(SplinePriorWeight, double);
  ///@}

  /**
   * @name Results of the last update
   */
  ///@{
  /**
   * The landmarks, the vertices warped (the components holding landmarks), the largest and
   * root-mean-square distance of a landmark from its target (mesh units), and the seconds spent
   * binding the landmarks.
   */
  vtkGetMacro(NumberOfLandmarks, int);
  /** The targets the last update warped to, moved ones included: three components a landmark. */
  vtkDoubleArray* GetWarpedTargets();
  int GetNumberOfWarpedVertices();
  vtkGetMacro(MaximumLandmarkDistance, double);
  vtkGetMacro(RMSLandmarkDistance, double);
  double GetBindingTime();
  ///@}

  /** Includes the landmarks' modification times. */
  vtkMTimeType GetMTime() override;

protected:
  vtkLaplacianLandmarkWarp();
  ~vtkLaplacianLandmarkWarp() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

private:
  vtkLaplacianLandmarkWarp(const vtkLaplacianLandmarkWarp&) = delete;
  void operator=(const vtkLaplacianLandmarkWarp&) = delete;

  // The landmarks of ports 1 and 2 or the vtkPoints; false, with the error reported, if they
  // are not usable.
  bool FindLandmarks(vtkPoints*& sources, vtkPoints*& targets);
  // The targets with the moved ones in place (the targets themselves if none moved).
  vtkPoints* MoveTargets(vtkPoints* targets);
  LaplacianEditing::Pipeline::SolverSettings Settings(double diagonal) const;
  // After a solve: the warning for an exact fit that missed, and the landmarks' misses.
  void ReportFit(vtkPolyData* output, vtkPoints* targets);

  vtkPoints* SourceLandmarks = nullptr;
  vtkPoints* TargetLandmarks = nullptr;
  vtkTypeBool ExactFit = 1;
  double LandmarkWeight = 1.0;
  double BendingWeight = 100.0;
  double SplinePriorWeight = 1.0;
  double BindingTolerance = 0.01;
  double MaximumBindingDistance = 0.1;

  int NumberOfLandmarks = 0;
  double MaximumLandmarkDistance = 0.0;
  double RMSLandmarkDistance = 0.0;

  struct vtkInternals;
  std::unique_ptr<vtkInternals> Internals;
};

#endif
