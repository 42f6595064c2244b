/**
 * @class   pqDeformationHandlePropertyWidget
 * @brief   the Laplacian Deformation filter's handle in ParaView: the 3D widget and its fields
 *
 * The properties panel's widget for the filter's "DeformationHandle" property group. It shows
 * vtkDeformationHandleWidget in the active render view (the same widget as in VTK), and fields
 * for the handle centre, the handle and ROI radii, the translation and the rotation, which stay
 * in sync with the widget both ways. During a drag the panel's values follow the widget; with
 * Auto Apply on, the filter re-solves at every move (moving and turning only re-solve; a resize
 * refactors once, on release). A click on the surface (or "P" over it) puts the handle there;
 * an edit in progress is committed first, as in VTK.
 * Commit Edit makes the current result the rest shape of the next edit; Reset Handle undoes the
 * current move.
 */
#ifndef pqDeformationHandlePropertyWidget_h
#define pqDeformationHandlePropertyWidget_h

#include "pqInteractivePropertyWidget.h"

class pqDeformationHandlePropertyWidget : public pqInteractivePropertyWidget
{
  Q_OBJECT
  typedef pqInteractivePropertyWidget Superclass;

public:
  pqDeformationHandlePropertyWidget(
    vtkSMProxy* proxy, vtkSMPropertyGroup* group, QWidget* parent = nullptr);
  ~pqDeformationHandlePropertyWidget() override = default;

protected Q_SLOTS:
  // Nothing: the handle stays where the filter's properties put it when the panel is shown.
  void placeWidget() override {}
  void setCenter(double x, double y, double z);
  void resetHandle();
  void commitEdit();
  void rememberEdit();
  void commitBeforePlacing();
  void leaveRendersToAutoApply();
  void restoreInteractionRenders();

private:
  // Sets widget properties, then tells the panel (and Auto Apply) that they changed.
  void pushWidgetChange();

  Q_DISABLE_COPY(pqDeformationHandlePropertyWidget)
  // At the start of an interaction: the rest centre, and whether the handle had moved.
  double StartCenter[3] = { 0.0, 0.0, 0.0 };
  bool StartMoved = false;
  // The view's EnableRenderOnInteraction before a drag that Auto Apply renders (-1: untouched).
  int SavedRenderOnInteraction = -1;
};

#endif
