#include "vtkPLaplacianDeformationFilter.h"

#include "vtkAppendPolyData.h"
#include "vtkBoundingBox.h"
#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkCellData.h"
#include "vtkCommunicator.h"
#include "vtkDataArray.h"
#include "vtkDataSetAttributes.h"
#include "vtkInformationVector.h"
#include "vtkIntArray.h"
#include "vtkLaplacianSurfaceAdapter.h"
#include "vtkMath.h"
#include "vtkMultiProcessController.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSelection.h"
#include "vtkSignedCharArray.h"

#include <algorithm>
#include <cmath>
#include <vector>

vtkStandardNewMacro(vtkPLaplacianDeformationFilter);

struct vtkPLaplacianDeformationFilter::vtkInternals
{
  // The current reach and, on rank 0, the one the parts were gathered for.
  vtkLaplacianSurfaceAdapter::Reach Reach;
  vtkLaplacianSurfaceAdapter::Reach GatheredReach;
  // This piece's selection labels and what they were made for (selection and piece times).
  vtkSmartPointer<vtkIntArray> PieceLabels;
  vtkMTimeType PieceLabelsKey[2] = { 0, 0 };
  // This piece's longest polygon edge and the piece content time it was measured on.
  vtkMTimeType LongestEdgeTime = 0;
  double LongestEdge = 0.0;
  // Rank 0: the gathered parts, what they were gathered for (each piece's content time and
  // selection MTime), and each piece's point and polygon counts in them.
  vtkSmartPointer<vtkPolyData> Gathered;
  std::vector<double> PieceTimes;
  std::vector<vtkIdType> PieceSizes;
  std::vector<vtkIdType> PieceCellSizes;
};
vtkCxxSetObjectMacro(vtkPLaplacianDeformationFilter, Controller, vtkMultiProcessController);

namespace
{
const int PointsTag = 40501;
// The point array that carries each piece's selection labels to the first rank.
const char* const GatheredLabels = "vtkLaplacianSelectionLabels";
}

vtkPLaplacianDeformationFilter::vtkPLaplacianDeformationFilter()
  : Internals(new vtkInternals)
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
  vtkDataArray* labels = this->LocalLabels(input, selection);
  this->UpdateGlobalReach(input, labels, selection != nullptr);
  vtkNew<vtkPolyData> edited;
  if (this->GatherPieces(input, selection))
  {
    this->EditSurface(this->Internals->Gathered, edited);
  }
  this->ScatterPoints(input, edited, output);
  return 1;
}

vtkDataArray* vtkPLaplacianDeformationFilter::LocalLabels(vtkPolyData* input, vtkSelection* selection)
{
  vtkInternals& internals = *this->Internals;
  // A selection's labels on this piece, made again only when the selection or the piece changes;
  // in array mode the labels array itself.
  if (!selection)
  {
    internals.PieceLabels = nullptr;
    return this->SelectionMode == SELECTION_ARRAY ? this->GetInputArrayToProcess(0, input) : nullptr;
  }
  const vtkMTimeType key[2] = { selection->GetMTime(),
    vtkLaplacianSurfaceAdapter::GetContentTime(input) };
  if (!internals.PieceLabels || !std::equal(key, key + 2, internals.PieceLabelsKey))
  {
    std::copy(key, key + 2, internals.PieceLabelsKey);
    internals.PieceLabels = LabelSelection(input, selection, this->Controller->GetLocalProcessId());
    internals.PieceLabels->SetName(GatheredLabels);
  }
  return internals.PieceLabels;
}

