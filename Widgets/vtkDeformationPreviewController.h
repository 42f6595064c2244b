/**
 * @class   vtkDeformationPreviewController
 * @brief   draws a vtkLaplacianDeformationFilter's drag preview for a handle representation
 *
 * The controller between a vtkDeformationHandleRepresentation and the filter whose edit it
 * previews, so that neither knows the other: with a filter and Previewing on, every change of
 * the representation's translation or rotation shows the filter's preview of that motion
 * (vtkLaplacianDragPreview) in place of the representation's renderer's actor that draws the
 * filter's output, with that actor's look, without updating the pipeline; turning Previewing
 * off, or hiding the representation, puts that actor back.
 *
 * vtkDeformationHandleWidget keeps one (SetPreviewFilter). ParaView, which creates its widgets
 * on the client alone, keeps one beside the representation where the view renders, so that a
 * drag on a remote server previews there.
 *
 * @sa vtkDeformationHandleWidget vtkLaplacianDragPreview
 */
#ifndef vtkDeformationPreviewController_h
#define vtkDeformationPreviewController_h

#include "vtkLaplacianEditingWidgetsModule.h" // for export macro
#include "vtkObject.h"

#include <memory> // for std::unique_ptr

class vtkDeformationHandleRepresentation;
class vtkLaplacianDeformationFilter;

class VTKLAPLACIANEDITINGWIDGETS_EXPORT vtkDeformationPreviewController : public vtkObject
{
public:
  static vtkDeformationPreviewController* New();
  vtkTypeMacro(vtkDeformationPreviewController, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /** The representation whose motion is previewed, in its renderer. */
  void SetRepresentation(vtkDeformationHandleRepresentation* representation);
  vtkDeformationHandleRepresentation* GetRepresentation();

  /** The filter whose edit is previewed. */
  void SetFilter(vtkLaplacianDeformationFilter* filter);
  vtkLaplacianDeformationFilter* GetFilter();

  ///@{
  /** Whether the preview follows the representation's motion. Default off. */
  void SetPreviewing(vtkTypeBool previewing);
  vtkGetMacro(Previewing, vtkTypeBool);
  vtkBooleanMacro(Previewing, vtkTypeBool);
  ///@}

  /** Whether the preview shows now (the filter could preview, and an actor showed its output). */
  int IsPreviewShown();

  /** Seconds the last preview took to solve and write (vtkLaplacianDragPreview::GetUpdateTime). */
  double GetPreviewTime();

  /** Shows or hides the preview as Previewing says, for the representation's motion now. */
  void Update();

protected:
  vtkDeformationPreviewController();
  ~vtkDeformationPreviewController() override;

  vtkTypeBool Previewing = 0;

private:
  vtkDeformationPreviewController(const vtkDeformationPreviewController&) = delete;
  void operator=(const vtkDeformationPreviewController&) = delete;

  struct vtkInternals;
  std::unique_ptr<vtkInternals> Internals;
};

#endif
