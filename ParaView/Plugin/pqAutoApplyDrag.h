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

#include <QPointer>

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

private:
  static void setDragging(vtkSMProxy* filter, bool dragging);

  vtkSMProxy* Filter = nullptr;
  QPointer<pqView> View;
  bool Active = false;
  // The view's EnableRenderOnInteraction before the drag, while it is held off (-1: it is not).
  int SavedRenderOnInteraction = -1;
};

#endif
