/**
 * @class   pqDeformationHandlePropertyWidget
 * @brief   the Laplacian Deformation filter's handle in ParaView: the 3D widget and its fields
 *
 * The properties panel's widget for the filter's "DeformationHandle" property group. It shows
 * vtkDeformationHandleWidget in the active render view (the same widget as in VTK), and fields
 * for the handle centre, the handle and ROI radii, the translation and the rotation, which stay
 * in sync with the widget both ways. During a drag the panel's values follow the widget; with
 * Auto Apply on, the surface follows every move. Where the filter runs in the process that
 * renders (the built-in session, or a one-process server rendering remotely), a drag of the
 * handle is drawn by the widget's preview: the filter solves each move outside the pipeline
 * and the view redraws only the moving part of the surface (vtkDeformationHandleRepresentation);
 * the pipeline updates once, on release, to what a scripted update gives. Elsewhere each move
 * is applied (moving and turning only re-solve; a resize refactors once, on release). A click on the surface (or "P" over it) puts the handle there;
 * an edit in progress is committed first, as in VTK.
 * Commit Edit makes the current result the rest shape of the next edit; Reset Handle undoes the
 * current move.
 *
 * In array mode, each further handle group (array values 3, 4, ...) gets a handle of its own in
 * the view, at the group's rest centroid, and a translation and a rotation field in the panel:
 * they drive the group's entry in HandleGroupMotions. A click on the surface moves only the
 * first handle.
 */
#ifndef pqDeformationHandlePropertyWidget_h
#define pqDeformationHandlePropertyWidget_h

#include "pqAutoApplyDrag.h"
#include "pqInteractivePropertyWidget.h"

#include <QList>
#include <QVariant>

#include <array>
#include <map>
#include <vector>

class pqDoubleLineEdit;
class QGridLayout;

class pqDeformationHandlePropertyWidget : public pqInteractivePropertyWidget
{
  Q_OBJECT
  typedef pqInteractivePropertyWidget Superclass;
  // HandleGroupMotions: seven numbers a group (the group, translation, rotation angles).
  Q_PROPERTY(QList<QVariant> groupMotions READ groupMotions WRITE setGroupMotions NOTIFY
      groupMotionsChanged)

public:
  pqDeformationHandlePropertyWidget(
    vtkSMProxy* proxy, vtkSMPropertyGroup* group, QWidget* parent = nullptr);
  ~pqDeformationHandlePropertyWidget() override;

  void setView(pqView* view) override;
  QList<QVariant> groupMotions() const;
  void setGroupMotions(const QList<QVariant>& values);

Q_SIGNALS:
  void groupMotionsChanged();

protected Q_SLOTS:
  // Nothing: the handle stays where the filter's properties put it when the panel is shown.
  void placeWidget() override {}
  void setCenter(double x, double y, double z);
  void resetHandle();
  void commitEdit();
  void rememberEdit();
  void commitBeforePlacing();
  // A drag with Auto Apply: previewed (`preview`, where the preview can draw it) or applied
  // at every move.
  void beginAutoApplyDrag(bool preview = true);
  void endAutoApplyDrag();
  // A move of the handle: the preview's, or Auto Apply's.
  void onInteraction();
  // After the filter updated: one handle per further group, at its rest centroid.
  void updateGroupHandles();
  void showGroupHandles(bool visible);

private:
  // The constructor's parts: the property fields and the further groups' rows, the buttons,
  // and the drag's connections.
  void addFields(vtkSMPropertyGroup* group, QGridLayout* layout, int& row);
  void addButtons(QGridLayout* layout, int& row);
  void connectInteraction();
  // Gives the widget's representation the filter, where both live in one process.
  void connectPreview(bool connect);
  // Whether a drag can be previewed: the filter runs where the view renders.
  bool canPreview();
  // Whether the handle's translation or rotation waits to be applied.
  bool hasUnappliedMotion();
  // Gives the view's surface back to the pipeline.
  void endPreview();
  // Sets widget properties, then tells the panel (and Auto Apply) that they changed.
  void pushWidgetChange();
  void addGroupHandle();
  void removeLastGroupHandle();
  // A group handle's widget events: its motion goes to the group's entry.
  void onGroupHandleEvent(vtkObject* caller, unsigned long event, void*);
  // Puts the stored motion of group `group` in its widget and its fields; in its fields only,
  // returning it.
  void showGroupMotion(int group);
  std::array<double, 6> showGroupFields(int group);
  void setGroupMotion(int group, const std::array<double, 6>& motion);
  void clearGroupMotions();
  bool anyGroupMoved() const;

  struct GroupHandle;
  // Groups 1, 2, ...: GroupHandles[g - 1].
  std::vector<GroupHandle> GroupHandles;
  // Every group's motion, as in HandleGroupMotions (also those without a handle yet).
  std::map<int, std::array<double, 6>> GroupMotions;
  QGridLayout* GroupLayout = nullptr;
  bool GroupHandlesVisible = false;

  Q_DISABLE_COPY(pqDeformationHandlePropertyWidget)
  // At the start of an interaction: the rest centre, and whether the handle had moved.
  double StartCenter[3] = { 0.0, 0.0, 0.0 };
  bool StartMoved = false;
  // A drag that Auto Apply applies move by move.
  pqAutoApplyDrag Drag;
  // Whether the representation has the filter, and whether the current drag is previewed.
  bool PreviewConnected = false;
  bool Previewing = false;
  // After a previewed drag: the preview shows until the pipeline updates with its values.
  bool PreviewUntilUpdate = false;
};

#endif
