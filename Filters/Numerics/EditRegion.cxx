#include "EditRegion.h"

#include "GeodesicDistance.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace LaplacianEditing
{
namespace
{
// Where each ROI vertex lies between the handles (0) and the fixed part (1): h / (h + b), with h
// its distance from the handles (`fromHandles`, per ROI row) and b its distance to the nearest
// fixed vertex through the ROI. The anchor padding thus lines the border with the untouched mesh
// (Section 6) whatever the ROI's shape, and anchor weights still rise with the distance from the
// handle. A part of the ROI with no fixed border is measured by h alone, against the largest h.
void AssignRelativeDistances(const SurfaceMesh& mesh, const std::vector<double>& fromHandles,
  DistanceMethod method, EditRegion& region)
{
  const int n = region.GetNumberOfVertices();
  std::vector<int> local(mesh.GetNumberOfVertices(), -1);
  for (int k = 0; k < n; ++k)
  {
    local[region.Vertices[k]] = k;
  }
  std::vector<int> border;
  std::vector<char> onBorder(mesh.GetNumberOfVertices(), 0);
  for (int v : region.Vertices)
  {
    for (const int* w = mesh.NeighborsBegin(v); w != mesh.NeighborsEnd(v); ++w)
    {
      if (local[*w] < 0 && !onBorder[*w])
      {
        onBorder[*w] = 1;
        border.push_back(*w);
      }
    }
  }
  const double infinity = std::numeric_limits<double>::infinity();
  std::vector<double> toFixed(n, infinity);
  GeodesicSearch(mesh, method).Visit(
    border, infinity,
    [&](int v, double d) {
      if (local[v] >= 0)
      {
        toFixed[local[v]] = d;
      }
    },
    [&](int v) { return local[v] >= 0; });
  double largest = 0.0;
  for (double h : fromHandles)
  {
    largest = std::isfinite(h) ? std::max(largest, h) : largest;
  }
  region.RelativeDistances.resize(n);
  for (int k = 0; k < n; ++k)
  {
    // A vertex the handles cannot reach counts as farthest, so it becomes an anchor.
    const double h = std::isfinite(fromHandles[k]) ? fromHandles[k] : largest;
    const double b = toFixed[k];
    region.RelativeDistances[k] = std::isfinite(b) ? (h + b > 0.0 ? h / (h + b) : 0.0)
                                                   : (largest > 0.0 ? h / largest : 0.0);
  }
}

// Handle, anchor (the outer padding of the relative distances) or free.
void AssignRoles(double anchorPadding, EditRegion& region)
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
}

// Whether the connected part of the ROI around row `seed` (marked in `visited`) is held: it
// touches a fixed vertex, holds an anchor, or holds two handle groups.
bool IsHeld(const SurfaceMesh& mesh, const EditRegion& region, const std::vector<int>& local,
  int seed, std::vector<char>& visited)
{
  bool held = false;
  int firstGroup = -1;
  visited[seed] = 1;
  std::vector<int> stack(1, seed);
  while (!stack.empty())
  {
    const int k = stack.back();
    stack.pop_back();
    held = held || region.Roles[k] == VertexRole::Anchor;
    if (region.HandleGroups[k] >= 0)
    {
      held = held || (firstGroup >= 0 && firstGroup != region.HandleGroups[k]);
      firstGroup = region.HandleGroups[k];
    }
    const int v = region.Vertices[k];
    for (const int* w = mesh.NeighborsBegin(v); w != mesh.NeighborsEnd(v); ++w)
    {
      if (local[*w] < 0)
      {
        held = true;
      }
      else if (!visited[local[*w]])
      {
        visited[local[*w]] = 1;
        stack.push_back(local[*w]);
      }
    }
  }
  return held;
}

// Assigns the roles, then checks that the edit is well posed: every connected part of the ROI
// must be held. A part held by one handle group alone would only follow it rigidly (and with a
// translation-invariant operator, its shape is otherwise undetermined).
std::string Finish(const SurfaceMesh& mesh, double anchorPadding, EditRegion& region)
{
  AssignRoles(anchorPadding, region);
  const int n = region.GetNumberOfVertices();
  std::vector<int> local(mesh.GetNumberOfVertices(), -1);
  for (int k = 0; k < n; ++k)
  {
    local[region.Vertices[k]] = k;
  }
  std::vector<char> visited(n, 0);
  for (int seed = 0; seed < n; ++seed)
  {
    if (!visited[seed] && !IsHeld(mesh, region, local, seed, visited))
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
  double roiRadius, double anchorPadding, EditRegion& region, DistanceMethod method)
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
  const std::vector<double> distance = ComputeGeodesicDistances(mesh, { centerVertex }, roiRadius, method);
  // The region is a geodesic disc: from a vertex at h, the fixed border lies R - h further out,
  // so the relative distance h / (h + b) is h / R and needs no second search. When the disc
  // swallows the whole component, R is the distance it actually reaches.
  bool touchesFixed = false;
  for (int v = 0; v < mesh.GetNumberOfVertices(); ++v)
  {
    if (std::isfinite(distance[v]))
    {
      region.Vertices.push_back(v);
      region.HandleGroups.push_back(distance[v] <= handleRadius ? 0 : -1);
      region.Radius = std::max(region.Radius, distance[v]);
      for (const int* w = mesh.NeighborsBegin(v); w != mesh.NeighborsEnd(v); ++w)
      {
        touchesFixed = touchesFixed || !std::isfinite(distance[*w]);
      }
    }
  }
  region.BordersFixedPart = touchesFixed;
  const double radius = touchesFixed || region.Radius <= 0.0 ? roiRadius : region.Radius;
  for (int v : region.Vertices)
  {
    region.RelativeDistances.push_back(distance[v] / radius);
  }
  region.NumberOfHandleGroups = 1;
  return Finish(mesh, anchorPadding, region);
}

std::string SelectLabeledRegion(const SurfaceMesh& mesh, std::vector<int> labels,
  double anchorPadding, EditRegion& region, DistanceMethod method, double roiRadius)
{
  region = EditRegion();
  std::vector<int> handles;
  for (int v = 0; v < mesh.GetNumberOfVertices(); ++v)
  {
    if (labels[v] < 0)
    {
      return "the selection array holds a negative value; use 0 fixed, 1 ROI, 2+ handle";
    }
    if (labels[v] >= 2)
    {
      handles.push_back(v);
    }
  }
  if (handles.empty())
  {
    return "the selection array marks no handle vertex (value 2 or more)";
  }
  if (roiRadius > 0.0)
  {
    GeodesicSearch(mesh, method).Visit(handles, roiRadius, [&](int v, double) {
      labels[v] = std::max(labels[v], 1);
    });
  }
  for (int v = 0; v < mesh.GetNumberOfVertices(); ++v)
  {
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
  }
  // Distances from the handles through the ROI.
  std::vector<int> local(mesh.GetNumberOfVertices(), -1);
  for (int k = 0; k < region.GetNumberOfVertices(); ++k)
  {
    local[region.Vertices[k]] = k;
  }
  std::vector<double> fromHandles(region.GetNumberOfVertices(), std::numeric_limits<double>::infinity());
  GeodesicSearch(mesh, method).Visit(
    handles, std::numeric_limits<double>::infinity(),
    [&](int v, double d) {
      fromHandles[local[v]] = d;
      region.Radius = std::max(region.Radius, d);
    },
    [&](int v) { return local[v] >= 0; });
  AssignRelativeDistances(mesh, fromHandles, method, region);
  return Finish(mesh, anchorPadding, region);
}

std::string SelectComponents(const SurfaceMesh& mesh, const std::vector<int>& seeds, EditRegion& region)
{
  const std::vector<int>& components = mesh.GetComponents();
  std::vector<char> chosen(mesh.GetNumberOfComponents(), 0);
  for (const int seed : seeds)
  {
    if (seed < 0 || seed >= mesh.GetNumberOfVertices() || components[seed] < 0)
    {
      return "a seed is not a vertex of the surface's triangles";
    }
    chosen[components[seed]] = 1;
  }
  region = EditRegion();
  Eigen::AlignedBox3d box;
  for (int v = 0; v < mesh.GetNumberOfVertices(); ++v)
  {
    if (components[v] >= 0 && chosen[components[v]])
    {
      region.Vertices.push_back(v);
      box.extend(mesh.GetPositions()[v]);
    }
  }
  if (region.Vertices.empty())
  {
    return "no seed";
  }
  const std::size_t n = region.Vertices.size();
  region.Roles.assign(n, VertexRole::Free);
  region.HandleGroups.assign(n, -1);
  region.RelativeDistances.assign(n, 0.0);
  region.Radius = box.diagonal().norm();
  region.BordersFixedPart = false;
  return {};
}
}
