// PreviewActors: draws a drag's preview in place of the actor that shows a filter's output.
//
// vtkDeformationPreviewController's helper for views that redraw a whole surface whenever a point
// of it moves (vtkLaplacianDragPreview). Show finds the renderer's actor whose input shares the filter's
// output points, hides it, and adds to the renderer two actors that draw the preview's still
// part and moving part with that actor's property, texture, placement and colouring (a copy of
// its mapper's settings); Hide hides them and puts the actor back. The parts stay in the renderer
// between drags, so that the still part's buffers on the graphics card serve every drag of a
// region; only the moving part's small buffers change from one move to the next.
#ifndef LaplacianEditing_Widgets_PreviewActors_h
#define LaplacianEditing_Widgets_PreviewActors_h

#include "PreviewPartMapper.h"
#include "vtkNew.h"
#include "vtkWeakPointer.h"

#include <array>

class vtkActor;
class vtkLaplacianDragPreview;
class vtkRenderer;

namespace LaplacianEditing
{
namespace Widgets
{
class PreviewActors
{
public:
  PreviewActors();
  ~PreviewActors();

  /// Shows `preview`'s parts for the handle's motion (translation, and rotation angles in
  /// degrees) in `renderer`; false, and hidden, where the filter cannot preview or no actor of
  /// the renderer shows its output.
  bool Show(vtkRenderer* renderer, vtkLaplacianDragPreview* preview, const double translation[3],
    const double rotation[3]);
  /// Puts the output's actor back and hides the parts.
  void Hide();
  /// Hides, and takes the parts out of their renderer.
  void Remove();
  bool IsShown() const { return this->Consumer != nullptr; }

private:
  // The renderer's actor whose mapper's input (or a block of it) has the preview filter's output
  // points.
  static vtkActor* FindConsumer(vtkRenderer* renderer, vtkLaplacianDragPreview* preview);
  void CopyLook(vtkActor* consumer);

  std::array<vtkNew<PreviewPartMapper>, 2> Mappers;
  std::array<vtkNew<vtkActor>, 2> Parts;
  vtkWeakPointer<vtkActor> Consumer;
  vtkWeakPointer<vtkRenderer> Renderer;
  int ConsumerVisibility = 1;
  // The motion shown: a representation sets it through several properties, each a call.
  std::array<double, 6> Shown = {};
};
}
}

#endif
