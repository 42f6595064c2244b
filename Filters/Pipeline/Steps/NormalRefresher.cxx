#include "NormalRefresher.h"

#include "SurfaceAdapter.h"

#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkSMPTools.h"
#include "vtkSmartPointer.h"

#include <algorithm>
#include <unordered_map>

namespace le = LaplacianEditing;

namespace LaplacianEditing
{
namespace Pipeline
{

namespace
{
// Writes normalOf(r), normalized, at tuple ids[r] (or r, `compact`) of `normals` (a
// 3-component array).
template <typename NormalOf>
void WriteNormals(
  vtkDataArray* normals, const std::vector<vtkIdType>& ids, bool compact, NormalOf normalOf)
{
  vtkSMPTools::For(0, static_cast<vtkIdType>(ids.size()), [&](vtkIdType begin, vtkIdType end) {
    for (vtkIdType r = begin; r < end; ++r)
    {
      const le::Vector3 n = normalOf(r).normalized();
      normals->SetTuple3(compact ? r : ids[r], n[0], n[1], n[2]);
    }
  });
}

// Vertex v's position: its solution row's, or its rest one outside the region.
struct PositionOf
{
  const std::vector<le::Vector3>& Rest;
  const std::vector<int>& RowOfVertex;
  const le::Positions& Solution;
  le::Vector3 operator()(int v) const
  {
    const int k = this->RowOfVertex[v];
    return k >= 0 ? le::Vector3(this->Solution.row(k).transpose()) : this->Rest[v];
  }
};
}

void NormalRefresher::Index(vtkPolyData* input, const SurfaceAdapter& surface)
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
  this->PointTriangleOffsets.assign(1, 0);
  this->PointTriangles.clear();
  this->TriangleVertices.clear();
  std::vector<int> slot(mesh.GetNumberOfTriangles(), -1);
  for (std::size_t i = 0; i < vertexOfPoint.size(); ++i)
  {
    const int v = vertexOfPoint[i];
    if (!near[v])
    {
      continue;
    }
    this->Points.push_back(surface.GetInputPoints()[i]);
    for (const int* t = mesh.TrianglesBegin(v); t != mesh.TrianglesEnd(v); ++t)
    {
      if (slot[*t] < 0)
      {
        slot[*t] = static_cast<int>(this->TriangleVertices.size() / 3);
        const auto& triangle = mesh.GetTriangles()[*t];
        this->TriangleVertices.insert(this->TriangleVertices.end(), triangle.begin(), triangle.end());
      }
      this->PointTriangles.push_back(slot[*t]);
    }
    this->PointTriangleOffsets.push_back(static_cast<int>(this->PointTriangles.size()));
  }
  // A polygon normal changes when one of its corners is in the ROI.
  this->Cells.clear();
  this->CellVertexOffsets.assign(1, 0);
  this->CellVertices.clear();
  // The input's polygons once more: the graph keeps no copy of them. A polygon with a corner in
  // the ROI was kept in the graph, so its corners all have vertices.
  const std::vector<int> pointOfInput = surface.GetPointOfInput(input->GetNumberOfPoints());
  auto vertexOfInput = [&](vtkIdType id) {
    const int point = pointOfInput[id];
    return point >= 0 ? vertexOfPoint[point] : -1;
  };
  vtkIdType cell = input->GetNumberOfVerts() + input->GetNumberOfLines();
  SurfaceAdapter::VisitPolygons(input, [&](vtkIdType size, const vtkIdType* ids) {
    if (std::any_of(ids, ids + size, [&](vtkIdType id) {
          const int v = vertexOfInput(id);
          return v >= 0 && rowOfVertex[v] >= 0;
        }))
    {
      this->Cells.push_back(cell);
      std::for_each(ids, ids + size, [&](vtkIdType id) { this->CellVertices.push_back(vertexOfInput(id)); });
      this->CellVertexOffsets.push_back(static_cast<int>(this->CellVertices.size()));
    }
    ++cell;
  });
  // Kept for the region's edit: grown piecemeal, they would hold up to twice their size.
  auto shrink = [](auto&... arrays) { (arrays.shrink_to_fit(), ...); };
  shrink(this->Points, this->PointTriangleOffsets, this->PointTriangles, this->TriangleVertices,
    this->Cells, this->CellVertexOffsets, this->CellVertices);
}

void NormalRefresher::WritePointNormals(vtkDataArray* normals,
  const std::vector<le::Vector3>& rest, const std::vector<int>& rowOfVertex,
  const le::Positions& solution, bool compact) const
{
  // Each triangle's (area-weighted) normal once, then their sums around each point.
  const PositionOf position{ rest, rowOfVertex, solution };
  std::vector<le::Vector3> triangleNormals(this->TriangleVertices.size() / 3);
  vtkSMPTools::For(0, static_cast<vtkIdType>(triangleNormals.size()),
    [&](vtkIdType begin, vtkIdType end) {
      for (vtkIdType s = begin; s < end; ++s)
      {
        const int* triangle = this->TriangleVertices.data() + 3 * s;
        const le::Vector3 origin = position(triangle[0]);
        triangleNormals[s] = (position(triangle[1]) - origin).cross(position(triangle[2]) - origin);
      }
    });
  WriteNormals(normals, this->Points, compact, [&](vtkIdType r) {
    le::Vector3 n = le::Vector3::Zero();
    for (int j = this->PointTriangleOffsets[r]; j < this->PointTriangleOffsets[r + 1]; ++j)
    {
      n += triangleNormals[this->PointTriangles[j]];
    }
    return n;
  });
}

void NormalRefresher::WriteCellNormals(vtkDataArray* normals,
  const std::vector<le::Vector3>& rest, const std::vector<int>& rowOfVertex,
  const le::Positions& solution, bool compact) const
{
  const PositionOf position{ rest, rowOfVertex, solution };
  WriteNormals(normals, this->Cells, compact, [&](vtkIdType r) {
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

NormalRefresher NormalRefresher::Restrict(
  const std::function<vtkIdType(vtkIdType)>& pointId,
  const std::function<vtkIdType(vtkIdType)>& cellId, std::vector<int>& vertices) const
{
  NormalRefresher part;
  vertices.clear();
  std::unordered_map<int, int> number;
  auto renumber = [&](int v) {
    const auto added = number.emplace(v, static_cast<int>(vertices.size()));
    if (added.second)
    {
      vertices.push_back(v);
    }
    return added.first->second;
  };
  std::vector<int> slot(this->TriangleVertices.size() / 3, -1);
  part.PointTriangleOffsets.assign(1, 0);
  for (std::size_t r = 0; r < this->Points.size(); ++r)
  {
    const vtkIdType id = pointId(this->Points[r]);
    if (id < 0)
    {
      continue;
    }
    part.Points.push_back(id);
    for (int j = this->PointTriangleOffsets[r]; j < this->PointTriangleOffsets[r + 1]; ++j)
    {
      const int s = this->PointTriangles[j];
      if (slot[s] < 0)
      {
        slot[s] = static_cast<int>(part.TriangleVertices.size() / 3);
        for (int c = 0; c < 3; ++c)
        {
          part.TriangleVertices.push_back(renumber(this->TriangleVertices[3 * s + c]));
        }
      }
      part.PointTriangles.push_back(slot[s]);
    }
    part.PointTriangleOffsets.push_back(static_cast<int>(part.PointTriangles.size()));
  }
  part.CellVertexOffsets.assign(1, 0);
  for (std::size_t r = 0; r + 1 < this->CellVertexOffsets.size(); ++r)
  {
    const vtkIdType id = cellId(this->Cells[r]);
    if (id < 0)
    {
      continue;
    }
    part.Cells.push_back(id);
    for (int j = this->CellVertexOffsets[r]; j < this->CellVertexOffsets[r + 1]; ++j)
    {
      part.CellVertices.push_back(renumber(this->CellVertices[j]));
    }
    part.CellVertexOffsets.push_back(static_cast<int>(part.CellVertices.size()));
  }
  return part;
}
}
}
