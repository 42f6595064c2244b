// FoldGuard: a template fit's watch on folds. Where the matches of neighbouring vertices
// disagree (thin parts matched to two sides, fingers to their neighbours), a strong pull folds
// the template: triangles turn over. The guard remembers each triangle's normal at the start of
// the stages, and after each round sets aside for good the vertices of the triangles that turned
// over since (by more than a right angle, which no stage's motion does): the template's own
// stiffness carries them from then on. It also lands a fitted shape on its matches without a
// fold: each point moves to its match unless one of its triangles would turn over. Last, it
// mends the slivers that turned over.
#ifndef LaplacianEditing_Pipeline_FoldGuard_h
#define LaplacianEditing_Pipeline_FoldGuard_h

#include "vtkType.h"

#include <array>
#include <vector>

class vtkPolyData;

namespace LaplacianEditing
{
namespace Pipeline
{
class FoldGuard
{
public:
  /// No vertex set aside, for a shape of `points` points.
  void Reset(vtkIdType points) { this->SetAside.assign(points, 0); }
  /// The triangles' normals of `shape` at the stages' start.
  void Remember(vtkPolyData* shape);
  /// Sets aside the corners of `shape`'s triangles turned over since Remember; returns how many
  /// vertices it set aside anew.
  int Check(vtkPolyData* shape);
  bool IsSetAside(vtkIdType point) const { return this->SetAside[point] != 0; }
  /// Moves each point of `shape` that `allowed` marks (and the guard has not set aside) to its
  /// target, in new points, except the corners of triangles that would turn over, tilt by more
  /// than 30 degrees or shrink to less than a quarter of their area, which keep their place; returns how many points moved.
  int Land(vtkPolyData* shape, const std::vector<std::array<double, 3>>& targets,
    const std::vector<char>& allowed) const;
  int GetNumberOfSetAside() const;
  /// Turns back each sliver of `rest` (its height under a twentieth of its longest edge) that
  /// `shape` turned over since Remember: its apex goes where `rest` has it against its longest
  /// edge, to the side the triangles around that edge face, in new points. Why: a sliver's apex
  /// lies a sliver's height from its base's line, so any turn of the base a few degrees off its
  /// neighbours' puts the apex on the other side, which no stiffness resists (the Armadillo's
  /// one boundary ear, 1/140 as high as long, turned over in four of five articulated fits).
  /// Returns how many it turned back.
  int MendSlivers(vtkPolyData* rest, vtkPolyData* shape) const;

private:
  std::vector<std::array<double, 3>> Normals;
  std::vector<char> SetAside;
};
}
}

#endif
