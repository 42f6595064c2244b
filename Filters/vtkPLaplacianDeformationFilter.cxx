#include "vtkPLaplacianDeformationFilter.h"

#include "vtkAppendPolyData.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkInformationVector.h"
#include "vtkIntArray.h"
#include "vtkMultiProcessController.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSelection.h"
#include "vtkLaplacianSurfaceAdapter.h"
#include "vtkSignedCharArray.h"

vtkStandardNewMacro(vtkPLaplacianDeformationFilter);
vtkCxxSetObjectMacro(vtkPLaplacianDeformationFilter, Controller, vtkMultiProcessController);

namespace
{
const int PointsTag = 40501;
// The point array that carries each piece's selection labels to the first rank.
const char* const GatheredLabels = "vtkLaplacianSelectionLabels";
}

vtkPLaplacianDeformationFilter::vtkPLaplacianDeformationFilter()
{
  this->SetController(vtkMultiProcessController::GetGlobalController());
}

vtkPLaplacianDeformationFilter::~vtkPLaplacianDeformationFilter()
{
  this->SetController(nullptr);
}

int vtkPLaplacianDeformationFilter::RequestData(
  vtkInformation* request, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  if (!this->Controller || this->Controller->GetNumberOfProcesses() < 2)
  {
    return this->Superclass::RequestData(request, inputVector, outputVector);
  }
  vtkPolyData* input = vtkPolyData::GetData(inputVector[0]);
  vtkPolyData* output = vtkPolyData::GetData(outputVector);
  vtkSelection* selection =
    this->GetNumberOfInputConnections(1) > 0 ? vtkSelection::GetData(inputVector[1]) : nullptr;
  vtkNew<vtkPolyData> edited;
  if (this->GatherPieces(input, selection))
  {
    this->EditSurface(this->Gathered, edited);
  }
  this->ScatterPoints(input, edited, output);
  return 1;
}

bool vtkPLaplacianDeformationFilter::GatherPieces(vtkPolyData* input, vtkSelection* selection)
{
  // Geometry travels only when some piece or selection changed.
  vtkMultiProcessController* controller = this->Controller;
  const int ranks = controller->GetNumberOfProcesses();
  const int rank = controller->GetLocalProcessId();
  const bool first = rank == 0;
  const double localTimes[2] = { static_cast<double>(vtkLaplacianSurfaceAdapter::GetContentTime(input)),
    selection ? static_cast<double>(selection->GetMTime()) : 0.0 };
  std::vector<double> times(2 * ranks, 0.0);
  controller->Gather(localTimes, times.data(), 2, 0);
  double changed = first && (times != this->PieceTimes || !this->Gathered) ? 1.0 : 0.0;
  controller->Broadcast(&changed, 1, 0);
  if (changed != 0.0)
  {
    vtkNew<vtkPolyData> local;
    local->ShallowCopy(input);
    if (selection)
    {
      vtkSmartPointer<vtkIntArray> labels = LabelSelection(input, selection, rank);
      labels->SetName(GatheredLabels);
      local->GetPointData()->AddArray(labels);
    }
    std::vector<vtkSmartPointer<vtkDataObject>> pieces;
    controller->Gather(local, pieces, 0);
    if (first)
    {
      vtkNew<vtkAppendPolyData> append;
      this->PieceSizes.assign(ranks, 0);
      this->PieceCellSizes.assign(ranks, 0);
      this->OnlyPolygons = true;
      for (int r = 0; r < ranks; ++r)
      {
        if (auto* piece = vtkPolyData::SafeDownCast(pieces[r]))
        {
          this->PieceSizes[r] = piece->GetNumberOfPoints();
          this->PieceCellSizes[r] = piece->GetNumberOfCells();
          this->OnlyPolygons = this->OnlyPolygons && piece->GetNumberOfCells() == piece->GetNumberOfPolys();
          append->AddInputData(piece);
        }
      }
      append->Update();
      this->Gathered = vtkSmartPointer<vtkPolyData>::New();
      this->Gathered->ShallowCopy(append->GetOutput());
      this->PieceTimes = times;
    }
  }
  return first;
}

vtkSmartPointer<vtkIntArray> vtkPLaplacianDeformationFilter::SelectionLabels(
  vtkPolyData* input, vtkSelection* selection)
{
  vtkIntArray* gathered = input == this->Gathered
    ? vtkIntArray::SafeDownCast(input->GetPointData()->GetArray(GatheredLabels))
    : nullptr;
  if (gathered)
  {
    return gathered;
  }
  return this->Superclass::SelectionLabels(input, selection);
}

