// VolumeFollower: a volume mesh's interior moved after an edit of its boundary surface, without
// inverting a cell, and written into the filter's output in place.
//
// The edit moved some boundary points (the surface editor's region). The follower takes the
// zone of the volume near them (VolumeMesh::SelectZone, within the region's radius of its
// points), factors its proxy once per region (InjectiveDeformation), and moves the zone's
// interior, the region's points pulled to their edited positions. A drag step iterates a few
// times from the last step's result; a settled update iterates to convergence, and where a
// target is missed, grows the zone (twice the reach) until it is met or the zone holds
// everything it can. A target no valid mesh can reach is left short: the cells around it are
// marked in EditFailed. Points outside the zone keep their rest coordinates exactly.
//
// Output: the rest grid with the zone's points moved, ScaledJacobian (VolumeMesh::Quality) and
// EditFailed (1 on a cell with a point that missed its target) cell arrays, each written in
// place between updates (OutputArray), so a move costs what its zone costs.
#ifndef LaplacianEditing_Pipeline_VolumeFollower_h
#define LaplacianEditing_Pipeline_VolumeFollower_h

#include "DeformationGraph.h"
#include "DisplacementArray.h"
#include "EditTypes.h"
#include "InjectiveDeformation.h"
#include "OutputArray.h"
#include "VolumeMesh.h"
#include "vtkLaplacianEditingFiltersModule.h" // for export macro

#include "vtkPoints.h" // for Follows
#include "vtkSmartPointer.h"

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

class vtkAlgorithm;
class vtkFloatArray;
class vtkUnsignedCharArray;
class vtkUnstructuredGrid;

namespace LaplacianEditing
{
namespace Pipeline
{
class VTKLAPLACIANEDITINGFILTERS_EXPORT VolumeFollower
{
public:
  struct Settings
  {
    /// Iterations at most of a settled update, and of a drag step.
    int Iterations = 300;
    int DragIterations = 1;
    bool Dragging = false;
    /// Drag steps follow the zone's deformation graph where no cell inverts by it (else they
    /// run DragIterations of the injective solve).
    bool Graph = true;
    SolverBackend Backend = SolverBackend::Cholmod;
    /// A settle's progress after each iteration (share of Iterations); returning false stops it
    /// there, every cell still positive (InjectiveOptions::Progress). Unused by drag steps.
    std::function<bool(double)> Progress;
    /// FollowEdit: the seconds a settle may take (0: no limit). Past them it stops after the
    /// iteration at hand (Facts::OutOfTime), and the next settle of the same targets goes on
    /// from there, with the iterations left.
    double TimeLimit = 0.0;
  };

  /// What the last Follow did.
  struct Facts
  {
    int ZonePoints = 0;
    int ZoneTetrahedra = 0;
    int Iterations = 0;
    int Factorizations = 0;
    /// Times the zone grew to meet its targets.
    int Growths = 0;
    int FailedCells = 0;
    /// Of the failed cells, those that were slivers at rest (scaled Jacobian below 0.1).
    int FailedSlivers = 0;
    /// Whether Settings::Progress stopped the settle short, and whether the time limit did with
    /// iterations left (the next settle of the same targets goes on).
    bool Stopped = false;
    bool OutOfTime = false;
    double LargestMiss = 0.0;
    /// Whether a drag step followed the zone's deformation graph (no cell flattened by it),
    /// rather than an iteration of the injective solve; the graph's nodes.
    bool ByGraph = false;
    int GraphNodes = 0;
    /// Cells the graph inverted that the step repaired (an injective solve around them).
    int RepairedCells = 0;
    double SetupTime = 0.0;
    double SolveTime = 0.0;
  };

  /// The filter whose output is written (see OutputArray::SetPipelineHolders), and which
  /// FollowEdit reports through.
  void SetFilter(vtkAlgorithm* filter);

  /// Brings the mesh up to date with `input` (VolumeMesh::Update), the edits starting from the
  /// points `rest` (the input's, or committed ones). Returns an error, empty on success.
  std::string Update(vtkUnstructuredGrid* input, vtkPoints* rest);
  VolumeMesh& GetMesh() { return this->Mesh; }

