#include "vtkLaplacianSurfaceAdapter.h"

#include "SurfaceMesh.h"

#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkDataArray.h"
#include "vtkLinearTransform.h"
#include "vtkLookupTable.h"
#include "vtkMatrix4x4.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSMPTools.h"
#include "vtkSignedCharArray.h"
#include "vtkVariant.h"

#include <algorithm>
#include <cmath>

namespace le = LaplacianEditing;

namespace
{
// The roles' colours as in the paper's Fig. 2 (fixed grey, anchors red, free green, handle
// yellow), as an indexed table the array carries: a plain vtkPolyDataMapper colours by it with
// its default settings.
vtkSmartPointer<vtkLookupTable> RoleColors()
{
  auto table = vtkSmartPointer<vtkLookupTable>::New();
  const struct
  {
    const char* Name;
    double Color[3];
  } roles[] = { { "fixed", { 0.75, 0.75, 0.75 } }, { "anchor", { 0.85, 0.20, 0.15 } },
    { "free", { 0.35, 0.75, 0.35 } }, { "handle", { 0.95, 0.85, 0.10 } } };
  table->IndexedLookupOn();
  table->SetNumberOfTableValues(4);
  for (int role = 0; role < 4; ++role)
  {
    table->SetTableValue(role, roles[role].Color[0], roles[role].Color[1], roles[role].Color[2]);
    table->SetAnnotation(vtkVariant(role), roles[role].Name);
  }
  return table;
}
}

std::string vtkLaplacianSurfaceAdapter::Build(vtkPolyData* input, bool mergeCoincidentPoints)
{
  this->Mesh.reset();
  const vtkIdType numberOfPoints = input->GetNumberOfPoints();
  for (vtkIdType i = 0; i < numberOfPoints; ++i)
  {
    const double* p = input->GetPoint(i);
    if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2]))
    {
      return "Point " + std::to_string(i) + " has a NaN or infinite coordinate.";
    }
  }
  double bounds[6];
  input->GetBounds(bounds);
  this->Center = le::Vector3(
    0.5 * (bounds[0] + bounds[1]), 0.5 * (bounds[2] + bounds[3]), 0.5 * (bounds[4] + bounds[5]));
  const double diagonal =
    le::Vector3(bounds[1] - bounds[0], bounds[3] - bounds[2], bounds[5] - bounds[4]).norm();
  if (!(diagonal > 0.0))
  {
    return "All input points coincide: there is no surface to edit.";
  }
  this->Scale = 1.0 / diagonal;

  std::vector<le::Vector3> points(numberOfPoints);
  for (vtkIdType i = 0; i < numberOfPoints; ++i)
  {
    points[i] = this->Normalize(input->GetPoint(i));
  }
  std::vector<std::int64_t> offsets, connectivity;
  vtkLaplacianSurfaceAdapter::GetPolygons(input, offsets, connectivity);
  auto mesh = std::make_shared<le::SurfaceMesh>(
    le::SurfaceMesh::FromPolygons(points, offsets, connectivity, mergeCoincidentPoints));
  if (mesh->GetNumberOfTriangles() == 0)
  {
    return "The input polygons are all degenerate: no triangle has three distinct corners.";
  }
  this->Mesh = std::move(mesh);
  return {};
}

void vtkLaplacianSurfaceAdapter::GetPolygons(
  vtkPolyData* input, std::vector<std::int64_t>& offsets, std::vector<std::int64_t>& connectivity)
{
  offsets.assign(1, 0);
  connectivity.clear();
  auto cells = vtk::TakeSmartPointer(input->GetPolys()->NewIterator());
  for (cells->GoToFirstCell(); !cells->IsDoneWithTraversal(); cells->GoToNextCell())
  {
    vtkIdType size;
    const vtkIdType* ids;
    cells->GetCurrentCell(size, ids);
    connectivity.insert(connectivity.end(), ids, ids + size);
    offsets.push_back(static_cast<std::int64_t>(connectivity.size()));
  }
}

