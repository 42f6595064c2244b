// Explicit rotation of the differential coordinates (Section 4). Each ROI vertex j gets the
// frame {n, u, n x u}: n its smooth normal, u the projection onto the tangent plane of the edge
// (j, i) that is closest to orthogonal to n. delta_j is written in the rest frame once; for a
// deformed shape, the same coefficients in the deformed frame give the rotated delta.
#ifndef LaplacianEditing_LocalFrames_h
#define LaplacianEditing_LocalFrames_h

#include "ParallelFor.h"
#include "SurfaceMesh.h"

#include <Eigen/Core>

#include <vector>

namespace LaplacianEditing
{
using Positions = Eigen::Matrix<double, Eigen::Dynamic, 3>;

class LocalFrames
{
public:
  /// `vertices`: the ROI; `restNormals`, `restDelta`: per ROI vertex.
  void Build(const SurfaceMesh& mesh, const std::vector<int>& vertices,
    const Positions& restNormals, const Positions& restDelta);

  /// The differential coordinates carried into the frames of a deformed ROI.
  Positions Rotate(const Positions& roiPositions, const Positions& normals,
    const ParallelFor& loop = SerialFor) const;

private:
  // The chosen edge's other end: its ROI row, or -1 and its (fixed) rest position.
  std::vector<int> EdgeRoiRow;
  Positions EdgeRestEnd;
  // Whether the rest frame exists (a non-zero normal and a tangent edge).
  std::vector<char> HasFrame;
  // delta in the rest frame: (along n, along u, along n x u).
  Positions Coefficients;
  Positions RestDelta;
};
}

#endif
