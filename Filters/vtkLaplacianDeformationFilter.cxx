#include "vtkLaplacianDeformationFilter.h"

#include "Numerics/EditRegion.h"
#include "Numerics/LaplacianEditor.h"
#include "Numerics/SurfaceMesh.h"

#include "vtkAppendPolyData.h"
#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkFloatArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkLinearTransform.h"
#include "vtkMatrix4x4.h"
#include "vtkMultiProcessController.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSMPTools.h"
#include "vtkSmartPointer.h"
#include "vtkTransform.h"
#include "vtkUnsignedCharArray.h"
#include <vtksys/SystemInformation.hxx>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <functional>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

namespace le = LaplacianEditing;

vtkStandardNewMacro(vtkLaplacianDeformationFilter);

namespace
{
using Clock = std::chrono::steady_clock;

double SecondsSince(Clock::time_point start)
{
  return std::chrono::duration<double>(Clock::now() - start).count();
}

bool IsIntegerType(int type)
{
  switch (type)
  {
    case VTK_CHAR:
    case VTK_SIGNED_CHAR:
    case VTK_UNSIGNED_CHAR:
    case VTK_SHORT:
    case VTK_UNSIGNED_SHORT:
    case VTK_INT:
    case VTK_UNSIGNED_INT:
    case VTK_LONG:
    case VTK_UNSIGNED_LONG:
    case VTK_LONG_LONG:
    case VTK_UNSIGNED_LONG_LONG:
    case VTK_ID_TYPE:
      return true;
    default:
      return false;
  }
}

// Copies a normals array and recomputes the tuples listed in `ids`: normals near the edit are
// fresh, and all others stay bit-identical to the input's.
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

struct vtkLaplacianDeformationFilter::vtkInternals
{
  std::vector<vtkSmartPointer<vtkLinearTransform>> HandleTransforms;

  // What the cached surface graph, and the cached factorization, were built from.
  std::vector<double> MeshKey;
  // Under MPI, on the first rank: the gathered surface, the pieces' MTimes and point counts.
  vtkSmartPointer<vtkPolyData> Gathered;
  std::vector<double> PieceTimes;
  std::vector<vtkIdType> PieceSizes;
  int GatheredVersion = 0;
  std::vector<double> CacheKey;
  std::string CacheArrayName;

  std::shared_ptr<le::SurfaceMesh> Mesh = std::make_shared<le::SurfaceMesh>();
  le::EditRegion Region;
  le::LaplacianEditor Editor;
  // Per region: the ROI row of each surface vertex (-1 outside), the input points in the ROI
  // with their row, and the EditRole array.
  std::vector<int> RowOfVertex;
  std::vector<std::pair<vtkIdType, int>> RoiPoints;
  vtkSmartPointer<vtkUnsignedCharArray> Roles;
  // Per region: the points and cells whose normals the edit can change, the triangles around
  // those points (and each mesh triangle's slot among them, -1 if none), and the surface
  // vertices of each such cell (offsets into CellVertices).
  std::vector<vtkIdType> NormalPoints;
  std::vector<int> NormalTriangles;
  std::vector<int> TriangleSlot;
  std::vector<vtkIdType> NormalCells;
  std::vector<int> CellVertexOffsets;
  std::vector<int> CellVertices;

  std::string BuildMesh(vtkPolyData* input, bool mergeCoincidentPoints);
  // Per-region lookups from input points to ROI rows, the EditRole array, and the normals the
  // edit can change.
  void IndexRegion(vtkPolyData* input);
  void FindNormalsToRefresh(vtkPolyData* input);
  // A handle transform in the normalized frame: x' = M x + t becomes x'_n = M x_n + s (M c + t - c).
  le::AffineMap NormalizedMap(vtkLinearTransform* transform) const;
  // Point and cell normals of the output, refreshed where the ROI moved to `solution`.
  void RefreshNormals(vtkPolyData* output, const le::Positions& solution) const;
  // The core works on coordinates centred on the input's bounding box and scaled to a unit
  // diagonal, so that offset or tiny models keep their precision.
  le::Vector3 Center = le::Vector3::Zero();
  double Scale = 1.0;