le::Vector3 vtkLaplacianSurfaceAdapter::Normalize(const double p[3]) const
{
  return (le::Vector3(p[0], p[1], p[2]) - this->Center) * this->Scale;
}

le::Vector3 vtkLaplacianSurfaceAdapter::Denormalize(const le::Vector3& p) const
{
  return p / this->Scale + this->Center;
}

le::AffineMap vtkLaplacianSurfaceAdapter::NormalizedMap(vtkLinearTransform* transform) const
{
  transform->Update();
  vtkMatrix4x4* m = transform->GetMatrix();
  Eigen::Matrix3d linear;
  Eigen::Vector3d translation;
  for (int r = 0; r < 3; ++r)
  {
    for (int c = 0; c < 3; ++c)
    {
      linear(r, c) = m->GetElement(r, c);
    }
    translation[r] = m->GetElement(r, 3);
  }
  le::AffineMap map;
  map.leftCols<3>() = linear;
  map.col(3) = this->Scale * (linear * this->Center + translation - this->Center);
  return map;
}

std::vector<int> vtkLaplacianSurfaceAdapter::VertexLabels(vtkDataArray* selection) const
{
  const auto& vertexOfPoint = this->Mesh->GetVertexOfPoint();
  std::vector<int> labels(this->Mesh->GetNumberOfVertices(), 0);
  for (vtkIdType i = 0; i < static_cast<vtkIdType>(vertexOfPoint.size()); ++i)
  {
    int& label = labels[vertexOfPoint[i]];
    label = std::max(label, static_cast<int>(selection->GetComponent(i, 0)));
  }
  return labels;
}

void vtkLaplacianSurfaceAdapter::IndexRegion(const le::EditRegion& region)
{
  const auto& vertexOfPoint = this->Mesh->GetVertexOfPoint();
  const vtkIdType numberOfPoints = static_cast<vtkIdType>(vertexOfPoint.size());
  this->RowOfVertex.assign(this->Mesh->GetNumberOfVertices(), -1);
  for (int k = 0; k < region.GetNumberOfVertices(); ++k)
  {
    this->RowOfVertex[region.Vertices[k]] = k;
  }
  this->RoiPoints.clear();
  this->Roles = NewRoles(numberOfPoints);
  for (vtkIdType i = 0; i < numberOfPoints; ++i)
  {
    const int k = this->RowOfVertex[vertexOfPoint[i]];
    if (k >= 0)
    {
      this->RoiPoints.emplace_back(i, k);
    }
    this->Roles->SetValue(
      i, static_cast<signed char>(k >= 0 ? region.Roles[k] : le::VertexRole::Fixed));
  }
}

vtkSmartPointer<vtkSignedCharArray> vtkLaplacianSurfaceAdapter::NewRoles(vtkIdType count)
{
  auto roles = vtkSmartPointer<vtkSignedCharArray>::New();
  roles->SetName("EditRole");
  roles->SetLookupTable(RoleColors());
  roles->SetNumberOfTuples(count);
  roles->FillValue(static_cast<signed char>(le::VertexRole::Fixed));
  return roles;
}

vtkSmartPointer<vtkPoints> vtkLaplacianSurfaceAdapter::MovePoints(
  vtkPoints* points, const le::Positions& solution) const
{
  // Every point outside the region keeps its input coordinates exactly.
  auto moved = vtkSmartPointer<vtkPoints>::New();
  moved->SetDataType(points->GetDataType());
  moved->DeepCopy(points);
  const auto& roiPoints = this->RoiPoints;
  vtkSMPTools::For(0, static_cast<vtkIdType>(roiPoints.size()), [&](vtkIdType begin, vtkIdType end) {
    for (vtkIdType r = begin; r < end; ++r)
    {
      const le::Vector3 p = this->Denormalize(solution.row(roiPoints[r].second).transpose());
      moved->SetPoint(roiPoints[r].first, p.data());
    }
  });
  return moved;
}
