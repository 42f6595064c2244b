#include "pqAutoApplyDrag.h"

#include "pqView.h"
#include "vtkClientServerStream.h"
#include "vtkPVGeneralSettings.h"
#include "vtkSMPropertyHelper.h"
#include "vtkSMProxy.h"
#include "vtkSMSession.h"
#include "vtkSMViewProxy.h"

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

void pqAutoApplyDrag::setDragging(vtkSMProxy* filter, bool dragging)
{
  vtkClientServerStream stream;
  stream << vtkClientServerStream::Invoke << VTKOBJECT(filter) << "SetDragging"
         << (dragging ? 1 : 0) << vtkClientServerStream::End;
  filter->GetSession()->ExecuteStream(filter->GetLocation(), stream, false);
}