  le::Vector3 Normalize(const double p[3]) const
  {
    return (le::Vector3(p[0], p[1], p[2]) - this->Center) * this->Scale;
  }
  le::Vector3 Denormalize(const le::Vector3& p) const { return p / this->Scale + this->Center; }

  void Invalidate()
  {
    this->CacheKey.clear();
    this->Region = le::EditRegion();
  }
};

std::string vtkLaplacianDeformationFilter::vtkInternals::BuildMesh(
  vtkPolyData* input, bool mergeCoincidentPoints)
{
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

  std::vector<le::Vector3> points(input->GetNumberOfPoints());
  for (vtkIdType i = 0; i < input->GetNumberOfPoints(); ++i)
  {
    points[i] = this->Normalize(input->GetPoint(i));
  }
  std::vector<std::int64_t> offsets(1, 0);
  std::vector<std::int64_t> connectivity;
  auto cells = vtk::TakeSmartPointer(input->GetPolys()->NewIterator());
  for (cells->GoToFirstCell(); !cells->IsDoneWithTraversal(); cells->GoToNextCell())
  {
    vtkIdType size;
    const vtkIdType* ids;
    cells->GetCurrentCell(size, ids);
    connectivity.insert(connectivity.end(), ids, ids + size);
    offsets.push_back(static_cast<std::int64_t>(connectivity.size()));
  }
  this->Mesh = std::make_shared<le::SurfaceMesh>(
    le::SurfaceMesh::FromPolygons(points, offsets, connectivity, mergeCoincidentPoints));
  if (this->Mesh->GetNumberOfTriangles() == 0)
  {
    return "The input polygons are all degenerate: no triangle has three distinct corners.";
  }
  return {};
}

void vtkLaplacianDeformationFilter::vtkInternals::IndexRegion(vtkPolyData* input)
{
  const vtkIdType numberOfPoints = input->GetNumberOfPoints();
  const auto& vertexOfPoint = this->Mesh->GetVertexOfPoint();
  this->RowOfVertex.assign(this->Mesh->GetNumberOfVertices(), -1);
  for (int k = 0; k < this->Region.GetNumberOfVertices(); ++k)
  {
    this->RowOfVertex[this->Region.Vertices[k]] = k;
  }
  this->RoiPoints.clear();
  this->Roles = vtkSmartPointer<vtkUnsignedCharArray>::New();
  this->Roles->SetName("EditRole");
  this->Roles->SetNumberOfTuples(numberOfPoints);
  for (vtkIdType i = 0; i < numberOfPoints; ++i)
  {
    const int k = this->RowOfVertex[vertexOfPoint[i]];
    if (k >= 0)
    {
      this->RoiPoints.emplace_back(i, k);
    }
    this->Roles->SetValue(
      i, static_cast<unsigned char>(k >= 0 ? this->Region.Roles[k] : le::VertexRole::Fixed));
  }
  this->FindNormalsToRefresh(input);
}

le::AffineMap vtkLaplacianDeformationFilter::vtkInternals::NormalizedMap(
  vtkLinearTransform* transform) const
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

void vtkLaplacianDeformationFilter::vtkInternals::RefreshNormals(
  vtkPolyData* output, const le::Positions& solution) const
{
  // The moved position of a vertex is its ROI row's.
  const std::vector<le::Vector3>& rest = this->Mesh->GetPositions();
  auto position = [&](int v) -> le::Vector3 {
    const int k = this->RowOfVertex[v];
    return k >= 0 ? le::Vector3(solution.row(k).transpose()) : rest[v];
  };
  const le::SurfaceMesh& mesh = *this->Mesh;
  if (output->GetPointData()->GetNormals())
  {
    // Each triangle's (area-weighted) normal once, then their sums around each point.
    std::vector<le::Vector3> triangleNormals(this->NormalTriangles.size());
    vtkSMPTools::For(0, static_cast<vtkIdType>(triangleNormals.size()),
      [&](vtkIdType begin, vtkIdType end) {
        for (vtkIdType s = begin; s < end; ++s)
        {
          const auto& tri = mesh.GetTriangles()[this->NormalTriangles[s]];
          triangleNormals[s] =
            (position(tri[1]) - position(tri[0])).cross(position(tri[2]) - position(tri[0]));
        }
      });
    RefreshNormalsArray(output->GetPointData(), this->NormalPoints, [&](vtkIdType r) {
      const int v = mesh.GetVertexOfPoint()[this->NormalPoints[r]];
      le::Vector3 n = le::Vector3::Zero();
      for (const int* t = mesh.TrianglesBegin(v); t != mesh.TrianglesEnd(v); ++t)
      {
        n += triangleNormals[this->TriangleSlot[*t]];
      }
      return n;
    });
  }
  RefreshNormalsArray(output->GetCellData(), this->NormalCells, [&](vtkIdType r) {
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

void vtkLaplacianDeformationFilter::vtkInternals::FindNormalsToRefresh(vtkPolyData* input)
{
  // A vertex normal changes when a vertex of an incident triangle moves: the ROI and its ring.
  const auto& vertexOfPoint = this->Mesh->GetVertexOfPoint();
  std::vector<char> near(this->Mesh->GetNumberOfVertices(), 0);
  for (int v : this->Region.Vertices)
  {
    near[v] = 1;
    for (const int* w = this->Mesh->NeighborsBegin(v); w != this->Mesh->NeighborsEnd(v); ++w)
    {
      near[*w] = 1;
    }
  }
  this->NormalPoints.clear();
  for (vtkIdType i = 0; i < static_cast<vtkIdType>(vertexOfPoint.size()); ++i)
  {
    if (near[vertexOfPoint[i]])
    {
      this->NormalPoints.push_back(i);
    }
  }
  this->NormalTriangles.clear();
  this->TriangleSlot.assign(this->Mesh->GetNumberOfTriangles(), -1);
  for (int v = 0; v < this->Mesh->GetNumberOfVertices(); ++v)
  {
    for (const int* t = this->Mesh->TrianglesBegin(v); near[v] && t != this->Mesh->TrianglesEnd(v); ++t)
    {
      if (this->TriangleSlot[*t] < 0)
      {
        this->TriangleSlot[*t] = static_cast<int>(this->NormalTriangles.size());
        this->NormalTriangles.push_back(*t);
      }
    }
  }
  // A polygon normal changes when one of its corners is in the ROI.
  this->NormalCells.clear();
  this->CellVertexOffsets.assign(1, 0);
  this->CellVertices.clear();
  const vtkIdType firstPoly = input->GetNumberOfVerts() + input->GetNumberOfLines();
  auto cells = vtk::TakeSmartPointer(input->GetPolys()->NewIterator());
  for (cells->GoToFirstCell(); !cells->IsDoneWithTraversal(); cells->GoToNextCell())
  {
    vtkIdType size;
    const vtkIdType* ids;
    cells->GetCurrentCell(size, ids);
    const bool moves = std::any_of(
      ids, ids + size, [&](vtkIdType id) { return this->RowOfVertex[vertexOfPoint[id]] >= 0; });
    if (moves)
    {
      this->NormalCells.push_back(firstPoly + cells->GetCurrentCellId());
      for (vtkIdType c = 0; c < size; ++c)
      {
        this->CellVertices.push_back(vertexOfPoint[ids[c]]);
      }
      this->CellVertexOffsets.push_back(static_cast<int>(this->CellVertices.size()));
    }
  }
}

vtkLaplacianDeformationFilter::vtkLaplacianDeformationFilter()
  : Internals(new vtkInternals)
{
  if (!IsCholmodAvailable())
  {
    this->Solver = SOLVER_SIMPLICIAL_LDLT;
  }
  // The core's per-move loops run on VTK's SMP backend.
  this->Internals->Editor.SetParallelFor(
    [](int begin, int end, const std::function<void(int, int)>& body) {
      vtkSMPTools::For(begin, end, [&](int first, int last) { body(first, last); });
    });
  this->SetInputArrayToProcess(
    0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, vtkDataSetAttributes::SCALARS);
}

vtkLaplacianDeformationFilter::~vtkLaplacianDeformationFilter() = default;

bool vtkLaplacianDeformationFilter::IsCholmodAvailable()
{
  return le::SparseCholesky::IsAvailable(le::SolverBackend::Cholmod);
}

void vtkLaplacianDeformationFilter::SetHandleTransform(int group, vtkLinearTransform* transform)
{
  if (group < 0)
  {
    vtkErrorMacro(<< "handle group " << group << " is negative");
    return;
  }
  auto& transforms = this->Internals->HandleTransforms;
  if (group >= static_cast<int>(transforms.size()))
  {
    transforms.resize(group + 1);
  }
  if (transforms[group] != transform)
  {
    transforms[group] = transform;
    this->Modified();
  }
}

vtkLinearTransform* vtkLaplacianDeformationFilter::GetHandleTransform(int group)
{
  const auto& transforms = this->Internals->HandleTransforms;
  return group >= 0 && group < static_cast<int>(transforms.size()) ? transforms[group].Get()
                                                                    : nullptr;
}

int vtkLaplacianDeformationFilter::GetNumberOfHandleTransforms()
{
  return static_cast<int>(this->Internals->HandleTransforms.size());
}

void vtkLaplacianDeformationFilter::RemoveAllHandleTransforms()
{
  if (!this->Internals->HandleTransforms.empty())
  {
    this->Internals->HandleTransforms.clear();
    this->Modified();
  }
}

vtkMTimeType vtkLaplacianDeformationFilter::GetMTime()
{
  vtkMTimeType time = this->Superclass::GetMTime();
  for (const auto& transform : this->Internals->HandleTransforms)
  {
    if (transform)
    {
      time = std::max(time, transform->GetMTime());
    }
  }
  return time;
}

int vtkLaplacianDeformationFilter::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkPolyData* input = vtkPolyData::GetData(inputVector[0]);
  vtkPolyData* output = vtkPolyData::GetData(outputVector);
  vtkMultiProcessController* controller = vtkMultiProcessController::GetGlobalController();
  if (controller && controller->GetNumberOfProcesses() > 1)
  {
    return this->EditGathered(controller, input, output);
  }
  return this->Edit(input, output, static_cast<double>(input->GetMTime()));
}

int vtkLaplacianDeformationFilter::EditGathered(
  vtkMultiProcessController* controller, vtkPolyData* input, vtkPolyData* output)
{
  // The edit is global (one sparse system over the region), so the pieces go to the first rank,
  // which edits the whole surface (coincident piece-boundary points merge) and sends each rank
  // its own points back, in its own order. Rank 0 caches the gathered surface on the pieces'
  // MTimes, so a handle move sends no geometry.
  vtkInternals& internals = *this->Internals;
  const int rank = controller->GetLocalProcessId();
  const int ranks = controller->GetNumberOfProcesses();
  const double localTime = static_cast<double>(input->GetMTime());
  std::vector<double> times(ranks, 0.0);
  controller->Gather(&localTime, times.data(), 1, 0);
  double changed = 0.0;
  if (rank == 0)
  {
    changed = times != internals.PieceTimes || !internals.Gathered ? 1.0 : 0.0;
  }
  controller->Broadcast(&changed, 1, 0);
  std::vector<vtkSmartPointer<vtkDataObject>> pieces;
  if (changed != 0.0)
  {
    vtkNew<vtkPolyData> local;
    local->ShallowCopy(input);
    controller->Gather(local, pieces, 0);
  }

  const int pointsTag = 40501;
  std::vector<double> moved;
  if (rank == 0)
  {
    if (changed != 0.0)
    {
      vtkNew<vtkAppendPolyData> append;
      internals.PieceSizes.assign(ranks, 0);
      for (int r = 0; r < ranks; ++r)
      {
        auto* piece = vtkPolyData::SafeDownCast(pieces[r]);
        internals.PieceSizes[r] = piece ? piece->GetNumberOfPoints() : 0;
        if (piece)
        {
          append->AddInputData(piece);
        }
      }
      append->Update();
      internals.Gathered = vtkSmartPointer<vtkPolyData>::New();
      internals.Gathered->ShallowCopy(append->GetOutput());
      internals.PieceTimes = times;
      ++internals.GatheredVersion;
    }
    vtkNew<vtkPolyData> edited;
    this->Edit(internals.Gathered, edited, static_cast<double>(internals.GatheredVersion));
    // Each rank's slice: coordinates, then the EditRole values.
    vtkIdType offset = 0;
    for (int r = 0; r < ranks; ++r)
    {
      const vtkIdType count = internals.PieceSizes[r];
      std::vector<double> slice(4 * count);
      vtkDataArray* roles = edited->GetPointData()->GetArray("EditRole");
      for (vtkIdType i = 0; i < count; ++i)
      {
        edited->GetPoint(offset + i, slice.data() + 3 * i);
        slice[3 * count + i] = roles ? roles->GetTuple1(offset + i) : 0.0;
      }
      offset += count;
      if (r == 0)
      {
        moved = std::move(slice);
      }
      else
      {
        controller->Send(slice.data(), 4 * count, r, pointsTag);
      }
    }
  }
  else
  {
    moved.resize(4 * input->GetNumberOfPoints());
    controller->Receive(moved.data(), 4 * input->GetNumberOfPoints(), 0, pointsTag);
  }

  // This rank's output: its input with the moved points and the roles. Normals are dropped
  // rather than left stale (the serial path refreshes them).
  output->ShallowCopy(input);
  output->GetPointData()->SetNormals(nullptr);
  output->GetCellData()->SetNormals(nullptr);
  const vtkIdType count = input->GetNumberOfPoints();
  vtkNew<vtkPoints> points;
  points->SetDataType(input->GetPoints() ? input->GetPoints()->GetDataType() : VTK_DOUBLE);
  points->SetNumberOfPoints(count);
  vtkNew<vtkUnsignedCharArray> roles;
  roles->SetName("EditRole");
  roles->SetNumberOfTuples(count);
  for (vtkIdType i = 0; i < count; ++i)
  {
    points->SetPoint(i, moved.data() + 3 * i);
    roles->SetValue(i, static_cast<unsigned char>(moved[3 * count + i]));
  }
  if (count > 0)
  {
    output->SetPoints(points);
  }
  if (this->GenerateEditRoles)
  {
    output->GetPointData()->AddArray(roles);
  }
  return 1;
}

int vtkLaplacianDeformationFilter::Edit(vtkPolyData* input, vtkPolyData* output, double inputVersion)
{
  vtkInternals& internals = *this->Internals;
  output->ShallowCopy(input);
  this->NumberOfROIVertices = 0;
  this->NumberOfHandleVertices = 0;
  this->TopologyTime = 0.0;
  this->SetupTime = 0.0;
  this->AnalysisTime = 0.0;
  this->FactorizationTime = 0.0;
  this->SolveTime = 0.0;

  // On bad input: say what is wrong and pass the input through unchanged.
  auto fail = [&](const std::string& message) {
    vtkErrorMacro(<< message);
    internals.Invalidate();
    output->ShallowCopy(input);
    return 1;
  };

  const vtkIdType numberOfPoints = input->GetNumberOfPoints();
  if (numberOfPoints == 0)
  {
    return fail("The input mesh is empty.");
  }
  if (input->GetNumberOfPolys() == 0)
  {
    return fail("The input has no polygons (only vertices, lines or strips): the filter edits "
                "triangle surfaces.");
  }
  if (input->GetNumberOfStrips() > 0)
  {
    return fail("The input has triangle strips; run vtkTriangleFilter first.");
  }
  vtkPoints* inputPoints = input->GetPoints();

  vtkDataArray* selection = nullptr;
  if (this->SelectionMode == SELECTION_ARRAY)
  {
    selection = this->GetInputArrayToProcess(0, input);
    if (!selection)
    {
      return fail("Selection mode is Array but the input has no such point array; name an "
                  "integer point array with SetInputArrayToProcess.");
    }
    if (!IsIntegerType(selection->GetDataType()) || selection->GetNumberOfComponents() != 1)
    {
      return fail(std::string("The selection array '") +
        (selection->GetName() ? selection->GetName() : "") +
        "' must be an integer array with one component (0 fixed, 1 ROI, 2+ handle).");
    }
  }
  else if (!(this->HandleRadius > 0.0) || !(this->ROIRadius > 0.0))
  {
    return fail("HandleRadius and ROIRadius must be positive.");
  }

  // The surface graph depends on the input alone: a new region reuses it.
  const std::vector<double> meshKey = { inputVersion,
    static_cast<double>(this->MergeCoincidentPoints) };
  if (meshKey != internals.MeshKey)
  {
    const Clock::time_point start = Clock::now();
    internals.Invalidate();
    internals.MeshKey.clear();
    // Checked once per input, not on every handle move.
    for (vtkIdType i = 0; i < numberOfPoints; ++i)
    {
      const double* p = inputPoints->GetPoint(i);
      if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2]))
      {
        return fail("Point " + std::to_string(i) + " has a NaN or infinite coordinate.");
      }
    }
    const std::string error = internals.BuildMesh(input, this->MergeCoincidentPoints != 0);
    if (!error.empty())
    {
      return fail(error);
    }
    internals.MeshKey = meshKey;
    this->TopologyTime = SecondsSince(start);
  }

