// How good an edit is, as the project judges it (Documentation/quality.md and the tests):
//  - Energy: the as-rigid-as-possible energy of the result against the rest shape. For each
//    region vertex, the best rotation R_i of its one-ring and sum_j w_ij |e'_ij - R_i e_ij|^2,
//    summed and divided by sum w_ij |e_ij|^2 (clamped cotangent weights). 0 for a rigid motion.
//  - AreaRatio: the area of the triangles touching the region, after over before.
//  - TurnedOverFaces: triangles touching the region whose normal points against the normals
//    around their corners, the sign of a fold.
#ifndef LaplacianEditing_EditMeasures_h
#define LaplacianEditing_EditMeasures_h

#include "LaplacianOperator.h"
#include "SurfaceMesh.h"

#include <vector>

namespace LaplacianEditing
{
struct EditMeasures
{
  double Energy = 0.0;
  double AreaRatio = 1.0;
  int TurnedOverFaces = 0;
};

/// The normalized ARAP energy alone.
double AsRigidAsPossibleEnergy(const SurfaceMesh& mesh, LaplacianWeights weights,
  const std::vector<int>& region, const std::vector<Vector3>& deformed);

/// `region`: surface vertices; `deformed`: a position for every surface vertex.
EditMeasures MeasureEdit(const SurfaceMesh& mesh, const std::vector<int>& region,
  const std::vector<Vector3>& deformed, LaplacianWeights weights = LaplacianWeights::Cotangent);
}

#endif
