#include "pqDeformationHandlePropertyWidget.h"

#include "pqDoubleLineEdit.h"
#include "pqPointPickingHelper.h"
#include "pqView.h"
#include "vtkPVGeneralSettings.h"
#include "vtkSMNewWidgetRepresentationProxy.h"
#include "vtkSMPropertyGroup.h"
#include "vtkSMPropertyHelper.h"
#include "vtkSMViewProxy.h"
#include "vtkSMProxy.h"

#include <QCheckBox>
#include <QGridLayout>
#include <QLabel>
#include <QPushButton>

pqDeformationHandlePropertyWidget::pqDeformationHandlePropertyWidget(
  vtkSMProxy* proxy, vtkSMPropertyGroup* group, QWidget* parent)
  : Superclass("representations", "DeformationHandleWidgetRepresentation", proxy, group, parent)
{
  auto* layout = new QGridLayout(this);
  layout->setContentsMargins(0, 0, 0, 0);
  int row = 0;
  auto* show = new QCheckBox(tr("Show Handle"), this);
  show->setChecked(true);
  layout->addWidget(show, row++, 0, 1, 4);

  // One field per component, each linked to the filter's property behind the group's function
  // (unchecked until Apply, so the fields follow a drag). Apply commits only linked values, so
  // every property the widget changes has its fields here.
  struct Field
  {
    const char* Function;
    const char* Label;
    int Components;
  };
  const Field fields[] = { { "Center", "Handle Center", 3 }, { "HandleRadius", "Handle Radius", 1 },
    { "ROIRadius", "ROI Radius", 1 }, { "Translation", "Translation", 3 },
    { "Rotation", "Rotation (degrees)", 3 } };
  for (const Field& field : fields)
  {
    vtkSMProperty* property = group->GetProperty(field.Function);
    if (!property)
    {
      continue;
    }
    layout->addWidget(new QLabel(tr(field.Label), this), row, 0);
    for (int i = 0; i < field.Components; ++i)
    {
      auto* edit = new pqDoubleLineEdit(this);
      edit->setObjectName(QString("%1_%2").arg(field.Function).arg(i));
      this->addPropertyLink(edit, "text2", SIGNAL(textChangedAndEditingFinished()), property, i);
      layout->addWidget(edit, row, 1 + i);
    }
    ++row;
  }

  auto* reset = new QPushButton(tr("Reset Handle"), this);
  reset->setObjectName("ResetHandle");
  reset->setToolTip(tr("Undo the current move: no translation, no rotation."));
  auto* commit = new QPushButton(tr("Commit Edit"), this);
  commit->setObjectName("CommitEdit");
  commit->setToolTip(
    tr("Make the current result the rest shape of the next edit; the handle stays where it is."));
  layout->addWidget(reset, row, 0, 1, 2);
  layout->addWidget(commit, row++, 2, 1, 2);
  layout->addWidget(
    new QLabel(tr("<p>Drag the sphere to move the handle, a ring to turn it (Control: along one "
                  "axis; Shift: resize; wheel over the handle: ROI size). "
                  "<b>P</b> on the surface puts the handle there.</p>"),
      this),
    row++, 0, 1, 4);
  QObject::connect(reset, &QPushButton::clicked, this, &pqDeformationHandlePropertyWidget::resetHandle);
  QObject::connect(commit, &QPushButton::clicked, this, &pqDeformationHandlePropertyWidget::commitEdit);

  QObject::connect(show, &QCheckBox::toggled, this, &pqDeformationHandlePropertyWidget::setWidgetVisible);
  QObject::connect(this, &pqDeformationHandlePropertyWidget::widgetVisibilityToggled, show,
    &QCheckBox::setChecked);
  this->setWidgetVisible(show->isChecked());

  auto* picker = new pqPointPickingHelper(QKeySequence(tr("P")), /*pick on mesh*/ true, this);
  QObject::connect(this, &pqPropertyWidget::viewChanged, picker, &pqPointPickingHelper::setView);
  QObject::connect(picker, &pqPointPickingHelper::pick, this, &pqDeformationHandlePropertyWidget::setCenter);

  // Auto Apply applies on changeFinished, which the base class emits at the end of a drag: emit
  // it at every move too, so the surface follows the handle during the drag (a move only
  // re-solves). The radii are applied on release (the widget reports them then).
  QObject::connect(this, &pqInteractivePropertyWidgetAbstract::interaction, this,
    &pqPropertyWidget::changeFinished);
  QObject::connect(this, &pqInteractivePropertyWidgetAbstract::startInteraction, this,
    &pqDeformationHandlePropertyWidget::rememberEdit);
  QObject::connect(this, &pqInteractivePropertyWidgetAbstract::endInteraction, this,
    &pqDeformationHandlePropertyWidget::commitBeforePlacing);
  QObject::connect(this, &pqInteractivePropertyWidgetAbstract::startInteraction, this,
    &pqDeformationHandlePropertyWidget::leaveRendersToAutoApply);
  QObject::connect(this, &pqInteractivePropertyWidgetAbstract::endInteraction, this,
    &pqDeformationHandlePropertyWidget::restoreInteractionRenders);
}