  const std::vector<double> key = { inputVersion,
    static_cast<double>(this->SelectionMode), this->HandleCenter[0], this->HandleCenter[1],
    this->HandleCenter[2], this->HandleRadius, this->ROIRadius, this->AnchorPadding,
    this->HandleWeight, this->AnchorWeight, static_cast<double>(this->LaplacianWeights),
    static_cast<double>(this->OperatorOrder), static_cast<double>(this->Solver),
    static_cast<double>(this->MergeCoincidentPoints), static_cast<double>(this->Ordering),
    this->MaximumFactorMemory };
  const std::string arrayName = selection && selection->GetName() ? selection->GetName() : "";

  if (key != internals.CacheKey || arrayName != internals.CacheArrayName)
  {
    const Clock::time_point start = Clock::now();
    internals.Invalidate();
    this->UpdateProgress(0.0);

    this->UpdateProgress(0.1);

    std::string error;
    const auto& vertexOfPoint = internals.Mesh->GetVertexOfPoint();
    if (selection)
    {
      std::vector<int> labels(internals.Mesh->GetNumberOfVertices(), 0);
      for (vtkIdType i = 0; i < numberOfPoints; ++i)
      {
        int& label = labels[vertexOfPoint[i]];
        label = std::max(label, static_cast<int>(selection->GetComponent(i, 0)));
      }
      error = le::SelectLabeledRegion(*internals.Mesh, labels, this->AnchorPadding, internals.Region);
    }
    else
    {
      const int centerVertex =
        internals.Mesh->FindNearestVertex(internals.Normalize(this->HandleCenter));
      error = le::SelectGeodesicRegion(*internals.Mesh, centerVertex,
        this->HandleRadius * internals.Scale, this->ROIRadius * internals.Scale,
        this->AnchorPadding, internals.Region);
    }
    if (!error.empty())
    {
      return fail("Cannot select the region: " + error + ".");
    }
    this->UpdateProgress(0.3);
    if (this->GetAbortExecute())
    {
      internals.Invalidate();
      return 1;
    }

    le::DeformationOptions options;
    options.Weights = this->LaplacianWeights == WEIGHTS_COTANGENT ? le::LaplacianWeights::Cotangent
                                                                  : le::LaplacianWeights::Uniform;
    options.Order = this->OperatorOrder;
    options.HandleWeight = this->HandleWeight;
    options.AnchorWeight = this->AnchorWeight;
    options.Backend = this->Solver == SOLVER_CHOLMOD ? le::SolverBackend::Cholmod
                                                     : le::SolverBackend::SimplicialLDLT;
    options.Ordering = static_cast<le::FillOrdering>(this->Ordering);
    options.MaximumFactorBytes = 1048576.0 *
      (this->MaximumFactorMemory > 0.0
          ? this->MaximumFactorMemory
          : 0.8 * static_cast<double>(vtksys::SystemInformation().GetAvailablePhysicalMemory()));
    error = internals.Editor.Build(internals.Mesh, internals.Region, options);
    this->NumberOfFactorizations = internals.Editor.GetNumberOfFactorizations();
    if (!error.empty())
    {
      return fail("Cannot factor the editing system: " + error + ".");
    }
    internals.IndexRegion(input);
    internals.CacheKey = key;
    internals.CacheArrayName = arrayName;
    this->SetupTime = SecondsSince(start);
    this->UpdateProgress(0.7);
  }

