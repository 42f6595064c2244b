// The edit every filter runs: prepare the surface (the core's graph of the part in reach,
// coincident points welded), bring the region and its system up to date, bring the rotation
// model up to date, solve, and write the output in place. Each step keeps its cache and is
// skipped while it holds; a handle move only solves and writes. A filter supplies only what is
// its own, an EditSource: where the region comes from and where the motions come from.
//
// The pipeline speaks through its filter: errors (which set the filter's error code), warnings,
// progress after each step that may take seconds, and the filter's abort flag between steps.
#ifndef LaplacianEditing_Pipeline_EditPipeline_h
#define LaplacianEditing_Pipeline_EditPipeline_h

#include "EditSource.h"
#include "EditTypes.h"
#include "LaplacianEditor.h"
#include "NormalRefresher.h"
#include "OutputWriter.h"
#include "SolverSettings.h"
#include "Stopwatch.h"
#include "SurfaceAdapter.h"
#include "vtkLaplacianEditingFiltersModule.h" // for export macro

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

class vtkAlgorithm;
class vtkPolyData;

namespace LaplacianEditing
{
namespace Pipeline
{
class VTKLAPLACIANEDITINGFILTERS_EXPORT EditPipeline
{
public:
  /// What the last update did; sizes and seconds are 0 for a step that did not run.
  struct Facts
  {
    int NumberOfROIVertices = 0;
    int NumberOfHandleVertices = 0;
    /// Vertices of the surface graph, the part of the input the edit can reach (kept until the
    /// graph is rebuilt).
    int NumberOfSurfaceVertices = 0;
    double TopologyTime = 0.0;
    double SetupTime = 0.0;
    double AnalysisTime = 0.0;
    double FactorizationTime = 0.0;
    double SolveTime = 0.0;
    int NumberOfARAPIterations = 0;
    double ARAPEnergy = 0.0;
    /// The largest distance of a point from its target, in the core's units.
    double LargestPointMiss = 0.0;
  };

  /// `filter` reports for the pipeline; `setErrorCode` sets its error code (which vtkAlgorithm
  /// keeps protected).
  EditPipeline(vtkAlgorithm* filter, std::function<void(unsigned long)> setErrorCode);
  // The editor's progress callback holds this object.
  EditPipeline(const EditPipeline&) = delete;
  EditPipeline& operator=(const EditPipeline&) = delete;

  /// Starts an update: no error, and the update's facts afresh.
  void BeginUpdate();

  /// The share of the filter's progress the runs that follow report in: from `start` to `end`
  /// (a fit runs many; 0 to 1 by default, which BeginUpdate restores).
  void SetProgressSpan(double start, double end);

  /// Reports a non-empty `error` as the filter's error; returns whether there was none.
  bool Check(const std::string& error);

  /// The edit of `rest` for `source`, each step skipped while its cache holds; then the result
  /// written into `output`, a shallow copy of `rest` (null: not written), with the arrays
  /// `options` asks for. `merge` welds coincident points. Returns whether it solved; if not, it
  /// reported why, or the filter was aborted.
  bool Run(vtkPolyData* rest, vtkPolyData* output, EditSource& source,
    const SolverSettings& settings, bool merge, const OutputOptions& options = {});

  /// Solves the last solved Run's edit again for the motions and point targets `source` gives
  /// now, on the same surface, region and factors: nothing is checked against the input or
  /// rebuilt, and no drag is recorded. A loop that only moves its targets (a fit's closest points)
  /// runs this, then Write once. `settings` may change the rotation model's iterations and
  /// tolerance, not what its factors hold. Returns false, with the error reported, when no Run has
  /// solved or the solve fails.
  bool Resolve(EditSource& source, const SolverSettings& settings);

  /// Resolve as one step of a drag (settings.DragARAPIterations), which the drag's end settles.
  bool SolveDragStep(EditSource& source, SolverSettings settings);

  /// Writes `edit` (null: nothing moved) into `output`, a shallow copy of `rest`, in place in the
  /// arrays kept from earlier updates (see OutputWriter).
  void Write(vtkPolyData* rest, vtkPolyData* output, const OutputEdit* edit,
    const OutputOptions& options);

  /// A drag starts or ends. After a drag, the next update settles the shape: ARAPIterations in
  /// full, without the convergence test. Returns whether that update must run although no
  /// property changed (false where the drag was previewed: the update that applies its motion
  /// settles it).
  bool SetDragging(bool dragging);

  /// Whether the last Run's iterations reached settings.TimeLimit with some left: the next Run
  /// for the same motions, region and rotation model continues them from its shape (one
  /// iterate as an uncut solve's), where any other Run starts afresh.
  bool IsSettling() const { return this->Unfinished.Iterations > 0; }

  /// Whether the last Run solved, and the last solve as the output writer takes it.
  bool HasSolved() const { return this->Solved; }
  OutputEdit GetEdit() const;
  /// The last solve as the filter holds it, for the parallel filter's pieces.
  EditState GetState() const;

  const Facts& GetFacts() const { return this->LastFacts; }
  const SurfaceAdapter& GetSurface() const { return this->Surface; }
  const LaplacianEditor& GetEditor() const { return this->Editor; }
  const OutputWriter& GetWriter() const { return this->Writer; }
  /// Megabytes of the factors held.
  double GetFactorMemory() const { return this->Editor.GetFactorBytes() / 1048576.0; }
  /// Changes whenever the surface, region, system or rotation model is rebuilt.
  std::uint64_t GetModelVersion() const { return this->ModelVersion; }

private:
  // Run's steps; each returns false, with the error reported, when the edit cannot go on.
  bool UpdateSurface(vtkPolyData* rest, const Reach& reach, bool merge);
  bool UpdateRegion(vtkPolyData* rest, EditSource& source, const SolverSettings& settings);
  bool UpdateRotationModel(const SolverSettings& settings);
  bool Solve(const EditMotions& motions, const SolverSettings& settings);
  // Run's settings for `motions`: the settle that TimeLimit cut short continued, if it was
  // for them, or `settings` with a settle after a drag.
  SolverSettings ContinueSettle(const SolverSettings& settings, const EditMotions& motions) const;
  bool Aborted(double progress);
  void ReportProgress(double progress);

  vtkAlgorithm* Filter;
  std::function<void(unsigned long)> SetErrorCode;
  SurfaceAdapter Surface;
  LaplacianEditor Editor;
  NormalRefresher Normals;
  OutputWriter Writer;
  double AvailableMemory = 0.0; // megabytes, taken once per surface
  std::vector<AffineMap> Maps;
  Positions Solution;
  std::uint64_t ModelVersion = 0;
  Facts LastFacts;
  bool Solved = false;
  bool Settle = false;
  // A settle that the time limit cut short: the iterations it has left, whether it tests
  // convergence, and what it solved (its motions and the model's version).
  struct Continuation
  {
    int Iterations = 0;
    bool Settle = false;
    EditMotions Motions;
    std::uint64_t ModelVersion = 0;
  } Unfinished;
  // The running solve's settings (their time limit, and the iterations of its settle done
  // before it, for the progress), its clock, and whether the limit stopped it.
  SolverSettings Solving;
  int SettleIterations = 0;
  Stopwatch SolveClock;
  bool OutOfTime = false;
  RotationMode Mode = RotationMode::None;
  bool Previewed = false;
  double ProgressStart = 0.0;
  double ProgressEnd = 1.0;
};
}
}

#endif
