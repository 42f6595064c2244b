#include "LocalFrames.h"

#include <cmath>
#include <limits>

namespace LaplacianEditing
{
namespace
{
// The unit tangent direction of `edge` at normal `n`; zero if the edge is along n.
Eigen::Vector3d Tangent(const Eigen::Vector3d& edge, const Eigen::Vector3d& n)
{
  const Eigen::Vector3d v = edge - edge.dot(n) * n;
  const double length = v.norm();
  return length > 0.0 ? Eigen::Vector3d(v / length) : Eigen::Vector3d::Zero();
}
}

void LocalFrames::Build(const SurfaceMesh& mesh, const std::vector<int>& vertices,
  const Positions& restNormals, const Positions& restDelta)
{
  const int n = static_cast<int>(vertices.size());
  const auto& positions = mesh.GetPositions();
  std::vector<int> roiRow(mesh.GetNumberOfVertices(), -1);
  for (int row = 0; row < n; ++row)
  {
    roiRow[vertices[row]] = row;
  }
  this->EdgeRoiRow.assign(n, -1);
  this->EdgeRestEnd.setZero(n, 3);
  this->Coefficients.setZero(n, 3);
  this->RestDelta = restDelta;
  this->HasFrame.assign(n, 0);
  for (int row = 0; row < n; ++row)
  {
    const int v = vertices[row];
    const Eigen::Vector3d normal = restNormals.row(row).transpose();
    // The first neighbour unless another is clearly closer to orthogonal; edges of zero
    // length (unmerged coincident points) cannot carry a direction.
    int best = -1;
    double bestCosine = std::numeric_limits<double>::infinity();
    for (const int* w = mesh.NeighborsBegin(v); w != mesh.NeighborsEnd(v); ++w)
    {
      const Eigen::Vector3d edge = positions[*w] - positions[v];
      const double length = edge.norm();
      if (!(length > 0.0))
      {
        continue;
      }
      // Near-ties (flat rings, where every edge is orthogonal to n) keep the first neighbour,
      // so that the last bits of the coordinates do not pick the frame.
      const double cosine = std::abs(edge.dot(normal)) / length;
      if (best < 0 || cosine < bestCosine - 1e-6)
      {
        bestCosine = cosine;
        best = *w;
      }
    }
    if (best < 0)
    {
      continue; // no frame: Rotate keeps this delta as it is
    }
    this->EdgeRoiRow[row] = roiRow[best];
    this->EdgeRestEnd.row(row) = positions[best].transpose();
    const Eigen::Vector3d u = Tangent(positions[best] - positions[v], normal);
    this->HasFrame[row] = normal.squaredNorm() > 0.0 && u.squaredNorm() > 0.0;
    const Eigen::Vector3d delta = restDelta.row(row).transpose();
    this->Coefficients.row(row) << delta.dot(normal), delta.dot(u), delta.dot(normal.cross(u));
  }
}

Positions LocalFrames::Rotate(
  const Positions& roiPositions, const Positions& normals, const ParallelFor& loop) const
{
  Positions rotated(roiPositions.rows(), 3);
  loop(0, static_cast<int>(roiPositions.rows()), [&](int first, int last) {
    for (int row = first; row < last; ++row)
    {
      // Without a frame (at rest or now), delta stays as it was.
      rotated.row(row) = this->RestDelta.row(row);
      const Eigen::Vector3d normal = normals.row(row).transpose();
      if (!this->HasFrame[row] || !(normal.squaredNorm() > 0.0))
      {
        continue;
      }
      const int end = this->EdgeRoiRow[row];
      const Eigen::Vector3d edge =
        (end >= 0 ? roiPositions.row(end) : this->EdgeRestEnd.row(row)) - roiPositions.row(row);
      const Eigen::Vector3d u = Tangent(edge, normal);
      if (u.squaredNorm() > 0.0)
      {
        const Eigen::Vector3d c = this->Coefficients.row(row).transpose();
        rotated.row(row) = (c[0] * normal + c[1] * u + c[2] * normal.cross(u)).transpose();
      }
    }
  });
  return rotated;
}
}
