#include "vtkLaplacianDeformationFilter.h"

#include "LaplacianEditor.h"
#include "SurfaceMesh.h"
#include "vtkLaplacianNormalRefresher.h"
#include "vtkLaplacianPieceEdit.h"
#include "vtkLaplacianSurfaceAdapter.h"

#include "vtkBoundingBox.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkErrorCode.h"
#include "vtkExtractSelection.h"
#include "vtkIdList.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkIntArray.h"
#include "vtkLinearTransform.h"
#include "vtkLookupTable.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSelection.h"
#include "vtkSelectionNode.h"
#include "vtkSignedCharArray.h"
#include "vtkSmartPointer.h"
#include "vtkSMPTools.h"
#include "vtkTransform.h"
#include "vtkVariant.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <functional>
#include <initializer_list>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace le = LaplacianEditing;

vtkStandardNewMacro(vtkLaplacianDeformationFilter);

// The filter's enums are the core's, value for value.
static_assert(static_cast<int>(le::LaplacianWeights::Uniform) ==
    vtkLaplacianDeformationFilter::WEIGHTS_UNIFORM &&
  static_cast<int>(le::LaplacianWeights::Cotangent) ==
    vtkLaplacianDeformationFilter::WEIGHTS_COTANGENT);
static_assert(static_cast<int>(le::RotationMode::None) ==
    vtkLaplacianDeformationFilter::ROTATION_NONE &&
  static_cast<int>(le::RotationMode::Explicit) == vtkLaplacianDeformationFilter::ROTATION_EXPLICIT &&
  static_cast<int>(le::RotationMode::Implicit) == vtkLaplacianDeformationFilter::ROTATION_IMPLICIT &&
  static_cast<int>(le::RotationMode::AsRigidAsPossible) ==
    vtkLaplacianDeformationFilter::ROTATION_AS_RIGID_AS_POSSIBLE);
static_assert(static_cast<int>(le::SolverBackend::Cholmod) ==
    vtkLaplacianDeformationFilter::SOLVER_CHOLMOD &&
  static_cast<int>(le::SolverBackend::SimplicialLDLT) ==
    vtkLaplacianDeformationFilter::SOLVER_SIMPLICIAL_LDLT &&
  static_cast<int>(le::SolverBackend::Distributed) == vtkLaplacianDeformationFilter::SOLVER_MUMPS);
static_assert(static_cast<int>(le::FillOrdering::Automatic) ==
    vtkLaplacianDeformationFilter::ORDERING_AUTOMATIC &&
  static_cast<int>(le::FillOrdering::AMD) == vtkLaplacianDeformationFilter::ORDERING_AMD &&
  static_cast<int>(le::FillOrdering::METIS) == vtkLaplacianDeformationFilter::ORDERING_METIS &&
  static_cast<int>(le::FillOrdering::NestedDissection) ==
    vtkLaplacianDeformationFilter::ORDERING_NESTED_DISSECTION);
static_assert(static_cast<int>(le::DistanceMethod::FastMarching) ==
    vtkLaplacianDeformationFilter::DISTANCE_FAST_MARCHING &&
  static_cast<int>(le::DistanceMethod::EdgePaths) ==
    vtkLaplacianDeformationFilter::DISTANCE_EDGE_PATHS);
static_assert(static_cast<int>(le::VertexRole::Fixed) == vtkLaplacianDeformationFilter::ROLE_FIXED &&
  static_cast<int>(le::VertexRole::Anchor) == vtkLaplacianDeformationFilter::ROLE_ANCHOR &&
  static_cast<int>(le::VertexRole::Free) == vtkLaplacianDeformationFilter::ROLE_FREE &&
  static_cast<int>(le::VertexRole::Handle) == vtkLaplacianDeformationFilter::ROLE_HANDLE);

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
// The handle properties as a transform: rotations in degrees about x, y, then z, about
// `center`, then a translation.
vtkSmartPointer<vtkTransform> PropertyTransform(
  const double center[3], const double rotation[3], const double translation[3])
{
  auto transform = vtkSmartPointer<vtkTransform>::New();
  transform->PostMultiply();
  transform->Translate(-center[0], -center[1], -center[2]);
  transform->RotateX(rotation[0]);
  transform->RotateY(rotation[1]);
  transform->RotateZ(rotation[2]);
  transform->Translate(center);
  transform->Translate(translation);
  return transform;
}
}

struct vtkLaplacianDeformationFilter::vtkInternals
{
  std::vector<vtkSmartPointer<vtkLinearTransform>> HandleTransforms;
  // Group -> (translation, rotation) for groups 1 and above moved by properties.
  std::map<int, std::array<double, 6>> HandleGroupMotions;
  // Per handle group of the current region: its rest centroid in mesh units, if it has
  // vertices; found once per region, as moves and ParaView's panel read it every update.
  std::vector<std::optional<std::array<double, 3>>> GroupCenters;
  // Committed rest shapes, newest last, for the input of the given MTime.
  std::vector<vtkSmartPointer<vtkPoints>> Commits;
  vtkMTimeType CommittedInput = 0;
  vtkNew<vtkPolyData> CommittedRest;
  vtkPolyData* LastInput = nullptr;

