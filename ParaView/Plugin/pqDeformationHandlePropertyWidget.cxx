#include "pqDeformationHandlePropertyWidget.h"

#include "pqApplicationCore.h"
#include "pqDoubleLineEdit.h"
#include "pqPipelineSource.h"
#include "pqPointPickingHelper.h"
#include "pqServer.h"
#include "pqServerManagerModel.h"
#include "pqView.h"
#include "vtkBoundingBox.h"
#include "vtkClientServerStream.h"
#include "vtkCommand.h"
#include "vtkNew.h"
#include "vtkPVDataInformation.h"
#include "vtkPVRenderView.h"
#include "vtkPVSession.h"
#include "vtkSMNewWidgetRepresentationProxy.h"
#include "vtkSMParaViewPipelineController.h"
#include "vtkSMPropertyGroup.h"
#include "vtkSMPropertyHelper.h"
#include "vtkSMProxy.h"
#include "vtkSMSession.h"
#include "vtkSMSessionProxyManager.h"
#include "vtkSMSourceProxy.h"
#include "vtkSMViewProxy.h"

#include <QCheckBox>
#include <QGridLayout>
#include <QLabel>
#include <QPushButton>

#include <algorithm>
#include <cstring>
#include <utility>

struct pqDeformationHandlePropertyWidget::GroupHandle
{
  vtkSmartPointer<vtkSMProxy> Widget;
  std::array<pqDoubleLineEdit*, 6> Fields; // translation, then rotation
  std::array<QLabel*, 2> Labels;
};

namespace
{
// Adds the widget to the view's hidden representations, or removes it, as ParaView does with the
// panel's own widget.
void ShowInView(vtkSMProxy* widget, pqView* view, bool add)
{
  if (!view)
  {
    return;
  }
  vtkSMPropertyHelper representations(view->getProxy(), "HiddenRepresentations", true);
  if (add)
  {
    representations.Add(widget);
  }
  else
  {
    representations.Remove(widget);
  }
  view->getProxy()->UpdateVTKObjects();
}
}

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
  this->addFields(group, layout, row);
  this->addButtons(layout, row);
  QObject::connect(show, &QCheckBox::toggled, this, &pqDeformationHandlePropertyWidget::setWidgetVisible);
  QObject::connect(this, &pqDeformationHandlePropertyWidget::widgetVisibilityToggled, show,
    &QCheckBox::setChecked);
  this->setWidgetVisible(show->isChecked());

  auto* picker = new pqPointPickingHelper(QKeySequence(tr("P")), /*pick on mesh*/ true, this);
  QObject::connect(this, &pqPropertyWidget::viewChanged, picker, &pqPointPickingHelper::setView);
  QObject::connect(picker, &pqPointPickingHelper::pick, this, &pqDeformationHandlePropertyWidget::setCenter);
  this->connectInteraction();
  this->connectPreview(true);
  QObject::connect(this, &pqInteractivePropertyWidgetAbstract::widgetVisibilityUpdated, this,
    &pqDeformationHandlePropertyWidget::showGroupHandles);
  if (auto* source =
        pqApplicationCore::instance()->getServerManagerModel()->findItem<pqPipelineSource*>(proxy))
  {
    QObject::connect(source, QOverload<pqPipelineSource*>::of(&pqPipelineSource::dataUpdated),
      this, &pqDeformationHandlePropertyWidget::updateGroupHandles);
  }
  this->Drag.settleBetweenEvents(this);
  this->updateGroupHandles();
}

void pqDeformationHandlePropertyWidget::addFields(vtkSMPropertyGroup* group, QGridLayout* layout, int& row)
{
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
  // Further handle groups: rows added as the filter reports them (updateGroupHandles).
  auto* groups = new QWidget(this);
  this->GroupLayout = new QGridLayout(groups);
  this->GroupLayout->setContentsMargins(0, 0, 0, 0);
  layout->addWidget(groups, row++, 0, 1, 4);
  if (vtkSMProperty* motions = group->GetProperty("GroupMotions"))
  {
    this->addPropertyLink(this, "groupMotions", SIGNAL(groupMotionsChanged()), motions);
  }
}

void pqDeformationHandlePropertyWidget::addButtons(QGridLayout* layout, int& row)
{
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
}

