/**
 * @class   vtkDeformationHandleRepresentation
 * @brief   the handle of a Laplacian edit: a sphere to drag, a ring to turn
 *
 * The representation draws the handle of a vtkLaplacianDeformationFilter edit where the handle
 * transform puts it: a wire sphere of the handle radius, and a ring around it,
 * perpendicular to the view. While the ROI is being resized it also shows the ROI as a
 * wireframe sphere. Its transform, GetTransform(), is what the filter consumes: a rotation
 * about the handle centre followed by a translation.
 *
 * Interaction states: dragging the sphere translates the handle in the view plane (along the
 * dominant axis of the motion when ConstrainToAxis is on); dragging the ring rotates it about
 * the view direction; ResizingROI and ResizingHandle set the radii from the distance between
 * the handle centre and the cursor, in the view plane.
 *
 * @sa vtkDeformationHandleWidget vtkLaplacianDeformationFilter
 */
#ifndef vtkDeformationHandleRepresentation_h
#define vtkDeformationHandleRepresentation_h

#include "vtkLaplacianEditingModule.h" // for export macro
#include "vtkNew.h"                           // for vtkNew
#include "vtkWidgetRepresentation.h"

class vtkActor;
class vtkCellPicker;
class vtkPolyDataMapper;
class vtkProperty;
class vtkRegularPolygonSource;
class vtkSphereSource;
class vtkTransform;
class vtkTubeFilter;

class VTKLAPLACIANEDITING_EXPORT vtkDeformationHandleRepresentation
  : public vtkWidgetRepresentation
{
public:
  static vtkDeformationHandleRepresentation* New();
  vtkTypeMacro(vtkDeformationHandleRepresentation, vtkWidgetRepresentation);
  void PrintSelf(ostream& os, vtkIndent indent) override;

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
   * The interaction state may be set by the widget (for the resize states).
   */
  vtkSetClampMacro(InteractionState, int, Outside, ResizingHandle);

  ///@{
  /**
   * Properties of the handle sphere and the ring, normal and while selected.
   */
  vtkGetObjectMacro(HandleProperty, vtkProperty);
  vtkGetObjectMacro(SelectedHandleProperty, vtkProperty);
  vtkGetObjectMacro(RingProperty, vtkProperty);
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
   * Registers the sphere and ring pickers with the interactor's picking manager;
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
  void Highlight(bool on);
  // Renders the visible actors with `render` (an opaque or translucent pass).
  int RenderActors(int (vtkProp::*render)(vtkViewport*), vtkViewport* viewport);

  double Center[3] = { 0.0, 0.0, 0.0 };
  double HandleRadius = 0.05;
  double ROIRadius = 0.5;
  vtkTypeBool ConstrainToAxis = 0;

  // The transform is rotation about the centre, then translation; both are kept to rebuild it.
  double Rotation[3][3] = { { 1.0, 0.0, 0.0 }, { 0.0, 1.0, 0.0 }, { 0.0, 0.0, 1.0 } };
  double Translation[3] = { 0.0, 0.0, 0.0 };
  vtkNew<vtkTransform> Transform;
  void UpdateTransform();

  // State at the start of an interaction.
  double StartPosition[2] = { 0.0, 0.0 };
  double StartWorld[3] = { 0.0, 0.0, 0.0 };
  double StartTranslation[3] = { 0.0, 0.0, 0.0 };
  double StartRotation[3][3];
  double Bounds[6];

  vtkNew<vtkSphereSource> HandleSource;
  vtkNew<vtkPolyDataMapper> HandleMapper;
  vtkNew<vtkActor> HandleActor;
  vtkNew<vtkRegularPolygonSource> RingSource;
  vtkNew<vtkTubeFilter> RingTube;
  vtkNew<vtkPolyDataMapper> RingMapper;
  vtkNew<vtkActor> RingActor;
  vtkNew<vtkSphereSource> ROISource;
  vtkNew<vtkPolyDataMapper> ROIMapper;
  vtkNew<vtkActor> ROIActor;
  vtkNew<vtkCellPicker> HandlePicker;
  vtkNew<vtkCellPicker> RingPicker;
  vtkProperty* HandleProperty;
  vtkProperty* SelectedHandleProperty;
  vtkProperty* RingProperty;

private:
  vtkDeformationHandleRepresentation(const vtkDeformationHandleRepresentation&) = delete;
  void operator=(const vtkDeformationHandleRepresentation&) = delete;
};

#endif
