/**
 * @class   vtkPLaplacianDeformationFilter
 * @brief   vtkLaplacianDeformationFilter on a surface distributed over MPI ranks
 *
 * The edit is global (one sparse system over the region), so the pieces go to the first rank,
 * which edits the whole surface (coincident piece-boundary points merge into one vertex) and
 * sends each rank its own points back, in its own order. The first rank caches the gathered
 * surface on the pieces' MTimes, so a handle move sends no geometry back up. Point and polygon
 * normals come back refreshed near the edit, as the serial filter leaves them (polygon normals
 * when the pieces hold only polygons; otherwise they are dropped rather than left stale). A
 * selection on port 1 is labelled on each rank, on its own piece (ParaView's selections of ids
 * address pieces), and the labels travel with the pieces. With one process, or no controller,
 * it is the serial filter.
 *
 * @sa vtkLaplacianDeformationFilter vtkMultiProcessController
 */
#ifndef vtkPLaplacianDeformationFilter_h
#define vtkPLaplacianDeformationFilter_h

#include "vtkLaplacianDeformationFilter.h"
#include "vtkLaplacianEditingModule.h" // for export macro
#include "vtkSmartPointer.h"           // for vtkSmartPointer

#include <vector> // for std::vector

class vtkMultiProcessController;

class VTKLAPLACIANEDITING_EXPORT vtkPLaplacianDeformationFilter
  : public vtkLaplacianDeformationFilter
{
public:
  static vtkPLaplacianDeformationFilter* New();
  vtkTypeMacro(vtkPLaplacianDeformationFilter, vtkLaplacianDeformationFilter);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * The controller of the ranks. Default: the global controller.
   */
  virtual void SetController(vtkMultiProcessController*);
  vtkGetObjectMacro(Controller, vtkMultiProcessController);
  ///@}

protected:
  vtkPLaplacianDeformationFilter();
  ~vtkPLaplacianDeformationFilter() override;

  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  // On the gathered surface, the labels each rank made on its piece.
  vtkSmartPointer<vtkIntArray> SelectionLabels(vtkPolyData* input, vtkSelection* selection) override;

  vtkMultiProcessController* Controller = nullptr;

private:
  vtkPLaplacianDeformationFilter(const vtkPLaplacianDeformationFilter&) = delete;
  void operator=(const vtkPLaplacianDeformationFilter&) = delete;

  // Rank 0: the gathered surface, each piece's content time and selection MTime, point and
  // cell counts, and whether the pieces hold polygons only.
  bool GatherPieces(vtkPolyData* input, vtkSelection* selection);
  void ScatterPoints(vtkPolyData* input, vtkPolyData* edited, vtkPolyData* output);
  vtkSmartPointer<vtkPolyData> Gathered;
  std::vector<double> PieceTimes;
  std::vector<vtkIdType> PieceSizes;
  std::vector<vtkIdType> PieceCellSizes;
  bool OnlyPolygons = true;
};

#endif
