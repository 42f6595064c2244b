/**
 * @class   vtkPLaplacianDeformationFilter
 * @brief   vtkLaplacianDeformationFilter on a surface distributed over MPI ranks
 *
 * The edit is global (one sparse system over the region), so it is solved on the first rank.
 * The ranks agree on the part of the surface the edit can reach (the serial filter's reach: a
 * ball around the handle centre, or around the labelled points, from a few reductions and the
 * labelled points), widened by two of the longest edges so that the ring around the region
 * comes along whole; each rank sends only its polygons in that part, which the first rank edits
 * (piece-boundary points that coincide, up to rounding, merge into one vertex). The first rank
 * caches the gathered part on the pieces' content, the selection and the reach, so a handle
 * move sends no geometry up.
 *
 * Once per region, each rank gets its share of the edit (PieceEdit): which of its
 * points move and from which rows, and what refreshes its normals near the edit, across piece
 * seams, as the serial filter does. Where the edit is affine in the handle maps (RotationMode
 * None, or Implicit without PreserveDetailScale), a move broadcasts the maps' entries and every
 * rank places its own points; otherwise each rank gets the positions of its rows alone. The
 * first rank's memory and the traffic follow the region, not the surface. A selection on port 1
 * is labelled on each rank, on its own piece (ParaView's selections of ids address pieces), and
 * the labels travel with the pieces. With one process, or no controller, it is the serial
 * filter.
 *
 * The first rank factors the region alone with CHOLMOD unless the factor would exceed
 * MaximumFactorMemory, or Solver is MUMPS: then, in a build with MUMPS, all ranks factor it
 * together (MumpsSolver), and each update's solves run on all of them.
 *
 * @sa vtkLaplacianDeformationFilter vtkMultiProcessController
 */
#ifndef vtkPLaplacianDeformationFilter_h
#define vtkPLaplacianDeformationFilter_h

#include "vtkLaplacianDeformationFilter.h"
#include "vtkLaplacianEditingFiltersParallelModule.h" // for export macro
#include "vtkSmartPointer.h"           // for vtkSmartPointer

#include <array>  // for std::array
#include <memory> // for std::unique_ptr
#include <vector> // for std::vector

class vtkDataArray;
class vtkIntArray;
class vtkMultiProcessController;
class vtkSelection;
namespace LaplacianEditing
{
namespace Pipeline
{
struct EditState;
}
}

class VTKLAPLACIANEDITINGFILTERSPARALLEL_EXPORT vtkPLaplacianDeformationFilter
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

  /**
   * On the first rank, how many points it gathered for the last edit: the parts of the pieces
   * the edit can reach (its memory follows them, not the whole surface); 0 elsewhere.
   */
  vtkGetMacro(NumberOfGatheredPoints, vtkIdType);

protected:
  vtkPLaplacianDeformationFilter();
  ~vtkPLaplacianDeformationFilter() override;

  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  // MUMPS across the controller's processes, in a build with MUMPS under MPI.
  LaplacianEditing::DistributedSolver* GetDistributedSolver() override;
  // On the gathered surface, the labels each rank made on its piece.
  vtkSmartPointer<vtkIntArray> SelectionLabels(vtkPolyData* input, vtkSelection* selection) override;

  vtkMultiProcessController* Controller = nullptr;
  vtkIdType NumberOfGatheredPoints = 0;

private:
  vtkPLaplacianDeformationFilter(const vtkPLaplacianDeformationFilter&) = delete;
  void operator=(const vtkPLaplacianDeformationFilter&) = delete;

  // This piece's labels: a selection's (cached on the selection and the piece), or the array
  // mode's array; nullptr in geodesic mode.
  vtkDataArray* LocalLabels(vtkPolyData* input, vtkSelection* selection);
  // The reach of the edit over the whole surface, the same on every rank (collective), into
  // the internals; sets WholeDiagonal.
  void UpdateGlobalReach(vtkPolyData* input, vtkDataArray* labels, bool fromSelection);
  // Its steps (collective): the pieces' extents, which set WholeDiagonal (returns the handle
  // centre's distance to the nearest polygon corner, -1 for none, and the longest edge); and
  // the labelled points of every piece (returns half their extent, -1 for none).
  double ReduceExtents(vtkPolyData* input, bool labelled, double& longestEdge);
  double GatherSeeds(vtkPolyData* input, vtkDataArray* labels, std::vector<std::array<double, 3>>& seeds);
  double LongestPolygonEdge(vtkPolyData* input);
  // Rank 0: the parts in reach of all pieces, appended; true on rank 0.
  bool GatherPieces(vtkPolyData* input, vtkSelection* selection);
  // Every rank's output, from its share of the edit (collective).
  void WritePieces(vtkPolyData* input, vtkPolyData* output);
  // Rank 0 sends each rank its share of `edit` (an empty one without an edit).
  void SharePieces(const LaplacianEditing::Pipeline::EditState& edit, bool edited, bool affine);

  // The reach, the piece's caches and, on rank 0, the gathered parts.
  struct vtkInternals;
  std::unique_ptr<vtkInternals> Internals;
};

#endif