  // What the rotation mode needs is built once per region too (the implicit mode factors).
  le::RotationOptions rotation;
  rotation.Mode = this->RotationMode == ROTATION_EXPLICIT ? le::RotationMode::Explicit
    : this->RotationMode == ROTATION_IMPLICIT             ? le::RotationMode::Implicit
                                                          : le::RotationMode::None;
  rotation.NormalSmoothingRadius = this->NormalSmoothingRadius > 0.0
    ? this->NormalSmoothingRadius * internals.Scale
    : 0.2 * internals.Region.Radius;
  rotation.Iterations = this->NumberOfIterations;
  rotation.PreserveDetailScale = this->PreserveDetailScale != 0;
  {
    const Clock::time_point start = Clock::now();
    bool built = false;
    const std::string error = internals.Editor.Prepare(rotation, built);
    this->NumberOfFactorizations = internals.Editor.GetNumberOfFactorizations();
    if (!error.empty())
    {
      return fail("Cannot factor the implicit rotation system: " + error + ".");
    }
    if (built)
    {
      this->SetupTime += SecondsSince(start);
    }
    this->FactorMemory = internals.Editor.GetFactorBytes() / 1048576.0;
    if (this->SetupTime > 0.0)
    {
      this->AnalysisTime = internals.Editor.GetAnalysisSeconds();
      this->FactorizationTime = internals.Editor.GetFactorizationSeconds();
    }
  }
  this->UpdateProgress(0.9);
  if (this->GetAbortExecute())
  {
    return 1; // the output is still the input; the factor stays cached
  }