  // What the surface graph was built from: the rest surface's MTime and the merge flag.
  vtkMTimeType SurfaceTime = 0;
  int SurfaceMerge = -1;
  vtkLaplacianSurfaceAdapter Surface;
  // The part of the rest surface the edit can reach, what it was computed from (rest time,
  // selection time, handle centre), the labelled points' half extent or the handle centre's
  // distance to the surface; and the reach the surface graph was built on.
  vtkLaplacianSurfaceAdapter::Reach Reach;
  double ReachKey[5] = { -1.0, -1.0, 0.0, 0.0, 0.0 };
  double ReachExtent = 0.0;
  vtkLaplacianSurfaceAdapter::Reach SurfaceReach;
  double AvailableMemory = 0.0; // megabytes
  double Diagonal = 0.0;        // of the rest surface's bounding box
  le::LaplacianEditor Editor;
  vtkLaplacianNormalRefresher Normals;
  vtkDataArray* Selection = nullptr;
  // The handle from a selection on port 1 (then Selection points to it), and what it was made
  // from (selection time, input content time).
  vtkSmartPointer<vtkIntArray> SelectedLabels;
  vtkMTimeType SelectedKey[2] = { 0, 0 };
  // The current handle maps and result, in the core's frame.
  std::vector<le::AffineMap> Maps;
  le::Positions Solution;
  // Whether the last EditSurface solved an edit, and a number bumped whenever the edit's
  // region, system or rotation model is rebuilt.
  bool Edited = false;
  unsigned long ModelVersion = 0;
};

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
  this->SetNumberOfInputPorts(2);
}

void vtkLaplacianDeformationFilter::SetSelectionData(vtkSelection* selection)
{
  this->SetInputData(1, selection);
}

