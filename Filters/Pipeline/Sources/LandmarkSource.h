// LandmarkSource: the landmark warp's edit source. The region is every connected component that
// holds a landmark, all of it free; the motions are the landmarks' targets, pulled on the points
// of the surface the landmarks are bound to (LandmarkBinder).
#ifndef LaplacianEditing_Pipeline_LandmarkSource_h
#define LaplacianEditing_Pipeline_LandmarkSource_h

#include "EditSource.h"
#include "LandmarkBinder.h"

class vtkObject;
class vtkPoints;

namespace LaplacianEditing
{
namespace Pipeline
{
class LandmarkSource : public EditSource
{
public:
  /// `reporter` warns about landmarks far from the surface.
  explicit LandmarkSource(vtkObject* reporter)
    : Reporter(reporter)
  {
  }

  /// This update's landmarks (input coordinates, as many targets as sources) and how they are
  /// held: distances in mesh units; a landmark farther than Tolerance from the surface warns,
  /// one farther than MaximumDistance is an error.
  vtkPoints* Sources = nullptr;
  vtkPoints* Targets = nullptr;
  double Tolerance = 0.0;
  double MaximumDistance = 0.0;
  bool Exact = true;
  double Weight = 1.0;
  /// Points that no polygon uses move with their nearest warped point (RegionChoice).
  bool FollowUnreferenced = false;

  const LandmarkBinder& GetBinder() const { return this->Binder; }
  /// Seconds the last update spent binding the landmarks (0 when the binding held).
  double GetBindingTime() const { return this->BindingTime; }

  std::string ChooseRegion(vtkPolyData* rest, const SurfaceAdapter& surface, RegionChoice& region) override;
  std::string ChooseMotions(
    const SurfaceAdapter& surface, const EditRegion& region, EditMotions& motions) override;

private:
  void WarnFarLandmarks() const;

  vtkObject* Reporter;
  LandmarkBinder Binder;
  double BindingTime = 0.0;
};
}
}

#endif
