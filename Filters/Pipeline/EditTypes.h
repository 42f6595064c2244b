// The types the edit pipeline's stages hand each other. A leaf: it includes nothing of the
// pipeline, so that any stage can take them without depending on another stage.
#ifndef LaplacianEditing_Pipeline_EditTypes_h
#define LaplacianEditing_Pipeline_EditTypes_h

#include "Types.h"

#include "vtkType.h"

#include <array>
#include <cstdint>
#include <vector>

namespace LaplacianEditing
{
class LaplacianEditor;

namespace Pipeline
{
class NormalRefresher;
class SurfaceAdapter;

/// The part of input space an edit can reach: within `Margin` of a seed point. A negative
/// margin reaches everything.
struct Reach
{
  std::vector<std::array<double, 3>> Seeds;
  double Margin = -1.0;
  bool operator==(const Reach& other) const
  {
    return this->Margin == other.Margin && this->Seeds == other.Seeds;
  }
};

/// The output points an edit moves: their ids, their rows of the solution and their roles; a
/// point that follows a row it is not (SurfaceAdapter::AddFollowers) is offset from it by its
/// Offset, in input coordinates (empty: none does).
struct MovedPoints
{
  std::vector<vtkIdType> Ids;
  std::vector<int> Rows;
  std::vector<signed char> Roles;
  std::vector<Vector3> Offsets;
};

/// What a filter's output carries besides its moved points: the EditRole array (and its
/// colours), and the Displacement array (output minus rest).
struct OutputOptions
{
  bool Roles = false;
  bool RoleColors = false;
  bool Displacement = false;
};

/// One update's edit, as the output writer takes it. Solution rows are in the core's frame
/// (input = core / Scale + Center); the normals' index (null: no normals to refresh) has each of
/// its vertices at VertexRest[v], or at the solution's row VertexRows[v] where that is not -1.
struct OutputEdit
{
  const MovedPoints* Moved = nullptr;
  const Positions* Solution = nullptr;
  Vector3 Center = Vector3::Zero();
  double Scale = 1.0;
  const NormalRefresher* Normals = nullptr;
  const std::vector<Vector3>* VertexRest = nullptr;
  const std::vector<int>* VertexRows = nullptr;
  /// Changes whenever Moved does (its roles are written again only then).
  std::uint64_t RegionVersion = 0;
};

/// A solved edit as the pipeline holds it, for those that share it out (the parallel filter's
/// pieces).
struct EditState
{
  const SurfaceAdapter* Surface = nullptr;
  const NormalRefresher* Normals = nullptr;
  const LaplacianEditor* Editor = nullptr;
  const std::vector<AffineMap>* Maps = nullptr;
  const Positions* Solution = nullptr;
  /// Changes whenever the surface, region, system or rotation model is rebuilt.
  std::uint64_t ModelVersion = 0;
};
}
}

#endif
