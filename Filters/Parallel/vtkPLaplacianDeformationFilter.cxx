#include "vtkPLaplacianDeformationFilter.h"

#include "vtkAppendPolyData.h"
#include "vtkBoundingBox.h"
#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkCellData.h"
#include "vtkCommunicator.h"
#include "vtkDataArray.h"
#include "vtkInformationVector.h"
#include "vtkIntArray.h"
#include "EditPipeline.h"
#include "PieceEdit.h"
#ifdef LAPLACIAN_EDITING_HAS_MUMPS
#include "MumpsSolver.h"
#endif
#include "RegionSelector.h"
#include "SurfaceAdapter.h"
#include "vtkMath.h"
#include "vtkMultiProcessController.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkSelection.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace le = LaplacianEditing;
namespace lep = LaplacianEditing::Pipeline;
#ifdef LAPLACIAN_EDITING_HAS_MUMPS
using LaplacianEditing::Parallel::MumpsSolver;
#endif
using LaplacianEditing::Parallel::PieceEdit;

vtkStandardNewMacro(vtkPLaplacianDeformationFilter);

struct vtkPLaplacianDeformationFilter::vtkInternals
{
  // The current reach and, on rank 0, the one the parts were gathered for.
  lep::Reach Reach;
  lep::Reach GatheredReach;
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
  // Bumped whenever the parts are gathered anew.
  unsigned long GatheredVersion = 0;
  // This piece's share of the edit and what it was shared for (WritePieces's header); rank 0:
  // the rows each piece's share needs.
  PieceEdit Piece;
  double SharedFor[4] = { -1.0, -1.0, -1.0, -1.0 };
  std::vector<std::vector<int>> PieceRows;
#ifdef LAPLACIAN_EDITING_HAS_MUMPS
  // The processes' MUMPS, for the controller it was made for.
  std::shared_ptr<MumpsSolver> Mumps;
  vtkMultiProcessController* MumpsController = nullptr;
#endif
};
vtkCxxSetObjectMacro(vtkPLaplacianDeformationFilter, Controller, vtkMultiProcessController);

namespace
{
const int ShareTag = 40501;
const int PositionsTag = 40502;
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
#ifdef LAPLACIAN_EDITING_HAS_MUMPS
  vtkInternals& internals = *this->Internals;
  if (internals.MumpsController != this->Controller)
  {
    internals.Mumps = MumpsSolver::New(this->Controller);
    internals.MumpsController = this->Controller;
  }
#endif
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
  if (this->GatherPieces(input, selection))
  {
    this->EditSurface(this->Internals->Gathered, nullptr); // each rank writes its own piece
  }
#ifdef LAPLACIAN_EDITING_HAS_MUMPS
  // The other processes factor and solve along with the first while it edits.
  if (internals.Mumps)
  {
    if (this->Controller->GetLocalProcessId() == 0)
    {
      internals.Mumps->EndService();
    }
    else
    {
      internals.Mumps->Serve();
    }
  }
#endif
  this->WritePieces(input, output);
  return 1;
}

LaplacianEditing::DistributedSolver* vtkPLaplacianDeformationFilter::GetDistributedSolver()
{
#ifdef LAPLACIAN_EDITING_HAS_MUMPS
  return this->Internals->Mumps.get();
#else
  return nullptr;
#endif
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
    lep::SurfaceAdapter::GetContentTime(input) };
  if (!internals.PieceLabels || !std::equal(key, key + 2, internals.PieceLabelsKey))
  {
    std::copy(key, key + 2, internals.PieceLabelsKey);
    internals.PieceLabels = lep::RegionSelector::LabelSelection(
      input, selection, this->Controller->GetLocalProcessId());
    internals.PieceLabels->SetName(GatheredLabels);
  }
  return internals.PieceLabels;
}

void vtkPLaplacianDeformationFilter::UpdateGlobalReach(
  vtkPolyData* input, vtkDataArray* labels, bool fromSelection)
{
  // The serial filter's reach (RegionSelector::ComputeReach) over the whole
  // surface, from a few numbers per rank and the labelled points, widened by two of the longest
  // edges: the polygons around the ring of fixed vertices then come along from every piece,
  // whichever holds them.
  const bool labelled = labels != nullptr || this->SelectionMode == SELECTION_ARRAY;
  double longestEdge = 0.0;
  double extent = this->ReduceExtents(input, labelled, longestEdge);
  lep::Reach& reach = this->Internals->Reach;
  reach = lep::Reach();
  if (labelled)
  {
    extent = this->GatherSeeds(input, labels, reach.Seeds);
  }
  else
  {
    reach.Seeds.push_back({ this->HandleCenter[0], this->HandleCenter[1], this->HandleCenter[2] });
  }
  // Nothing labelled, or no polygon: every piece goes whole, and the edit says why.
  const double growth = fromSelection ? this->AbsoluteRadius(this->ROIRadius) : 0.0;
  lep::RegionSelector::SetMargin(
    reach, this->RegionParameters(), labelled, extent, growth, 2.0 * longestEdge);
}

