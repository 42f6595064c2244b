// A displacement field over a regular lattice, fit to displacements known at scattered points
// (a warped surface's points): continuous (trilinear in each cell), defined inside and outside
// the surface, what an image warp samples (VTK's vtkGridTransform).
//
// The nodes' displacements minimize sum_p |trilinear(p) - d_p|^2 + mu sum_edges |u_a - u_b|^2:
// near the points the field meets them, between and beyond them it is harmonic, the lattice's
// own Laplace interpolation. mu is `smoothness` times the points' mean weight per node, so the
// fit does not depend on how many points there are. One sparse factorization, three right-hand
// sides.
#ifndef LaplacianEditing_DisplacementLattice_h
#define LaplacianEditing_DisplacementLattice_h

#include "SparseCholesky.h"
#include "Types.h"

#include <array>
#include <string>

namespace LaplacianEditing
{
struct LatticeGeometry
{
  Vector3 Origin = Vector3::Zero();
  Vector3 Spacing = Vector3::Ones();
  std::array<int, 3> Dimensions = { 2, 2, 2 }; // nodes along x, y, z; node (i, j, k) is row
                                               // i + nx (j + ny k)
};

/// Fits the nodes' displacements (one row a node) to `displacements` at `points`, points outside
/// the lattice left out. Returns an error, empty on success.
std::string FitDisplacementLattice(const LatticeGeometry& lattice, const Positions& points,
  const Positions& displacements, double smoothness, Positions& nodes,
  SolverBackend backend = SolverBackend::Cholmod);
}

#endif
