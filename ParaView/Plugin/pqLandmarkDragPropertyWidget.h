/**
 * @class   pqLandmarkDragPropertyWidget
 * @brief   the Laplacian Landmark Warp's landmark dragger: a handle on one target in the view
 *
 * The properties panel's widget for the warp's "MovedTargets" property group. A handle sits on
 * the target of the chosen landmark (the Landmark field, or P over the render view: the
 * landmark whose target is nearest the point under the cursor); dragging it moves that target,
 * which the warp takes in place of the given one (vtkLaplacianLandmarkWarp::SetMovedTarget).
 * With Auto Apply on, the surface follows every move on the same factorization, a few ARAP
 * iterations a move, and settles on release. Reset Moved Targets gives the landmarks their
 * given targets back.
 */
#ifndef pqLandmarkDragPropertyWidget_h
#define pqLandmarkDragPropertyWidget_h

#include "pqAutoApplyDrag.h"
#include "pqInteractivePropertyWidget.h"

#include <QList>
#include <QVariant>

#include <array>
#include <map>

class QSpinBox;

class pqLandmarkDragPropertyWidget : public pqInteractivePropertyWidget
{
  Q_OBJECT
  typedef pqInteractivePropertyWidget Superclass;
  // MovedTargets: four numbers a target (the landmark, its position).
  Q_PROPERTY(QList<QVariant> movedTargets READ movedTargets WRITE setMovedTargets NOTIFY
      movedTargetsChanged)

public:
  pqLandmarkDragPropertyWidget(vtkSMProxy* proxy, vtkSMPropertyGroup* group, QWidget* parent = nullptr);
  ~pqLandmarkDragPropertyWidget() override;

  QList<QVariant> movedTargets() const;
  void setMovedTargets(const QList<QVariant>& values);

Q_SIGNALS:
  void movedTargetsChanged();

protected Q_SLOTS:
  // The handle on the chosen landmark's target.
  void placeWidget() override;
  // The landmark whose target is nearest a picked point.
  void pickLandmark(double x, double y, double z);
  void onInteraction();
  void endDrag();
  void resetTargets();

private:
  // The chosen landmark's target: as moved here, or as the warp's last update had it.
  bool target(int landmark, std::array<double, 3>& position);

  QSpinBox* Landmark = nullptr;
  std::map<int, std::array<double, 3>> Moved;
  pqAutoApplyDrag Drag;

  Q_DISABLE_COPY(pqLandmarkDragPropertyWidget)
};

#endif
