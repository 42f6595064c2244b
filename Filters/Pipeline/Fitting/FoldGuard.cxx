#include "FoldGuard.h"

#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkSmartPointer.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"

#include <algorithm>

namespace LaplacianEditing
{
namespace Pipeline
{
namespace
{
// Landing may tilt a triangle by at most 30 degrees (the cosine): more, on a noisy target, and a
// small triangle is a step away from turning over. Nor may it shrink one to less than a quarter
// of its area: a sliver's normal is a rounding error away from turning over (the noisy turned
// head's one triangle turned over was landed to a 2,000th of its true area).
constexpr double LandingTilt = 0.8660;
constexpr double LandingShrink = 0.25;
// A sliver: a triangle whose height over its longest edge is under this share of it.
constexpr double SliverHeight = 0.05;

// Each polygon's normal times its area (a fan's sum): a collapsed polygon's is zero.
std::vector<std::array<double, 3>> AreaNormals(vtkPolyData* shape)
{
  std::vector<std::array<double, 3>> normals(shape->GetNumberOfPolys());
  vtkIdType count = 0;
  const vtkIdType* ids = nullptr;
  const vtkIdType firstPolygon = shape->GetNumberOfVerts() + shape->GetNumberOfLines();
  for (vtkIdType c = 0; c < shape->GetNumberOfPolys(); ++c)
  {
    shape->GetCellPoints(firstPolygon + c, count, ids);
    std::array<double, 3>& n = normals[c];
    n = { { 0.0, 0.0, 0.0 } };
    double origin[3];
    shape->GetPoint(ids[0], origin); // near the polygon, for its digits
    for (vtkIdType k = 1; k + 1 < count; ++k)
    {
      double a[3], b[3], cross[3];
      shape->GetPoint(ids[k], a);
      shape->GetPoint(ids[k + 1], b);
      vtkMath::Subtract(a, origin, a);
      vtkMath::Subtract(b, origin, b);
      vtkMath::Cross(a, b, cross);
      for (int axis = 0; axis < 3; ++axis)
      {
        n[axis] += 0.5 * cross[axis];
      }
    }
  }
  return normals;
}
}

void FoldGuard::Remember(vtkPolyData* shape)
{
  this->Normals = AreaNormals(shape);
}

int FoldGuard::Check(vtkPolyData* shape)
{
  const std::vector<std::array<double, 3>> now = AreaNormals(shape);
  if (now.size() != this->Normals.size())
  {
    return 0;
  }
  int added = 0;
  vtkIdType count = 0;
  const vtkIdType* ids = nullptr;
  const vtkIdType firstPolygon = shape->GetNumberOfVerts() + shape->GetNumberOfLines();
  for (std::size_t c = 0; c < now.size(); ++c)
  {
    if (vtkMath::Dot(now[c].data(), this->Normals[c].data()) >= 0.0)
    {
      continue;
    }
    shape->GetCellPoints(firstPolygon + static_cast<vtkIdType>(c), count, ids);
    for (vtkIdType k = 0; k < count; ++k)
    {
      added += this->SetAside[ids[k]] == 0;
      this->SetAside[ids[k]] = 1;
    }
  }
  return added;
}

int FoldGuard::Land(vtkPolyData* shape, const std::vector<std::array<double, 3>>& targets,
  const std::vector<char>& allowed) const
{
  const std::vector<std::array<double, 3>> before = AreaNormals(shape);
  // Held: the shape lets go of its points when it takes the landed ones.
  vtkSmartPointer<vtkPoints> kept = shape->GetPoints();
  vtkNew<vtkPoints> landed;
  landed->SetDataTypeToDouble();
  landed->SetNumberOfPoints(kept->GetNumberOfPoints());
  std::vector<char> moved(kept->GetNumberOfPoints(), 0);
  for (vtkIdType i = 0; i < kept->GetNumberOfPoints(); ++i)
  {
    moved[i] = allowed[i] && !this->SetAside[i];
    landed->SetPoint(i, moved[i] ? targets[i].data() : kept->GetPoint(i));
  }
  shape->SetPoints(landed);
  // A triangle that turns over, tilts too far or shrinks too far keeps its corners where they were; the triangles
  // around them then change again, so until none does (each pass only puts points back).
  vtkIdType count = 0;
  const vtkIdType* ids = nullptr;
  const vtkIdType firstPolygon = shape->GetNumberOfVerts() + shape->GetNumberOfLines();
  for (bool reverted = true; reverted;)
  {
    reverted = false;
    const std::vector<std::array<double, 3>> now = AreaNormals(shape);
    for (std::size_t c = 0; c < now.size(); ++c)
    {
      const double turn = vtkMath::Dot(now[c].data(), before[c].data());
      const double area = vtkMath::Norm(now[c].data()), rest = vtkMath::Norm(before[c].data());
      if (rest == 0.0 || (turn > LandingTilt * area * rest && area >= LandingShrink * rest))
      {
        continue;
      }
      shape->GetCellPoints(firstPolygon + static_cast<vtkIdType>(c), count, ids);
      for (vtkIdType k = 0; k < count; ++k)
      {
        if (moved[ids[k]])
        {
          moved[ids[k]] = 0;
          landed->SetPoint(ids[k], kept->GetPoint(ids[k]));
          reverted = true;
        }
      }
    }
  }
  return static_cast<int>(std::count(moved.begin(), moved.end(), 1));
}

int FoldGuard::MendSlivers(vtkPolyData* rest, vtkPolyData* shape) const
{
  const std::vector<std::array<double, 3>> now = AreaNormals(shape);
  if (now.size() != this->Normals.size() || rest->GetNumberOfPoints() != shape->GetNumberOfPoints())
  {
    return 0;
  }
  vtkIdType count = 0;
  const vtkIdType* ids = nullptr;
  const vtkIdType firstPolygon = shape->GetNumberOfVerts() + shape->GetNumberOfLines();
  auto turned = [&](std::size_t c) { return vtkMath::Dot(now[c].data(), this->Normals[c].data()) < 0.0; };
  // The candidates, checked against the rest shape below; most fits have none.
  std::vector<std::size_t> slivers;
  for (std::size_t c = 0; c < now.size(); ++c)
  {
    if (turned(c))
    {
      slivers.push_back(c);
    }
  }
  if (slivers.empty())
  {
    return 0;
  }
  // Around each point, the area normals of the polygons that did not turn over: the side a
  // mended sliver faces.
  std::vector<std::array<double, 3>> around(shape->GetNumberOfPoints(), { { 0.0, 0.0, 0.0 } });
  for (std::size_t c = 0; c < now.size(); ++c)
  {
    if (turned(c))
    {
      continue;
    }
    shape->GetCellPoints(firstPolygon + static_cast<vtkIdType>(c), count, ids);
    for (vtkIdType k = 0; k < count; ++k)
    {
      vtkMath::Add(around[ids[k]].data(), now[c].data(), around[ids[k]].data());
    }
  }
  int mended = 0;
  vtkSmartPointer<vtkPoints> points;
  for (const std::size_t c : slivers)
  {
    shape->GetCellPoints(firstPolygon + static_cast<vtkIdType>(c), count, ids);
    if (count != 3)
    {
      continue;
    }
    // The base: the rest triangle's longest edge, from a to b in the triangle's order, so that
    // its normal is (b - a) x (apex - a).
    double r[3][3];
    for (int k = 0; k < 3; ++k)
    {
      rest->GetPoint(ids[k], r[k]);
    }
    int first = 0;
    for (int k = 1; k < 3; ++k)
    {
      if (vtkMath::Distance2BetweenPoints(r[k], r[(k + 1) % 3]) >
        vtkMath::Distance2BetweenPoints(r[first], r[(first + 1) % 3]))
      {
        first = k;
      }
    }
    const int second = (first + 1) % 3, apex = (first + 2) % 3;
    double base[3], offset[3];
    vtkMath::Subtract(r[second], r[first], base);
    vtkMath::Subtract(r[apex], r[first], offset);
    const double length2 = vtkMath::Dot(base, base);
    if (length2 == 0.0)
    {
      continue;
    }
    const double along = vtkMath::Dot(offset, base) / length2;
    double height[3] = { offset[0] - along * base[0], offset[1] - along * base[1], offset[2] - along * base[2] };
    const double restHeight = vtkMath::Norm(height);
    if (restHeight >= SliverHeight * std::sqrt(length2))
    {
      continue;
    }
    if (!points)
    {
      points = vtkSmartPointer<vtkPoints>::New();
      points->SetDataType(shape->GetPoints()->GetDataType()); // DeepCopy keeps its own type
      points->DeepCopy(shape->GetPoints());
    }
    double a[3], b[3], side[3], facing[3], edge[3];
    points->GetPoint(ids[first], a);
    points->GetPoint(ids[second], b);
    vtkMath::Subtract(b, a, edge);
    vtkMath::Add(around[ids[first]].data(), around[ids[second]].data(), facing);
    // (b - a) x side along the facing normal: side = facing x (b - a), perpendicular to the base.
    vtkMath::Cross(facing, edge, side);
    const double sideLength = vtkMath::Norm(side);
    if (sideLength == 0.0)
    {
      continue;
    }
    const double scale = restHeight * std::sqrt(vtkMath::Dot(edge, edge) / length2) / sideLength;
    double moved[3];
    for (int axis = 0; axis < 3; ++axis)
    {
      moved[axis] = a[axis] + along * edge[axis] + scale * side[axis];
    }
    points->SetPoint(ids[apex], moved);
    ++mended;
  }
  if (points)
  {
    shape->SetPoints(points);
  }
  return mended;
}

int FoldGuard::GetNumberOfSetAside() const
{
  return static_cast<int>(std::count(this->SetAside.begin(), this->SetAside.end(), 1));
}
}
}