void vtkPLaplacianDeformationFilter::UpdateGlobalReach(
  vtkPolyData* input, vtkDataArray* labels, bool fromSelection)
{
  // The serial filter's reach (ComputeReach) over the whole surface, from a few numbers per
  // rank and the labelled points, widened by two of the longest edges: the polygons around the
  // ring of fixed vertices then come along from every piece, whichever holds them.
  vtkMultiProcessController* controller = this->Controller;
  double local[8];
  double bounds[6];
  input->GetBounds(bounds);
  const bool empty = input->GetNumberOfPoints() == 0;
  for (int a = 0; a < 3; ++a)
  {
    local[2 * a] = empty ? VTK_DOUBLE_MIN : -bounds[2 * a];
    local[2 * a + 1] = empty ? VTK_DOUBLE_MIN : bounds[2 * a + 1];
  }
  local[6] = LongestPolygonEdge(input);
  const bool labelled = labels != nullptr || this->SelectionMode == SELECTION_ARRAY;
  const vtkIdType nearest =
    labelled ? -1 : vtkLaplacianSurfaceAdapter::FindNearestCorner(input, this->HandleCenter);
  local[7] = nearest < 0 ? VTK_DOUBLE_MIN
                         : -std::sqrt(vtkMath::Distance2BetweenPoints(input->GetPoint(nearest), this->HandleCenter));
  double global[8];
  controller->AllReduce(local, global, 8, vtkCommunicator::MAX_OP);
  double box[6];
  for (int a = 0; a < 3; ++a)
  {
    box[2 * a] = -global[2 * a];
    box[2 * a + 1] = global[2 * a + 1];
  }
  this->WholeDiagonal = vtkBoundingBox(box).IsValid() ? vtkBoundingBox(box).GetDiagonalLength() : 0.0;

  vtkLaplacianSurfaceAdapter::Reach& reach = this->Internals->Reach;
  reach = vtkLaplacianSurfaceAdapter::Reach();
  double extent = -global[7];
  if (labelled)
  {
    std::vector<double> seeds;
    for (vtkIdType i = 0; labels && i < labels->GetNumberOfTuples(); ++i)
    {
      if (labels->GetComponent(i, 0) != 0.0)
      {
        const double* p = input->GetPoint(i);
        seeds.insert(seeds.end(), p, p + 3);
      }
    }
    const int ranks = controller->GetNumberOfProcesses();
    const vtkIdType count = static_cast<vtkIdType>(seeds.size());
    std::vector<vtkIdType> counts(ranks), offsets(ranks, 0);
    controller->AllGather(&count, counts.data(), 1);
    for (int r = 1; r < ranks; ++r)
    {
      offsets[r] = offsets[r - 1] + counts[r - 1];
    }
    std::vector<double> all(offsets[ranks - 1] + counts[ranks - 1]);
    controller->AllGatherV(seeds.data(), all.data(), count, counts.data(), offsets.data());
    vtkBoundingBox seedBox;
    for (std::size_t k = 0; k + 2 < all.size(); k += 3)
    {
      reach.Seeds.push_back({ all[k], all[k + 1], all[k + 2] });
      seedBox.AddPoint(all.data() + k);
    }
    extent = seedBox.IsValid() ? 0.5 * seedBox.GetDiagonalLength() : -1.0;
  }
  else
  {
    reach.Seeds.push_back({ this->HandleCenter[0], this->HandleCenter[1], this->HandleCenter[2] });
  }
  if (reach.Seeds.empty() || extent < 0.0)
  {
    reach.Seeds.clear();
    return; // nothing labelled, or no polygon: every piece goes, and the edit says why
  }
  const double growth = fromSelection ? this->AbsoluteRadius(this->ROIRadius) : 0.0;
  reach.Margin = this->ReachMargin(labelled, extent, growth) + 2.0 * global[6];
}

double vtkPLaplacianDeformationFilter::LongestPolygonEdge(vtkPolyData* input)
{
  // One pass over the polygons, repeated only when the piece changes.
  vtkInternals& internals = *this->Internals;
  const vtkMTimeType time = vtkLaplacianSurfaceAdapter::GetContentTime(input);
  if (time != internals.LongestEdgeTime)
  {
    double longest2 = 0.0;
    auto cells = vtk::TakeSmartPointer(input->GetPolys()->NewIterator());
    for (cells->GoToFirstCell(); !cells->IsDoneWithTraversal(); cells->GoToNextCell())
    {
      vtkIdType size;
      const vtkIdType* ids;
      cells->GetCurrentCell(size, ids);
      for (vtkIdType c = 0; c < size; ++c)
      {
        longest2 = std::max(longest2,
          vtkMath::Distance2BetweenPoints(input->GetPoint(ids[c]), input->GetPoint(ids[(c + 1) % size])));
      }
    }
    internals.LongestEdgeTime = time;
    internals.LongestEdge = std::sqrt(longest2);
  }
  return internals.LongestEdge;
}

