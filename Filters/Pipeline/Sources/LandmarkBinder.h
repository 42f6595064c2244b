// LandmarkBinder: binds landmarks to the nearest points of a surface, and turns their targets into the core's point targets.
//
// A source landmark need not be a vertex, nor lie on the surface: it is bound to the nearest
// point of the surface's triangles (barycentric weights on the corners, found through a
// vtkStaticCellLocator), and that point moves by the landmark's displacement. Landmarks at
// their sources therefore leave the surface as it is, wherever they lie, and a landmark off the
// surface keeps its offset from it.
#ifndef LaplacianEditing_Pipeline_LandmarkBinder_h
#define LaplacianEditing_Pipeline_LandmarkBinder_h

#include "PointConstraints.h"

#include "vtkType.h"

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

class vtkDoubleArray;
class vtkPoints;

namespace LaplacianEditing
{
class SurfaceMesh;

namespace Pipeline
{
class SurfaceAdapter;

class LandmarkBinder
{
public:
  /// Binds `sources` (input coordinates) to the surface's triangles, unless they and the
  /// surface are those of the last binding; `rebound` says whether it bound. Returns an error
  /// message (a coordinate not finite, a landmark farther than `maximumDistance` from the
  /// surface), empty on success.
  std::string Update(vtkPoints* sources, const SurfaceAdapter& surface,
    double maximumDistance, bool& rebound);

  /// The bound points, and a version that changes with them.
  const std::shared_ptr<const std::vector<LaplacianEditing::SurfacePoint>>& GetPoints() const
  {
    return this->Points;
  }
  std::uint64_t GetVersion() const { return this->Version; }
  /// Each landmark's distance from the surface, in input units.
  const std::vector<double>& GetDistances() const { return this->Distances; }
  /// A vertex of each landmark's triangle: the components to warp.
  std::vector<int> GetSeeds() const;

  /// The core's targets for `targets` (input coordinates, a point per landmark): each bound
  /// point moved by its landmark's displacement. Returns an error message for a coordinate
  /// that is not finite, empty on success.
  std::string Targets(vtkPoints* targets, const SurfaceAdapter& surface,
    LaplacianEditing::PointTargets& points) const;

  /// How far each landmark ended from its target in the written output (input units): its
  /// bound point on the output's points, plus its offset from the surface.
  void Misses(vtkPoints* output, const SurfaceAdapter& surface, vtkPoints* targets,
    vtkDoubleArray* misses) const;

private:
  std::shared_ptr<const std::vector<LaplacianEditing::SurfacePoint>> Points;
  // Each landmark's offset from its bound point, in the core's frame.
  LaplacianEditing::Positions Offsets;
  // An input point of each landmark's corners, three a landmark.
  std::vector<vtkIdType> CornerPoints;
  std::vector<double> Distances;
  std::uint64_t Version = 0;
  // What the binding was made from; the mesh is held, so that a new one is never mistaken for
  // it at the same address.
  std::shared_ptr<const LaplacianEditing::SurfaceMesh> BoundMesh;
  vtkPoints* BoundSources = nullptr;
  vtkMTimeType BoundTime = 0;
  double BoundDistance = 0.0;
};

}
}

#endif
