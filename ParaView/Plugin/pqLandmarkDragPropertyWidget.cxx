#include "pqLandmarkDragPropertyWidget.h"

#include "pqApplicationCore.h"
#include "pqPipelineSource.h"
#include "pqPointPickingHelper.h"
#include "pqServerManagerModel.h"
#include "vtkSMNewWidgetRepresentationProxy.h"
#include "vtkSMPropertyGroup.h"
#include "vtkSMPropertyHelper.h"
#include "vtkSMProxy.h"

#include <QCheckBox>
#include <QGridLayout>
#include <QLabel>
#include <QPushButton>
#include <QSpinBox>

#include <limits>

pqLandmarkDragPropertyWidget::pqLandmarkDragPropertyWidget(
  vtkSMProxy* proxy, vtkSMPropertyGroup* group, QWidget* parent)
  : Superclass("representations", "HandleWidgetRepresentation", proxy, group, parent)
{
  auto* layout = new QGridLayout(this);
  layout->setContentsMargins(0, 0, 0, 0);
  auto* show = new QCheckBox(tr("Show Landmark Handle"), this);
  show->setChecked(true);
  layout->addWidget(show, 0, 0, 1, 2);
  layout->addWidget(new QLabel(tr("Landmark"), this), 1, 0);
  this->Landmark = new QSpinBox(this);
  this->Landmark->setObjectName("Landmark");
  this->Landmark->setRange(0, std::numeric_limits<int>::max());
  layout->addWidget(this->Landmark, 1, 1);
  auto* reset = new QPushButton(tr("Reset Moved Targets"), this);
  layout->addWidget(reset, 2, 0, 1, 2);
  layout->addWidget(new QLabel(tr("<p>Drag the handle to move the landmark's target. <b>P</b> "
                                  "over the view picks the landmark whose target is nearest.</p>"),
                      this),
    3, 0, 1, 2);

  if (vtkSMProperty* moved = group->GetProperty("MovedTargets"))
  {
    this->addPropertyLink(this, "movedTargets", SIGNAL(movedTargetsChanged()), moved);
  }
  QObject::connect(show, &QCheckBox::toggled, this, &pqLandmarkDragPropertyWidget::setWidgetVisible);
  QObject::connect(this, &pqLandmarkDragPropertyWidget::widgetVisibilityToggled, show, &QCheckBox::setChecked);
  QObject::connect(this->Landmark, QOverload<int>::of(&QSpinBox::valueChanged), this,
    &pqLandmarkDragPropertyWidget::placeWidget);
  QObject::connect(reset, &QPushButton::clicked, this, &pqLandmarkDragPropertyWidget::resetTargets);
  QObject::connect(this, &pqInteractivePropertyWidgetAbstract::startInteraction, this,
    [this]() { this->Drag.begin(this->proxy(), this->view()); });
  QObject::connect(this, &pqInteractivePropertyWidgetAbstract::interaction, this,
    &pqLandmarkDragPropertyWidget::onInteraction);
  QObject::connect(this, &pqInteractivePropertyWidgetAbstract::endInteraction, this,
    &pqLandmarkDragPropertyWidget::endDrag);
  auto* picker = new pqPointPickingHelper(QKeySequence(tr("P")), false, this);
  picker->connect(this, SIGNAL(viewChanged(pqView*)), SLOT(setView(pqView*)));
  QObject::connect(picker, &pqPointPickingHelper::pick, this, &pqLandmarkDragPropertyWidget::pickLandmark);
  // The targets are known once the warp has updated: the handle follows each update (a drag's
  // updates put it where it is already).
  if (auto* source =
        pqApplicationCore::instance()->getServerManagerModel()->findItem<pqPipelineSource*>(proxy))
  {
    QObject::connect(source, QOverload<pqPipelineSource*>::of(&pqPipelineSource::dataUpdated),
      this, &pqLandmarkDragPropertyWidget::placeWidget);
  }
  // As the handle widget's: a scan's whole-surface warp would hold the window for every step.
  this->Drag.settleBetweenEvents(this);
  this->setWidgetVisible(true);
  this->placeWidget();
}