  const Clock::time_point solveStart = Clock::now();
  std::vector<le::AffineMap> maps(internals.Region.NumberOfHandleGroups, le::AffineMap::Identity());
  for (int g = 0; g < internals.Region.NumberOfHandleGroups; ++g)
  {
    if (vtkLinearTransform* transform = this->GetHandleTransform(g))
    {
      maps[g] = internals.NormalizedMap(transform);
    }
  }
  if (!this->GetHandleTransform(0) && !maps.empty())
  {
    vtkNew<vtkTransform> properties;
    properties->PostMultiply();
    properties->Translate(-this->HandleCenter[0], -this->HandleCenter[1], -this->HandleCenter[2]);
    properties->RotateX(this->HandleRotation[0]);
    properties->RotateY(this->HandleRotation[1]);
    properties->RotateZ(this->HandleRotation[2]);
    properties->Translate(this->HandleCenter);
    properties->Translate(this->HandleTranslation);
    maps[0] = internals.NormalizedMap(properties);
  }
  le::Positions solution;
  internals.Editor.Solve(rotation, maps, solution);
  if (!solution.allFinite())
  {
    return fail("The solve produced non-finite coordinates; the handle transform may be "
                "degenerate.");
  }

  // Write the moved ROI points; every other point keeps its input coordinates exactly.
  vtkNew<vtkPoints> outputPoints;
  outputPoints->SetDataType(inputPoints->GetDataType());
  outputPoints->DeepCopy(inputPoints);
  const auto& roiPoints = internals.RoiPoints;
  vtkSMPTools::For(0, static_cast<vtkIdType>(roiPoints.size()), [&](vtkIdType begin, vtkIdType end) {
    for (vtkIdType r = begin; r < end; ++r)
    {
      const le::Vector3 p = internals.Denormalize(solution.row(roiPoints[r].second).transpose());
      outputPoints->SetPoint(roiPoints[r].first, p.data());
    }
  });
  output->SetPoints(outputPoints);
  this->SolveTime = SecondsSince(solveStart);