void pqDeformationHandlePropertyWidget::connectInteraction()
{
  // Auto Apply applies on changeFinished, which the base class emits at the end of a drag: emit
  // it at every move too, so the surface follows the handle during the drag (a move only
  // re-solves). The radii are applied on release (the widget reports them then).
  QObject::connect(this, &pqInteractivePropertyWidgetAbstract::interaction, this,
    &pqDeformationHandlePropertyWidget::onInteraction);
  QObject::connect(this, &pqInteractivePropertyWidgetAbstract::startInteraction, this,
    &pqDeformationHandlePropertyWidget::rememberEdit);
  QObject::connect(this, &pqInteractivePropertyWidgetAbstract::endInteraction, this,
    &pqDeformationHandlePropertyWidget::commitBeforePlacing);
  QObject::connect(this, &pqInteractivePropertyWidgetAbstract::startInteraction, this,
    [this]() { this->beginAutoApplyDrag(true); });
  QObject::connect(this, &pqInteractivePropertyWidgetAbstract::endInteraction, this,
    &pqDeformationHandlePropertyWidget::endAutoApplyDrag);
}

pqDeformationHandlePropertyWidget::~pqDeformationHandlePropertyWidget()
{
  this->endPreview();
  this->connectPreview(false);
  while (!this->GroupHandles.empty())
  {
    this->removeLastGroupHandle();
  }
}

void pqDeformationHandlePropertyWidget::setView(pqView* view)
{
  for (GroupHandle& handle : this->GroupHandles)
  {
    ShowInView(handle.Widget, this->view(), false);
  }
  this->Superclass::setView(view);
  for (GroupHandle& handle : this->GroupHandles)
  {
    ShowInView(handle.Widget, this->view(), true);
  }
}

QList<QVariant> pqDeformationHandlePropertyWidget::groupMotions() const
{
  QList<QVariant> values;
  for (const auto& entry : this->GroupMotions)
  {
    values << static_cast<double>(entry.first);
    for (double value : entry.second)
    {
      values << value;
    }
  }
  return values;
}

void pqDeformationHandlePropertyWidget::setGroupMotions(const QList<QVariant>& values)
{
  this->GroupMotions.clear();
  for (int i = 0; i + 7 <= values.size(); i += 7)
  {
    std::array<double, 6> motion;
    for (int k = 0; k < 6; ++k)
    {
      motion[k] = values[i + 1 + k].toDouble();
    }
    this->GroupMotions[values[i].toInt()] = motion;
  }
  for (int g = 1; g <= static_cast<int>(this->GroupHandles.size()); ++g)
  {
    this->showGroupMotion(g);
  }
  this->render();
}

void pqDeformationHandlePropertyWidget::setGroupMotion(int group, const std::array<double, 6>& motion)
{
  this->GroupMotions[group] = motion;
  this->showGroupMotion(group);
  Q_EMIT this->groupMotionsChanged();
}

void pqDeformationHandlePropertyWidget::clearGroupMotions()
{
  if (!this->GroupMotions.empty())
  {
    this->setGroupMotions({});
    Q_EMIT this->groupMotionsChanged();
  }
}

bool pqDeformationHandlePropertyWidget::anyGroupMoved() const
{
  return std::any_of(this->GroupMotions.begin(), this->GroupMotions.end(), [](const auto& entry) {
    return std::any_of(
      entry.second.begin(), entry.second.end(), [](double value) { return value != 0.0; });
  });
}

void pqDeformationHandlePropertyWidget::showGroupMotion(int group)
{
  if (group < 1 || group > static_cast<int>(this->GroupHandles.size()))
  {
    return;
  }
  const std::array<double, 6> motion = this->showGroupFields(group);
  vtkSMProxy* widget = this->GroupHandles[group - 1].Widget;
  vtkSMPropertyHelper(widget, "Translation").Set(motion.data(), 3);
  vtkSMPropertyHelper(widget, "Rotation").Set(motion.data() + 3, 3);
  widget->UpdateVTKObjects();
}

std::array<double, 6> pqDeformationHandlePropertyWidget::showGroupFields(int group)
{
  const auto found = this->GroupMotions.find(group);
  const std::array<double, 6> motion =
    found == this->GroupMotions.end() ? std::array<double, 6>{} : found->second;
  for (int k = 0; k < 6; ++k)
  {
    this->GroupHandles[group - 1].Fields[k]->setTextAndResetCursor(
      QString::number(motion[k], 'g', 17));
  }
  return motion;
}

