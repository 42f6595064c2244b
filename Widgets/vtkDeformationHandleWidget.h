/**
 * @class   vtkDeformationHandleWidget
 * @brief   pick, drag and rotate the handle of a Laplacian edit and watch the surface follow
 *
 * vtkDeformationHandleWidget pairs a vtkDeformationHandleRepresentation with a
 * vtkLaplacianDeformationFilter (SetDeformationFilter): the filter's handle transform becomes
 * the representation's, so the surface rendered from the filter's output follows the handle
 * during a drag. Only moving the handle re-solves; the radii reach the filter when a resize
 * ends, so the region is refactored once per resize. A drag turns the filter's Dragging on
 * and, on release, off: in the as-rigid-as-possible mode the frames of a drag then run a few
 * iterations each, and the update after the release settles the shape with the filter's
 * ARAPIterations in full. Where the filter's SettleTimeLimit stops that settle, the widget
 * continues it update by update between the interactor's events (a one-shot timer), so that a
 * large region's release keeps the window responsive; a new grab ends it.
 *
 * Default bindings (left button), set in the event translator so that applications can rebind
 * them (GetEventTranslator()->SetTranslation(...)):
 * - vtkWidgetEvent::Select (press, no modifier): on the sphere, translate in the view plane; on
 *   a ring, rotate about its axis (the view direction for the outer ring, the handle's own x,
 *   y or z axis for the red, green and blue rings); anywhere else the event goes on to the
 *   interactor style, so a drag orbits the camera as in any VTK application, and a click (a
 *   release within 3 pixels of the press) on the surface (SetSurfaceProp) puts the handle on
 *   the picked vertex. An edit in progress is committed first (CommitEdit), never thrown away:
 *   the new handle starts from the edited shape;
 * - vtkWidgetEvent::Translate (Control + press): the same, translating along one axis of the
 *   handle's frame, the one the motion follows most, drawn through the handle during the drag;
 * - vtkWidgetEvent::Resize (Shift + press): on the sphere, resize the region of interest; on the
 *   ring, resize the handle; elsewhere as Select;
 * - vtkWidgetEvent::Move and EndSelect (mouse move, release, any modifier);
 * - vtkWidgetEvent::Up and Down (mouse wheel): over the handle or a ring, grow or shrink the
 *   region of interest by 10% (the filter refactors once per step); elsewhere the camera zooms.
 * SetTranslation adds a binding and the first that matches wins, so remove one before binding
 * its event anew. For example, Control + drag resizes instead of translating along one axis after
 * @code
 * vtkWidgetEventTranslator* translator = widget->GetEventTranslator();
 * translator->RemoveTranslation(
 *   vtkCommand::LeftButtonPressEvent, vtkEvent::ControlModifier, 0, 0, nullptr);
 * translator->SetTranslation(vtkCommand::LeftButtonPressEvent, vtkEvent::ControlModifier, 0, 0,
 *   nullptr, vtkWidgetEvent::Resize);
 * @endcode
 * (The widget starts observing a VTK event it had no binding for when it is next enabled.)
 *
 * The widget (surface picker) and the representation (sphere and ring pickers) register their
 * pickers with the interactor's picking manager and pick through it, so the handle stays
 * pickable in applications that turn the manager on. vtkDeformationHandleRepresentation::
 * PlaceWidget(bounds) puts the handle in the centre of the bounds; the paired filter follows.
 *
 * Drag preview: the widget's preview controller (GetPreviewController(), a
 * vtkDeformationPreviewController on the widget's representation), given a filter and turned
 * on, shows the filter's preview of every change of the handle's motion in place of the actor
 * that draws the filter's output, without updating the pipeline. Applications whose views redraw
 * a whole surface for any moved point use it to drag large surfaces, and update once on release.
 *
 * ResetHandle() undoes the current edit, CommitEdit() makes the edited surface the rest surface
 * of the next edit, UndoCommit() goes back one commit. The widget fires StartInteractionEvent,
 * InteractionEvent and EndInteractionEvent.
 *
 * Several handle groups (labels 2, 3, ... of the filter's array selection) take one widget
 * each, all paired with the same filter: SetHandleGroup(g) makes a widget drive group g's
 * transform. A commit or undo through any of them, or through the filter, puts every paired
 * handle at rest. Only group 0 has a handle and region of its own (HandleCenter and the radii),
 * so the widgets of other groups neither move nor resize the region, and a click places only
 * group 0's handle: the others keep their pivot at their group's centroid.
 *
 * @sa vtkDeformationHandleRepresentation vtkLaplacianDeformationFilter
 */
#ifndef vtkDeformationHandleWidget_h
#define vtkDeformationHandleWidget_h