  /// Follows the edit that moved the boundary points `moved` (grid ids) to their coordinates in
  /// `edited`; `region` changes whenever `moved` does. Returns an error, empty on success.
  std::string Follow(const std::vector<vtkIdType>& moved, vtkPoints* edited, std::uint64_t region,
    const Settings& settings);
  /// What every filter with a volume does with its boundary's edit, `edit` with the moved points'
  /// coordinates in `edited` (null edit: nothing moved): Follow it, the settle's progress
  /// reported as the filter's from `from` to `to` and ended by its abort flag
  /// (Settings::Progress), a settled update's unmet targets warned, and the result written into
  /// `output` (Write). Returns an error, empty on success; on an error nothing is written.
  std::string FollowEdit(const OutputEdit* edit, vtkPoints* edited, Settings settings,
    vtkUnstructuredGrid* output, bool displacement, double from, double to);
  /// Nothing moved: the next Write writes the rest.
  void Reset();
  /// Whether the last Follow followed `edited` as it is now (a stopped settle did not).
  bool Follows(vtkPoints* edited) const
  {
    return this->Followed && edited == this->LastEdited && edited->GetMTime() == this->LastEditedTime;
  }

  /// What a filter warns after a settled Follow that left targets unmet; empty if none was.
  std::string FailureWarning() const;

  /// Writes the last Follow into `output`, a shallow copy of the input, with the Displacement
  /// point array if `displacement` is on.
  void Write(vtkUnstructuredGrid* output, bool displacement = false);

  const Facts& GetFacts() const { return this->LastFacts; }

private:
  std::string SelectZone(const std::vector<vtkIdType>& moved, const Settings& settings);
  // The grid's frame positions of the zone's rows after a solve (Placed), and any point's.
  void Place();
  Vector3 Position(vtkIdType id) const;
  // The zone's deformation graph, its shape at rest, and the zone rows' tetrahedra.
  std::string BuildGraph();
  // A drag step by the graph (Facts::ByGraph), where it and its repairs invert no cell.
  void FollowGraph(const Positions& targets);
  // Moves the free points around the tetrahedra `inverted` in `followed` (the graph's shape)
  // so that none is, from the last step's shape; false where it cannot.
  bool Repair(std::vector<int> inverted, Positions& followed);
  // One patch of Repair, by at most `iterations`, written into `followed`; false where the
  // patch's solve failed.
  bool RepairPatch(const std::vector<int>& inverted, Positions& followed, int iterations);
  // The distance of each zone row from its target after the last Follow (0 off targets).
  const std::vector<double>& Misses() const
  {
    return this->LastFacts.ByGraph ? this->GraphMisses : this->Solver.GetMisses();
  }

  vtkAlgorithm* Filter = nullptr;
  VolumeMesh Mesh;
  const vtkPoints* LastEdited = nullptr; // compared, never dereferenced
  vtkMTimeType LastEditedTime = 0;
  vtkSmartPointer<vtkPoints> Rest;
  vtkMTimeType RestTime = 0;
  vtkSmartPointer<vtkFloatArray> RestQuality;
  VolumeMesh::Zone Zone;
  InjectiveDeformation Solver;
  DeformationGraph Graph;  // the zone's, built at its second drag step
  Positions ZoneRest;      // zone rows at rest, relative to Center
  Positions GraphShape;    // the graph's last shape, zone rows
  std::vector<double> GraphMisses; // of the last step by the graph
  std::vector<int> PointTetOffsets, PointTets; // per zone row, its tetrahedra (with the graph)
  Positions Solution; // zone rows, relative to Center
  Positions Edited;   // the targeted rows' edited positions, in the grid's frame
  Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor> Placed; // zone rows, grid's frame
  Vector3 Center = Vector3::Zero();
  std::vector<int> LocalOf; // grid id -> zone row, -1 outside
  double Reach = 0.0;
  double Snap = 0.0;
  std::uint64_t Region = 0;
  bool Followed = false;
  bool Dragged = false; // the zone holds a drag step's result
  // The iterations a settle cut by its time limit ran so far (0: none was cut) and the targets
  // it was settling towards: the next settle of the same targets goes on where the solver
  // stopped (InjectiveOptions::Resume).
  int CutSettleIterations = 0;
  Positions CutSettleTargets;
  std::vector<vtkIdType> Movable;
  std::vector<double> ZoneQuality; // of the zone's cells
  std::vector<char> Failed;         // of the zone's cells: 1 on a failed one (EditFailed)
  std::uint64_t Writes = 0;
  OutputArray Points;
  OutputArray Quality;
  OutputArray Failures;
  DisplacementArray Displacement;
  vtkSmartPointer<vtkUnsignedCharArray> NoFailures;
  Facts LastFacts;
};
}
}

#endif