void pqDeformationHandlePropertyWidget::updateGroupHandles()
{
  if (this->PreviewUntilUpdate && !this->hasUnappliedMotion())
  {
    this->endPreview(); // the pipeline has the drag's result: the view renders it next
  }
  // The filter reports its groups after an update; each further group's handle sits at the
  // group's rest centroid, which only the filter's process knows.
  vtkSMProxy* filter = this->proxy();
  filter->UpdatePropertyInformation();
  const int further =
    std::max(0, vtkSMPropertyHelper(filter, "NumberOfHandleGroups", true).GetAsInt() - 1);
  while (static_cast<int>(this->GroupHandles.size()) > further)
  {
    this->removeLastGroupHandle();
  }
  while (static_cast<int>(this->GroupHandles.size()) < further)
  {
    this->addGroupHandle();
  }
  // The first handle's size; array mode does not use it, so it may be unset (a source whose
  // bounds were unknown): then 5% of the output's extent, as a new handle in VTK.
  double radius = vtkSMPropertyHelper(filter, "HandleRadius").GetAsDouble();
  if (!(radius > 0.0))
  {
    const vtkBoundingBox bounds(
      vtkSMSourceProxy::SafeDownCast(filter)->GetDataInformation(0)->GetBounds());
    radius = bounds.IsValid() ? 0.05 * bounds.GetDiagonalLength() : 1.0;
  }
  for (int g = 1; g <= further; ++g)
  {
    vtkClientServerStream stream;
    stream << vtkClientServerStream::Invoke << VTKOBJECT(filter) << "GetHandleGroupCenter" << g
           << vtkClientServerStream::End;
    filter->GetSession()->ExecuteStream(vtkPVSession::DATA_SERVER_ROOT, stream, false);
    double center[3] = { 0.0, 0.0, 0.0 };
    filter->GetSession()->GetLastResult(vtkPVSession::DATA_SERVER_ROOT).GetArgument(0, 0, center, 3);
    vtkSMProxy* widget = this->GroupHandles[g - 1].Widget;
    vtkSMPropertyHelper(widget, "Center").Set(center, 3);
    vtkSMPropertyHelper(widget, "HandleRadius").Set(radius);
    vtkSMPropertyHelper(widget, "ROIRadius").Set(radius);
    this->showGroupMotion(g);
  }
}

void pqDeformationHandlePropertyWidget::addGroupHandle()
{
  const int group = static_cast<int>(this->GroupHandles.size()) + 1;
  GroupHandle handle;
  handle.Widget.TakeReference(this->proxy()->GetSessionProxyManager()->NewProxy(
    "representations", "DeformationHandleWidgetRepresentation"));
  vtkNew<vtkSMParaViewPipelineController> controller;
  controller->InitializeProxy(handle.Widget);
  handle.Widget->PrototypeOn(); // as the panel's own widget: out of undo and state files
  for (unsigned long event : { vtkCommand::StartInteractionEvent, vtkCommand::InteractionEvent,
         vtkCommand::EndInteractionEvent })
  {
    handle.Widget->AddObserver(event, this, &pqDeformationHandlePropertyWidget::onGroupHandleEvent);
  }
  ShowInView(handle.Widget, this->view(), true);
  vtkSMPropertyHelper(handle.Widget, "Visibility").Set(this->GroupHandlesVisible);
  vtkSMPropertyHelper(handle.Widget, "Enabled").Set(this->GroupHandlesVisible);
  handle.Widget->UpdateVTKObjects();

  const int row = 2 * (group - 1);
  const QString names[2] = { tr("Group %1 Translation").arg(group),
    tr("Group %1 Rotation").arg(group) };
  for (int line = 0; line < 2; ++line)
  {
    handle.Labels[line] = new QLabel(names[line], this);
    this->GroupLayout->addWidget(handle.Labels[line], row + line, 0);
    for (int i = 0; i < 3; ++i)
    {
      auto* edit = new pqDoubleLineEdit(this);
      edit->setObjectName(QString("Group%1_%2").arg(group).arg(3 * line + i));
      this->GroupLayout->addWidget(edit, row + line, 1 + i);
      handle.Fields[3 * line + i] = edit;
      QObject::connect(edit, &pqLineEdit::textChangedAndEditingFinished, this, [this, group]() {
        std::array<double, 6> motion;
        for (int k = 0; k < 6; ++k)
        {
          motion[k] = this->GroupHandles[group - 1].Fields[k]->text().toDouble();
        }
        this->setGroupMotion(group, motion);
        Q_EMIT this->changeAvailable();
        this->render();
      });
    }
  }
  this->GroupHandles.push_back(handle);
}

