#include "LandmarkSource.h"

#include "Stopwatch.h"

#include "vtkObject.h"

#include <algorithm>

namespace LaplacianEditing
{
namespace Pipeline
{
std::string LandmarkSource::ChooseRegion(
  vtkPolyData* /*rest*/, const SurfaceAdapter& surface, RegionChoice& region)
{
  const Stopwatch watch;
  bool rebound = false;
  const std::string error =
    this->Binder.Update(this->Sources, surface, this->MaximumDistance, rebound);
  this->BindingTime = rebound ? watch.Seconds() : 0.0;
  if (!error.empty())
  {
    return error;
  }
  if (rebound)
  {
    this->WarnFarLandmarks();
  }
  region.Request.Selection = RegionRequest::Kind::Components;
  region.Request.Seeds = this->Binder.GetSeeds();
  region.Points = this->Binder.GetPoints();
  region.PointsVersion = this->Binder.GetVersion();
  region.PointWeight = this->Weight;
  region.FollowUnreferenced = this->FollowUnreferenced;
  return {};
}

void LandmarkSource::WarnFarLandmarks() const
{
  const std::vector<double>& distances = this->Binder.GetDistances();
  const double tolerance = this->Tolerance;
  const auto far = std::count_if(
    distances.begin(), distances.end(), [tolerance](double d) { return d > tolerance; });
  if (far == 0)
  {
    return;
  }
  const auto farthest = std::max_element(distances.begin(), distances.end());
  vtkWarningWithObjectMacro(this->Reporter, << far << " source landmark(s) lie farther from the "
    << "surface than BindingTolerance (" << tolerance << " in mesh units), the farthest, "
    << "landmark " << (farthest - distances.begin()) << ", " << *farthest << " away. Each is "
    << "bound to the nearest surface point, which moves by the landmark's displacement.");
}

std::string LandmarkSource::ChooseMotions(
  const SurfaceAdapter& surface, const EditRegion& /*region*/, EditMotions& motions)
{
  motions.HasPoints = true;
  motions.Points.Exact = this->Exact;
  return this->Binder.Targets(this->Targets, surface, motions.Points);
}
}
}
