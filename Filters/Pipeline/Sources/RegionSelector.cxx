#include "RegionSelector.h"

#include "vtkBoundingBox.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkExtractSelection.h"
#include "vtkIdList.h"
#include "vtkInformation.h"
#include "vtkIntArray.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkObject.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkSelection.h"
#include "vtkSelectionNode.h"

#include <algorithm>
#include <cmath>

namespace le = LaplacianEditing;

namespace LaplacianEditing
{
namespace Pipeline
{

namespace
{
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
}

std::string RegionSelector::SelectLabels(vtkPolyData* input, vtkSelection* selection,
  bool fromArray, vtkDataArray* array, const Labeler& label)
{
  this->Labels = nullptr;
  if (selection)
  {
    // The selection's labels are the array mode's (2: handle group 0), made again only when
    // the selection or the input changes.
    const vtkMTimeType key[2] = { selection->GetMTime(),
      SurfaceAdapter::GetContentTime(input) };
    if (!this->SelectedLabels || !std::equal(key, key + 2, this->SelectedKey))
    {
      std::copy(key, key + 2, this->SelectedKey);
      this->SelectedLabels = label(input, selection);
    }
    const int* labels = this->SelectedLabels->GetPointer(0);
    const int* end = labels + input->GetNumberOfPoints();
    if (std::find(labels, end, 2) == end)
    {
      return "The selection on input port 1 selects no point of the input.";
    }
    this->Labels = this->SelectedLabels;
    return {};
  }
  this->SelectedLabels = nullptr; // a point each: not kept once the selection is gone
  if (!fromArray)
  {
    return {};
  }
  if (!array)
  {
    return "Selection mode is Array but the input has no such point array; name an integer "
           "point array with SetInputArrayToProcess.";
  }
  if (!IsIntegerType(array->GetDataType()) || array->GetNumberOfComponents() != 1)
  {
    return std::string("The selection array '") + (array->GetName() ? array->GetName() : "") +
      "' must be an integer array with one component (0 fixed, 1 ROI, 2+ handle).";
  }
  this->Labels = array;
  return {};
}

vtkSmartPointer<vtkIntArray> RegionSelector::LabelSelection(
  vtkPolyData* input, vtkSelection* selection, int piece)
{
  // vtkExtractSelection, keeping the topology, marks what is selected in vtkInsidedness arrays.
  vtkNew<vtkSelection> own;
  for (unsigned int n = 0; n < selection->GetNumberOfNodes(); ++n)
  {
    vtkSelectionNode* node = selection->GetNode(n);
    vtkInformation* properties = node->GetProperties();
    const int process = properties->Has(vtkSelectionNode::PROCESS_ID())
      ? properties->Get(vtkSelectionNode::PROCESS_ID())
      : -1;
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

double RegionSelector::SelectionGrowth(const Parameters& parameters) const
{
  const bool fromSelection = this->SelectedLabels && this->Labels == this->SelectedLabels;
  return fromSelection ? parameters.ROIRadius : 0.0;
}

const Reach& RegionSelector::ComputeReach(
  vtkPolyData* rest, const Parameters& parameters)
{
  // Every vertex the edit can touch lies within a geodesic distance, hence a Euclidean one, of
  // its seeds: in geodesic mode, the handle centre with the ROI radius around its nearest corner
  // (so any corner as near is covered too); in array mode, the labelled points. The search for
  // the nearest corner or the labelled points is one pass over the input, repeated only when
  // what it reads changes.
  vtkDataArray* labels = this->Labels;
  const double* c = parameters.HandleCenter;
  const double key[5] = { static_cast<double>(SurfaceAdapter::GetContentTime(rest)),
    labels ? static_cast<double>(labels->GetMTime()) : -1.0, labels ? 0.0 : c[0],
    labels ? 0.0 : c[1], labels ? 0.0 : c[2] };
  Reach& reach = this->LastReach;
  if (!std::equal(key, key + 5, this->ReachKey))
  {
    std::copy(key, key + 5, this->ReachKey);
    reach.Seeds.clear();
    this->ReachExtent = 0.0;
    if (labels)
    {
      vtkBoundingBox box;
      for (vtkIdType i = 0; i < rest->GetNumberOfPoints(); ++i)
      {
        if (labels->GetComponent(i, 0) != 0.0)
        {
          const double* p = rest->GetPoint(i);
          reach.Seeds.push_back({ p[0], p[1], p[2] });
          box.AddPoint(p[0], p[1], p[2]);
        }
      }
      this->ReachExtent = box.IsValid() ? 0.5 * box.GetDiagonalLength() : 0.0;
    }
    else
    {
      const vtkIdType nearest = SurfaceAdapter::FindNearestCorner(rest, c);
      reach.Seeds.push_back({ c[0], c[1], c[2] });
      this->ReachExtent =
        nearest < 0 ? -1.0 : std::sqrt(vtkMath::Distance2BetweenPoints(rest->GetPoint(nearest), c));
    }
  }
  SetMargin(reach, parameters, labels != nullptr, this->ReachExtent, this->SelectionGrowth(parameters));
  return reach;
}

void RegionSelector::SetMargin(Reach& reach, const Parameters& parameters, bool labelled,
  double extent, double growth, double widening)
{
  if (reach.Seeds.empty() || extent < 0.0)
  {
    reach.Margin = -1.0;
    return;
  }
  // Around the seeds: the ROI, the explicit mode's normal smoothing support (by default 0.2 of
  // the ROI radius; for labels, of the labelled points' extent), plus 10% against the
  // discretization of the distances.
  const double roi = labelled ? extent : parameters.ROIRadius;
  const double smoothing = parameters.NormalSmoothingRadius > 0.0
    ? parameters.NormalSmoothingRadius
    : 0.2 * (labelled ? 2.0 * roi + growth : roi);
  reach.Margin = 1.1 * ((labelled ? growth : 2.0 * extent + roi) + smoothing) + widening;
}

le::RegionRequest RegionSelector::Request(vtkPolyData* rest,
  const SurfaceAdapter& surface, const Parameters& parameters) const
{
  le::RegionRequest region;
  region.AnchorPadding = parameters.AnchorPadding;
  region.Distances = static_cast<le::DistanceMethod>(parameters.DistanceMethod);
  if (this->Labels)
  {
    region.Selection = le::RegionRequest::Kind::Labeled;
    region.LabelsVersion =
      std::max(SurfaceAdapter::GetContentTime(rest), this->Labels->GetMTime());
    region.GrowRadius = this->SelectionGrowth(parameters) * surface.GetScale();
  }
  else
  {
    region.CenterVertex = this->NearestVertex(surface, parameters.HandleCenter);
    region.HandleRadius = parameters.HandleRadius * surface.GetScale();
    region.ROIRadius = parameters.ROIRadius * surface.GetScale();
  }
  return region;
}

int RegionSelector::NearestVertex(const SurfaceAdapter& surface, const double center[3]) const
{
  // The graph is shared and never changed: the same one, owned by the same control block,
  // which the weak reference keeps from being reused, has the same nearest vertex.
  const std::shared_ptr<const le::SurfaceMesh> mesh = surface.GetMesh();
  const le::Vector3 point = surface.Normalize(center);
  const bool same = !this->NearestMesh.owner_before(mesh) && !mesh.owner_before(this->NearestMesh);
  if (!same || point != this->NearestPoint)
  {
    this->NearestMesh = mesh;
    this->NearestPoint = point;
    this->NearestId = mesh->FindNearestVertex(point);
  }
  return this->NearestId;
}

void RegionSelector::Warn(vtkObject* reporter, const le::RegionRequest& request,
  const le::EditRegion& region, const SurfaceAdapter& surface,
  const Parameters& parameters, double diagonal) const
{
  const auto handles = std::count(region.Roles.begin(), region.Roles.end(), le::VertexRole::Handle);
  if (!this->Labels)
  {
    const double* c = parameters.HandleCenter;
    const le::Vector3 vertex =
      surface.Denormalize(surface.GetMesh()->GetPositions()[request.CenterVertex]);
    const double away = (vertex - le::Vector3(c[0], c[1], c[2])).norm();
    if (away > parameters.HandleRadius)
    {
      vtkWarningWithObjectMacro(reporter, << "HandleCenter (" << c[0] << ", " << c[1] << ", "
        << c[2] << ") lies " << away << " from the surface, farther than the handle radius ("
        << parameters.HandleRadius << " in mesh units): the handle is on the nearest vertex, ("
        << vertex.x() << ", " << vertex.y() << ", " << vertex.z()
        << "). Put HandleCenter on the surface.");
    }
    if (!region.BordersFixedPart)
    {
      vtkWarningWithObjectMacro(reporter, << "The ROI (radius " << parameters.ROIRadius
        << " in mesh units) covers the whole connected part of the surface it lies on: nothing "
        << "holds it in place but the anchors. Use a smaller ROIRadius, or "
        << "SetRadiusUnitsToDiagonalFraction() if the radii were meant relative to the mesh's "
        << "size.");
    }
  }
  if (region.GetNumberOfVertices() == 1)
  {
    vtkWarningWithObjectMacro(reporter, << "The ROI holds a single vertex, so the edit moves "
      << "only that vertex: the radii are likely too small for this mesh (diagonal " << diagonal
      << "); see SetRadiusUnitsToDiagonalFraction().");
  }
  else if (handles == 1)
  {
    vtkWarningWithObjectMacro(reporter, << "The handle holds a single vertex: a larger "
      << "HandleRadius moves the surface more smoothly.");
  }
}
}
}