void pqDeformationHandlePropertyWidget::removeLastGroupHandle()
{
  GroupHandle& handle = this->GroupHandles.back();
  handle.Widget->RemoveObservers(vtkCommand::StartInteractionEvent);
  handle.Widget->RemoveObservers(vtkCommand::InteractionEvent);
  handle.Widget->RemoveObservers(vtkCommand::EndInteractionEvent);
  vtkSMPropertyHelper(handle.Widget, "Enabled").Set(0);
  handle.Widget->UpdateVTKObjects();
  ShowInView(handle.Widget, this->view(), false);
  for (QWidget* field : handle.Fields)
  {
    delete field;
  }
  for (QWidget* label : handle.Labels)
  {
    delete label;
  }
  this->GroupHandles.pop_back();
}

void pqDeformationHandlePropertyWidget::showGroupHandles(bool visible)
{
  this->GroupHandlesVisible = visible;
  for (GroupHandle& handle : this->GroupHandles)
  {
    vtkSMPropertyHelper(handle.Widget, "Visibility").Set(visible);
    vtkSMPropertyHelper(handle.Widget, "Enabled").Set(visible);
    handle.Widget->UpdateVTKObjects();
  }
}

void pqDeformationHandlePropertyWidget::onGroupHandleEvent(
  vtkObject* caller, unsigned long event, void*)
{
  const auto found = std::find_if(this->GroupHandles.begin(), this->GroupHandles.end(),
    [caller](const GroupHandle& handle) { return handle.Widget == caller; });
  if (found == this->GroupHandles.end())
  {
    return;
  }
  const int group = static_cast<int>(found - this->GroupHandles.begin()) + 1;
  vtkSMProxy* widget = found->Widget;
  widget->UpdatePropertyInformation();
  double center[3], rest[3];
  vtkSMPropertyHelper(widget, "CenterInfo").Get(center, 3);
  vtkSMPropertyHelper(widget, "Center").Get(rest, 3);
  if (center[0] != rest[0] || center[1] != rest[1] || center[2] != rest[2])
  {
    // A click on the surface placed this handle too: only the first handle follows clicks.
    vtkSMPropertyHelper(widget, "Center").Set(rest, 3);
    this->showGroupMotion(group);
    this->endAutoApplyDrag();
    return;
  }
  // As the first handle's drags: Auto Apply applies every move and renders alone meanwhile.
  // (The first handle's start and end signals would also commit on a placement: not here.)
  if (event == vtkCommand::StartInteractionEvent)
  {
    this->beginAutoApplyDrag(false); // the preview shows the first group's motion alone
    return;
  }
  std::array<double, 6> motion;
  vtkSMPropertyHelper(widget, "TranslationInfo").Get(motion.data(), 3);
  vtkSMPropertyHelper(widget, "RotationInfo").Get(motion.data() + 3, 3);
  this->GroupMotions[group] = motion;
  this->showGroupFields(group); // the widget already shows it
  Q_EMIT this->groupMotionsChanged();
  Q_EMIT this->changeAvailable();
  Q_EMIT this->changeFinished();
  if (event == vtkCommand::EndInteractionEvent)
  {
    this->endAutoApplyDrag();
  }
}

void pqDeformationHandlePropertyWidget::connectPreview(bool connect)
{
  // The preview controller on the process that has the filter (the built-in session's, or a
  // server's that renders too) previews with it, beside the representation there; elsewhere
  // the filter has no object.
  vtkSMProxy* filter = this->proxy();
  vtkSMProxy* widget = this->widgetProxy();
  pqServer* server = pqApplicationCore::instance()->getServerManagerModel()->findServer(
    filter->GetSession());
  // The sub-proxies, through properties they expose (GetSubProxy is protected).
  vtkSMProxy* preview = widget ? widget->GetProperty("Previewing")->GetParent() : nullptr;
  vtkSMProxy* representation = widget ? widget->GetProperty("Translation")->GetParent() : nullptr;
  // A volume's drag updates the pipeline: its clips and slices show the interior follow, which
  // a preview of the boundary would hide.
  const bool volume =
    std::strcmp(filter->GetVTKClassName(), "vtkLaplacianVolumeDeformationFilter") == 0;
  if (!preview || !representation || !server || server->isRenderServerSeparate() || volume ||
    connect == this->PreviewConnected)
  {
    return;
  }
  vtkClientServerStream stream;
  for (const auto& [method, object] :
    { std::make_pair("SetRepresentation", representation), std::make_pair("SetFilter", filter) })
  {
    stream << vtkClientServerStream::Invoke << VTKOBJECT(preview) << method;
    if (connect)
    {
      stream << VTKOBJECT(object);
    }
    else
    {
      stream << vtkClientServerID(0);
    }
    stream << vtkClientServerStream::End;
  }
  filter->GetSession()->ExecuteStream(vtkPVSession::DATA_SERVER, stream, false);
  this->PreviewConnected = connect;
}