void vtkPLaplacianDeformationFilter::ScatterPoints(
  vtkPolyData* input, vtkPolyData* edited, vtkPolyData* output)
{
  // Each rank's slice: coordinates, the EditRole values, then the refreshed point normals and
  // polygon normals where the gathered surface has them (polygon normals only when the pieces
  // hold polygons alone, so that the appended cells follow the pieces in order).
  vtkMultiProcessController* controller = this->Controller;
  const bool first = controller->GetLocalProcessId() == 0;
  double normals[2] = { 0.0, 0.0 };
  if (first)
  {
    normals[0] = edited->GetPointData()->GetNormals() ? 1.0 : 0.0;
    normals[1] = edited->GetCellData()->GetNormals() && this->OnlyPolygons ? 1.0 : 0.0;
  }
  controller->Broadcast(normals, 2, 0);
  const bool pointNormals = normals[0] != 0.0;
  const bool cellNormals = normals[1] != 0.0;
  auto sliceSize = [&](vtkIdType points, vtkIdType cells) {
    return (pointNormals ? 7 : 4) * points + (cellNormals ? 3 * cells : 0);
  };
  const vtkIdType count = input->GetNumberOfPoints();
  const vtkIdType cells = input->GetNumberOfCells();
  std::vector<double> moved(sliceSize(count, cells));
  if (first)
  {
    vtkDataArray* roles = edited->GetPointData()->GetArray("EditRole");
    vtkIdType offset = 0, cellOffset = 0;
    for (int r = 0; r < controller->GetNumberOfProcesses(); ++r)
    {
      const vtkIdType size = this->PieceSizes[r];
      const vtkIdType cellSize = this->PieceCellSizes[r];
      std::vector<double> slice(sliceSize(size, cellSize));
      for (vtkIdType i = 0; i < size && edited->GetPoints(); ++i)
      {
        edited->GetPoint(offset + i, slice.data() + 3 * i);
        slice[3 * size + i] = roles ? roles->GetTuple1(offset + i) : 0.0;
        if (pointNormals)
        {
          edited->GetPointData()->GetNormals()->GetTuple(offset + i, slice.data() + 4 * size + 3 * i);
        }
      }
      for (vtkIdType c = 0; c < cellSize && cellNormals; ++c)
      {
        edited->GetCellData()->GetNormals()->GetTuple(
          cellOffset + c, slice.data() + (pointNormals ? 7 : 4) * size + 3 * c);
      }
      offset += size;
      cellOffset += cellSize;
      if (r == 0)
      {
        moved = std::move(slice);
      }
      else
      {
        controller->Send(slice.data(), static_cast<vtkIdType>(slice.size()), r, PointsTag);
      }
    }
  }
  else
  {
    controller->Receive(moved.data(), static_cast<vtkIdType>(moved.size()), 0, PointsTag);
  }

  output->ShallowCopy(input);
  vtkNew<vtkPoints> points;
  points->SetDataType(input->GetPoints() ? input->GetPoints()->GetDataType() : VTK_DOUBLE);
  points->SetNumberOfPoints(count);
  vtkSmartPointer<vtkSignedCharArray> roles = vtkLaplacianSurfaceAdapter::NewRoles(count);
  for (vtkIdType i = 0; i < count; ++i)
  {
    points->SetPoint(i, moved.data() + 3 * i);
    roles->SetValue(i, static_cast<signed char>(moved[3 * count + i]));
  }
  if (count > 0)
  {
    output->SetPoints(points);
  }
  // The normals as the serial filter leaves them: the input's, refreshed near the edit.
  auto refresh = [](vtkDataSetAttributes* attributes, const double* values, bool sent) {
    vtkDataArray* original = attributes->GetNormals();
    if (!original || !sent)
    {
      attributes->SetNormals(nullptr);
      return;
    }
    auto copy = vtk::TakeSmartPointer(original->NewInstance());
    copy->DeepCopy(original);
    for (vtkIdType i = 0; i < copy->GetNumberOfTuples(); ++i)
    {
      copy->SetTuple(i, values + 3 * i);
    }
    attributes->SetNormals(copy);
  };
  refresh(output->GetPointData(), moved.data() + 4 * count, pointNormals);
  refresh(output->GetCellData(), moved.data() + (pointNormals ? 7 : 4) * count, cellNormals);
  this->AddEditRoles(output, roles);
}

void vtkPLaplacianDeformationFilter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Controller: " << this->Controller << "\n";
}