int vtkLaplacianDeformationFilter::FillInputPortInformation(int port, vtkInformation* info)
{
  if (port == 1)
  {
    info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkSelection");
    info->Set(vtkAlgorithm::INPUT_IS_OPTIONAL(), 1);
    return 1;
  }
  return this->Superclass::FillInputPortInformation(port, info);
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

void vtkLaplacianDeformationFilter::SetHandleGroupMotion(vtkIdType group, double translationX,
  double translationY, double translationZ, double rotationX, double rotationY, double rotationZ)
{
  if (group < 1 || group > VTK_INT_MAX)
  {
    vtkErrorMacro(<< "handle group " << group << " cannot take a motion: motions are for groups "
                  << "1 and above (group 0 moves with HandleTranslation and HandleRotation)");
    return;
  }
  const std::array<double, 6> motion = { translationX, translationY, translationZ, rotationX,
    rotationY, rotationZ };
  auto& motions = this->Internals->HandleGroupMotions;
  const auto found = motions.find(static_cast<int>(group));
  if (found == motions.end() || found->second != motion)
  {
    motions[static_cast<int>(group)] = motion;
    this->Modified();
  }
}

bool vtkLaplacianDeformationFilter::GetHandleGroupMotion(int group, double motion[6])
{
  const auto& motions = this->Internals->HandleGroupMotions;
  const auto found = motions.find(group);
  if (found == motions.end())
  {
    return false;
  }
  std::copy(found->second.begin(), found->second.end(), motion);
  return true;
}

int vtkLaplacianDeformationFilter::GetNumberOfHandleGroupMotions()
{
  return static_cast<int>(this->Internals->HandleGroupMotions.size());
}

void vtkLaplacianDeformationFilter::RemoveAllHandleGroupMotions()
{
  if (!this->Internals->HandleGroupMotions.empty())
  {
    this->Internals->HandleGroupMotions.clear();
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
  this->EditSurface(vtkPolyData::GetData(inputVector[0]), vtkPolyData::GetData(outputVector));
  return 1;
}

void vtkLaplacianDeformationFilter::EditSurface(vtkPolyData* input, vtkPolyData* output)
{
  this->ResetStatistics();
  this->Internals->Edited = false;
  output->ShallowCopy(input);
  if (!this->CheckInput(input))
  {
    return;
  }
  vtkPolyData* rest = this->RestSurface(input);
  output->ShallowCopy(rest);
  // Progress after each stage that may take seconds (graph, region and its factor, rotation
  // model and its factor); each stage is skipped when its cache holds.
  this->UpdateProgress(0.1);
  if (!this->UpdateSurfaceGraph(rest) || this->GetAbortExecute())
  {
    return;
  }
  this->UpdateProgress(0.3);
  if (!this->UpdateRegion(rest) || this->GetAbortExecute())
  {
    return;
  }
  this->UpdateProgress(0.6);
  if (!this->UpdateRotationModel() || this->GetAbortExecute())
  {
    return;
  }
  this->UpdateProgress(0.9);
  this->MapHandles();
  if (this->Solve())
  {
    this->WriteOutput(rest, output);
  }
  this->UpdateProgress(1.0);
}

bool vtkLaplacianDeformationFilter::Fail(const std::string& message)
{
  vtkErrorMacro(<< message);
  this->SetErrorCode(vtkErrorCode::UserError);
  return false;
}

void vtkLaplacianDeformationFilter::ResetStatistics()
{
  this->SetErrorCode(vtkErrorCode::NoError);
  this->NumberOfROIVertices = 0;
  this->NumberOfHandleVertices = 0;
  this->TopologyTime = 0.0;
  this->SetupTime = 0.0;
  this->AnalysisTime = 0.0;
  this->FactorizationTime = 0.0;
  this->SolveTime = 0.0;
  this->NumberOfARAPIterations = 0;
  this->ARAPEnergy = 0.0;
}

double vtkLaplacianDeformationFilter::DiagonalOfWhole(double ownDiagonal) const
{
  return this->WholeDiagonal > 0.0 ? this->WholeDiagonal : ownDiagonal;
}

double vtkLaplacianDeformationFilter::AbsoluteRadius(double radius) const
{
  return this->RadiusUnits == RADIUS_DIAGONAL_FRACTION
    ? radius * this->DiagonalOfWhole(this->Internals->Diagonal)
    : radius;
}

double vtkLaplacianDeformationFilter::GetRadiusScale()
{
  auto* input = vtkPolyData::SafeDownCast(this->GetInputDataObject(0, 0));
  const double diagonal =
    this->DiagonalOfWhole(input && input->GetNumberOfPoints() > 0 ? input->GetLength() : 0.0);
  return this->RadiusUnits == RADIUS_DIAGONAL_FRACTION && diagonal > 0.0 ? diagonal : 1.0;
}

void vtkLaplacianDeformationFilter::WarnAboutRegion(int centerVertex)
{
  const vtkInternals& internals = *this->Internals;
  const le::EditRegion& region = internals.Editor.GetRegion();
  const auto handles = std::count(region.Roles.begin(), region.Roles.end(), le::VertexRole::Handle);
  if (!internals.Selection)
  {
    const double* c = this->HandleCenter;
    const le::Vector3 vertex =
      internals.Surface.Denormalize(internals.Surface.GetMesh()->GetPositions()[centerVertex]);
    const double away = (vertex - le::Vector3(c[0], c[1], c[2])).norm();
    if (away > this->AbsoluteRadius(this->HandleRadius))
    {
      vtkWarningMacro(<< "HandleCenter (" << c[0] << ", " << c[1] << ", " << c[2] << ") lies "
                      << away << " from the surface, farther than the handle radius ("
                      << this->AbsoluteRadius(this->HandleRadius) << " in mesh units): the handle "
                      << "is on the nearest vertex, (" << vertex.x() << ", " << vertex.y()
                      << ", " << vertex.z() << "). Put HandleCenter on the surface.");
    }
    if (!region.BordersFixedPart)
    {
      vtkWarningMacro(<< "The ROI (radius " << this->AbsoluteRadius(this->ROIRadius)
                      << " in mesh units) covers the whole connected part of the surface it "
                      << "lies on: nothing holds it in place but the anchors. Use a smaller "
                      << "ROIRadius, or SetRadiusUnitsToDiagonalFraction() if the radii were "
                      << "meant relative to the mesh's size.");
    }
  }
  if (region.GetNumberOfVertices() == 1)
  {
    vtkWarningMacro(<< "The ROI holds a single vertex, so the edit moves only that vertex: the "
                    << "radii are likely too small for this mesh (diagonal "
                    << internals.Diagonal << "); see SetRadiusUnitsToDiagonalFraction().");
  }
  else if (handles == 1)
  {
    vtkWarningMacro(<< "The handle holds a single vertex: a larger HandleRadius moves the "
                    << "surface more smoothly.");
  }
}

bool vtkLaplacianDeformationFilter::CheckInput(vtkPolyData* input)
{
  vtkInternals& internals = *this->Internals;
  internals.Selection = nullptr;
  if (input->GetNumberOfPoints() == 0)
  {
    return this->Fail("The input mesh is empty.");
  }
  if (input->GetNumberOfPolys() == 0)
  {
    return this->Fail("The input has no polygons (only vertices, lines or strips): the filter "
                      "edits triangle surfaces.");
  }
  if (input->GetNumberOfStrips() > 0)
  {
    return this->Fail("The input has triangle strips; run vtkTriangleFilter first.");
  }
  if (auto* selection = vtkSelection::SafeDownCast(this->GetInputDataObject(1, 0)))
  {
    return this->LabelSelectedPoints(input, selection);
  }
  internals.SelectedLabels = nullptr; // a point each: not kept once the selection is gone
  if (this->SelectionMode == SELECTION_GEODESIC)
  {
    return this->HandleRadius > 0.0 && this->ROIRadius > 0.0
      ? true
      : this->Fail("HandleRadius and ROIRadius must be positive.");
  }
  vtkDataArray* selection = this->GetInputArrayToProcess(0, input);
  if (!selection)
  {
    return this->Fail("Selection mode is Array but the input has no such point array; name an "
                      "integer point array with SetInputArrayToProcess.");
  }
  if (!IsIntegerType(selection->GetDataType()) || selection->GetNumberOfComponents() != 1)
  {
    return this->Fail(std::string("The selection array '") +
      (selection->GetName() ? selection->GetName() : "") +
      "' must be an integer array with one component (0 fixed, 1 ROI, 2+ handle).");
  }
  internals.Selection = selection;
  return true;
}

bool vtkLaplacianDeformationFilter::LabelSelectedPoints(vtkPolyData* input, vtkSelection* selection)
{
  // The selection's labels (SelectionLabels) are the array mode's (2: handle group 0), made
  // again only when the selection or the input changes.
  vtkInternals& internals = *this->Internals;
  if (this->ROIRadius <= 0.0)
  {
    return this->Fail("ROIRadius must be positive: with a selection on input port 1, the ROI is "
                      "every point within ROIRadius of the selected handle.");
  }
  const vtkMTimeType key[2] = { selection->GetMTime(),
    vtkLaplacianSurfaceAdapter::GetContentTime(input) };
  if (!internals.SelectedLabels || !std::equal(key, key + 2, internals.SelectedKey))
  {
    std::copy(key, key + 2, internals.SelectedKey);
    internals.SelectedLabels = this->SelectionLabels(input, selection);
  }
  const int* labels = internals.SelectedLabels->GetPointer(0);
  if (std::find(labels, labels + input->GetNumberOfPoints(), 2) == labels + input->GetNumberOfPoints())
  {
    return this->Fail("The selection on input port 1 selects no point of the input.");
  }
  internals.Selection = internals.SelectedLabels;
  return true;
}

vtkSmartPointer<vtkIntArray> vtkLaplacianDeformationFilter::LabelSelection(
  vtkPolyData* input, vtkSelection* selection, int piece)
{
  // vtkExtractSelection, keeping the topology, marks what is selected in vtkInsidedness arrays.
  vtkNew<vtkSelection> own;
  for (unsigned int n = 0; n < selection->GetNumberOfNodes(); ++n)
  {
    vtkSelectionNode* node = selection->GetNode(n);
    vtkInformation* properties = node->GetProperties();
    const int process =
      properties->Has(vtkSelectionNode::PROCESS_ID()) ? properties->Get(vtkSelectionNode::PROCESS_ID()) : -1;
    if (process == -1 || process == piece)
    {
      own->AddNode(node);
    }
  }
  auto labels = vtkSmartPointer<vtkIntArray>::New();
  labels->SetName("SelectedHandle");
  labels->SetNumberOfValues(input->GetNumberOfPoints());
  labels->FillValue(0);
  if (own->GetNumberOfNodes() == 0)
  {
    return labels;
  }
  vtkNew<vtkExtractSelection> extract;
  extract->PreserveTopologyOn();
  extract->SetInputData(0, input);
  extract->SetInputData(1, own);
  extract->Update();
  auto* marked = vtkDataSet::SafeDownCast(extract->GetOutputDataObject(0));
  vtkDataArray* points = marked ? marked->GetPointData()->GetArray("vtkInsidedness") : nullptr;
  vtkDataArray* cells = marked ? marked->GetCellData()->GetArray("vtkInsidedness") : nullptr;
  for (vtkIdType i = 0; points && i < points->GetNumberOfTuples(); ++i)
  {
    if (points->GetComponent(i, 0) > 0.0)
    {
      labels->SetValue(i, 2);
    }
  }
  vtkNew<vtkIdList> cellPoints;
  for (vtkIdType c = 0; cells && c < cells->GetNumberOfTuples(); ++c)
  {
    if (cells->GetComponent(c, 0) > 0.0)
    {
      input->GetCellPoints(c, cellPoints);
      for (vtkIdType k = 0; k < cellPoints->GetNumberOfIds(); ++k)
      {
        labels->SetValue(cellPoints->GetId(k), 2);
      }
    }
  }
  return labels;
}

vtkSmartPointer<vtkIntArray> vtkLaplacianDeformationFilter::SelectionLabels(
  vtkPolyData* input, vtkSelection* selection)
{
  return LabelSelection(input, selection, 0);
}

double vtkLaplacianDeformationFilter::SelectionGrowth() const
{
  const vtkInternals& internals = *this->Internals;
  const bool fromSelection =
    internals.SelectedLabels && internals.Selection == internals.SelectedLabels;
  return fromSelection ? this->AbsoluteRadius(this->ROIRadius) : 0.0;
}

vtkPolyData* vtkLaplacianDeformationFilter::RestSurface(vtkPolyData* input)
{
  // The input, or after CommitEdit the input with the committed points.
  vtkInternals& internals = *this->Internals;
  const vtkMTimeType inputTime = vtkLaplacianSurfaceAdapter::GetContentTime(input);
  if (input != internals.LastInput || inputTime != internals.CommittedInput)
  {
    internals.Commits.clear();
  }
  internals.LastInput = input;
  internals.CommittedInput = inputTime;
  if (internals.Commits.empty())
  {
    return input;
  }
  if (internals.CommittedRest->GetPoints() != internals.Commits.back())
  {
    internals.CommittedRest->ShallowCopy(input);
    internals.CommittedRest->SetPoints(internals.Commits.back());
  }
  return internals.CommittedRest;
}

void vtkLaplacianDeformationFilter::ComputeReach(vtkPolyData* rest)
{
  // Every vertex the edit can touch lies within a geodesic distance, hence a Euclidean one, of
  // its seeds: in geodesic mode, the handle centre with the ROI radius around its nearest corner
  // (so any corner as near is covered too); in array mode, the labelled points. Around them, the
  // explicit mode's normal smoothing support (by default 0.2 of the ROI radius; in array mode,
  // of the labelled points' extent), plus 10% against the discretization of the distances. The
  // search for the nearest corner or the labelled points is one pass over the input, repeated
  // only when what it reads changes.
  vtkInternals& internals = *this->Internals;
  vtkDataArray* selection = internals.Selection;
  const double key[5] = { static_cast<double>(vtkLaplacianSurfaceAdapter::GetContentTime(rest)),
    selection ? static_cast<double>(selection->GetMTime()) : -1.0,
    selection ? 0.0 : this->HandleCenter[0], selection ? 0.0 : this->HandleCenter[1],
    selection ? 0.0 : this->HandleCenter[2] };
  vtkLaplacianSurfaceAdapter::Reach& reach = internals.Reach;
  if (!std::equal(key, key + 5, internals.ReachKey))
  {
    std::copy(key, key + 5, internals.ReachKey);
    reach.Seeds.clear();
    internals.ReachExtent = 0.0;
    if (selection)
    {
      for (vtkIdType i = 0; i < rest->GetNumberOfPoints(); ++i)
      {
        if (selection->GetComponent(i, 0) != 0.0)
        {
          const double* p = rest->GetPoint(i);
          reach.Seeds.push_back({ p[0], p[1], p[2] });
        }
      }
      vtkBoundingBox box;
      for (auto seed : reach.Seeds)
      {
        box.AddPoint(seed.data());
      }
      internals.ReachExtent = box.IsValid() ? 0.5 * box.GetDiagonalLength() : 0.0;
    }
    else
    {
      const vtkIdType nearest = vtkLaplacianSurfaceAdapter::FindNearestCorner(rest, this->HandleCenter);
      reach.Seeds.push_back({ this->HandleCenter[0], this->HandleCenter[1], this->HandleCenter[2] });
      internals.ReachExtent = nearest < 0
        ? -1.0
        : std::sqrt(vtkMath::Distance2BetweenPoints(rest->GetPoint(nearest), this->HandleCenter));
    }
  }
  if (reach.Seeds.empty() || internals.ReachExtent < 0.0)
  {
    reach.Margin = -1.0; // nothing labelled, or no polygon: the core reports it on the whole input
    return;
  }
  reach.Margin = this->ReachMargin(selection != nullptr, internals.ReachExtent, this->SelectionGrowth());
}

double vtkLaplacianDeformationFilter::ReachMargin(bool labelled, double extent, double growth) const
{
  const double roi = labelled ? extent : this->AbsoluteRadius(this->ROIRadius);
  const double smoothing = this->NormalSmoothingRadius > 0.0
    ? this->AbsoluteRadius(this->NormalSmoothingRadius)
    : 0.2 * (labelled ? 2.0 * roi + growth : roi);
  return 1.1 * ((labelled ? growth : 2.0 * extent + roi) + smoothing);
}

bool vtkLaplacianDeformationFilter::UpdateSurfaceGraph(vtkPolyData* rest)
{
  // The surface graph depends on the rest surface and on the part of it the edit can reach.
  vtkInternals& internals = *this->Internals;
  const vtkMTimeType time = vtkLaplacianSurfaceAdapter::GetContentTime(rest);
  internals.Diagonal = rest->GetLength();
  this->ComputeReach(rest);
  const vtkLaplacianSurfaceAdapter::Reach& reach = internals.Reach;
  if (time == internals.SurfaceTime && this->MergeCoincidentPoints == internals.SurfaceMerge &&
    reach == internals.SurfaceReach)
  {
    return true;
  }
  const Clock::time_point start = Clock::now();
  internals.SurfaceTime = 0;
  const std::string error = internals.Surface.Build(rest, this->MergeCoincidentPoints != 0, reach);
  internals.Editor.SetMesh(internals.Surface.GetMesh());
  if (!error.empty())
  {
    return this->Fail(error);
  }
  // The automatic factor limit, taken once per surface so that it does not refactor each move.
  internals.AvailableMemory = vtkLaplacianSurfaceAdapter::GetAutomaticFactorLimit();
  internals.SurfaceTime = time;
  internals.SurfaceMerge = this->MergeCoincidentPoints;
  internals.SurfaceReach = reach;
  this->NumberOfSurfaceVertices = internals.Surface.GetMesh()->GetNumberOfVertices();
  this->TopologyTime = SecondsSince(start);
  return true;
}

bool vtkLaplacianDeformationFilter::UpdateRegion(vtkPolyData* rest)
{
  // The property-to-core mapping of the region and its system, in one place.
  vtkInternals& internals = *this->Internals;
  const vtkLaplacianSurfaceAdapter& surface = internals.Surface;
  le::RegionRequest region;
  region.AnchorPadding = this->AnchorPadding;
  region.Distances = static_cast<le::DistanceMethod>(this->DistanceMethod);
  vtkDataArray* selection = internals.Selection;
  if (selection)
  {
    region.Selection = le::RegionRequest::Kind::Labeled;
    region.LabelsVersion =
      std::max(vtkLaplacianSurfaceAdapter::GetContentTime(rest), selection->GetMTime());
    region.GrowRadius = this->SelectionGrowth() * surface.GetScale();
  }
  else
  {
    region.CenterVertex = surface.GetMesh()->FindNearestVertex(surface.Normalize(this->HandleCenter));
    region.HandleRadius = this->AbsoluteRadius(this->HandleRadius) * surface.GetScale();
    region.ROIRadius = this->AbsoluteRadius(this->ROIRadius) * surface.GetScale();
  }
  le::DeformationOptions system;
  system.Weights = static_cast<le::LaplacianWeights>(this->LaplacianWeights);
  system.Order = this->OperatorOrder;
  system.HandleWeight = this->HandleWeight;
  system.AnchorWeight = this->AnchorWeight;
  system.Backend = static_cast<le::SolverBackend>(this->Solver);
  system.Ordering = static_cast<le::FillOrdering>(this->Ordering);
  system.LeastSquares = this->RotationMode != ROTATION_AS_RIGID_AS_POSSIBLE;
  system.MaximumFactorBytes = 1048576.0 *
    (this->MaximumFactorMemory > 0.0 ? this->MaximumFactorMemory : internals.AvailableMemory);
  system.Distributed = this->GetDistributedSolver();
  if (this->Solver == SOLVER_MUMPS && !system.Distributed)
  {
    return this->Fail("The MUMPS solver factors across MPI processes: it needs "
                      "vtkPLaplacianDeformationFilter in an MPI run, in a build with MUMPS. Use "
                      "CHOLMOD or SimplicialLDLT here.");
  }

  const Clock::time_point start = Clock::now();
  const le::EditStatus status = internals.Editor.UpdateRegion(
    region, [&] { return surface.VertexLabels(selection); }, system);
  this->NumberOfFactorizations = internals.Editor.GetNumberOfFactorizations();
  this->NumberOfFactorizationAttempts = internals.Editor.GetNumberOfFactorizationAttempts();
  if (!status.Ok())
  {
    return this->Fail("Cannot edit: " + status.Error + ".");
  }
  if (status.Work & le::RebuiltRegion)
  {
    this->WarnAboutRegion(region.CenterVertex);
  }
  if (status.Work != le::RebuiltNothing)
  {
    ++internals.ModelVersion;
    internals.Surface.IndexRegion(internals.Editor.GetRegion());
    this->FindGroupCenters();
    internals.Normals.Index(rest, surface);
    this->SetupTime = SecondsSince(start);
  }
  return true;
}

void vtkLaplacianDeformationFilter::SetDragging(vtkTypeBool dragging)
{
  if (this->Dragging == dragging)
  {
    return;
  }
  this->Dragging = dragging;
  this->SettleAfterDrag = !dragging;
  if (!dragging)
  {
    this->Modified(); // the next update settles the pose the drag left
  }
}

bool vtkLaplacianDeformationFilter::UpdateRotationModel()
{
  vtkInternals& internals = *this->Internals;
  le::RotationOptions rotation;
  rotation.Mode = static_cast<le::RotationMode>(this->RotationMode);
  rotation.NormalSmoothingRadius = this->NormalSmoothingRadius > 0.0
    ? this->AbsoluteRadius(this->NormalSmoothingRadius) * internals.Surface.GetScale()
    : 0.2 * internals.Editor.GetRegion().Radius;
  rotation.Iterations = this->NumberOfIterations;
  rotation.PreserveDetailScale = this->PreserveDetailScale != 0;
  const bool paper = this->ImplicitFormulation == IMPLICIT_PAPER;
  rotation.Formulation.PerEdge = !paper;
  rotation.Formulation.AllowScaling = paper;
  rotation.Arap.MaximumIterations =
    this->Dragging ? std::min(this->DragARAPIterations, this->ARAPIterations) : this->ARAPIterations;
  rotation.Arap.Tolerance = this->SettleAfterDrag ? 0.0 : this->Convergence;
  this->SettleAfterDrag = false;
  rotation.Arap.Accelerate = this->Acceleration != 0;
  rotation.Arap.Extrapolate = this->Extrapolation != 0;

  const Clock::time_point start = Clock::now();
  const le::EditStatus status = internals.Editor.UpdateRotationModel(rotation);
  this->NumberOfFactorizations = internals.Editor.GetNumberOfFactorizations();
  this->NumberOfFactorizationAttempts = internals.Editor.GetNumberOfFactorizationAttempts();
  if (!status.Ok())
  {
    return this->Fail("Cannot edit: " + status.Error + ".");
  }
  if (status.Work != le::RebuiltNothing)
  {
    ++internals.ModelVersion;
    this->SetupTime += SecondsSince(start);
    const bool firstOrderEnergy = this->RotationMode == ROTATION_AS_RIGID_AS_POSSIBLE ||
      (this->RotationMode == ROTATION_IMPLICIT && !paper);
    if (this->OperatorOrder == 2 && firstOrderEnergy)
    {
      vtkWarningMacro(<< "OperatorOrder 2 has no effect in this rotation mode: its energy "
                      << "compares one-ring edges, a first-order measure. The bi-Laplacian "
                      << "applies in the None and Explicit modes and in the Paper implicit "
                      << "formulation.");
    }
  }
  if (this->SetupTime > 0.0)
  {
    this->AnalysisTime = internals.Editor.GetAnalysisSeconds();
    this->FactorizationTime = internals.Editor.GetFactorizationSeconds();
  }
  this->FactorMemory = internals.Editor.GetFactorBytes() / 1048576.0;
  this->FactoredAcrossProcesses = internals.Editor.IsFactorDistributed();
  return true;
}

void vtkLaplacianDeformationFilter::MapHandles()
{
  // Group g follows its transform; without one, group 0 follows the handle properties and
  // the others their motions about their rest centroids.
  vtkInternals& internals = *this->Internals;
  const int groups = internals.Editor.GetRegion().NumberOfHandleGroups;
  internals.Maps.assign(groups, le::AffineMap::Identity());
  for (int g = 0; g < groups; ++g)
  {
    double motion[6], center[3];
    if (vtkLinearTransform* transform = this->GetHandleTransform(g))
    {
      internals.Maps[g] = internals.Surface.NormalizedMap(transform);
    }
    else if (g == 0)
    {
      internals.Maps[0] = internals.Surface.NormalizedMap(
        PropertyTransform(this->HandleCenter, this->HandleRotation, this->HandleTranslation));
    }
    else if (this->GetHandleGroupMotion(g, motion) && this->GetHandleGroupCenter(g, center))
    {
      internals.Maps[g] =
        internals.Surface.NormalizedMap(PropertyTransform(center, motion + 3, motion));
    }
  }
}

bool vtkLaplacianDeformationFilter::Solve()
{
  vtkInternals& internals = *this->Internals;
  const Clock::time_point start = Clock::now();
  const le::EditStatus status = internals.Editor.Solve(internals.Maps, internals.Solution);
  this->SolveTime = SecondsSince(start);
  const bool arap = this->RotationMode == ROTATION_AS_RIGID_AS_POSSIBLE;
  this->NumberOfARAPIterations = arap ? internals.Editor.GetLastArapResult().Iterations : 0;
  this->ARAPEnergy = arap ? internals.Editor.GetLastArapResult().Energy : 0.0;
  if (!status.Ok())
  {
    return this->Fail("Cannot edit: " + status.Error + ".");
  }
  internals.Edited = true;
  const le::EditRegion& region = internals.Editor.GetRegion();
  this->NumberOfROIVertices = region.GetNumberOfVertices();
  this->NumberOfHandleVertices = static_cast<int>(
    std::count(region.Roles.begin(), region.Roles.end(), le::VertexRole::Handle));
  return true;
}

void vtkLaplacianDeformationFilter::WriteOutput(vtkPolyData* rest, vtkPolyData* output)
{
  vtkInternals& internals = *this->Internals;
  const Clock::time_point start = Clock::now();
  const vtkLaplacianSurfaceAdapter& surface = internals.Surface;
  output->SetPoints(surface.MovePoints(rest->GetPoints(), internals.Solution));
  internals.Normals.Refresh(
    output, surface.GetMesh()->GetPositions(), surface.GetRowOfVertex(), internals.Solution);
  this->AddEditRoles(output, surface.GetRoles());
  this->SolveTime += SecondsSince(start);
}

void vtkLaplacianDeformationFilter::AddEditRoles(vtkPolyData* output, vtkDataArray* roles)
{
  if (!this->GenerateEditRoles)
  {
    return;
  }
  roles->SetLookupTable(this->RoleColors ? NewRoleColors() : nullptr);
  vtkPointData* pointData = output->GetPointData();
  pointData->AddArray(roles);
  if (!pointData->GetScalars())
  {
    pointData->SetActiveScalars("EditRole"); // a default mapper then shows the roles
  }
}

bool vtkLaplacianDeformationFilter::GetEditState(vtkLaplacianEditState& state) const
{
  const vtkInternals& internals = *this->Internals;
  state.Surface = &internals.Surface;
  state.Normals = &internals.Normals;
  state.Editor = &internals.Editor;
  state.Maps = &internals.Maps;
  state.Solution = &internals.Solution;
  state.ModelVersion = internals.ModelVersion;
  return internals.Edited;
}

void vtkLaplacianDeformationFilter::CommitEdit()
{
  vtkPolyData* input = vtkPolyData::SafeDownCast(this->GetInputDataObject(0, 0));
  if (!input)
  {
    vtkErrorMacro(<< "CommitEdit needs an input.");
    return;
  }
  this->Update();
  vtkPolyData* output = this->GetOutput();
  if (this->GetErrorCode() != vtkErrorCode::NoError || !output->GetPoints())
  {
    return;
  }
  // The handle property transform moves HandleCenter along; the edit starts anew from there.
  double center[3];
  PropertyTransform(this->HandleCenter, this->HandleRotation, this->HandleTranslation)
    ->TransformPoint(this->HandleCenter, center);
  auto committed = vtkSmartPointer<vtkPoints>::New();
  committed->SetDataType(output->GetPoints()->GetDataType()); // DeepCopy keeps float otherwise
  committed->DeepCopy(output->GetPoints());
  this->Internals->Commits.push_back(committed);
  if (!this->GetHandleTransform(0))
  {
    this->SetHandleCenter(center);
  }
  this->SetHandleTranslation(0.0, 0.0, 0.0);
  this->SetHandleRotation(0.0, 0.0, 0.0);
  this->RemoveAllHandleGroupMotions();
  this->Modified();
  this->InvokeEvent(EditCommittedEvent);
}

bool vtkLaplacianDeformationFilter::UndoCommit()
{
  if (this->Internals->Commits.empty())
  {
    return false;
  }
  this->Internals->Commits.pop_back();
  this->Modified();
  this->InvokeEvent(CommitUndoneEvent);
  return true;
}

bool vtkLaplacianDeformationFilter::GetRestPoint(vtkIdType id, double point[3])
{
  auto* input = vtkPolyData::SafeDownCast(this->GetInputDataObject(0, 0));
  if (!input || id < 0 || id >= input->GetNumberOfPoints())
  {
    return false;
  }
  const auto& commits = this->Internals->Commits;
  vtkPoints* rest = !commits.empty() && commits.back()->GetNumberOfPoints() == input->GetNumberOfPoints()
    ? commits.back().Get()
    : input->GetPoints();
  rest->GetPoint(id, point);
  return true;
}

void vtkLaplacianDeformationFilter::FindGroupCenters()
{
  vtkInternals& internals = *this->Internals;
  const le::EditRegion& region = internals.Editor.GetRegion();
  std::vector<le::Vector3> sums(region.NumberOfHandleGroups, le::Vector3::Zero());
  std::vector<int> counts(region.NumberOfHandleGroups, 0);
  for (std::size_t row = 0; row < region.HandleGroups.size(); ++row)
  {
    const int group = region.HandleGroups[row];
    if (group >= 0 && group < region.NumberOfHandleGroups)
    {
      sums[group] += internals.Surface.GetMesh()->GetPositions()[region.Vertices[row]];
      ++counts[group];
    }
  }
  internals.GroupCenters.assign(region.NumberOfHandleGroups, std::nullopt);
  for (int group = 0; group < region.NumberOfHandleGroups; ++group)
  {
    if (counts[group] > 0)
    {
      const le::Vector3 mean = internals.Surface.Denormalize(sums[group] / counts[group]);
      internals.GroupCenters[group] = std::array<double, 3>{ mean[0], mean[1], mean[2] };
    }
  }
}

bool vtkLaplacianDeformationFilter::GetHandleGroupCenter(int group, double center[3])
{
  const auto& centers = this->Internals->GroupCenters;
  if (group < 0 || group >= static_cast<int>(centers.size()) || !centers[group])
  {
    return false;
  }
  std::copy(centers[group]->begin(), centers[group]->end(), center);
  return true;
}

double* vtkLaplacianDeformationFilter::GetHandleGroupCenter(int group)
{
  if (!this->GetHandleGroupCenter(group, this->ReturnedGroupCenter))
  {
    std::fill_n(this->ReturnedGroupCenter, 3, 0.0);
  }
  return this->ReturnedGroupCenter;
}

int vtkLaplacianDeformationFilter::GetNumberOfHandleGroups()
{
  return this->Internals->Editor.GetRegion().NumberOfHandleGroups;
}

int vtkLaplacianDeformationFilter::GetNumberOfCommits()
{
  return static_cast<int>(this->Internals->Commits.size());
}

void vtkLaplacianDeformationFilter::PrintSelf(ostream& os, vtkIndent indent)
{
  // Enums by name, then the facts of the last update.
  auto name = [](int value, std::initializer_list<const char*> names) {
    return value >= 0 && value < static_cast<int>(names.size()) ? names.begin()[value] : "?";
  };
  auto printVector = [&](const char* label, const double v[3]) {
    os << indent << label << ": (" << v[0] << ", " << v[1] << ", " << v[2] << ")\n";
  };
  this->Superclass::PrintSelf(os, indent);
  os << indent << "SelectionMode: " << name(this->SelectionMode, { "Geodesic", "Array" }) << "\n";
  os << indent << "Selection input: "
     << (this->GetNumberOfInputConnections(1) > 0 ? "connected" : "none")
     << "\n";
  os << indent << "RadiusUnits: "
     << name(this->RadiusUnits, { "Absolute", "DiagonalFraction" }) << "\n";
  printVector("HandleCenter", this->HandleCenter);
  printVector("HandleTranslation", this->HandleTranslation);
  printVector("HandleRotation", this->HandleRotation);
  os << indent << "HandleRadius: " << this->HandleRadius << "\n";
  os << indent << "ROIRadius: " << this->ROIRadius << "\n";
  os << indent << "AnchorPadding: " << this->AnchorPadding << "\n";
  os << indent << "DistanceMethod: "
     << name(this->DistanceMethod, { "FastMarching", "EdgePaths" }) << "\n";
  os << indent << "HandleWeight: " << this->HandleWeight << "\n";
  os << indent << "AnchorWeight: " << this->AnchorWeight << "\n";
  os << indent << "LaplacianWeights: "
     << name(this->LaplacianWeights, { "Uniform", "Cotangent" }) << "\n";
  os << indent << "OperatorOrder: " << this->OperatorOrder << "\n";
  os << indent << "RotationMode: "
     << name(this->RotationMode, { "None", "Explicit", "Implicit", "AsRigidAsPossible" }) << "\n";
  os << indent << "NormalSmoothingRadius: " << this->NormalSmoothingRadius << "\n";
  os << indent << "NumberOfIterations: " << this->NumberOfIterations << "\n";
  os << indent << "PreserveDetailScale: " << (this->PreserveDetailScale ? "On" : "Off") << "\n";
  os << indent << "ImplicitFormulation: "
     << name(this->ImplicitFormulation, { "PerEdge", "Paper" }) << "\n";
  os << indent << "ARAPIterations: " << this->ARAPIterations << "\n";
  os << indent << "Dragging: " << (this->Dragging ? "On" : "Off") << "\n";
  os << indent << "DragARAPIterations: " << this->DragARAPIterations << "\n";
  os << indent << "Convergence: " << this->Convergence << "\n";
  os << indent << "Acceleration: " << (this->Acceleration ? "On" : "Off") << "\n";
  os << indent << "Extrapolation: " << (this->Extrapolation ? "On" : "Off") << "\n";
  os << indent << "Solver: " << name(this->Solver, { "CHOLMOD", "SimplicialLDLT", "MUMPS" }) << "\n";
  os << indent << "Ordering: "
     << name(this->Ordering, { "Automatic", "AMD", "METIS", "NestedDissection" }) << "\n";
  os << indent << "MaximumFactorMemory: " << this->MaximumFactorMemory << " MB";
  if (this->MaximumFactorMemory <= 0.0)
  {
    os << " (automatic: " << vtkLaplacianSurfaceAdapter::GetAutomaticFactorLimit() << " MB now)";
  }
  os << "\n";
  os << indent << "MergeCoincidentPoints: " << (this->MergeCoincidentPoints ? "On" : "Off") << "\n";
  os << indent << "GenerateEditRoles: " << (this->GenerateEditRoles ? "On" : "Off") << "\n";
  os << indent << "RoleColors: " << (this->RoleColors ? "On" : "Off") << "\n";
  os << indent << "NumberOfHandleTransforms: " << this->Internals->HandleTransforms.size() << "\n";
  for (const auto& [group, motion] : this->Internals->HandleGroupMotions)
  {
    os << indent << "HandleGroupMotion " << group << ": translation (" << motion[0] << ", "
       << motion[1] << ", " << motion[2] << "), rotation (" << motion[3] << ", " << motion[4]
       << ", " << motion[5] << ")\n";
  }
  os << indent << "NumberOfCommits: " << this->Internals->Commits.size() << "\n";
  os << indent << "Last update:\n";
  const vtkIndent next = indent.GetNextIndent();
  os << next << "NumberOfROIVertices: " << this->NumberOfROIVertices << "\n";
  os << next << "NumberOfHandleVertices: " << this->NumberOfHandleVertices << "\n";
  os << next << "TopologyTime: " << this->TopologyTime << " s\n";
  os << next << "SetupTime: " << this->SetupTime << " s (analysis " << this->AnalysisTime
     << " s, factorization " << this->FactorizationTime << " s)\n";
  os << next << "SolveTime: " << this->SolveTime << " s\n";
  os << next << "NumberOfARAPIterations: " << this->NumberOfARAPIterations << "\n";
  os << next << "ARAPEnergy: " << this->ARAPEnergy << "\n";
  os << next << "NumberOfSurfaceVertices: " << this->NumberOfSurfaceVertices << "\n";
  os << next << "FactorMemory: " << this->FactorMemory << " MB\n";
  os << next << "FactoredAcrossProcesses: " << this->FactoredAcrossProcesses << "\n";
  os << next << "NumberOfFactorizations: " << this->NumberOfFactorizations << " (attempted "
     << this->NumberOfFactorizationAttempts << ")\n";
}