bool vtkPLaplacianDeformationFilter::GatherPieces(vtkPolyData* input, vtkSelection* selection)
{
  vtkInternals& internals = *this->Internals;
  const vtkLaplacianSurfaceAdapter::Reach& reach = internals.Reach;
  // Each rank sends the part of its piece in reach; geometry travels only when some piece, the
  // selection or the reach changed.
  vtkMultiProcessController* controller = this->Controller;
  const int ranks = controller->GetNumberOfProcesses();
  const bool first = controller->GetLocalProcessId() == 0;
  const double localTimes[2] = { static_cast<double>(vtkLaplacianSurfaceAdapter::GetContentTime(input)),
    selection ? static_cast<double>(selection->GetMTime()) : 0.0 };
  std::vector<double> times(2 * ranks, 0.0);
  controller->Gather(localTimes, times.data(), 2, 0);
  const bool stale =
    times != internals.PieceTimes || !internals.Gathered || !(reach == internals.GatheredReach);
  double changed = first && stale ? 1.0 : 0.0;
  controller->Broadcast(&changed, 1, 0);
  if (changed == 0.0)
  {
    return first;
  }
  vtkNew<vtkPolyData> source;
  source->ShallowCopy(input);
  if (internals.PieceLabels)
  {
    source->GetPointData()->AddArray(internals.PieceLabels);
  }
  vtkSmartPointer<vtkPolyData> part = vtkLaplacianSurfaceAdapter::ExtractReach(source, reach);
  std::vector<vtkSmartPointer<vtkDataObject>> parts;
  controller->Gather(part, parts, 0);
  if (first)
  {
    vtkNew<vtkAppendPolyData> append;
    internals.PieceSizes.assign(ranks, 0);
    internals.PieceCellSizes.assign(ranks, 0);
    for (int r = 0; r < ranks; ++r)
    {
      auto* piece = vtkPolyData::SafeDownCast(parts[r]);
      if (piece && piece->GetNumberOfPoints() > 0)
      {
        internals.PieceSizes[r] = piece->GetNumberOfPoints();
        internals.PieceCellSizes[r] = piece->GetNumberOfCells();
        append->AddInputData(piece);
      }
    }
    append->Update();
    internals.Gathered = vtkSmartPointer<vtkPolyData>::New();
    internals.Gathered->ShallowCopy(append->GetOutput());
    this->NumberOfGatheredPoints = internals.Gathered->GetNumberOfPoints();
    internals.PieceTimes = times;
    internals.GatheredReach = reach;
  }
  return first;
}