#include "vtkAbstractWidget.h"
#include "vtkLaplacianEditingWidgetsModule.h" // for export macro

#include <memory> // for std::unique_ptr

class vtkDeformationHandleRepresentation;
class vtkDeformationPreviewController;
class vtkLaplacianDeformationFilter;
class vtkProp;

class VTKLAPLACIANEDITINGWIDGETS_EXPORT vtkDeformationHandleWidget : public vtkAbstractWidget
{
public:
  static vtkDeformationHandleWidget* New();
  vtkTypeMacro(vtkDeformationHandleWidget, vtkAbstractWidget);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * Use this rather than SetWidgetRepresentation(): it pairs the representation with the filter.
   */
  void SetRepresentation(vtkDeformationHandleRepresentation* representation);
  vtkDeformationHandleRepresentation* GetDeformationHandleRepresentation();
  void CreateDefaultRepresentation() override;

  /**
   * Pairs the widget with a filter: the representation takes the filter's handle centre and
   * radii, and the filter takes the representation's transform as its handle transform.
   */
  void SetDeformationFilter(vtkLaplacianDeformationFilter* filter);
  vtkGetObjectMacro(DeformationFilter, vtkLaplacianDeformationFilter);

  /**
   * The handle group whose transform the widget drives (default 0). A group other than 0
   * starts at its rest centroid in the filter's last update.
   */
  void SetHandleGroup(int group);
  vtkGetMacro(HandleGroup, int);

  /**
   * The prop showing the surface; a click on it places the handle. Without one (the default,
   * and in ParaView), a click on any prop but the handle places it.
   */
  void SetSurfaceProp(vtkProp* prop);
  vtkGetObjectMacro(SurfaceProp, vtkProp);

  /**
   * Places the handle on the input vertex nearest `point` (the rest surface), with the
   * identity transform.
   */
  void PlaceHandle(const double point[3]);

  /**
   * The drag preview of the widget's representation (see the class description): set its filter
   * and turn Previewing on. Off by default.
   */
  vtkDeformationPreviewController* GetPreviewController();

  /**
   * Undo the current edit: the identity transform.
   */
  void ResetHandle();

  /**
   * Forward to the filter's CommitEdit() and UndoCommit(), and put the handle at rest where it
   * is (after a commit) or reset it (after an undo). UndoCommit returns false if there is no
   * commit to undo.
   */
  void CommitEdit();
  bool UndoCommit();

protected:
  vtkDeformationHandleWidget();
  ~vtkDeformationHandleWidget() override;

  // The actions of vtkWidgetEvent::Select, Resize, Translate, Move and EndSelect.
  static void SelectAction(vtkAbstractWidget* widget);
  static void ResizeAction(vtkAbstractWidget* widget);
  static void ConstrainedAction(vtkAbstractWidget* widget);
  void BeginInteraction(bool resize, bool constrain);
  static void MoveAction(vtkAbstractWidget* widget);
  static void EndSelectAction(vtkAbstractWidget* widget);
  // vtkWidgetEvent::Up and Down (the mouse wheel): over the handle, grow or shrink the ROI.
  static void GrowAction(vtkAbstractWidget* widget);
  static void ShrinkAction(vtkAbstractWidget* widget);
  void ScaleRegion(double factor);
  // vtkWidgetEvent::TimedOut: the settle timer's continues the filter's settle (its
  // SettleTimeLimit stopped it) by one update, and ScheduleSettle asks for the next.
  static void SettleAction(vtkAbstractWidget* widget);
  void ScheduleSettle();

  /**
   * Registers the surface picker with the picking manager (vtkInteractorObserver API).
   */
  void RegisterPickers() override;

  // The surface point under (x, y), if any.
  bool PickSurface(int x, int y, vtkIdType& pointId);
  // A click (press and release within a few pixels) outside the handle: on the surface, commit
  // the edit in progress and put the handle on the picked point.
  void ClickAction(int x, int y);
  static void WatchClick(vtkObject* caller, unsigned long event, void* clientData, void*);
  void PushToFilter();
  // After the filter's rest shape changed: the handle rests where the edit put it (commit), or
  // where it was (undo).
  void RestAtCurrentCenter();
  // The filter's handle and transform to the representation, the representation's
  // PlaceWidgetEvent to the filter, and the representation to the preview.
  void PairRepresentation();

  vtkLaplacianDeformationFilter* DeformationFilter = nullptr;
  vtkProp* SurfaceProp = nullptr;
  int HandleGroup = 0;
  bool Interacting = false;

private:
  vtkDeformationHandleWidget(const vtkDeformationHandleWidget&) = delete;
  void operator=(const vtkDeformationHandleWidget&) = delete;

  struct vtkInternals;
  std::unique_ptr<vtkInternals> Internals;
};

#endif