void pqDeformationHandlePropertyWidget::leaveRendersToAutoApply()
{
  // With Auto Apply, every move is applied and the view rendered with the new surface and
  // handle: the render the widget asks for first would show the old surface, and costs as much
  // (half the frame rate of a drag in the GUI). The view renders only for Auto Apply meanwhile.
  pqView* view = this->view();
  vtkSMProperty* property =
    view ? view->getViewProxy()->GetProperty("EnableRenderOnInteraction") : nullptr;
  if (!property || !vtkPVGeneralSettings::GetInstance()->GetAutoApply())
  {
    return;
  }
  this->SavedRenderOnInteraction = vtkSMPropertyHelper(property).GetAsInt();
  vtkSMPropertyHelper(property).Set(0);
  view->getViewProxy()->UpdateVTKObjects();
}

void pqDeformationHandlePropertyWidget::restoreInteractionRenders()
{
  pqView* view = this->view();
  if (this->SavedRenderOnInteraction < 0 || !view)
  {
    return;
  }
  vtkSMPropertyHelper(view->getViewProxy(), "EnableRenderOnInteraction")
    .Set(this->SavedRenderOnInteraction);
  view->getViewProxy()->UpdateVTKObjects();
  this->SavedRenderOnInteraction = -1;
  this->render();
}

void pqDeformationHandlePropertyWidget::rememberEdit()
{
  // The representation's own values (the information properties): the proxy's may not have
  // caught up with the event yet.
  vtkSMProxy* widget = this->widgetProxy();
  widget->UpdatePropertyInformation();
  double translation[3], rotation[3];
  vtkSMPropertyHelper(widget, "CenterInfo").Get(this->StartCenter, 3);
  vtkSMPropertyHelper(widget, "TranslationInfo").Get(translation, 3);
  vtkSMPropertyHelper(widget, "RotationInfo").Get(rotation, 3);
  this->StartMoved = false;
  for (int i = 0; i < 3; ++i)
  {
    this->StartMoved = this->StartMoved || translation[i] != 0.0 || rotation[i] != 0.0;
  }
}

void pqDeformationHandlePropertyWidget::commitBeforePlacing()
{
  // Only a click moves the rest centre. The clicked point is on the edited surface, which the
  // commit makes the rest shape: the filter commits the edit it last applied, and the new
  // handle's values wait for Apply (or Auto Apply) as usual.
  vtkSMProxy* widget = this->widgetProxy();
  widget->UpdatePropertyInformation();
  double center[3];
  vtkSMPropertyHelper(widget, "CenterInfo").Get(center, 3);
  const bool placed = center[0] != this->StartCenter[0] || center[1] != this->StartCenter[1] ||
    center[2] != this->StartCenter[2];
  if (placed && this->StartMoved)
  {
    this->proxy()->InvokeCommand("CommitEdit");
  }
}

void pqDeformationHandlePropertyWidget::pushWidgetChange()
{
  this->widgetProxy()->UpdateVTKObjects();
  Q_EMIT this->changeAvailable();
  Q_EMIT this->changeFinished();
  this->render();
}

void pqDeformationHandlePropertyWidget::setCenter(double x, double y, double z)
{
  // A new handle: it starts at rest.
  const double center[3] = { x, y, z }, zero[3] = { 0.0, 0.0, 0.0 };
  vtkSMProxy* widget = this->widgetProxy();
  vtkSMPropertyHelper(widget, "Center").Set(center, 3);
  vtkSMPropertyHelper(widget, "Translation").Set(zero, 3);
  vtkSMPropertyHelper(widget, "Rotation").Set(zero, 3);
  this->pushWidgetChange();
}

void pqDeformationHandlePropertyWidget::resetHandle()
{
  const double zero[3] = { 0.0, 0.0, 0.0 };
  vtkSMProxy* widget = this->widgetProxy();
  vtkSMPropertyHelper(widget, "Translation").Set(zero, 3);
  vtkSMPropertyHelper(widget, "Rotation").Set(zero, 3);
  this->pushWidgetChange();
}

void pqDeformationHandlePropertyWidget::commitEdit()
{
  // The filter commits its applied edit, sets its translation and rotation to zero and moves
  // its centre with the handle; the proxy's values are set to the same, so that the next Apply
  // does not move the handle again.
  this->proxy()->InvokeCommand("CommitEdit");
  vtkSMProxy* widget = this->widgetProxy();
  double center[3], translation[3];
  vtkSMPropertyHelper(widget, "Center").Get(center, 3);
  vtkSMPropertyHelper(widget, "Translation").Get(translation, 3);
  for (int i = 0; i < 3; ++i)
  {
    center[i] += translation[i];
  }
  this->setCenter(center[0], center[1], center[2]);
}
