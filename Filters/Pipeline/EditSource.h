// What a filter supplies to the edit pipeline: where its region comes from and where its
// motions come from. The deformation filters' handles and selections (HandleSource), the
// landmark warp's landmarks (LandmarkSource); the pipeline does the rest.
#ifndef LaplacianEditing_Pipeline_EditSource_h
#define LaplacianEditing_Pipeline_EditSource_h

#include "EditTypes.h"
#include "LaplacianEditor.h"

#include <functional>
#include <memory>
#include <string>
#include <vector>

class vtkPolyData;

namespace LaplacianEditing
{
namespace Pipeline
{
class SurfaceAdapter;

/// The region an update asks for.
struct RegionChoice
{
  RegionRequest Request;
  /// A labeled request's labels per surface vertex; called only when the region is selected
  /// anew.
  std::function<std::vector<int>()> Labels = [] { return std::vector<int>(); };
  /// Points pulled to targets (a landmark warp's), their version and their weight.
  std::shared_ptr<const std::vector<SurfacePoint>> Points;
  std::uint64_t PointsVersion = 0;
  double PointWeight = 100.0;
  /// Whether the input's points that no polygon uses move too, each by the displacement of the
  /// region's point nearest it at rest (as a thin-plate spline moves every point).
  bool FollowUnreferenced = false;
};

/// The motions of one update, in the core's frame: one map per handle group and, where the
/// region has points, their targets.
struct EditMotions
{
  std::vector<AffineMap> Maps;
  PointTargets Points;
  bool HasPoints = false;
};

class EditSource
{
public:
  virtual ~EditSource() = default;

  /// The part of `rest` the edit can reach; by default all of it.
  virtual Reach ComputeReach(vtkPolyData* /*rest*/) { return Reach(); }

  /// The region on `surface` (built from `rest`). Returns an error message, empty on success.
  virtual std::string ChooseRegion(
    vtkPolyData* rest, const SurfaceAdapter& surface, RegionChoice& region) = 0;

  /// After the region `request` asked for was selected anew (warnings, per-region caches).
  virtual void RegionSelected(const RegionRequest& /*request*/, const EditRegion& /*region*/,
    const SurfaceAdapter& /*surface*/)
  {
  }

  /// This update's motions for `region`. Returns an error message, empty on success.
  virtual std::string ChooseMotions(
    const SurfaceAdapter& surface, const EditRegion& region, EditMotions& motions) = 0;
};
}
}

#endif