vtkSmartPointer<vtkIntArray> vtkPLaplacianDeformationFilter::SelectionLabels(
  vtkPolyData* input, vtkSelection* selection)
{
  vtkIntArray* gathered = input == this->Internals->Gathered
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
  vtkInternals& internals = *this->Internals;
  // Each rank gets back only its part in reach: per point its id in the piece, coordinates,
  // EditRole and, where the edited surface has them, the refreshed normal; per polygon its id
  // and refreshed normal. Everything else is the piece as it came in.
  vtkMultiProcessController* controller = this->Controller;
  const bool first = controller->GetLocalProcessId() == 0;
  double normals[2] = { 0.0, 0.0 };
  if (first)
  {
    normals[0] = edited->GetPointData()->GetNormals() ? 1.0 : 0.0;
    normals[1] = edited->GetCellData()->GetNormals() ? 1.0 : 0.0;
  }
  controller->Broadcast(normals, 2, 0);
  const int pointWidth = normals[0] != 0.0 ? 8 : 5;
  const int cellWidth = normals[1] != 0.0 ? 4 : 0;
  std::vector<double> slice;
  vtkIdType sizes[2] = { 0, 0 }; // points and polygons of this rank's part
  if (first)
  {
    vtkDataArray* roles = edited->GetPointData()->GetArray("EditRole");
    vtkDataArray* pointIds = internals.Gathered->GetPointData()->GetArray("vtkOriginalPointIds");
    vtkDataArray* cellIds = internals.Gathered->GetCellData()->GetArray("vtkOriginalCellIds");
    vtkIdType offset = 0, cellOffset = 0;
    for (int r = 0; r < controller->GetNumberOfProcesses(); ++r)
    {
      const vtkIdType rankSizes[2] = { internals.PieceSizes[r], internals.PieceCellSizes[r] };
      std::vector<double> values(pointWidth * rankSizes[0] + cellWidth * rankSizes[1]);
      for (vtkIdType i = 0; i < rankSizes[0] && edited->GetPoints(); ++i)
      {
        double* v = values.data() + pointWidth * i;
        v[0] = pointIds->GetComponent(offset + i, 0);
        edited->GetPoint(offset + i, v + 1);
        v[4] = roles ? roles->GetComponent(offset + i, 0) : 0.0;
        if (pointWidth == 8)
        {
          edited->GetPointData()->GetNormals()->GetTuple(offset + i, v + 5);
        }
      }
      for (vtkIdType c = 0; c < rankSizes[1] && cellWidth > 0; ++c)
      {
        double* v = values.data() + pointWidth * rankSizes[0] + cellWidth * c;
        v[0] = cellIds->GetComponent(cellOffset + c, 0);
        edited->GetCellData()->GetNormals()->GetTuple(cellOffset + c, v + 1);
      }
      offset += rankSizes[0];
      cellOffset += rankSizes[1];
      if (r == 0)
      {
        slice = std::move(values);
        std::copy(rankSizes, rankSizes + 2, sizes);
      }
      else
      {
        controller->Send(rankSizes, 2, r, PointsTag);
        controller->Send(values.data(), static_cast<vtkIdType>(values.size()), r, PointsTag);
      }
    }
  }
  else
  {
    controller->Receive(sizes, 2, 0, PointsTag);
    slice.resize(pointWidth * sizes[0] + cellWidth * sizes[1]);
    controller->Receive(slice.data(), static_cast<vtkIdType>(slice.size()), 0, PointsTag);
  }

  output->ShallowCopy(input);
  const vtkIdType count = input->GetNumberOfPoints();
  vtkSmartPointer<vtkSignedCharArray> roles = vtkLaplacianSurfaceAdapter::NewRoles(count);
  vtkSmartPointer<vtkDataArray> pointNormals = WritableNormals(output->GetPointData(), pointWidth == 8);
  vtkSmartPointer<vtkDataArray> cellNormals = WritableNormals(output->GetCellData(), cellWidth > 0);
  if (count > 0)
  {
    vtkNew<vtkPoints> points;
    points->SetDataType(input->GetPoints()->GetDataType());
    points->DeepCopy(input->GetPoints());
    for (vtkIdType i = 0; i < sizes[0]; ++i)
    {
      const double* v = slice.data() + pointWidth * i;
      const vtkIdType id = static_cast<vtkIdType>(v[0]);
      points->SetPoint(id, v + 1);
      roles->SetValue(id, static_cast<signed char>(v[4]));
      if (pointNormals)
      {
        pointNormals->SetTuple(id, v + 5);
      }
    }
    output->SetPoints(points);
  }
  for (vtkIdType c = 0; c < sizes[1] && cellNormals; ++c)
  {
    const double* v = slice.data() + pointWidth * sizes[0] + cellWidth * c;
    cellNormals->SetTuple(static_cast<vtkIdType>(v[0]), v + 1);
  }
  this->AddEditRoles(output, roles);
}

vtkSmartPointer<vtkDataArray> vtkPLaplacianDeformationFilter::WritableNormals(
  vtkDataSetAttributes* attributes, bool refreshed)
{
  // The normals as the serial filter leaves them: the input's, refreshed near the edit; none
  // where the edit could not refresh them.
  vtkDataArray* original = attributes->GetNormals();
  if (!original || !refreshed)
  {
    attributes->SetNormals(nullptr);
    return nullptr;
  }
  auto copy = vtk::TakeSmartPointer(original->NewInstance());
  copy->DeepCopy(original);
  attributes->SetNormals(copy);
  return copy;
}

void vtkPLaplacianDeformationFilter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Controller: " << this->Controller << "\n";
  os << indent << "NumberOfGatheredPoints: " << this->NumberOfGatheredPoints << "\n";
}