double vtkPLaplacianDeformationFilter::ReduceExtents(
  vtkPolyData* input, bool labelled, double& longestEdge)
{
  // One reduction: the pieces' bounds (which set WholeDiagonal), their longest edge, and the
  // handle centre's distance to the nearest polygon corner (-1 if there is none).
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
  const vtkIdType nearest =
    labelled ? -1 : lep::SurfaceAdapter::FindNearestCorner(input, this->HandleCenter);
  local[7] = nearest < 0
    ? VTK_DOUBLE_MIN
    : -std::sqrt(vtkMath::Distance2BetweenPoints(input->GetPoint(nearest), this->HandleCenter));
  double global[8];
  this->Controller->AllReduce(local, global, 8, vtkCommunicator::MAX_OP);
  double box[6];
  for (int a = 0; a < 3; ++a)
  {
    box[2 * a] = -global[2 * a];
    box[2 * a + 1] = global[2 * a + 1];
  }
  this->WholeDiagonal =
    vtkBoundingBox(box).IsValid() ? vtkBoundingBox(box).GetDiagonalLength() : 0.0;
  longestEdge = global[6];
  return -global[7];
}

double vtkPLaplacianDeformationFilter::GatherSeeds(
  vtkPolyData* input, vtkDataArray* labels, std::vector<std::array<double, 3>>& seeds)
{
  // Every rank's labelled points; returns half their extent (-1 if there are none).
  std::vector<double> local;
  for (vtkIdType i = 0; labels && i < labels->GetNumberOfTuples(); ++i)
  {
    if (labels->GetComponent(i, 0) != 0.0)
    {
      const double* p = input->GetPoint(i);
      local.insert(local.end(), p, p + 3);
    }
  }
  vtkMultiProcessController* controller = this->Controller;
  const int ranks = controller->GetNumberOfProcesses();
  const vtkIdType count = static_cast<vtkIdType>(local.size());
  std::vector<vtkIdType> counts(ranks), offsets(ranks, 0);
  controller->AllGather(&count, counts.data(), 1);
  for (int r = 1; r < ranks; ++r)
  {
    offsets[r] = offsets[r - 1] + counts[r - 1];
  }
  std::vector<double> all(offsets[ranks - 1] + counts[ranks - 1]);
  controller->AllGatherV(local.data(), all.data(), count, counts.data(), offsets.data());
  vtkBoundingBox box;
  for (std::size_t k = 0; k + 2 < all.size(); k += 3)
  {
    seeds.push_back({ all[k], all[k + 1], all[k + 2] });
    box.AddPoint(all.data() + k);
  }
  return box.IsValid() ? 0.5 * box.GetDiagonalLength() : -1.0;
}

