#include "OutputWriter.h"

#include "EditRegion.h"
#include "NormalRefresher.h"

#include "vtkAlgorithm.h"
#include "vtkArrayDispatch.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkDataArrayRange.h"
#include "vtkExecutive.h"
#include "vtkInformationExecutivePortVectorKey.h"
#include "vtkInformation.h"
#include "vtkLookupTable.h"
#include "vtkPointData.h"
#include "vtkPointSet.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSMPTools.h"
#include "vtkSignedCharArray.h"
#include "vtkVariant.h"

#include <algorithm>
#include <numeric>


namespace le = LaplacianEditing;

namespace LaplacianEditing
{
namespace Pipeline
{

namespace
{
// The roles' colours as in the paper's Fig. 2 (fixed grey, anchors red, free green, handle
// yellow), as an indexed table, annotated with the roles' names for colour legends.
vtkSmartPointer<vtkLookupTable> NewRoleColors()
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

// References to `object` held by `data` (see CountDownstreamReferences).
int CountReferences(vtkDataObject* data, vtkObjectBase* object, vtkObjectBase* ownPoints)
{
  auto* dataSet = vtkDataSet::SafeDownCast(data);
  if (!dataSet)
  {
    return 0;
  }
  int count = 0;
  if (auto* pointSet = vtkPointSet::SafeDownCast(dataSet))
  {
    vtkPoints* points = pointSet->GetPoints();
    count += points && (points == object || (points != ownPoints && points->GetData() == object));
  }
  for (vtkFieldData* fields : { static_cast<vtkFieldData*>(dataSet->GetPointData()),
         static_cast<vtkFieldData*>(dataSet->GetCellData()) })
  {
    for (int i = 0; i < fields->GetNumberOfArrays(); ++i)
    {
      count += fields->GetAbstractArray(i) == object;
    }
  }
  return count;
}

// The normals array of `attributes` the writer refreshes: three components, or none.
vtkDataArray* RestNormals(vtkDataSetAttributes* attributes)
{
  vtkDataArray* normals = attributes->GetNormals();
  return normals && normals->GetNumberOfComponents() == 3 ? normals : nullptr;
}
}

void OutputWriter::Write(
  vtkPolyData* rest, vtkPolyData* output, const Edit* edit, const OutputOptions& options)
{
  static const std::vector<vtkIdType> none;
  const std::uint64_t key = ++this->Writes;
  const std::vector<vtkIdType>& moved = edit ? edit->Moved->Ids : none;
  output->SetPoints(this->Points.Update(rest->GetPoints(), moved, key, [&](vtkDataArray* points) {
    this->OrderByRows(*edit);
    OutputArray::SetTuples<3>(points, this->RowOrderedIds, [&](vtkIdType j, double* p) {
      le::Vector3 position =
        edit->Solution->row(this->RowOrderedRows[j]).transpose() / edit->Scale + edit->Center;
      if (!this->RowOrderedOffsets.empty())
      {
        position += this->RowOrderedOffsets[j];
      }
      std::copy(position.data(), position.data() + 3, p);
    }, this->Points.WriteExtremes());
  }));
  const NormalRefresher* normals = edit ? edit->Normals : nullptr;
  if (vtkDataArray* pointNormals = RestNormals(rest->GetPointData()))
  {
    output->GetPointData()->SetNormals(this->PointNormals.Update(pointNormals,
      normals ? normals->GetPointIds() : none, key, [&](vtkDataArray* array) {
        normals->WritePointNormals(array, *edit->VertexRest, *edit->VertexRows, *edit->Solution);
      }));
  }
  if (vtkDataArray* cellNormals = RestNormals(rest->GetCellData()))
  {
    output->GetCellData()->SetNormals(this->CellNormals.Update(cellNormals,
      normals ? normals->GetCellIds() : none, key, [&](vtkDataArray* array) {
        normals->WriteCellNormals(array, *edit->VertexRest, *edit->VertexRows, *edit->Solution);
      }));
  }
  if (options.Displacement)
  {
    output->GetPointData()->AddArray(
      this->Displacement.Update(rest->GetPoints(), output->GetPoints(), moved, key));
  }
  if (!options.Roles)
  {
    return;
  }
  vtkDataArray* editRoles = this->UpdateRoles(rest->GetNumberOfPoints(), edit);
  if (!this->RoleColors)
  {
    this->RoleColors = NewRoleColors();
  }
  editRoles->SetLookupTable(options.RoleColors ? this->RoleColors.Get() : nullptr);
  vtkPointData* pointData = output->GetPointData();
  pointData->AddArray(editRoles);
  if (!pointData->GetScalars())
  {
    pointData->SetActiveScalars("EditRole"); // a default mapper then shows the roles
  }
}

void OutputWriter::OrderByRows(const Edit& edit)
{
  const MovedPoints& moved = *edit.Moved;
  if (this->RowOrderVersion == edit.RegionVersion && this->RowOrderedIds.size() == moved.Ids.size())
  {
    return;
  }
  std::vector<int> order(moved.Rows.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(
    order.begin(), order.end(), [&](int a, int b) { return moved.Rows[a] < moved.Rows[b]; });
  this->RowOrderedIds.resize(order.size());
  this->RowOrderedRows.resize(order.size());
  this->RowOrderedOffsets.resize(moved.Offsets.empty() ? 0 : order.size());
  for (std::size_t j = 0; j < order.size(); ++j)
  {
    this->RowOrderedIds[j] = moved.Ids[order[j]];
    this->RowOrderedRows[j] = moved.Rows[order[j]];
    if (!moved.Offsets.empty())
    {
      this->RowOrderedOffsets[j] = moved.Offsets[order[j]];
    }
  }
  this->RowOrderVersion = edit.RegionVersion;
}

vtkDataArray* OutputWriter::UpdateRoles(vtkIdType count, const Edit* edit)
{
  if (!this->FixedRoles || this->FixedRoles->GetNumberOfTuples() != count)
  {
    this->FixedRoles = vtkSmartPointer<vtkSignedCharArray>::New();
    this->FixedRoles->SetName("EditRole");
    this->FixedRoles->SetNumberOfTuples(count);
    this->FixedRoles->FillValue(static_cast<signed char>(le::VertexRole::Fixed));
  }
  static const std::vector<vtkIdType> none;
  const std::vector<vtkIdType>& moved = edit ? edit->Moved->Ids : none;
  return this->Roles.Update(this->FixedRoles, moved, edit ? edit->RegionVersion : 0,
    [&](vtkDataArray* array) {
      auto* roles = vtkArrayDownCast<vtkSignedCharArray>(array);
      for (std::size_t i = 0; i < moved.size(); ++i)
      {
        roles->SetValue(moved[i], edit->Moved->Roles[i]);
      }
    });
}

int OutputWriter::CountDownstreamReferences(
  vtkAlgorithm* filter, vtkObjectBase* object, vtkObjectBase* ownPoints)
{
  // The filters connected to port 0 (one level: ParaView's pass-through filter; a deeper
  // consumer holds the arrays through it).
  vtkInformation* info = filter && filter->GetNumberOfOutputPorts() > 0
    ? filter->GetExecutive()->GetOutputInformation(0)
    : nullptr;
  const int consumers = info ? vtkExecutive::CONSUMERS()->Length(info) : 0;
  vtkExecutive** executives = consumers ? vtkExecutive::CONSUMERS()->GetExecutives(info) : nullptr;
  int count = 0;
  for (int c = 0; c < consumers; ++c)
  {
    vtkExecutive* consumer = executives[c];
    for (int p = 0; consumer && consumer->GetAlgorithm() && p < consumer->GetNumberOfOutputPorts(); ++p)
    {
      count += CountReferences(consumer->GetOutputData(p), object, ownPoints);
    }
  }
  return count;
}

OutputArray::Holders OutputWriter::PipelineHolders(vtkAlgorithm* filter)
{
  return [filter](vtkObjectBase* object, vtkObjectBase* ownPoints) {
    return CountDownstreamReferences(filter, object, ownPoints);
  };
}

void OutputWriter::SetFilter(vtkAlgorithm* filter)
{
  const OutputArray::Holders holders = PipelineHolders(filter);
  for (OutputArray* array : { &this->Points, &this->PointNormals, &this->CellNormals, &this->Roles })
  {
    array->SetPipelineHolders(holders);
  }
  this->Displacement.SetPipelineHolders(holders);
}

vtkIdType OutputWriter::GetNumberOfCopies() const
{
  return this->Points.GetNumberOfCopies() + this->PointNormals.GetNumberOfCopies() +
    this->CellNormals.GetNumberOfCopies() + this->Roles.GetNumberOfCopies();
}
}
}
