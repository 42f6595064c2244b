/**
 * @class   vtkDeformationHandlePreview
 * @brief   draws a drag's preview in place of the actor that shows a filter's output (not
 *          wrapped)
 *
 * The handle representation's helper for views that redraw a whole surface whenever a point of
 * it moves (vtkLaplacianDeformationFilter::PreviewHandleMotion). Show finds the renderer's actor
 * whose input shares the filter's output points, hides it, and draws the filter's still part
 * and moving part with that actor's property, texture, placement and colouring (a copy of its
 * mapper's settings); Hide puts it back. Only the moving part's small buffers change from one
 * move to the next.
 */
#ifndef vtkDeformationHandlePreview_h
#define vtkDeformationHandlePreview_h

#include "vtkNew.h"
#include "vtkWeakPointer.h"

#include <array>

class vtkActor;
class vtkLaplacianDeformationFilter;
class vtkPolyDataMapper;
class vtkRenderer;

class vtkDeformationHandlePreview
{
public:
  vtkDeformationHandlePreview();
  ~vtkDeformationHandlePreview();

  /// Shows `filter`'s preview of the handle's motion (translation, and rotation angles in
  /// degrees) in `renderer`; false, and hidden, where the filter cannot preview or no actor
  /// of the renderer shows its output.
  bool Show(vtkRenderer* renderer, vtkLaplacianDeformationFilter* filter,
    const double translation[3], const double rotation[3]);
  /// Puts the output's actor back and hides the parts.
  void Hide();
  bool IsShown() const { return this->Consumer != nullptr; }

  /// The parts' actors (the still part first), for the representation's render passes.
  std::array<vtkActor*, 2> Actors();

private:
  // The renderer's actor whose mapper's input (or a block of it) has the output's points.
  static vtkActor* FindConsumer(vtkRenderer* renderer, vtkLaplacianDeformationFilter* filter);
  void CopyLook(vtkActor* consumer);

  std::array<vtkNew<vtkPolyDataMapper>, 2> Mappers;
  std::array<vtkNew<vtkActor>, 2> Parts;
  vtkWeakPointer<vtkActor> Consumer;
  int ConsumerVisibility = 1;
  // The motion shown: a representation sets it through several properties, each a call.
  std::array<double, 6> Shown = {};
};

#endif
