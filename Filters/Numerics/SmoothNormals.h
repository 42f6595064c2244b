// Normals of the underlying smooth surface (Section 7): at each ROI vertex j, the average of the
// area-weighted vertex normals within radius r, weighted by p(t) = 2t^3/r^3 - 3t^2/r^2 + 1
// over the Dijkstra distance t. The neighbourhoods and weights depend only on the rest mesh
// and the region, so Build computes them once; Compute then costs one sparse product.
#ifndef LaplacianEditing_SmoothNormals_h
#define LaplacianEditing_SmoothNormals_h

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
  /// Precomputes the weights for the ROI `vertices` and support radius `radius`.
  void Build(const SurfaceMesh& mesh, const std::vector<int>& vertices, double radius);

  /// Unit smooth normals at the ROI vertices, for ROI positions `roiPositions` (rows follow
  /// `vertices`); vertices outside the ROI keep their rest positions.
  Positions Compute(const Positions& roiPositions) const;

  double GetRadius() const { return this->Radius; }
  /// Stored neighbour weights: the memory and per-move cost grow with it.
  Eigen::Index GetNumberOfWeights() const { return this->Weights.nonZeros(); }

private:
  double Radius = 0.0;
  // Rows: ROI vertices; columns: support vertices (within the radius of some ROI vertex).
  Eigen::SparseMatrix<double, Eigen::RowMajor> Weights;
  // Support vertices and the one-ring around them, with their rest positions, and the ROI row
  // of each (-1 outside the ROI).
  std::vector<int> ExtendedRoiRow;
  Positions ExtendedRest;
  // Triangles touching the support, as indices into the extended set.
  std::vector<std::array<int, 3>> Triangles;
  int NumberOfSupportVertices = 0;
};
}

#endif
