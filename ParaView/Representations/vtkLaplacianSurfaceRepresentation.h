/**
 * @class   vtkLaplacianSurfaceRepresentation
 * @brief   ParaView's surface representation, for a surface whose updates move its points
 *
 * ParaView's "Surface" (vtkGeometryRepresentationWithFaces), with two changes for a surface
 * whose updates move points and keep the cells, as an edit's do. The release of a drag of 93
 * vertices on a 2M-point sphere spent 1.2 s of its 2.0 s in work those updates do not need:
 * - the bounds it and its mapper take from the surface's cells are known without a pass over
 *   every cell while the cells stay the same (UsedPointsBounds): 0.9 s;
 * - its mapper, vtkLaplacianSurfaceMapper, keeps the surface's index buffers: 0.3 s.
 *
 * The plugin adds it to the render view's representation types as "Editable Surface", the one
 * the Laplacian filters' outputs are shown with.
 */
#ifndef vtkLaplacianSurfaceRepresentation_h
#define vtkLaplacianSurfaceRepresentation_h

#include "vtkGeometryRepresentationWithFaces.h"
#include "vtkLaplacianEditingRepresentationsModule.h" // for export macro

#include <memory> // for std::unique_ptr

class VTKLAPLACIANEDITINGREPRESENTATIONS_EXPORT vtkLaplacianSurfaceRepresentation
  : public vtkGeometryRepresentationWithFaces
{
public:
  static vtkLaplacianSurfaceRepresentation* New();
  vtkTypeMacro(vtkLaplacianSurfaceRepresentation, vtkGeometryRepresentationWithFaces);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  int ProcessViewRequest(vtkInformationRequestKey* request, vtkInformation* inInfo,
    vtkInformation* outInfo) override;

  /** How many times a surface's cells were passed over to learn which points they use. */
  int GetNumberOfCellPasses();

  /** Whether the last render drew the surface alone (vtkLaplacianSurfaceMapper). */
  bool GetDrewSurfaceAlone();

  /** How many times the mapper built the surface's index buffers. */
  int GetNumberOfIndexBuilds();

protected:
  vtkLaplacianSurfaceRepresentation();
  ~vtkLaplacianSurfaceRepresentation() override;

  int RequestData(vtkInformation* request, vtkInformationVector** inputVector,
    vtkInformationVector* outputVector) override;

private:
  vtkLaplacianSurfaceRepresentation(const vtkLaplacianSurfaceRepresentation&) = delete;
  void operator=(const vtkLaplacianSurfaceRepresentation&) = delete;

  struct vtkInternals;
  std::unique_ptr<vtkInternals> Internals;
};

#endif
