#include "HandleMaps.h"

#include "HandleMotion.h"

#include "SurfaceAdapter.h"

#include "vtkLinearTransform.h"
#include "vtkTransform.h"

#include <algorithm>

namespace le = LaplacianEditing;

namespace LaplacianEditing
{
namespace Pipeline
{

bool HandleMaps::SetTransform(int group, vtkLinearTransform* transform)
{
  if (group >= static_cast<int>(this->Transforms.size()))
  {
    this->Transforms.resize(group + 1);
  }
  if (this->Transforms[group] == transform)
  {
    return false;
  }
  this->Transforms[group] = transform;
  return true;
}

vtkLinearTransform* HandleMaps::GetTransform(int group) const
{
  return group >= 0 && group < static_cast<int>(this->Transforms.size())
    ? this->Transforms[group].Get()
    : nullptr;
}

bool HandleMaps::RemoveAllTransforms()
{
  const bool had = !this->Transforms.empty();
  this->Transforms.clear();
  return had;
}

vtkMTimeType HandleMaps::GetTransformsMTime() const
{
  vtkMTimeType time = 0;
  for (const auto& transform : this->Transforms)
  {
    time = transform ? std::max(time, transform->GetMTime()) : time;
  }
  return time;
}

bool HandleMaps::SetMotion(int group, const std::array<double, 6>& motion)
{
  const auto found = this->Motions.find(group);
  if (found != this->Motions.end() && found->second == motion)
  {
    return false;
  }
  this->Motions[group] = motion;
  return true;
}

bool HandleMaps::GetMotion(int group, double motion[6]) const
{
  const auto found = this->Motions.find(group);
  if (found == this->Motions.end())
  {
    return false;
  }
  std::copy(found->second.begin(), found->second.end(), motion);
  return true;
}

bool HandleMaps::RemoveAllMotions()
{
  const bool had = !this->Motions.empty();
  this->Motions.clear();
  return had;
}

void HandleMaps::FindGroupCenters(
  const le::EditRegion& region, const SurfaceAdapter& surface)
{
  std::vector<le::Vector3> sums(region.NumberOfHandleGroups, le::Vector3::Zero());
  std::vector<int> counts(region.NumberOfHandleGroups, 0);
  for (std::size_t row = 0; row < region.HandleGroups.size(); ++row)
  {
    const int group = region.HandleGroups[row];
    if (group >= 0 && group < region.NumberOfHandleGroups)
    {
      sums[group] += surface.GetMesh()->GetPositions()[region.Vertices[row]];
      ++counts[group];
    }
  }
  this->GroupCenters.assign(region.NumberOfHandleGroups, std::nullopt);
  for (int group = 0; group < region.NumberOfHandleGroups; ++group)
  {
    if (counts[group] > 0)
    {
      const le::Vector3 mean = surface.Denormalize(sums[group] / counts[group]);
      this->GroupCenters[group] = std::array<double, 3>{ mean[0], mean[1], mean[2] };
    }
  }
}

const double* HandleMaps::GetGroupCenter(int group) const
{
  const auto& centers = this->GroupCenters;
  return group >= 0 && group < static_cast<int>(centers.size()) && centers[group]
    ? centers[group]->data()
    : nullptr;
}

std::vector<le::AffineMap> HandleMaps::Maps(int groups,
  const SurfaceAdapter& surface, const double center[3], const double rotation[3],
  const double translation[3]) const
{
  std::vector<le::AffineMap> maps(groups, le::AffineMap::Identity());
  for (int g = 0; g < groups; ++g)
  {
    double motion[6];
    const double* groupCenter = this->GetGroupCenter(g);
    if (vtkLinearTransform* transform = this->GetTransform(g))
    {
      maps[g] = surface.NormalizedMap(transform);
    }
    else if (g == 0)
    {
      maps[0] = surface.NormalizedMap(HandleMotion::Transform(center, rotation, translation));
    }
    else if (groupCenter && this->GetMotion(g, motion))
    {
      maps[g] = surface.NormalizedMap(HandleMotion::Transform(groupCenter, motion + 3, motion));
    }
  }
  return maps;
}

void HandleMaps::PrintSelf(ostream& os, vtkIndent indent) const
{
  os << indent << "NumberOfHandleTransforms: " << this->Transforms.size() << "\n";
  for (const auto& [group, motion] : this->Motions)
  {
    os << indent << "HandleGroupMotion " << group << ": translation (" << motion[0] << ", "
       << motion[1] << ", " << motion[2] << "), rotation (" << motion[3] << ", " << motion[4]
       << ", " << motion[5] << ")\n";
  }
}
}
}
