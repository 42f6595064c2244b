#include "FoldGuard.h"

#include "vtkMath.h"
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

int FoldGuard::GetNumberOfSetAside() const
{
  return static_cast<int>(std::count(this->SetAside.begin(), this->SetAside.end(), 1));
}
}
}