pqLandmarkDragPropertyWidget::~pqLandmarkDragPropertyWidget()
{
  this->Drag.end();
}

QList<QVariant> pqLandmarkDragPropertyWidget::movedTargets() const
{
  QList<QVariant> values;
  for (const auto& entry : this->Moved)
  {
    values << static_cast<double>(entry.first) << entry.second[0] << entry.second[1] << entry.second[2];
  }
  return values;
}

void pqLandmarkDragPropertyWidget::setMovedTargets(const QList<QVariant>& values)
{
  this->Moved.clear();
  for (int i = 0; i + 4 <= values.size(); i += 4)
  {
    this->Moved[values[i].toInt()] = { { values[i + 1].toDouble(), values[i + 2].toDouble(),
      values[i + 3].toDouble() } };
  }
  this->placeWidget();
}

bool pqLandmarkDragPropertyWidget::target(int landmark, std::array<double, 3>& position)
{
  const auto moved = this->Moved.find(landmark);
  if (moved != this->Moved.end())
  {
    position = moved->second;
    return true;
  }
  this->proxy()->UpdatePropertyInformation();
  vtkSMPropertyHelper targets(this->proxy(), "WarpedTargets");
  if (3 * landmark + 2 >= static_cast<int>(targets.GetNumberOfElements()))
  {
    return false;
  }
  for (int c = 0; c < 3; ++c)
  {
    position[c] = targets.GetAsDouble(3 * landmark + c);
  }
  return true;
}

void pqLandmarkDragPropertyWidget::placeWidget()
{
  std::array<double, 3> position;
  if (this->target(this->Landmark->value(), position))
  {
    vtkSMProxy* widget = this->widgetProxy();
    vtkSMPropertyHelper(widget, "WorldPosition").Set(position.data(), 3);
    widget->UpdateVTKObjects();
    this->render();
  }
}

void pqLandmarkDragPropertyWidget::pickLandmark(double x, double y, double z)
{
  this->proxy()->UpdatePropertyInformation();
  vtkSMPropertyHelper targets(this->proxy(), "WarpedTargets");
  const int count = static_cast<int>(targets.GetNumberOfElements() / 3);
  int nearest = -1;
  double best = std::numeric_limits<double>::max();
  for (int landmark = 0; landmark < count; ++landmark)
  {
    std::array<double, 3> position;
    this->target(landmark, position);
    const double squared = (position[0] - x) * (position[0] - x) +
      (position[1] - y) * (position[1] - y) + (position[2] - z) * (position[2] - z);
    if (squared < best)
    {
      best = squared;
      nearest = landmark;
    }
  }
  if (nearest >= 0)
  {
    this->Landmark->setValue(nearest);
    this->placeWidget();
  }
}

void pqLandmarkDragPropertyWidget::onInteraction()
{
  // The handle's own position (the information property: the proxy's may not have caught up).
  vtkSMProxy* widget = this->widgetProxy();
  widget->UpdatePropertyInformation();
  std::array<double, 3> position;
  vtkSMPropertyHelper(widget, "WorldPositionInfo").Get(position.data(), 3);
  this->Moved[this->Landmark->value()] = position;
  Q_EMIT this->movedTargetsChanged();
  Q_EMIT this->changeAvailable();
  Q_EMIT this->changeFinished(); // Auto Apply applies every move
}

void pqLandmarkDragPropertyWidget::endDrag()
{
  if (this->Drag.end())
  {
    // Dragging went off on the server alone: mark the pipeline so that the render updates it,
    // settled.
    this->proxy()->MarkModified(this->proxy());
    this->render();
  }
}

void pqLandmarkDragPropertyWidget::resetTargets()
{
  this->Moved.clear();
  Q_EMIT this->movedTargetsChanged();
  Q_EMIT this->changeAvailable();
  Q_EMIT this->changeFinished();
  this->placeWidget();
}
