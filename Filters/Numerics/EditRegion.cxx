#include "EditRegion.h"

#include "GeodesicDistance.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace LaplacianEditing
{
namespace
{
// Assigns anchor and free roles from the relative distances, then checks that the edit is well
// posed: every connected part of the ROI must touch a fixed vertex, hold an anchor, or hold two
// handle groups. A part held by one handle group alone would only follow it rigidly (and with a
// translation-invariant operator, its shape is otherwise undetermined).
std::string Finish(const SurfaceMesh& mesh, double anchorPadding, EditRegion& region)
{
  const int n = region.GetNumberOfVertices();
  region.Roles.resize(n);
  for (int k = 0; k < n; ++k)
  {
    if (region.HandleGroups[k] >= 0)
    {
      region.Roles[k] = VertexRole::Handle;
    }
    else if (anchorPadding > 0.0 && region.RelativeDistances[k] > 1.0 - anchorPadding)
    {
      region.Roles[k] = VertexRole::Anchor;
    }
    else
    {
      region.Roles[k] = VertexRole::Free;
    }
  }

  std::vector<int> local(mesh.GetNumberOfVertices(), -1);
  for (int k = 0; k < n; ++k)
  {
    local[region.Vertices[k]] = k;
  }
  std::vector<char> visited(n, 0);
  std::vector<int> stack;
  for (int seed = 0; seed < n; ++seed)
  {
    if (visited[seed])
    {
      continue;
    }
    bool pinned = false;
    int firstGroup = -1;
    visited[seed] = 1;
    stack.assign(1, seed);
    while (!stack.empty())
    {
      const int k = stack.back();
      stack.pop_back();
      pinned = pinned || region.Roles[k] == VertexRole::Anchor;
      if (region.HandleGroups[k] >= 0)
      {
        pinned = pinned || (firstGroup >= 0 && firstGroup != region.HandleGroups[k]);
        firstGroup = region.HandleGroups[k];
      }
      const int v = region.Vertices[k];
      for (const int* w = mesh.NeighborsBegin(v); w != mesh.NeighborsEnd(v); ++w)
      {
        if (local[*w] < 0)
        {
          pinned = true;
        }
        else if (!visited[local[*w]])
        {
          visited[local[*w]] = 1;
          stack.push_back(local[*w]);
        }
      }
    }
    if (!pinned)
    {
      return "a connected part of the region of interest has no fixed vertex and no anchor (and "
             "at most one handle group), so nothing holds it in place: make the ROI smaller than "
             "the component or set AnchorPadding > 0";
    }
  }
  return {};
}
}

std::string SelectGeodesicRegion(const SurfaceMesh& mesh, int centerVertex, double handleRadius,
  double roiRadius, double anchorPadding, EditRegion& region)
{
  region = EditRegion();
  if (centerVertex < 0 || centerVertex >= mesh.GetNumberOfVertices())
  {
    return "no surface vertex to put the handle on";
  }
  if (!(handleRadius > 0.0) || !(roiRadius > 0.0))
  {
    return "HandleRadius and ROIRadius must be positive";
  }
  if (handleRadius >= roiRadius)
  {
    return "the handle reaches outside the region of interest: HandleRadius must be smaller "
           "than ROIRadius";
  }
  const std::vector<double> distance = ComputeGeodesicDistances(mesh, { centerVertex }, roiRadius);
  // When the ROI swallows the whole component, the anchor band is measured from the distance
  // it actually reaches, so that the far end is still held.
  double reach = 0.0;
  bool touchesFixed = false;
  for (int v = 0; v < mesh.GetNumberOfVertices(); ++v)
  {
    if (std::isfinite(distance[v]))
    {
      reach = std::max(reach, distance[v]);
      for (const int* w = mesh.NeighborsBegin(v); w != mesh.NeighborsEnd(v); ++w)
      {
        touchesFixed = touchesFixed || !std::isfinite(distance[*w]);
      }
    }
  }
  const double radius = touchesFixed || reach <= 0.0 ? roiRadius : reach;
  for (int v = 0; v < mesh.GetNumberOfVertices(); ++v)
  {
    if (std::isfinite(distance[v]))
    {
      region.Vertices.push_back(v);
      region.HandleGroups.push_back(distance[v] <= handleRadius ? 0 : -1);
      region.RelativeDistances.push_back(distance[v] / radius);
    }
  }
  region.NumberOfHandleGroups = 1;
  region.Radius = radius;
  return Finish(mesh, anchorPadding, region);
}

std::string SelectLabeledRegion(const SurfaceMesh& mesh, const std::vector<int>& labels,
  double anchorPadding, EditRegion& region)
{
  region = EditRegion();
  std::vector<int> handles;
  for (int v = 0; v < mesh.GetNumberOfVertices(); ++v)
  {
    if (labels[v] < 0)
    {
      return "the selection array holds a negative value; use 0 fixed, 1 ROI, 2+ handle";
    }
    if (labels[v] == 0)
    {
      continue;
    }
    if (mesh.GetValence(v) == 0)
    {
      return "the selection puts a vertex that no triangle references into the region of "
             "interest";
    }
    region.Vertices.push_back(v);
    region.HandleGroups.push_back(labels[v] >= 2 ? labels[v] - 2 : -1);
    region.NumberOfHandleGroups = std::max(region.NumberOfHandleGroups, labels[v] - 1);
    if (labels[v] >= 2)
    {
      handles.push_back(v);
    }
  }
  if (handles.empty())
  {
    return "the selection array marks no handle vertex (value 2 or more)";
  }
  // A ROI vertex the handles cannot reach counts as farthest, so it becomes an anchor.
  const std::vector<double> distance =
    ComputeGeodesicDistances(mesh, handles, std::numeric_limits<double>::infinity());
  double largest = 0.0;
  for (int v : region.Vertices)
  {
    if (std::isfinite(distance[v]))
    {
      largest = std::max(largest, distance[v]);
    }
  }
  region.Radius = largest;
  for (int v : region.Vertices)
  {
    const double d = std::isfinite(distance[v]) ? distance[v] : largest;
    region.RelativeDistances.push_back(largest > 0.0 ? d / largest : 0.0);
  }
  return Finish(mesh, anchorPadding, region);
}
}
