/**
 * @class   vtkLaplacianDragPreview
 * @brief   a drag's preview of a vtkLaplacianDeformationFilter edit, solved outside the pipeline
 *
 * A view that redraws a whole surface whenever any point of it moves (ParaView's
 * representations take about a second a frame at 2M points) can draw a drag as two parts: the
 * still part, the rest of the surface, uploaded once per region, and the moving part, the
 * polygons with a corner in the region, on a compact copy of their points and point and cell
 * data, rewritten each move. Update() solves the filter's last edit with the handle's
 * translation and rotation (as HandleTranslation and HandleRotation) replaced by its own, as one
 * update of a drag would (DragARAPIterations), and writes the moving part, normals refreshed.
 * Neither the filter nor its output is modified: the next update solves and writes as usual.
 *
 * Update() returns false, previewing nothing, when the filter's last update solved no edit or
 * anything but the handle's motion changed since (properties, transforms, input). The still
 * part costs in proportion to the surface once per region (its own polygons); the parts are
 * kept until Release() or the next region. A handle group that has a transform keeps it.
 * vtkDeformationHandleWidget draws the parts in place of the output (SetPreviewFilter).
 *
 * @sa vtkLaplacianDeformationFilter vtkDeformationHandleWidget
 */
#ifndef vtkLaplacianDragPreview_h
#define vtkLaplacianDragPreview_h

#include "vtkLaplacianEditingFiltersModule.h" // for export macro
#include "vtkObject.h"

#include <memory> // for std::unique_ptr

class vtkLaplacianDeformationFilter;
class vtkPolyData;

class VTKLAPLACIANEDITINGFILTERS_EXPORT vtkLaplacianDragPreview : public vtkObject
{
public:
  static vtkLaplacianDragPreview* New();
  vtkTypeMacro(vtkLaplacianDragPreview, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * The filter whose edit is previewed. Setting another releases the parts.
   */
  void SetFilter(vtkLaplacianDeformationFilter* filter);
  vtkGetObjectMacro(Filter, vtkLaplacianDeformationFilter);

  ///@{
  /**
   * Previews the filter's edit with handle group 0 translated by `translation` (mesh units)
   * after a rotation by `rotation` (degrees about x, then y, then z, about HandleCenter).
   * Returns false when there is nothing to preview (see the class description).
   */
  bool Update(const double translation[3], const double rotation[3]);
  bool Update(double tx, double ty, double tz, double rx, double ry, double rz);
  ///@}

  ///@{
  /** The parts, written in place by each Update. */
  vtkPolyData* GetStillPart();
  vtkPolyData* GetMovingPart();
  ///@}

  /**
   * Seconds the last Update that previewed took: the drag step's solve and the moving part's writing (and, at
   * a region's first, the still part's building). 0 before any.
   */
  double GetUpdateTime();

  /** Forgets both parts. */
  void Release();

protected:
  vtkLaplacianDragPreview();
  ~vtkLaplacianDragPreview() override;

  vtkLaplacianDeformationFilter* Filter = nullptr;

private:
  vtkLaplacianDragPreview(const vtkLaplacianDragPreview&) = delete;
  void operator=(const vtkLaplacianDragPreview&) = delete;

  struct vtkInternals;
  std::unique_ptr<vtkInternals> Internals;
};

#endif
