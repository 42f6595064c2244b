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

int FoldGuard::GetNumberOfSetAside() const
{
  return static_cast<int>(std::count(this->SetAside.begin(), this->SetAside.end(), 1));
}
}
}
