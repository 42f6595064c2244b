// A coarse, rotation-aware stand-in for a volume zone, which a drag step solves at the cost of a
// few hundred nodes instead of the zone's tetrahedra: the embedded deformation of Sumner, Schmid
// and Pauly ("Embedded Deformation for Shape Manipulation", SIGGRAPH 2007).
//
//  - Nodes: zone points no two closer than a spacing chosen for the number of nodes asked for.
//    Each point follows its K nearest nodes along the mesh's edges (so parts that touch only
//    across the outside do not pull on each other): x = sum_n w_n (c_n + R_n (p - q_n)), with
//    w_n = (1 - d_n / d_K+1)^2, normalized. The rest, and any rigid motion, are reproduced.
//  - Nodes that a point shares are joined. A solve lowers the graph's as-rigid-as-possible
//    energy sum_n sum_m~n |c_m - c_n - R_n (q_m - q_n)|^2 plus the constrained points' pull,
//    alpha sum_t |x(p_t) - y_t|^2 (targeted points towards their targets, fixed ones at rest),
//    by local-global iterations (R_n the closest rotation; then c, whose matrix is factored once).
//
// The result is smooth and keeps no cell positive by construction: the caller checks it and
// falls back on InjectiveDeformation where a cell would flatten.
#ifndef LaplacianEditing_DeformationGraph_h
#define LaplacianEditing_DeformationGraph_h

#include "InjectiveDeformation.h"
#include "ParallelFor.h"
#include "SparseCholesky.h"
#include "Types.h"

#include <Eigen/Geometry>
#include <Eigen/StdVector>

#include <string>
#include <vector>

namespace LaplacianEditing
{
class DeformationGraph
{
public:
  /// Samples about `nodes` nodes over the points at `rest` (joined by the tetrahedra's edges),
  /// weighs the points and factors the global step. Returns an error, empty on success.
  std::string Build(const Positions& rest, const Tetrahedra& tetrahedra,
    const std::vector<PointKind>& kinds, int nodes, const ParallelFor& loop = SerialFor);

  /// Lowers the energy towards `targets` (the targeted rows are read) by `iterations`
  /// local-global iterations from the last solve's nodes (the rest's after Build), and writes
  /// the free rows of `points`; targeted rows get their targets, fixed rows are not written.
  void Solve(const Positions& targets, Positions& points, int iterations,
    const ParallelFor& loop = SerialFor);

  /// Adds to the free rows of `points` near constrained points the constrained rows of `misses`,
  /// fading over a node spacing: how the band near the boundary takes up where the boundary
  /// stands off a smooth field.
  void Spread(const Positions& misses, Positions& points, const ParallelFor& loop = SerialFor) const;

  /// The nodes back at rest: the next Solve starts from there.
  void ResetToRest();

  int GetNumberOfNodes() const { return static_cast<int>(this->NodePoints.size()); }
  bool IsBuilt() const { return !this->NodePoints.empty(); }

private:
  // The position of point p after the nodes' motion.
  Vector3 Follow(int p) const;

  Positions Rest;
  std::vector<PointKind> Kinds;
  std::vector<int> NodePoints;            // per node, its point
  Positions NodeRest;                     // q_n
  Positions NodeCenters;                  // c_n
  std::vector<Eigen::Matrix3d> Rotations; // R_n
  std::vector<Eigen::Quaterniond, Eigen::aligned_allocator<Eigen::Quaterniond>> Turns; // R_n's
  // Per point, its nodes and weights from WeightOffsets[p] on.
  std::vector<int> WeightOffsets, WeightNodes;
  std::vector<double> Weights;
  // Per node, its neighbours from NeighbourOffsets[n] on.
  std::vector<int> NeighbourOffsets, Neighbours;
  std::vector<int> Constrained; // the targeted and fixed points
  // The band's points, and per band point its constrained points (rows of Constrained) and
  // weights from BandOffsets on.
  std::vector<int> BandPoints, BandOffsets, BandSources;
  std::vector<double> BandWeights;
  double Alpha = 0.0;
  // The pull's constant sums (Build): per node, and per pair of nodes sharing a constrained
  // point, from PairOffsets[n] on.
  Positions PulledOffsets;
  std::vector<int> PairOffsets, PairNodes;
  Positions PairOffsetSums;
  SparseCholesky Factor;
};
}

#endif