double vtkPLaplacianDeformationFilter::LongestPolygonEdge(vtkPolyData* input)
{
  // One pass over the polygons, repeated only when the piece changes.
  vtkInternals& internals = *this->Internals;
  const vtkMTimeType time = lep::SurfaceAdapter::GetContentTime(input);
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
  const lep::Reach& reach = internals.Reach;
  // Each rank sends the part of its piece in reach; geometry travels only when some piece, the
  // selection or the reach changed.
  vtkMultiProcessController* controller = this->Controller;
  const int ranks = controller->GetNumberOfProcesses();
  const bool first = controller->GetLocalProcessId() == 0;
  const double localTimes[2] = { static_cast<double>(lep::SurfaceAdapter::GetContentTime(input)),
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
  vtkSmartPointer<vtkPolyData> part = lep::SurfaceAdapter::ExtractReach(source, reach);
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
    ++internals.GatheredVersion;
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

void vtkPLaplacianDeformationFilter::WritePieces(vtkPolyData* input, vtkPolyData* output)
{
  // Each rank writes its own piece from its share of the edit, which travels once per region.
  // A move then sends the handle maps' entries where the edit is affine in them (every rank
  // places its own rows), and otherwise each rank the positions of its rows alone.
  vtkInternals& internals = *this->Internals;
  vtkMultiProcessController* controller = this->Controller;
  const bool first = controller->GetLocalProcessId() == 0;
  const lep::EditPipeline& pipeline = this->GetEditPipeline();
  const lep::EditState edit = pipeline.GetState();
  Eigen::VectorXd parameters;
  // Whether there is an edit, whether it is affine, what it was shared for, and the number of
  // the maps' entries.
  double header[5] = { 0.0, 0.0, 0.0, 0.0, 0.0 };
  if (first && pipeline.HasSolved())
  {
    header[0] = 1.0;
    header[1] = PieceEdit::GetAffineParameters(edit, parameters) ? 1.0 : 0.0;
    header[2] = static_cast<double>(edit.ModelVersion);
    header[3] = static_cast<double>(internals.GatheredVersion);
    header[4] = static_cast<double>(parameters.size());
  }
  controller->Broadcast(header, 5, 0);
  if (!std::equal(header, header + 4, internals.SharedFor))
  {
    this->SharePieces(edit, header[0] != 0.0, header[1] != 0.0);
    std::copy(header, header + 4, internals.SharedFor);
  }
  le::Positions positions;
  if (header[0] != 0.0 && header[1] != 0.0)
  {
    parameters.resize(static_cast<Eigen::Index>(header[4]));
    controller->Broadcast(parameters.data(), parameters.size(), 0);
    positions = internals.Piece.Evaluate(parameters);
  }
  else if (header[0] != 0.0 && first)
  {
    for (int r = 1; r < controller->GetNumberOfProcesses(); ++r)
    {
      const le::Positions rows = PieceEdit::GetRowPositions(edit, internals.PieceRows[r]);
      controller->Send(rows.data(), rows.size(), r, PositionsTag);
    }
    positions = PieceEdit::GetRowPositions(edit, internals.Piece.GetRows());
  }
  else if (header[0] != 0.0)
  {
    positions.resize(static_cast<Eigen::Index>(internals.Piece.GetRows().size()), 3);
    controller->Receive(positions.data(), positions.size(), 0, PositionsTag);
  }
  output->ShallowCopy(input);
  lep::OutputEdit pieceEdit;
  this->WriteEdit(
    input, output, internals.Piece.GetEdit(positions, pieceEdit) ? &pieceEdit : nullptr);
}

void vtkPLaplacianDeformationFilter::SharePieces(
  const lep::EditState& edit, bool edited, bool affine)
{
  // The first rank cuts the edit of the gathered parts into one share per piece: the parts
  // follow each other in rank order, and carry their ids in the pieces.
  vtkInternals& internals = *this->Internals;
  vtkMultiProcessController* controller = this->Controller;
  const int ranks = controller->GetNumberOfProcesses();
  if (controller->GetLocalProcessId() != 0)
  {
    vtkIdType size = 0;
    controller->Receive(&size, 1, 0, ShareTag);
    std::vector<double> message(size);
    controller->Receive(message.data(), size, 0, ShareTag);
    if (!internals.Piece.Unpack(message))
    {
      vtkErrorMacro(<< "The first rank sent this piece a malformed share of the edit.");
      internals.Piece = PieceEdit();
    }
    return;
  }
  PieceEdit::Range range;
  if (edited)
  {
    range.PointIds = internals.Gathered->GetPointData()->GetArray("vtkOriginalPointIds");
    range.CellIds = internals.Gathered->GetCellData()->GetArray("vtkOriginalCellIds");
  }
  internals.PieceRows.assign(ranks, {});
  for (int r = 0; r < ranks; ++r)
  {
    range.NumberOfPoints = internals.PieceSizes[r];
    range.NumberOfCells = internals.PieceCellSizes[r];
    PieceEdit piece;
    if (edited)
    {
      piece.Build(edit, range, affine);
    }
    internals.PieceRows[r] = piece.GetRows();
    range.FirstPoint += range.NumberOfPoints;
    range.FirstCell += range.NumberOfCells;
    if (r == 0)
    {
      internals.Piece = std::move(piece);
      continue;
    }
    const std::vector<double> message = piece.Pack();
    const vtkIdType size = static_cast<vtkIdType>(message.size());
    controller->Send(&size, 1, r, ShareTag);
    controller->Send(message.data(), size, r, ShareTag);
  }
}

void vtkPLaplacianDeformationFilter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Controller: " << this->Controller << "\n";
  os << indent << "NumberOfGatheredPoints: " << this->NumberOfGatheredPoints << "\n";
}
