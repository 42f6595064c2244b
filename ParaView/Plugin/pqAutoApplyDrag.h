/**
 * @class   pqAutoApplyDrag
 * @brief   a drag in the render view that Auto Apply applies move by move
 *
 * What the panel's handle and landmark widgets do around such a drag: while it lasts, the view
 * renders only for Auto Apply (the render the widget asks for first would show the old surface
 * and costs as much, half the frame rate of a drag), and the filter's Dragging is on (a few
 * ARAP iterations a move); after it, both are back as they were. Dragging is set straight on
 * the filter, not through a property: pushing a property marks the proxy modified, and ParaView
 * would update the whole surface's representation at the drag's start and its release (a
 * second each at 2M points).
 */
#ifndef pqAutoApplyDrag_h
#define pqAutoApplyDrag_h

#include <QElapsedTimer>
#include <QPointer>

class QObject;
class pqPropertyWidget;
class pqView;
class vtkSMProxy;

class pqAutoApplyDrag
{
public:
  /// Starts a drag of `filter` in `view`; false, with nothing done, without Auto Apply.
  bool begin(vtkSMProxy* filter, pqView* view);
  /// Ends the drag; false if none was going on. With `holdRendering`, the view's renders on
  /// interaction stay off until resumeRendering(): where an update is coming that will render
  /// the drag's result, the render the release asks for first would draw a preview it replaces
  /// (a still render: 0.35 s on a 2M-point surface).
  bool end(bool holdRendering = false);
  /// Gives the view back the renders on interaction that end(true) held off; nothing during a
  /// drag or otherwise.
  void resumeRendering();

  /// Settles `widget`'s filter between the GUI's events. Gives the filter the GUI's settle time
  /// limit (its SettleTimeLimit, set on the server alone as Dragging is, so that a script or a
  /// saved state settles in full): an update then waits at most about that long, or one step
  /// where a step takes longer. After each of its updates outside a drag whose settle stopped
  /// there with iterations left (its Settling information), continues it (the filter's
  /// ContinueSettling, then its update) once the events waiting are handled, unless a drag has
  /// begun by then, so that the window waits at most one update and a new grab ends the
  /// settle. The widget's view renders the settle's shape every few seconds and at its end, not
  /// at each update: ParaView's update of a changed output and its render cost about a second on
  /// a 2.4M-point scan, as much as a 269k region's step. `widget` owns this object.
  void settleBetweenEvents(pqPropertyWidget* widget);

private:
  void continueSettle(vtkSMProxy* filter, pqView* view, QObject* context);
  template <typename... Arguments>
  static void invoke(vtkSMProxy* filter, const char* method, Arguments... arguments);
  static void setDragging(vtkSMProxy* filter, bool dragging);

  vtkSMProxy* Filter = nullptr;
  QPointer<pqView> View;
  bool Active = false;
  // Since the view last drew the settle's shape (or the drag's release), and whether an update
  // of the settle has not been drawn yet.
  QElapsedTimer SinceSettleRender;
  bool SettleUndrawn = false;
  // The view's EnableRenderOnInteraction before the drag, while it is held off (-1: it is not).
  int SavedRenderOnInteraction = -1;
};

#endif
