#include "FoldGuard.h"

#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkSmartPointer.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPolygon.h"

#include <algorithm>

namespace LaplacianEditing
{
namespace Pipeline
{
namespace
{
// Landing may tilt a triangle by at most 30 degrees (the cosine): more, on a noisy target, and a
// small triangle is a step away from turning over.
constexpr double LandingTilt = 0.8660;

std::vector<std::array<double, 3>> PolygonNormals(vtkPolyData* shape)
{
  std::vector<std::array<double, 3>> normals(shape->GetNumberOfPolys());
  vtkIdType count = 0;
  const vtkIdType* ids = nullptr;
  const vtkIdType firstPolygon = shape->GetNumberOfVerts() + shape->GetNumberOfLines();
  for (vtkIdType c = 0; c < shape->GetNumberOfPolys(); ++c)
  {
    shape->GetCellPoints(firstPolygon + c, count, ids);
    vtkPolygon::ComputeNormal(shape->GetPoints(), static_cast<int>(count), ids, normals[c].data());
  }
  return normals;
}
}

void FoldGuard::Remember(vtkPolyData* shape)
{
  this->Normals = PolygonNormals(shape);
}

int FoldGuard::Check(vtkPolyData* shape)
{
  const std::vector<std::array<double, 3>> now = PolygonNormals(shape);
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
  const std::vector<std::array<double, 3>> before = PolygonNormals(shape);
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
  // A triangle that turns over, tilts too far or collapses keeps its corners where they were; the triangles
  // around them then change again, so until none does (each pass only puts points back).
  vtkIdType count = 0;
  const vtkIdType* ids = nullptr;
  const vtkIdType firstPolygon = shape->GetNumberOfVerts() + shape->GetNumberOfLines();
  for (bool reverted = true; reverted;)
  {
    reverted = false;
    const std::vector<std::array<double, 3>> now = PolygonNormals(shape);
    for (std::size_t c = 0; c < now.size(); ++c)
    {
      const double turn = vtkMath::Dot(now[c].data(), before[c].data());
      if (vtkMath::Dot(before[c].data(), before[c].data()) == 0.0 ||
        turn > LandingTilt * vtkMath::Norm(now[c].data()) * vtkMath::Norm(before[c].data()))
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
