#include "vtkLaplacianNormalRefresher.h"

#include "vtkLaplacianSurfaceAdapter.h"

#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkSMPTools.h"
#include "vtkSmartPointer.h"

#include <algorithm>

namespace le = LaplacianEditing;

namespace
{
// Copies a normals array and recomputes the tuples listed in `ids`.
template <typename NormalOf>
void RefreshNormalsArray(vtkDataSetAttributes* attributes, const std::vector<vtkIdType>& ids,
  NormalOf normalOf)
{
  vtkDataArray* stale = attributes->GetNormals();
  if (!stale || stale->GetNumberOfComponents() != 3)
  {
    return;
  }
  vtkSmartPointer<vtkDataArray> fresh = vtk::TakeSmartPointer(stale->NewInstance());
  fresh->DeepCopy(stale);
  vtkSMPTools::For(0, static_cast<vtkIdType>(ids.size()), [&](vtkIdType begin, vtkIdType end) {
    for (vtkIdType r = begin; r < end; ++r)
    {
      const le::Vector3 n = normalOf(r).normalized();
      fresh->SetTuple3(ids[r], n[0], n[1], n[2]);
    }
  });
  attributes->SetNormals(fresh);
}
}

void vtkLaplacianNormalRefresher::Index(vtkPolyData* input, const vtkLaplacianSurfaceAdapter& surface)
{
  // A vertex normal changes when a vertex of an incident triangle moves: the ROI and its ring.
  const le::SurfaceMesh& mesh = *surface.GetMesh();
  const std::vector<int>& rowOfVertex = surface.GetRowOfVertex();
  const auto& vertexOfPoint = mesh.GetVertexOfPoint();
  std::vector<char> near(mesh.GetNumberOfVertices(), 0);
  for (int v = 0; v < mesh.GetNumberOfVertices(); ++v)
  {
    if (rowOfVertex[v] >= 0)
    {
      near[v] = 1;
      std::for_each(mesh.NeighborsBegin(v), mesh.NeighborsEnd(v), [&](int w) { near[w] = 1; });
    }
  }
  this->Points.clear();
  this->PointVertices.clear();
  for (std::size_t i = 0; i < vertexOfPoint.size(); ++i)
  {
    if (near[vertexOfPoint[i]])
    {
      this->Points.push_back(surface.GetInputPoints()[i]);
      this->PointVertices.push_back(vertexOfPoint[i]);
    }
  }
  this->Triangles.clear();
  this->TriangleSlot.assign(mesh.GetNumberOfTriangles(), -1);
  for (int v = 0; v < mesh.GetNumberOfVertices(); ++v)
  {
    for (const int* t = mesh.TrianglesBegin(v); near[v] && t != mesh.TrianglesEnd(v); ++t)
    {
      if (this->TriangleSlot[*t] < 0)
      {
        this->TriangleSlot[*t] = static_cast<int>(this->Triangles.size());
        this->Triangles.push_back(*t);
      }
    }
  }
  // A polygon normal changes when one of its corners is in the ROI.
  this->Cells.clear();
  this->CellVertexOffsets.assign(1, 0);
  this->CellVertices.clear();
  const vtkIdType firstPoly = input->GetNumberOfVerts() + input->GetNumberOfLines();
  const auto& offsets = surface.GetPolygonOffsets();
  const auto& corners = surface.GetPolygonConnectivity();
  for (std::size_t c = 0; c + 1 < offsets.size(); ++c)
  {
    const auto first = corners.begin() + offsets[c];
    const auto last = corners.begin() + offsets[c + 1];
    if (std::any_of(first, last, [&](std::int64_t p) { return rowOfVertex[vertexOfPoint[p]] >= 0; }))
    {
      this->Cells.push_back(firstPoly + surface.GetInputPolygons()[c]);
      std::for_each(first, last, [&](std::int64_t p) { this->CellVertices.push_back(vertexOfPoint[p]); });
      this->CellVertexOffsets.push_back(static_cast<int>(this->CellVertices.size()));
    }
  }
}

void vtkLaplacianNormalRefresher::Refresh(vtkPolyData* output, const le::SurfaceMesh& mesh,
  const std::vector<int>& rowOfVertex, const le::Positions& solution) const
{
  // The moved position of a vertex is its ROI row's.
  const std::vector<le::Vector3>& rest = mesh.GetPositions();
  auto position = [&](int v) -> le::Vector3 {
    const int k = rowOfVertex[v];
    return k >= 0 ? le::Vector3(solution.row(k).transpose()) : rest[v];
  };
  if (output->GetPointData()->GetNormals())
  {
    // Each triangle's (area-weighted) normal once, then their sums around each point.
    std::vector<le::Vector3> triangleNormals(this->Triangles.size());
    vtkSMPTools::For(0, static_cast<vtkIdType>(triangleNormals.size()),
      [&](vtkIdType begin, vtkIdType end) {
        for (vtkIdType s = begin; s < end; ++s)
        {
          const auto& tri = mesh.GetTriangles()[this->Triangles[s]];
          triangleNormals[s] =
            (position(tri[1]) - position(tri[0])).cross(position(tri[2]) - position(tri[0]));
        }
      });
    RefreshNormalsArray(output->GetPointData(), this->Points, [&](vtkIdType r) {
      const int v = this->PointVertices[r];
      le::Vector3 n = le::Vector3::Zero();
      for (const int* t = mesh.TrianglesBegin(v); t != mesh.TrianglesEnd(v); ++t)
      {
        n += triangleNormals[this->TriangleSlot[*t]];
      }
      return n;
    });
  }
  RefreshNormalsArray(output->GetCellData(), this->Cells, [&](vtkIdType r) {
    const int* corners = this->CellVertices.data() + this->CellVertexOffsets[r];
    const int size = this->CellVertexOffsets[r + 1] - this->CellVertexOffsets[r];
    le::Vector3 n = le::Vector3::Zero();
    for (int c = 1; c + 1 < size; ++c)
    {
      n += (position(corners[c]) - position(corners[0]))
             .cross(position(corners[c + 1]) - position(corners[0]));
    }
    return n;
  });
}
