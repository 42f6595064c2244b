#include "ProxyArapSolver.h"

#include <algorithm>
#include <chrono>
#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace LaplacianEditing
{
namespace
{
// The global step's conjugate gradients stop once they cut the residual of their start, the
// last step's solution, by this factor: the closer the iteration comes, the more exact its
// steps. At 1e-2 a first step can raise the energy, which stops the iteration; 1e-4 converges
// a rigid motion to 5e-12 (TestLargeRegions), as the factor does.
constexpr double SettleTolerance = 1e-4;
// A drag step iterates the proxy up to this many times its iterations (ArapOptions::Dragging's
// MaximumIterations, the filter's DragARAPIterations). That cap bounds a frame's cost in
// iterations of a small region, and an iteration of a proxy of 10k nodes costs about two
// thirds of a 32k-vertex region's (3.3 ms against 5 ms on scan:3); with twice the iterations,
// a drag whose handle jumps stays in the minimum's basin, where 2 left a 152k region's release
// at 1.75 times the minimum's energy (Documentation/performance.md, "Large regions").
constexpr int ProxyIterationsPerDragIteration = 2;
// A settle that comes before the full-resolution system is built reports (and may be stopped)
// this often while it waits: well within a drag frame.
constexpr std::chrono::milliseconds WaitReportInterval(20);
}

std::string ProxyArapSolver::Build(std::shared_ptr<const SurfaceMesh> mesh, const EditRegion& region,
  const DeformationOptions& options, int nodes, const ParallelFor& loop)
{
  this->FineBuild = {}; // waits for a build still running, as std::async's future does
  this->FineError.clear();
  std::string error = this->Proxy.Build(*mesh, region, nodes, loop);
  if (!error.empty())
  {
    return error;
  }
  DeformationOptions coarse = options;
  coarse.BendingLength = this->Proxy.GetEdgeLength();
  coarse.Backend = SparseCholesky::IsAvailable(SolverBackend::Cholmod) ? SolverBackend::Cholmod
                                                                        : SolverBackend::SimplicialLDLT;
  error = this->Coarse.Build(this->Proxy.GetMesh(), this->Proxy.GetRegion(), coarse, loop);
  if (!error.empty())
  {
    return "the region's proxy: " + error;
  }
  DeformationOptions fine = options;
  fine.Backend = SolverBackend::Multigrid;
  this->Fine.SetSolveTolerance(SettleTolerance);
  this->ResetToRest();
  // Why a thread: the full-resolution system is a third of a 610k region's set-up (1.1 of 2.9
  // s), and only the settle needs it. Serial, to leave the drag a core. Not at a lower
  // priority: Linux lets no unprivileged thread raise it again once the settle waits, and on
  // a loaded machine the settle then waited on a starved build (Documentation/performance.md).
  this->FineBuild = std::async(std::launch::async, [this, mesh, region, fine] {
    std::string built = this->Fine.Build(*mesh, region, fine, SerialFor);
#if defined(__GLIBC__)
    // The build's temporaries were freed into this thread's own malloc arena, where the main
    // thread's allocations (the settle's) do not reuse them: handed back, not kept on top of
    // the settle's peak (about 50 MB at 610k, Documentation/performance.md).
    malloc_trim(0);
#endif
    return built;
  });
  return {};
}

void ProxyArapSolver::ResetToRest()
{
  this->CoarseIterate = ArapIterate();
  this->FineIterate = ArapIterate();
  this->Base = this->Proxy.GetRest();
  this->BaseNodes = this->Proxy.RestShape();
  this->LastMaps.clear();
  this->Dragged = false;
}

bool ProxyArapSolver::WaitForFine(const ArapOptions& options, const ParallelFor& loop)
{
  if (this->FineBuild.valid())
  {
    while (this->FineBuild.wait_for(WaitReportInterval) != std::future_status::ready)
    {
      if (options.Progress && !options.Progress(0.0))
      {
        return false;
      }
    }
    this->FineError = this->FineBuild.get();
    this->Fine.SetParallelFor(loop);
  }
  return this->FineError.empty();
}

RegionProxy::NodeShape ProxyArapSolver::Nodes(const std::vector<AffineMap>& handleMaps) const
{
  const EditRegion& region = this->Proxy.GetRegion();
  RegionProxy::NodeShape shape;
  shape.Points = this->CoarseIterate.Points;
  shape.Turns.resize(region.GetNumberOfVertices());
  for (int r = 0; r < region.GetNumberOfVertices(); ++r)
  {
    // A handle's node turns as its handle's map.
    const int group = region.HandleGroups[r];
    if (group < 0)
    {
      shape.Turns[r] = this->CoarseIterate.Rotations[r].toRotationMatrix();
    }
    else if (group < static_cast<int>(handleMaps.size()))
    {
      shape.Turns[r] = handleMaps[group].leftCols<3>();
    }
    else
    {
      shape.Turns[r].setIdentity();
    }
  }
  return shape;
}

ArapResult ProxyArapSolver::Drag(const std::vector<AffineMap>& handleMaps,
  const ArapOptions& options, Positions& roiPositions, const ParallelFor& loop)
{
  if (this->CoarseIterate.Points.rows() != this->Proxy.GetRegion().GetNumberOfVertices())
  {
    this->CoarseIterate = this->Coarse.InitialGuess(handleMaps);
    this->Coarse.Solve(handleMaps, this->CoarseIterate, ArapOptions{ 0 }, loop); // its rotations
  }
  else if (!this->Dragged && this->FineIterate.Points.rows() > 0)
  {
    // A drag after a settle moves the settled shape by the nodes' motion from here on.
    this->Base = this->FineIterate.Points;
    this->BaseNodes = this->Nodes(this->LastMaps);
  }
  ArapOptions proxy = options;
  if (options.Dragging)
  {
    proxy.MaximumIterations *= ProxyIterationsPerDragIteration;
  }
  const ArapResult result = this->Coarse.Solve(handleMaps, this->CoarseIterate, proxy, loop);
  this->Proxy.Prolong(this->Base, this->BaseNodes, this->Nodes(handleMaps), handleMaps, roiPositions, loop);
  this->LastMaps = handleMaps;
  this->DragEnergy = result.Energy;
  this->Dragged = true;
  return result;
}

ArapResult ProxyArapSolver::Settle(const std::vector<AffineMap>& handleMaps,
  const ArapOptions& options, Positions& roiPositions, const ParallelFor& loop)
{
  if (std::all_of(handleMaps.begin(), handleMaps.end(),
        [](const AffineMap& map) { return map == AffineMap::Identity(); }))
  {
    // Handles at rest: the rest is the minimum, exactly (energy 0), where iterations would
    // chase the rounding of the proxy's solve, and a 610k region's first update waited 10 s
    // for them (Documentation/performance.md).
    this->ResetToRest();
    roiPositions = this->Proxy.GetRest();
    ArapResult rest;
    rest.Converged = true;
    return rest;
  }
  // The proxy's solve at these handles, where no drag reached them.
  ArapOptions proxy = options;
  proxy.Extrapolate = false;
  proxy.Progress = nullptr; // the settle's own iterations report
  if (!this->Dragged && this->FineIterate.Points.rows() == 0)
  {
    this->Drag(handleMaps, proxy, roiPositions, loop); // a first solve without a drag
  }
  if (!this->WaitForFine(options, loop))
  {
    ArapResult waited;
    if (handleMaps != this->LastMaps)
    {
      this->Drag(handleMaps, proxy, roiPositions, loop);
    }
    else
    {
      this->Proxy.Prolong(this->Base, this->BaseNodes, this->Nodes(this->LastMaps), this->LastMaps,
        roiPositions, loop);
    }
    waited.Energy = this->DragEnergy;
    return waited;
  }
  ArapOptions settle = options;
  if (this->Dragged)
  {
    // The full-resolution iteration starts from the dragged shape (prolonged again here rather
    // than copied at every drag step), its rotations seeded by exact polar decompositions there.
    this->FineIterate = ArapIterate();
    this->Proxy.Prolong(this->Base, this->BaseNodes, this->Nodes(this->LastMaps), this->LastMaps,
      this->FineIterate.Points, loop);
    this->Dragged = false;
    settle.Continue = false; // a settle cut while it waited has no iterations to continue
  }
  settle.Extrapolate = false; // the handles are where the drag left them
  settle.Newton = true; // local-global iterations crawl at this size (ArapOptions::Newton)
  const ArapResult result = this->Fine.Solve(handleMaps, this->FineIterate, settle, loop);
  roiPositions = this->FineIterate.Points;
  this->LastMaps = handleMaps;
  return result;
}
}
