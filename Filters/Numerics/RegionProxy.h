// A coarse stand-in for a large region of interest, which an edit drags at the cost of a small
// region, and whose rotations carry the full-resolution detail (Documentation/how-it-works.md,
// "Regions of any size").
//
//  - Nodes: vertices spread over the ROI and a band of the fixed part around it, no two closer
//    than a spacing chosen for the number of nodes asked for (greedy sampling along the
//    vertices' spatial order, each new node's disc marked by a bounded Dijkstra search); each
//    vertex belongs to its nearest node (geodesic Voronoi cells).
//  - The proxy mesh: the nodes, joined by a triangle wherever three cells meet at a triangle of
//    the surface (the cells' dual). Its region: the nodes of ROI vertices, handle nodes where
//    the vertex is a handle's; the band's nodes are fixed.
//  - Prolongation: a free ROI vertex follows the nodes near it, each moving it rigidly, blended
//    with smooth weights (Wendland's compactly supported function of the distance, normalized):
//    x_i = p_i + sum_k w_ik ((R_k - I)(p_i - c_k) + (c'_k - c_k)). Fixed nodes stay; handle
//    vertices follow their handle's map exactly. So the rest is reproduced exactly, a rigid
//    motion of the region too, and details turn with the proxy's rotations.
#ifndef LaplacianEditing_RegionProxy_h
#define LaplacianEditing_RegionProxy_h

#include "EditRegion.h"
#include "ParallelFor.h"
#include "SurfaceMesh.h"
#include "Types.h"

#include <Eigen/Geometry>
#include <Eigen/StdVector>

#include <string>
#include <vector>

namespace LaplacianEditing
{
class RegionProxy
{
public:
  /// Builds the proxy of `region` on `mesh` with about `nodes` nodes. Returns an error message,
  /// empty on success.
  std::string Build(const SurfaceMesh& mesh, const EditRegion& region, int nodes,
    const ParallelFor& loop = SerialFor);

  /// The proxy's surface and region (vertices are the nodes).
  const SurfaceMesh& GetMesh() const { return this->Mesh; }
  const EditRegion& GetRegion() const { return this->Region; }

  /// Where the proxy's ROI nodes are and how they turn: per row of its region, the position
  /// and a 3 x 3 linear map (a rotation; a handle node's, its handle's linear part).
  struct NodeShape
  {
    Positions Points;
    std::vector<Eigen::Matrix3d> Turns;
  };
  /// The proxy at rest.
  NodeShape RestShape() const;

  /// The ROI positions (rows follow the fine region's Vertices) after the nodes moved from
  /// `from` to `to`, starting from `base` (ROI rows; the rest at a first drag): each free row
  /// moves by sum_k w_k ((T_k T0_k^-1 - I)(b - c0_k) + (c_k - c0_k)); a handle's rows go to
  /// their handle's map of the rest.
  void Prolong(const Positions& base, const NodeShape& from, const NodeShape& to,
    const std::vector<AffineMap>& handleMaps, Positions& roiPositions,
    const ParallelFor& loop = SerialFor) const;

  /// The fine region's rest positions (ROI rows).
  const Positions& GetRest() const { return this->Rest; }

  /// Each free fine ROI row's weighted sum of its nodes' values (proxy ROI rows) with the
  /// prolongation's weights, 0 at a handle's rows.
  void Interpolate(const Positions& nodeValues, Positions& fineValues, const ParallelFor& loop = SerialFor) const;

  /// Per node (a vertex of the proxy's mesh), its vertex of the fine mesh.
  const std::vector<int>& GetNodeVertices() const { return this->Seeds; }

  /// The largest node spacing, and the fine surface's mean edge length (the smallest), in the
  /// mesh's units.
  double GetSpacing() const { return this->Spacing; }
  double GetEdgeLength() const { return this->EdgeLength; }

private:
  // Build's steps: the vertices sampled (ROI and band), the nodes and cells, the proxy mesh
  // and region, the prolongation's weights.
  std::vector<char> SampledVertices(const SurfaceMesh& mesh, const EditRegion& region, double band) const;
  void Sample(const SurfaceMesh& mesh, const std::vector<char>& sampled);
  std::string Triangulate(const SurfaceMesh& mesh, const EditRegion& region);
  void Weigh(const SurfaceMesh& mesh, const EditRegion& region, const ParallelFor& loop);

  double Spacing = 0.0;
  double EdgeLength = 0.0;
  std::vector<int> Seeds;       // per node, its mesh vertex
  std::vector<double> NodeSpacing; // per node, the spacing at its vertex
  std::vector<int> Owner;       // per mesh vertex, its node (-1: not sampled)
  SurfaceMesh Mesh;
  EditRegion Region;
  std::vector<int> RoiRowOfNode; // per node, its row in Region.Vertices (-1: fixed)
  // Per fine ROI row: its handle group (-1: free), rest position, and its moving nodes' rows
  // (of the proxy's region) and weights, compressed; the fixed nodes' share goes to a still
  // node, one row past the region's, so a free row's weights sum to one (BlendRows). Floats:
  // the blend reads them as differences from its first node, exact for rigid motions.
  std::vector<int> HandleGroups;
  std::vector<int> HandleRows; // the rows of handle groups, in order
  Positions Rest;
  std::vector<int> WeightOffsets;
  std::vector<int> WeightNodes;
  std::vector<float> Weights;
  // Prolong's per-node motions, kept between drag steps.
  mutable std::vector<AffineMap> Motions;
};
}

#endif
