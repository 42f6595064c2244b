#include "HandleSource.h"

#include "vtkPolyData.h"

namespace LaplacianEditing
{
namespace Pipeline
{
Reach HandleSource::ComputeReach(vtkPolyData* rest)
{
  return this->Selector.ComputeReach(rest, this->Parameters);
}

std::string HandleSource::ChooseRegion(
  vtkPolyData* rest, const SurfaceAdapter& surface, RegionChoice& region)
{
  this->Diagonal = rest->GetLength();
  region.Request = this->Selector.Request(rest, surface, this->Parameters);
  vtkDataArray* labels = this->Selector.GetLabels();
  region.Labels = [&surface, labels] { return surface.VertexLabels(labels); };
  return {};
}

void HandleSource::RegionSelected(
  const RegionRequest& request, const EditRegion& region, const SurfaceAdapter& surface)
{
  this->Selector.Warn(this->Reporter, request, region, surface, this->Parameters, this->Diagonal);
  this->Handles.FindGroupCenters(region, surface);
}

std::string HandleSource::ChooseMotions(
  const SurfaceAdapter& surface, const EditRegion& region, EditMotions& motions)
{
  motions.Maps = this->Handles.Maps(region.NumberOfHandleGroups, surface,
    this->Parameters.HandleCenter, this->Rotation, this->Translation);
  return {};
}
}
}