bool pqDeformationHandlePropertyWidget::canPreview()
{
  pqView* view = this->view();
  pqServer* server = view ? view->getServer() : nullptr;
  if (!this->PreviewConnected || !server)
  {
    return false;
  }
  // A remote server draws the preview where it renders: with one process, when the view
  // renders there (a large surface; a small one is delivered and drawn here, and applied).
  auto* renderView = vtkPVRenderView::SafeDownCast(view->getViewProxy()->GetClientSideObject());
  return !server->isRemote() ||
    (server->getNumberOfPartitions() == 1 && renderView &&
      renderView->GetUseDistributedRenderingForRender());
}

void pqDeformationHandlePropertyWidget::onInteraction()
{
  if (this->Previewing)
  {
    this->widgetProxy()->UpdateVTKObjects(); // the motion, to a server's representation
    this->render();
  }
  else
  {
    Q_EMIT this->changeFinished(); // Auto Apply applies the move
  }
}

void pqDeformationHandlePropertyWidget::beginAutoApplyDrag(bool preview)
{
  if (!this->Drag.begin(this->proxy(), this->view()))
  {
    return;
  }
  this->endPreview(); // one left from a drag whose values were never applied
  this->Previewing = preview && this->canPreview();
  if (this->Previewing)
  {
    vtkSMPropertyHelper(this->widgetProxy(), "Previewing").Set(1);
    this->widgetProxy()->UpdateVTKObjects();
  }
}

void pqDeformationHandlePropertyWidget::endAutoApplyDrag()
{
  // Auto Apply applies the drag's values and updates the pipeline once, settled (Dragging is
  // off); that update ends the preview, so that no frame shows the surface of before the drag,
  // and nothing marks the pipeline before it. Until then the view does not render the release:
  // the update's render draws the result.
  const bool updateComing = this->Previewing && this->hasUnappliedMotion();
  if (!this->Drag.end(updateComing))
  {
    return;
  }
  if (updateComing)
  {
    this->PreviewUntilUpdate = true;
    return;
  }
  // The filter is modified on the server alone: mark the pipeline so that the render updates
  // it (the drag's last move is applied already: the settled update remains).
  this->endPreview();
  this->proxy()->MarkModified(this->proxy());
  this->render();
}

bool pqDeformationHandlePropertyWidget::hasUnappliedMotion()
{
  for (const char* name : { "HandleTranslation", "HandleRotation" })
  {
    vtkSMPropertyHelper applied(this->proxy(), name), dragged(this->proxy(), name);
    dragged.SetUseUnchecked(true);
    for (unsigned int i = 0; i < applied.GetNumberOfElements(); ++i)
    {
      if (applied.GetAsDouble(i) != dragged.GetAsDouble(i))
      {
        return true;
      }
    }
  }
  return false;
}

void pqDeformationHandlePropertyWidget::endPreview()
{
  if (this->Previewing)
  {
    vtkSMPropertyHelper(this->widgetProxy(), "Previewing").Set(0);
    this->widgetProxy()->UpdateVTKObjects();
  }
  this->Previewing = false;
  this->PreviewUntilUpdate = false;
  this->Drag.resumeRendering();
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
  this->StartMoved = this->anyGroupMoved();
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
    this->clearGroupMotions(); // the commit rested them
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
  this->clearGroupMotions();
  this->pushWidgetChange();
}

void pqDeformationHandlePropertyWidget::commitEdit()
{
  // The filter commits its applied edit, sets its translation and rotation to zero and moves
  // its centre with the handle; the proxy's values are set to the same, so that the next Apply
  // does not move the handle again.
  this->proxy()->InvokeCommand("CommitEdit");
  this->clearGroupMotions();
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
