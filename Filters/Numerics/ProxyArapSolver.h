// As-rigid-as-possible editing of a region of any size: a drag costs what a small region costs,
// and the release settles at full resolution without a factorization (Documentation/
// how-it-works.md, "Regions of any size").
//
//  - Set-up: the region's proxy (RegionProxy), its own ARAP system factored (small), and the
//    full-resolution system with algebraic multigrid in place of a factor (AlgebraicMultigrid):
//    seconds less than factoring a region of hundreds of thousands of vertices. The
//    full-resolution system is built on a thread of its own while the user drags, which needs
//    only the proxy; the settle waits for it.
//  - Drag: the proxy iterates, with its bending scaled to the fine mesh's (ARAP's resistance
//    to bending grows with the square of the edges' length; DeformationOptions::BendingLength),
//    and its motion since the drag began moves the shape the drag began from, the details
//    turning with the nodes. A drag that follows a settle so starts from the settled shape.
//  - Settle: Newton's steps at full resolution from the dragged shape (ArapOptions::Newton),
//    each a truncated conjugate-gradient solve with the full Hessian, one multigrid cycle per
//    step as its preconditioner; local-global iterations needed on the order of a thousand
//    iterations at 150k vertices and more.
#ifndef LaplacianEditing_ProxyArapSolver_h
#define LaplacianEditing_ProxyArapSolver_h

#include "AsRigidAsPossibleSolver.h"
#include "RegionProxy.h"

#include <future>
#include <memory>
#include <string>
#include <vector>

namespace LaplacianEditing
{
class ProxyArapSolver
{
public:
  ProxyArapSolver() = default;
  // Not copied or moved: the full-resolution build writes this object's members.
  ProxyArapSolver(const ProxyArapSolver&) = delete;
  ProxyArapSolver& operator=(const ProxyArapSolver&) = delete;

  /// Builds the proxy of about `nodes` nodes and its system, and starts building the
  /// full-resolution system on its own thread, serially (it holds `mesh` until done). Returns
  /// an error, empty on success; the full-resolution build's is the settle's (GetSettleError).
  std::string Build(std::shared_ptr<const SurfaceMesh> mesh, const EditRegion& region,
    const DeformationOptions& options, int nodes, const ParallelFor& loop = SerialFor);

  /// A drag step: the proxy iterates from its last state (at most options.MaximumIterations),
  /// and `roiPositions` receives the shape. The result's energy is the proxy's.
  ArapResult Drag(const std::vector<AffineMap>& handleMaps, const ArapOptions& options,
    Positions& roiPositions, const ParallelFor& loop = SerialFor);

  /// Full-resolution iterations from the current shape (the last drag's, or the last
  /// settle's), at most options.MaximumIterations; with every handle map the identity, the
  /// rest itself, at once. Until the full-resolution system is built it
  /// waits, calling options.Progress(0) every few milliseconds; where that returns false, or
  /// the build failed, it leaves the dragged shape with no iteration.
  ArapResult Settle(const std::vector<AffineMap>& handleMaps, const ArapOptions& options,
    Positions& roiPositions, const ParallelFor& loop = SerialFor);

  /// Why the full-resolution system could not be built, empty if it was or still builds.
  const std::string& GetSettleError() const { return this->FineError; }

  /// Whether a drag came after the last settle.
  bool IsDragged() const { return this->Dragged; }

  const RegionProxy& GetProxy() const { return this->Proxy; }
  /// Bytes held by the proxy's factor (the full-resolution system has none).
  double GetFactorBytes() const { return this->Coarse.GetFactor().GetFactorBytes(); }

private:
  // The proxy's nodes as the coarse iterate and the handle maps have them.
  RegionProxy::NodeShape Nodes(const std::vector<AffineMap>& handleMaps) const;
  // Back to the state a new region starts from: the rest, no drag, no settle.
  void ResetToRest();
  // Waits for the full-resolution build (see Settle); whether the system is ready.
  bool WaitForFine(const ArapOptions& options, const ParallelFor& loop);

  RegionProxy Proxy;
  AsRigidAsPossibleSolver Coarse;
  AsRigidAsPossibleSolver Fine;
  ArapIterate CoarseIterate;
  ArapIterate FineIterate;
  // Where the current drag began: the fine shape and the nodes.
  Positions Base;
  RegionProxy::NodeShape BaseNodes;
  std::vector<AffineMap> LastMaps;
  double DragEnergy = 0.0;
  bool Dragged = false;
  std::string FineError;
  // std::async's: its destruction waits for the build. Declared last, so that it goes before
  // the members the build writes.
  std::future<std::string> FineBuild;
};
}

#endif
