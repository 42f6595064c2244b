// Normals of the underlying smooth surface (Section 7): averages of the area-weighted vertex
// normals within radius r, weighted by p(t) = 2t^3/r^3 - 3t^2/r^2 + 1 over the Dijkstra
// distance t.
//
// Evaluating that kernel at every vertex costs O(n r^2) per handle move, which is too slow for
// interactive editing of large regions with a radius wider than the details. So the kernel is
// evaluated exactly at sample vertices spaced r/4 apart (a greedy geodesic cover of the ROI),
// and each ROI vertex blends the unit normals of the samples within r/2 with the same fall-off
// over r/2. The cost is then O(n) whatever the radius, the result stays smooth, and it is
// exactly equivariant: a rigid motion of the mesh rotates the normals with it.
//
// The samples, neighbourhoods and weights depend only on the rest mesh and the region, so Build
// computes them once; Compute then costs two sparse products.
#ifndef LaplacianEditing_SmoothNormals_h
#define LaplacianEditing_SmoothNormals_h

#include "ParallelFor.h"
#include "GeodesicDistance.h"
#include "SurfaceMesh.h"

#include <Eigen/SparseCore>

#include <array>
#include <vector>

namespace LaplacianEditing
{
using Positions = Eigen::Matrix<double, Eigen::Dynamic, 3>;

class SmoothNormals
{
public:
  /// Precomputes the samples and weights for the ROI `vertices` and support radius `radius`.
  void Build(const SurfaceMesh& mesh, const std::vector<int>& vertices, double radius,
    DistanceMethod method = DistanceMethod::FastMarching, const ParallelFor& loop = SerialFor);

  /// Unit smooth normals at the ROI vertices, for ROI positions `roiPositions` (rows follow
  /// `vertices`); vertices outside the ROI keep their rest positions.
  Positions Compute(const Positions& roiPositions, const ParallelFor& loop = SerialFor) const;

  double GetRadius() const { return this->Radius; }

private:
  // The triangles around the support vertices, whose corners join the extended index (each
  // mesh vertex's number, -1 where none, and the numbered vertices).
  void IndexSupportTriangles(
    const SurfaceMesh& mesh, std::vector<int>& extended, std::vector<int>& extendedVertices);

  double Radius = 0.0;
  // Rows: samples; columns: support vertices (within the radius of a sample).
  Eigen::SparseMatrix<double, Eigen::RowMajor> SampleWeights;
  // Rows: ROI vertices; columns: samples within half the radius.
  Eigen::SparseMatrix<double, Eigen::RowMajor> BlendWeights;
  // Support vertices and the one-ring around them, with their rest positions, and the ROI row
  // of each (-1 outside the ROI).
  std::vector<int> ExtendedRoiRow;
  Positions ExtendedRest;
  // Triangles touching the support, as indices into the extended set, and the triangles around
  // each support vertex (compressed rows into Triangles).
  std::vector<std::array<int, 3>> Triangles;
  std::vector<int> SupportTriangleOffsets;
  std::vector<int> SupportTriangles;
  int NumberOfSupportVertices = 0;
};
}

#endif
