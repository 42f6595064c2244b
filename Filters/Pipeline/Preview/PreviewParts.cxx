#include "PreviewParts.h"

#include "CachedRangePoints.h"
#include "NormalRefresher.h"

#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkIdList.h"
#include "vtkPointData.h"
#include "vtkPoints.h"

#include <array>
#include <limits>
#include <unordered_map>

namespace le = LaplacianEditing;

namespace LaplacianEditing
{
namespace Pipeline
{

namespace
{
// A 3-component normals array of `attributes`, or none.
vtkDataArray* NormalsOf(vtkDataSetAttributes* attributes)
{
  vtkDataArray* normals = attributes->GetNormals();
  return normals && normals->GetNumberOfComponents() == 3 ? normals : nullptr;
}

// (min, max) per coordinate, none yet: (+inf, -inf).
std::array<double, 6> Extremes()
{
  const double inf = std::numeric_limits<double>::infinity();
  return { inf, -inf, inf, -inf, inf, -inf };
}

// Widens `extremes` to hold p (NaN coordinates are left out, as vtkDataArray's ranges do).
void Extend(std::array<double, 6>& extremes, const double p[3])
{
  for (int c = 0; c < 3; ++c)
  {
    extremes[2 * c] = p[c] < extremes[2 * c] ? p[c] : extremes[2 * c];
    extremes[2 * c + 1] = p[c] > extremes[2 * c + 1] ? p[c] : extremes[2 * c + 1];
  }
}
}

void PreviewParts::Build(
  vtkPolyData* rest, vtkPolyData* output, const OutputEdit& edit)
{
  this->BuildStill(rest, output, edit.Normals->GetCellIds());
  this->BuildMoving(output, edit);
  this->RegionVersion = edit.RegionVersion;
  this->Built = true;
}

void PreviewParts::BuildStill(
  vtkPolyData* rest, vtkPolyData* output, const std::vector<vtkIdType>& movingCells)
{
  // The rest surface's points and arrays, without the moving polygons.
  vtkPolyData* still = this->Still;
  still->Initialize();
  still->SetPoints(rest->GetPoints());
  still->GetPointData()->ShallowCopy(rest->GetPointData());
  if (vtkDataArray* roles = output->GetPointData()->GetArray("EditRole"))
  {
    auto fixed = vtk::TakeSmartPointer(roles->NewInstance());
    fixed->SetName("EditRole");
    fixed->SetNumberOfTuples(rest->GetNumberOfPoints());
    fixed->Fill(0.0); // every point of the still part is fixed
    fixed->SetLookupTable(roles->GetLookupTable());
    still->GetPointData()->AddArray(fixed);
  }
  // The output's active scalars (EditRole where the input had none), which a mapper colours by.
  if (vtkDataArray* scalars = output->GetPointData()->GetScalars())
  {
    still->GetPointData()->SetActiveScalars(scalars->GetName());
  }
  still->SetVerts(rest->GetVerts());
  still->SetLines(rest->GetLines());
  const vtkIdType firstPoly = rest->GetNumberOfVerts() + rest->GetNumberOfLines();
  std::vector<char> moving(rest->GetNumberOfPolys(), 0);
  for (const vtkIdType id : movingCells)
  {
    moving[id - firstPoly] = 1;
  }
  vtkNew<vtkCellArray> polys;
  if (rest->GetNumberOfPoints() < VTK_INT_MAX)
  {
    polys->Use32BitStorage(); // half the memory of the copy
  }
  polys->AllocateEstimate(rest->GetNumberOfPolys() - static_cast<vtkIdType>(movingCells.size()), 3);
  vtkNew<vtkIdList> kept; // the still part's cells in the rest surface's numbering
  for (vtkIdType c = 0; c < firstPoly; ++c)
  {
    kept->InsertNextId(c);
  }
  auto cells = vtk::TakeSmartPointer(rest->GetPolys()->NewIterator());
  for (cells->GoToFirstCell(); !cells->IsDoneWithTraversal(); cells->GoToNextCell())
  {
    if (!moving[cells->GetCurrentCellId()])
    {
      polys->InsertNextCell(cells->GetCurrentCell());
      kept->InsertNextId(firstPoly + cells->GetCurrentCellId());
    }
  }
  still->SetPolys(polys);
  if (rest->GetCellData()->GetNumberOfArrays() > 0)
  {
    vtkNew<vtkIdList> order;
    order->SetNumberOfIds(kept->GetNumberOfIds());
    for (vtkIdType c = 0; c < kept->GetNumberOfIds(); ++c)
    {
      order->SetId(c, c);
    }
    still->GetCellData()->CopyAllocate(rest->GetCellData(), kept->GetNumberOfIds());
    still->GetCellData()->CopyData(rest->GetCellData(), kept, order);
  }
}

void PreviewParts::BuildMoving(vtkPolyData* output, const OutputEdit& edit)
{
  // The moving polygons on a compact copy of their points: the normal refresher's first, then
  // any corner it does not index (the far corner of a quad).
  std::vector<vtkIdType> points = edit.Normals->GetPointIds();
  std::unordered_map<vtkIdType, vtkIdType> compact;
  for (std::size_t k = 0; k < points.size(); ++k)
  {
    compact.emplace(points[k], static_cast<vtkIdType>(k));
  }
  const vtkIdType firstPoly = output->GetNumberOfVerts() + output->GetNumberOfLines();
  vtkNew<vtkCellArray> polys;
  vtkNew<vtkIdList> corners;
  for (const vtkIdType id : edit.Normals->GetCellIds())
  {
    output->GetPolys()->GetCellAtId(id - firstPoly, corners);
    for (vtkIdType c = 0; c < corners->GetNumberOfIds(); ++c)
    {
      const auto added = compact.emplace(corners->GetId(c), static_cast<vtkIdType>(points.size()));
      if (added.second)
      {
        points.push_back(corners->GetId(c));
      }
      corners->SetId(c, added.first->second);
    }
    polys->InsertNextCell(corners);
  }
  std::unordered_map<vtkIdType, int> rowOfId;
  for (std::size_t i = 0; i < edit.Moved->Ids.size(); ++i)
  {
    rowOfId.emplace(edit.Moved->Ids[i], edit.Moved->Rows[i]);
  }
  vtkPolyData* moving = this->Moving;
  moving->Initialize();
  vtkNew<vtkPoints> positions;
  positions->SetDataType(output->GetPoints()->GetDataType());
  positions->SetNumberOfPoints(static_cast<vtkIdType>(points.size()));
  this->RowOfPoint.assign(points.size(), -1);
  vtkPointData* pointData = moving->GetPointData();
  pointData->CopyAllocate(output->GetPointData(), static_cast<vtkIdType>(points.size()));
  for (std::size_t k = 0; k < points.size(); ++k)
  {
    positions->SetPoint(static_cast<vtkIdType>(k), output->GetPoint(points[k]));
    pointData->CopyData(output->GetPointData(), points[k], static_cast<vtkIdType>(k));
    const auto row = rowOfId.find(points[k]);
    this->RowOfPoint[k] = row == rowOfId.end() ? -1 : row->second;
  }
  this->StillPointsExtremes = Extremes();
  for (std::size_t k = 0; k < points.size(); ++k)
  {
    if (this->RowOfPoint[k] < 0)
    {
      Extend(this->StillPointsExtremes, positions->GetPoint(static_cast<vtkIdType>(k)));
    }
  }
  moving->SetPoints(positions);
  moving->SetPolys(polys);
  vtkCellData* cellData = moving->GetCellData();
  const std::vector<vtkIdType>& cells = edit.Normals->GetCellIds();
  cellData->CopyAllocate(output->GetCellData(), static_cast<vtkIdType>(cells.size()));
  for (std::size_t j = 0; j < cells.size(); ++j)
  {
    cellData->CopyData(output->GetCellData(), cells[j], static_cast<vtkIdType>(j));
  }
}

void PreviewParts::Write(const OutputEdit& edit)
{
  vtkPoints* points = this->Moving->GetPoints();
  // The points' ranges as they are written, cached on their array: the mapper's bounds read
  // them, a pass over the part every frame otherwise.
  std::array<double, 6> extremes = this->StillPointsExtremes;
  for (std::size_t k = 0; k < this->RowOfPoint.size(); ++k)
  {
    if (this->RowOfPoint[k] >= 0)
    {
      const le::Vector3 p =
        edit.Solution->row(this->RowOfPoint[k]).transpose() / edit.Scale + edit.Center;
      points->SetPoint(static_cast<vtkIdType>(k), p.data());
      Extend(extremes, points->GetPoint(static_cast<vtkIdType>(k))); // as stored (float or double)
    }
  }
  points->Modified();
  if (extremes[0] <= extremes[1])
  {
    CachedRangePoints::StoreRanges(points->GetData(), extremes.data());
  }
  if (vtkDataArray* normals = NormalsOf(this->Moving->GetPointData()))
  {
    edit.Normals->WritePointNormals(
      normals, *edit.VertexRest, *edit.VertexRows, *edit.Solution, true);
    normals->Modified();
  }
  if (vtkDataArray* normals = NormalsOf(this->Moving->GetCellData()))
  {
    edit.Normals->WriteCellNormals(normals, *edit.VertexRest, *edit.VertexRows, *edit.Solution, true);
    normals->Modified();
  }
}

void PreviewParts::Release()
{
  this->Still->Initialize();
  this->Moving->Initialize();
  this->RowOfPoint.clear();
  this->Built = false;
}
}
}
