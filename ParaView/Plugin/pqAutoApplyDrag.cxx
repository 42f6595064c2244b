#include "pqAutoApplyDrag.h"

#include "pqApplicationCore.h"
#include "pqPipelineSource.h"
#include "pqPropertyWidget.h"
#include "pqServerManagerModel.h"
#include "pqView.h"
#include "vtkWeakPointer.h"
#include "vtkClientServerStream.h"
#include "vtkPVGeneralSettings.h"
#include "vtkSMPropertyHelper.h"
#include "vtkSMProxy.h"
#include "vtkSMSession.h"
#include "vtkSMSourceProxy.h"
#include "vtkSMViewProxy.h"

#include <QPointer>
#include <QTimer>

bool pqAutoApplyDrag::begin(vtkSMProxy* filter, pqView* view)
{
  vtkSMProperty* property =
    view ? view->getViewProxy()->GetProperty("EnableRenderOnInteraction") : nullptr;
  if (!property || !vtkPVGeneralSettings::GetInstance()->GetAutoApply())
  {
    return false;
  }
  this->resumeRendering(); // held since an earlier drag
  this->Filter = filter;
  this->View = view;
  this->SavedRenderOnInteraction = vtkSMPropertyHelper(property).GetAsInt();
  vtkSMPropertyHelper(property).Set(0);
  view->getViewProxy()->UpdateVTKObjects();
  pqAutoApplyDrag::setDragging(filter, true);
  this->Active = true;
  return true;
}

bool pqAutoApplyDrag::end(bool holdRendering)
{
  if (!this->Active)
  {
    return false;
  }
  pqAutoApplyDrag::setDragging(this->Filter, false);
  this->Active = false;
  this->SinceSettleRender.start(); // the release's update renders
  if (!holdRendering)
  {
    this->resumeRendering();
  }
  return true;
}

void pqAutoApplyDrag::resumeRendering()
{
  if (this->Active)
  {
    return; // the drag holds them off until it ends
  }
  if (this->View && this->SavedRenderOnInteraction >= 0)
  {
    vtkSMPropertyHelper(this->View->getViewProxy(), "EnableRenderOnInteraction")
      .Set(this->SavedRenderOnInteraction);
    this->View->getViewProxy()->UpdateVTKObjects();
  }
  this->SavedRenderOnInteraction = -1;
}

void pqAutoApplyDrag::continueSettle(vtkSMProxy* filter, pqView* view, QObject* context)
{
  vtkSMProperty* settling = filter ? filter->GetProperty("Settling") : nullptr;
  if (this->Active || !settling || !view)
  {
    return;
  }
  filter->UpdatePropertyInformation(settling);
  if (vtkSMPropertyHelper(settling).GetAsInt() == 0)
  {
    if (this->SettleUndrawn)
    {
      this->SettleUndrawn = false;
      view->render(); // the settled shape
    }
    return;
  }
  // Every 3 seconds the shape so far.
  constexpr qint64 SettleRenderMilliseconds = 3000;
  vtkWeakPointer<vtkSMSourceProxy> weakFilter = vtkSMSourceProxy::SafeDownCast(filter);
  QPointer<pqView> weakView = view;
  QTimer::singleShot(0, context, [this, weakFilter, weakView]() {
    if (this->Active || !weakFilter || !weakView)
    {
      return; // a grab ended the settle
    }
    // As after a drag, the filter is modified on the server alone: mark the pipeline too.
    pqAutoApplyDrag::invoke(weakFilter, "ContinueSettling");
    weakFilter->MarkModified(weakFilter);
    if (this->SinceSettleRender.isValid() &&
      this->SinceSettleRender.elapsed() < SettleRenderMilliseconds)
    {
      this->SettleUndrawn = true;
      weakFilter->UpdatePipeline(); // its dataUpdated continues
      return;
    }
    this->SettleUndrawn = false;
    this->SinceSettleRender.start();
    weakView->render();
  });
}

template <typename... Arguments>
void pqAutoApplyDrag::invoke(vtkSMProxy* filter, const char* method, Arguments... arguments)
{
  vtkClientServerStream stream;
  stream << vtkClientServerStream::Invoke << VTKOBJECT(filter) << method;
  (stream << ... << arguments);
  stream << vtkClientServerStream::End;
  filter->GetSession()->ExecuteStream(filter->GetLocation(), stream, false);
}

void pqAutoApplyDrag::settleBetweenEvents(pqPropertyWidget* widget)
{
  vtkSMProxy* filter = widget->proxy();
  auto* source =
    pqApplicationCore::instance()->getServerManagerModel()->findItem<pqPipelineSource*>(filter);
  if (!source || !filter->GetProperty("Settling"))
  {
    return;
  }
  // Half a second: a 269k-vertex region's Newton step takes about that long, a 610k one's a
  // second (Documentation/paraview.md).
  constexpr double SettleSeconds = 0.5;
  pqAutoApplyDrag::invoke(filter, "SetSettleTimeLimit", SettleSeconds);
  QObject::connect(source, QOverload<pqPipelineSource*>::of(&pqPipelineSource::dataUpdated), widget,
    [this, widget]() { this->continueSettle(widget->proxy(), widget->view(), widget); });
}

void pqAutoApplyDrag::setDragging(vtkSMProxy* filter, bool dragging)
{
  pqAutoApplyDrag::invoke(filter, "SetDragging", dragging ? 1 : 0);
}
