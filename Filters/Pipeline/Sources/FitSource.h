// FitSource: a template fit's edit source. The region is the whole template (every component,
// all free); the motions pull the template's trusted vertices to their matches on the target,
// and its landmarks (bound as a landmark warp binds them, LandmarkBinder) to theirs.
//
// The fit sets the matches before each solve. A new set of matched points is a new system (its
// factor); new targets for the same points only a new right-hand side.
#ifndef LaplacianEditing_Pipeline_FitSource_h
#define LaplacianEditing_Pipeline_FitSource_h

#include "EditSource.h"
#include "LandmarkBinder.h"

#include <array>

class vtkPoints;

namespace LaplacianEditing
{
namespace Pipeline
{
class FitSource : public EditSource
{
public:
  /// The input points pulled, and their targets (input coordinates, one per point). `newPoints`
  /// says whether the points differ from the last call's (only their targets changed if not).
  void SetMatches(std::vector<vtkIdType> points, std::vector<std::array<double, 3>> targets,
    bool newPoints);

  /// The landmarks (input coordinates; null: none), bound to the template within
  /// MaximumBindingDistance. With no matches they are met exactly, otherwise pulled as the
  /// matches are.
  vtkPoints* LandmarkSources = nullptr;
  vtkPoints* LandmarkTargets = nullptr;
  double MaximumBindingDistance = 0.0;
  /// The pull of every point, relative to the template's stiffness.
  double Weight = 1.0;
  /// A landmark's pull among the matches, in matched vertices' (its square).
  double LandmarkPull = 1.0;
  /// Points that no polygon uses move with their nearest fitted point (RegionChoice).
  bool FollowUnreferenced = true;

  std::string ChooseRegion(vtkPolyData* rest, const SurfaceAdapter& surface, RegionChoice& region) override;
  std::string ChooseMotions(
    const SurfaceAdapter& surface, const EditRegion& region, EditMotions& motions) override;

private:
  LandmarkBinder Binder;
  std::vector<vtkIdType> MatchedPoints;
  std::vector<std::array<double, 3>> MatchTargets;
  // The mesh vertex of each matched point (-1: no polygon uses it).
  std::vector<int> MatchedVertices;
  // The matched points' version, the one the constraint points were built for, and theirs.
  std::uint64_t Version = 0;
  std::uint64_t BuiltFor = 0;
  std::uint64_t PointsVersion = 0;
  std::shared_ptr<const std::vector<SurfacePoint>> Points;
};
}
}

#endif
