/**
 * @class   vtkDeformationHandleRepresentation
 * @brief   the handle of a Laplacian edit: a sphere to drag, a ring to turn
 *
 * The representation draws the handle of a vtkLaplacianDeformationFilter edit where the handle
 * transform puts it: a wire sphere of the handle radius; around it, a light blue ring
 * perpendicular to the view, and three rings in the handle's own frame (red, green and blue
 * about its x, y and z axes, which start as the world's and turn with the handle). While the
 * ROI is being resized it also shows the ROI as a wireframe sphere. Its transform,
 * GetTransform(), is what the filter consumes: a rotation about the handle centre followed by
 * a translation.
 *
 * Interaction states: dragging the sphere translates the handle in the view plane; with
 * ConstrainToAxis on, along the handle's frame axis the motion follows most, drawn as a line
 * through the handle while the drag lasts. Dragging a ring rotates the handle about the ring's
 * axis (GetRotationAxis): the angle is the one the cursor sweeps in the ring's plane, so a
 * turn about an axis at any angle to the view follows the cursor. ResizingROI and
 * ResizingHandle set the radii from the distance between the handle centre and the cursor, in
 * the view plane.
 *
 * The representation knows nothing of the filter, as VTK's representations know no algorithm:
 * vtkDeformationHandleWidget pairs its transform with the filter and draws the drag preview.
 *
 * @sa vtkDeformationHandleWidget vtkLaplacianDeformationFilter
 */
#ifndef vtkDeformationHandleRepresentation_h
#define vtkDeformationHandleRepresentation_h

#include "vtkLaplacianEditingWidgetsModule.h" // for export macro
#include "vtkNew.h"                           // for vtkNew
#include "vtkWidgetRepresentation.h"

#include <array> // for std::array

class vtkActor;
class vtkCellPicker;
class vtkLineSource;
class vtkPolyDataMapper;
class vtkProperty;
class vtkRegularPolygonSource;
class vtkSphereSource;
class vtkTransform;
class vtkTubeFilter;