  internals.RefreshNormals(output, solution);
  if (this->GenerateEditRoles)
  {
    output->GetPointData()->AddArray(internals.Roles);
  }

  this->NumberOfROIVertices = internals.Region.GetNumberOfVertices();
  for (auto role : internals.Region.Roles)
  {
    this->NumberOfHandleVertices += role == le::VertexRole::Handle ? 1 : 0;
  }
  this->UpdateProgress(1.0);
  return 1;
}

void vtkLaplacianDeformationFilter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "SelectionMode: " << this->SelectionMode << "\n";
  os << indent << "HandleCenter: (" << this->HandleCenter[0] << ", " << this->HandleCenter[1]
     << ", " << this->HandleCenter[2] << ")\n";
  os << indent << "HandleTranslation: (" << this->HandleTranslation[0] << ", "
     << this->HandleTranslation[1] << ", " << this->HandleTranslation[2] << ")\n";
  os << indent << "HandleRotation: (" << this->HandleRotation[0] << ", " << this->HandleRotation[1]
     << ", " << this->HandleRotation[2] << ")\n";
  os << indent << "HandleRadius: " << this->HandleRadius << "\n";
  os << indent << "ROIRadius: " << this->ROIRadius << "\n";
  os << indent << "AnchorPadding: " << this->AnchorPadding << "\n";
  os << indent << "HandleWeight: " << this->HandleWeight << "\n";
  os << indent << "AnchorWeight: " << this->AnchorWeight << "\n";
  os << indent << "LaplacianWeights: " << this->LaplacianWeights << "\n";
  os << indent << "OperatorOrder: " << this->OperatorOrder << "\n";
  os << indent << "RotationMode: " << this->RotationMode << "\n";
  os << indent << "NormalSmoothingRadius: " << this->NormalSmoothingRadius << "\n";
  os << indent << "NumberOfIterations: " << this->NumberOfIterations << "\n";
  os << indent << "PreserveDetailScale: " << this->PreserveDetailScale << "\n";
  os << indent << "Solver: " << this->Solver << "\n";
  os << indent << "Ordering: " << this->Ordering << "\n";
  os << indent << "MaximumFactorMemory: " << this->MaximumFactorMemory << "\n";
  os << indent << "MergeCoincidentPoints: " << this->MergeCoincidentPoints << "\n";
  os << indent << "GenerateEditRoles: " << this->GenerateEditRoles << "\n";
  os << indent << "NumberOfHandleTransforms: " << this->Internals->HandleTransforms.size() << "\n";
  os << indent << "NumberOfFactorizations: " << this->NumberOfFactorizations << "\n";
  os << indent << "NumberOfROIVertices: " << this->NumberOfROIVertices << "\n";
}