class VTKLAPLACIANEDITINGWIDGETS_EXPORT vtkDeformationHandleRepresentation
  : public vtkWidgetRepresentation
{
public:
  static vtkDeformationHandleRepresentation* New();
  vtkTypeMacro(vtkDeformationHandleRepresentation, vtkWidgetRepresentation);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum RotationAxes
  {
    AxisX = 0,
    AxisY,
    AxisZ,
    ViewAxis
  };

  enum InteractionStates
  {
    Outside = 0,
    OnHandle,
    OnRing,
    Translating,
    Rotating,
    ResizingROI,
    ResizingHandle
  };

  ///@{
  /**
   * The handle's rest centre (on the surface) and its radii. Setting the centre resets the
   * transform.
   */
  void SetCenter(double x, double y, double z);
  void SetCenter(const double center[3]) { this->SetCenter(center[0], center[1], center[2]); }
  vtkGetVector3Macro(Center, double);
  vtkSetClampMacro(HandleRadius, double, 1e-12, VTK_DOUBLE_MAX);
  vtkGetMacro(HandleRadius, double);
  vtkSetClampMacro(ROIRadius, double, 1e-12, VTK_DOUBLE_MAX);
  vtkGetMacro(ROIRadius, double);
  ///@}

  /**
   * The handle transform: rotation about the centre, then translation. The filter consumes it;
   * the representation modifies it in place during interaction.
   */
  vtkTransform* GetTransform();

  /**
   * Move the rest centre and keep the transform (ParaView sets the centre, the translation and
   * the rotation as separate properties, in any order).
   */
  void SetRestCenter(double x, double y, double z);

  ///@{
  /**
   * The transform as the filter's HandleTranslation and HandleRotation properties give it: a
   * translation, and angles in degrees about x, then y, then z (R = Rz Ry Rx), about the centre.
   */
  void SetTranslation(double x, double y, double z);
  vtkGetVector3Macro(Translation, double);
  void SetRotationAngles(double x, double y, double z);
  vtkGetVector3Macro(RotationAngles, double);
  ///@}

  /**
   * Where the transform puts the centre.
   */
  void GetCurrentCenter(double center[3]);

  /**
   * Back to the rest pose: identity transform.
   */
  void ResetTransform();

  ///@{
  /**
   * Translate along one axis only (the one the motion follows most). The widget turns it on
   * while Control is held.
   */
  vtkSetMacro(ConstrainToAxis, vtkTypeBool);
  vtkGetMacro(ConstrainToAxis, vtkTypeBool);
  vtkBooleanMacro(ConstrainToAxis, vtkTypeBool);
  ///@}

  /**
   * The axis of the ring last picked (AxisX, AxisY, AxisZ in the handle's frame, or ViewAxis),
   * about which Rotating turns the handle. The widget may set it.
   */
  vtkSetClampMacro(RotationAxis, int, AxisX, ViewAxis);
  vtkGetMacro(RotationAxis, int);

  /**
   * The handle's frame: column `axis` of its rotation, in world coordinates.
   */
  void GetFrameAxis(int axis, double direction[3]);

  /**
   * The interaction state may be set by the widget (for the resize states).
   */
  vtkSetClampMacro(InteractionState, int, Outside, ResizingHandle);

  ///@{
  /**
   * Properties of the handle sphere, normal and while selected, and of the rings (`axis` one
   * of RotationAxes; GetRingProperty() is the view ring's).
   */
  vtkGetObjectMacro(HandleProperty, vtkProperty);
  vtkGetObjectMacro(SelectedHandleProperty, vtkProperty);
  vtkProperty* GetRingProperty() { return this->GetRingProperty(ViewAxis); }
  vtkProperty* GetRingProperty(int axis);
  ///@}

  // vtkWidgetRepresentation API
  /**
   * Centre the handle in `bounds` (scaled about their centre by PlaceFactor, through
   * AdjustBounds, as VTK's representations do), with radii of 0.05 and 0.3 of the largest side
   * of the scaled bounds, and the identity transform. Fires vtkCommand::PlaceWidgetEvent, on
   * which vtkDeformationHandleWidget passes the handle to its filter.
   */
  void PlaceWidget(double bounds[6]) override;

  /**
   * Registers the picker of the sphere and the rings with the interactor's picking manager;
   * ComputeInteractionState picks through it (GetAssemblyPath) where it is enabled.
   */
  void RegisterPickers() override;
  void BuildRepresentation() override;
  int ComputeInteractionState(int X, int Y, int modify = 0) override;
  void StartWidgetInteraction(double eventPosition[2]) override;
  void WidgetInteraction(double eventPosition[2]) override;
  void EndWidgetInteraction(double eventPosition[2]) override;
  double* GetBounds() override;
  void GetActors(vtkPropCollection* actors) override;
  void ReleaseGraphicsResources(vtkWindow* window) override;
  int RenderOpaqueGeometry(vtkViewport* viewport) override;
  int RenderTranslucentPolygonalGeometry(vtkViewport* viewport) override;
  vtkTypeBool HasTranslucentPolygonalGeometry() override;

protected:
  vtkDeformationHandleRepresentation();
  ~vtkDeformationHandleRepresentation() override;

  // The world point under display position (x, y) in the plane through the current centre
  // perpendicular to the view.
  void DisplayToViewPlane(double x, double y, double world[3]);
  // The same in the plane through the current centre with the given normal; false where the
  // plane is seen edge-on.
  bool DisplayToPlane(double x, double y, const double normal[3], double world[3]);
  // The direction of rotation axis `axis` (RotationAxes) now.
  void GetRotationAxisDirection(int axis, double direction[3]);
  void Highlight(bool on);
  // At the start of a turn: where a ring seen nearly edge-on is grabbed, the screen motion
  // of a radian along it (TangentPerRadian); zero for a ring seen well.
  void StartRingTangent();
  // Draws the axis of a constrained translation through the handle.
  void ShowAxis(const double direction[3]);
  // WidgetInteraction's drags: the translation to the view-plane point `world` (along one
  // frame axis when constrained), and the turn of a ring about `center`.
  void Translate(const double world[3]);
  void Rotate(const double eventPosition[2], const double center[3]);
  // Every actor, the rings first.
  std::array<vtkActor*, 7> Actors();
  // Renders the visible actors with `render` (an opaque or translucent pass).
  int RenderActors(int (vtkProp::*render)(vtkViewport*), vtkViewport* viewport);

  double Center[3] = { 0.0, 0.0, 0.0 };
  double HandleRadius = 0.05;
  double ROIRadius = 0.5;
  vtkTypeBool ConstrainToAxis = 0;
  int RotationAxis = ViewAxis;

  // The transform is rotation about the centre, then translation; both are kept to rebuild it.
  double Rotation[3][3] = { { 1.0, 0.0, 0.0 }, { 0.0, 1.0, 0.0 }, { 0.0, 0.0, 1.0 } };
  double Translation[3] = { 0.0, 0.0, 0.0 };
  double RotationAngles[3] = { 0.0, 0.0, 0.0 }; // of Rotation, kept by UpdateTransform
  vtkNew<vtkTransform> Transform;
  void UpdateTransform();

  // State at the start of an interaction.
  double StartPosition[2] = { 0.0, 0.0 };
  double StartWorld[3] = { 0.0, 0.0, 0.0 };
  double StartTranslation[3] = { 0.0, 0.0, 0.0 };
  double StartRotation[3][3];
  double StartAxis[3] = { 0.0, 0.0, 1.0 }; // of the rotation in progress
  double TangentPerRadian[2] = { 0.0, 0.0 };
  double Bounds[6];

  vtkNew<vtkSphereSource> HandleSource;
  vtkNew<vtkPolyDataMapper> HandleMapper;
  vtkNew<vtkActor> HandleActor;
  // The rings, indexed by RotationAxes.
  vtkNew<vtkRegularPolygonSource> RingSources[4];
  vtkNew<vtkTubeFilter> RingTubes[4];
  vtkNew<vtkPolyDataMapper> RingMappers[4];
  vtkNew<vtkActor> RingActors[4];
  // The axis of a constrained translation.
  vtkNew<vtkLineSource> AxisSource;
  vtkNew<vtkPolyDataMapper> AxisMapper;
  vtkNew<vtkActor> AxisActor;
  vtkNew<vtkSphereSource> ROISource;
  vtkNew<vtkPolyDataMapper> ROIMapper;
  vtkNew<vtkActor> ROIActor;
  vtkNew<vtkCellPicker> Picker; // the sphere and the rings
  // What the shapes were last built for: the radii, the frame's axes and the view's direction.
  std::array<double, 14> ShapeKey = {};
  vtkProperty* HandleProperty;
  vtkProperty* SelectedHandleProperty;
  vtkNew<vtkProperty> RingProperties[4];

private:
  vtkDeformationHandleRepresentation(const vtkDeformationHandleRepresentation&) = delete;
  void operator=(const vtkDeformationHandleRepresentation&) = delete;
};

#endif
