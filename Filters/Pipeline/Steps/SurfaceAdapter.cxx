#include "SurfaceAdapter.h"

#include "ContentTime.h"

#include "CoincidentPoints.h"
#include "SurfaceMesh.h"

#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkIdTypeArray.h"
#include "vtkLinearTransform.h"
#include "vtkMath.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkStaticPointLocator.h"
#include "vtkPolyData.h"
#include "vtkSignedCharArray.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <unordered_map>

namespace le = LaplacianEditing;

namespace LaplacianEditing
{
namespace Pipeline
{

void SurfaceAdapter::VisitPolygons(vtkPolyData* input, const std::function<void(vtkIdType, const vtkIdType*)>& visit)
{
  auto cells = vtk::TakeSmartPointer(input->GetPolys()->NewIterator());
  for (cells->GoToFirstCell(); !cells->IsDoneWithTraversal(); cells->GoToNextCell())
  {
    vtkIdType size;
    const vtkIdType* ids;
    cells->GetCurrentCell(size, ids);
    visit(size, ids);
  }
}

vtkMTimeType SurfaceAdapter::GetContentTime(vtkPolyData* surface)
{
  return ContentTime(surface);
}

vtkIdType SurfaceAdapter::FindNearestCorner(vtkPolyData* input, const double point[3])
{
  std::vector<char> corner(input->GetNumberOfPoints(), 0);
  VisitPolygons(input, [&](vtkIdType size, const vtkIdType* ids) {
    std::for_each(ids, ids + size, [&](vtkIdType id) { corner[id] = 1; });
  });
  vtkIdType nearest = -1;
  double nearestDistance = VTK_DOUBLE_MAX;
  for (vtkIdType i = 0; i < input->GetNumberOfPoints(); ++i)
  {
    const double distance = vtkMath::Distance2BetweenPoints(input->GetPoint(i), point);
    if (corner[i] && distance < nearestDistance)
    {
      nearest = i;
      nearestDistance = distance;
    }
  }
  return nearest;
}

namespace
{
// Which points lie within `reach.Margin` of a seed: a box test, then the seeds hashed on a grid
// of the margin's size, so that the cost is one pass over the points whatever the seeds.
class ReachTest
{
public:
  explicit ReachTest(const Reach& reach)
    : Seeds(reach.Seeds)
    , Margin(reach.Margin)
  {
    for (int a = 0; a < 3; ++a)
    {
      this->Box[2 * a] = VTK_DOUBLE_MAX;
      this->Box[2 * a + 1] = VTK_DOUBLE_MIN;
    }
    for (const auto& seed : this->Seeds)
    {
      for (int a = 0; a < 3; ++a)
      {
        this->Box[2 * a] = std::min(this->Box[2 * a], seed[a] - this->Margin);
        this->Box[2 * a + 1] = std::max(this->Box[2 * a + 1], seed[a] + this->Margin);
      }
      this->Cells[this->Key(seed.data(), 0, 0, 0)].push_back(&seed);
    }
  }

  bool operator()(const double p[3]) const
  {
    if (this->Margin < 0.0)
    {
      return true;
    }
    for (int a = 0; a < 3; ++a)
    {
      if (p[a] < this->Box[2 * a] || p[a] > this->Box[2 * a + 1])
      {
        return false;
      }
    }
    const double margin2 = this->Margin * this->Margin;
    for (int dx = -1; dx <= 1; ++dx)
      for (int dy = -1; dy <= 1; ++dy)
        for (int dz = -1; dz <= 1; ++dz)
        {
          const auto cell = this->Cells.find(this->Key(p, dx, dy, dz));
          if (cell != this->Cells.end() &&
            std::any_of(cell->second.begin(), cell->second.end(), [&](const std::array<double, 3>* s) {
              return vtkMath::Distance2BetweenPoints(p, s->data()) <= margin2;
            }))
          {
            return true;
          }
        }
    return false;
  }

private:
  std::uint64_t Key(const double p[3], int dx, int dy, int dz) const
  {
    // Cell indices clamped so that no conversion overflows (far cells merely share a bucket),
    // mixed in unsigned arithmetic.
    const double size = this->Margin > 0.0 ? this->Margin : 1.0;
    const int offsets[3] = { dx, dy, dz };
    std::uint64_t key = 0;
    for (int a = 0; a < 3; ++a)
    {
      const double cell = std::max(-1e15, std::min(1e15, std::floor(p[a] / size))) + offsets[a];
      key = key * 1000003u ^ static_cast<std::uint64_t>(static_cast<std::int64_t>(cell));
    }
    return key;
  }

  const std::vector<std::array<double, 3>>& Seeds;
  double Margin;
  double Box[6];
  std::unordered_map<std::uint64_t, std::vector<const std::array<double, 3>*>> Cells;
};
}

vtkSmartPointer<vtkPolyData> SurfaceAdapter::ExtractReach(
  vtkPolyData* input, const Reach& reach)
{
  const ReachTest inReach(reach);
  std::vector<char> reached(input->GetNumberOfPoints());
  for (vtkIdType i = 0; i < input->GetNumberOfPoints(); ++i)
  {
    reached[i] = inReach(input->GetPoint(i));
  }
  std::vector<vtkIdType> pointOfInput(input->GetNumberOfPoints(), -1);
  vtkNew<vtkIdTypeArray> originalPoints, originalCells;
  originalPoints->SetName("vtkOriginalPointIds");
  originalCells->SetName("vtkOriginalCellIds");
  vtkNew<vtkCellArray> polygons;
  // The polygons are the input's cells after its vertices and lines.
  const vtkIdType firstPolygon = input->GetNumberOfVerts() + input->GetNumberOfLines();
  vtkIdType polygon = -1;
  std::vector<vtkIdType> corners;
  VisitPolygons(input, [&](vtkIdType size, const vtkIdType* ids) {
    ++polygon;
    if (std::none_of(ids, ids + size, [&](vtkIdType id) { return reached[id] != 0; }))
    {
      return;
    }
    corners.clear();
    for (vtkIdType c = 0; c < size; ++c)
    {
      if (pointOfInput[ids[c]] < 0)
      {
        pointOfInput[ids[c]] = originalPoints->GetNumberOfTuples();
        originalPoints->InsertNextValue(ids[c]);
      }
      corners.push_back(pointOfInput[ids[c]]);
    }
    polygons->InsertNextCell(size, corners.data());
    originalCells->InsertNextValue(firstPolygon + polygon);
  });
  auto part = vtkSmartPointer<vtkPolyData>::New();
  vtkNew<vtkPoints> points;
  points->SetDataType(input->GetPoints() ? input->GetPoints()->GetDataType() : VTK_DOUBLE);
  points->SetNumberOfPoints(originalPoints->GetNumberOfTuples());
  part->GetPointData()->CopyAllocate(input->GetPointData(), originalPoints->GetNumberOfTuples());
  for (vtkIdType i = 0; i < originalPoints->GetNumberOfTuples(); ++i)
  {
    points->SetPoint(i, input->GetPoint(originalPoints->GetValue(i)));
    part->GetPointData()->CopyData(input->GetPointData(), originalPoints->GetValue(i), i);
  }
  part->SetPoints(points);
  part->SetPolys(polygons);
  part->GetCellData()->CopyAllocate(input->GetCellData(), originalCells->GetNumberOfTuples());
  for (vtkIdType c = 0; c < originalCells->GetNumberOfTuples(); ++c)
  {
    part->GetCellData()->CopyData(input->GetCellData(), originalCells->GetValue(c), c);
  }
  part->GetPointData()->AddArray(originalPoints);
  part->GetCellData()->AddArray(originalCells);
  return part;
}

std::string SurfaceAdapter::CheckSurface(vtkPolyData* input)
{
  if (input->GetNumberOfPoints() == 0)
  {
    return "The input mesh is empty.";
  }
  if (input->GetNumberOfPolys() == 0)
  {
    return "The input has no polygons (only vertices, lines or strips): the filter edits "
           "triangle surfaces.";
  }
  if (input->GetNumberOfStrips() > 0)
  {
    return "The input has triangle strips; run vtkTriangleFilter first.";
  }
  return {};
}

std::string SurfaceAdapter::Update(
  vtkPolyData* input, bool mergeCoincidentPoints, const Reach& reach, bool& rebuilt)
{
  const vtkMTimeType time = GetContentTime(input);
  rebuilt = !(this->Mesh && time == this->BuiltTime &&
    mergeCoincidentPoints == this->BuiltMerge && reach == this->BuiltReach);
  if (!rebuilt)
  {
    return {};
  }
  const std::string error = this->Build(input, mergeCoincidentPoints, reach);
  if (error.empty())
  {
    this->BuiltTime = time;
    this->BuiltMerge = mergeCoincidentPoints;
    this->BuiltReach = reach;
  }
  return error;
}

std::string SurfaceAdapter::Build(
  vtkPolyData* input, bool mergeCoincidentPoints, const Reach& reach)
{
  this->Mesh.reset();
  std::vector<char> mark;
  std::string error = MarkReach(input, reach, mark);
  if (!error.empty())
  {
    return error;
  }
  MarkRing(input, mergeCoincidentPoints && reach.Margin >= 0.0, mark);
  std::vector<std::int64_t> offsets, connectivity;
  this->KeepMarkedPolygons(input, mark, offsets, connectivity);
  if (this->InputPoints.empty())
  {
    return "No polygon lies within reach of the handle.";
  }
  error = this->ChooseFrame(input);
  if (!error.empty())
  {
    return error;
  }
  // The input's own coordinates too: they number the vertices alike whatever the reach.
  std::vector<le::Vector3> points(this->InputPoints.size()), inputPoints(points.size());
  for (std::size_t i = 0; i < points.size(); ++i)
  {
    const double* p = input->GetPoint(this->InputPoints[i]);
    inputPoints[i] = le::Vector3(p[0], p[1], p[2]);
    points[i] = this->Normalize(p);
  }
  auto mesh = std::make_shared<le::SurfaceMesh>(le::SurfaceMesh::FromPolygons(
    points, offsets, connectivity, mergeCoincidentPoints, &inputPoints));
  if (mesh->GetNumberOfTriangles() == 0)
  {
    return "The input polygons are all degenerate: no triangle has three distinct corners.";
  }
  this->Mesh = std::move(mesh);
  return {};
}

std::string SurfaceAdapter::MarkReach(
  vtkPolyData* input, const Reach& reach, std::vector<char>& mark)
{
  // One pass over the points: their coordinates, and which lie in reach (1).
  mark.assign(input->GetNumberOfPoints(), 0);
  const ReachTest inReach(reach);
  for (vtkIdType i = 0; i < input->GetNumberOfPoints(); ++i)
  {
    const double* p = input->GetPoint(i);
    if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2]))
    {
      return "Point " + std::to_string(i) + " has a NaN or infinite coordinate.";
    }
    mark[i] = inReach(p);
  }
  return {};
}

void SurfaceAdapter::MarkRing(
  vtkPolyData* input, bool mergeCopies, std::vector<char>& mark)
{
  // Polygons with a corner in reach mark their other corners (2), so that the ring of fixed
  // vertices around the region keeps its whole one-ring once every polygon with a marked corner
  // is kept.
  std::vector<vtkIdType> ring;
  VisitPolygons(input, [&](vtkIdType size, const vtkIdType* ids) {
    if (std::any_of(ids, ids + size, [&](vtkIdType id) { return mark[id] == 1; }))
    {
      std::for_each(ids, ids + size, [&](vtkIdType id) {
        if (!mark[id])
        {
          mark[id] = 2;
          ring.push_back(id);
        }
      });
    }
  });
  if (!mergeCopies || ring.empty())
  {
    return;
  }
  // The ring's points that coincide with another point are that point too (a seam, a triangle
  // soup): mark their copies, so that the ring keeps its whole one-ring. The tolerance, relative
  // to the whole input, is at least the mesh's, relative to the part kept.
  double bounds[6];
  input->GetPoints()->GetBounds(bounds);
  const le::Vector3 low(bounds[0], bounds[2], bounds[4]);
  const double diagonal = (le::Vector3(bounds[1], bounds[3], bounds[5]) - low).norm();
  le::CoincidentPoints copies(le::CoincidentPoints::RelativeTolerance * diagonal, low);
  for (vtkIdType id : ring)
  {
    copies.Add(le::Vector3(input->GetPoint(id)), 0);
  }
  for (vtkIdType i = 0; i < input->GetNumberOfPoints(); ++i)
  {
    mark[i] = mark[i] ? mark[i] : (copies.Find(le::Vector3(input->GetPoint(i))) == 0 ? 2 : 0);
  }
}

void SurfaceAdapter::KeepMarkedPolygons(vtkPolyData* input, const std::vector<char>& mark,
  std::vector<std::int64_t>& offsets, std::vector<std::int64_t>& connectivity)
{
  // The polygons with a marked corner; then their corners and the points in reach, in the
  // input's order (points in reach that no polygon uses stay, as isolated vertices, so that the
  // core can say what it thinks of them: a labelled one is refused); then the polygons' corners
  // renumbered. Three passes, because a scan's corners jump about the input's points: one pass
  // that numbered points as it met them spent a second in cache misses on a 2.4M-point scan.
  std::vector<char> kept(input->GetNumberOfPoints(), 0);
  std::vector<char> keptPolygon;
  std::size_t polygons = 0;
  std::size_t corners = 0;
  VisitPolygons(input, [&](vtkIdType size, const vtkIdType* ids) {
    const bool keep = std::any_of(ids, ids + size, [&](vtkIdType id) { return mark[id] != 0; });
    keptPolygon.push_back(keep);
    if (keep)
    {
      std::for_each(ids, ids + size, [&](vtkIdType id) { kept[id] = 1; });
      ++polygons;
      corners += static_cast<std::size_t>(size);
    }
  });
  std::vector<int> pointOfInput(input->GetNumberOfPoints(), -1);
  this->InputPoints.clear();
  for (vtkIdType i = 0; i < input->GetNumberOfPoints(); ++i)
  {
    if (kept[i] || mark[i] == 1)
    {
      pointOfInput[i] = static_cast<int>(this->InputPoints.size());
      this->InputPoints.push_back(i);
    }
  }
  offsets.assign(1, 0);
  offsets.reserve(polygons + 1);
  connectivity.clear();
  connectivity.reserve(corners);
  std::size_t polygon = 0;
  VisitPolygons(input, [&](vtkIdType size, const vtkIdType* ids) {
    if (keptPolygon[polygon++])
    {
      std::for_each(ids, ids + size, [&](vtkIdType id) { connectivity.push_back(pointOfInput[id]); });
      offsets.push_back(static_cast<std::int64_t>(connectivity.size()));
    }
  });
}

std::vector<int> SurfaceAdapter::GetPointOfInput(vtkIdType numberOfInputPoints) const
{
  std::vector<int> pointOfInput(numberOfInputPoints, -1);
  for (std::size_t i = 0; i < this->InputPoints.size(); ++i)
  {
    pointOfInput[this->InputPoints[i]] = static_cast<int>(i);
  }
  return pointOfInput;
}

std::string SurfaceAdapter::ChooseFrame(vtkPolyData* input)
{
  // The core's frame: centred on the kept points' bounding box, scaled to a unit diagonal.
  double bounds[6] = { VTK_DOUBLE_MAX, VTK_DOUBLE_MIN, VTK_DOUBLE_MAX, VTK_DOUBLE_MIN,
    VTK_DOUBLE_MAX, VTK_DOUBLE_MIN };
  for (vtkIdType id : this->InputPoints)
  {
    const double* p = input->GetPoint(id);
    for (int a = 0; a < 3; ++a)
    {
      bounds[2 * a] = std::min(bounds[2 * a], p[a]);
      bounds[2 * a + 1] = std::max(bounds[2 * a + 1], p[a]);
    }
  }
  this->Center = le::Vector3(
    0.5 * (bounds[0] + bounds[1]), 0.5 * (bounds[2] + bounds[3]), 0.5 * (bounds[4] + bounds[5]));
  const double diagonal =
    le::Vector3(bounds[1] - bounds[0], bounds[3] - bounds[2], bounds[5] - bounds[4]).norm();
  if (!(diagonal > 0.0))
  {
    return "All input points coincide: there is no surface to edit.";
  }
  this->Scale = 1.0 / diagonal;
  return {};
}

void SurfaceAdapter::GetPolygons(
  vtkPolyData* input, std::vector<std::int64_t>& offsets, std::vector<std::int64_t>& connectivity)
{
  offsets.assign(1, 0);
  connectivity.clear();
  VisitPolygons(input, [&](vtkIdType size, const vtkIdType* ids) {
    connectivity.insert(connectivity.end(), ids, ids + size);
    offsets.push_back(static_cast<std::int64_t>(connectivity.size()));
  });
}

le::Vector3 SurfaceAdapter::Normalize(const double p[3]) const
{
  return (le::Vector3(p[0], p[1], p[2]) - this->Center) * this->Scale;
}

le::Vector3 SurfaceAdapter::Denormalize(const le::Vector3& p) const
{
  return p / this->Scale + this->Center;
}

le::AffineMap SurfaceAdapter::NormalizedMap(vtkLinearTransform* transform) const
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

std::vector<int> SurfaceAdapter::VertexLabels(vtkDataArray* selection) const
{
  const auto& vertexOfPoint = this->Mesh->GetVertexOfPoint();
  std::vector<int> labels(this->Mesh->GetNumberOfVertices(), 0);
  for (vtkIdType i = 0; i < static_cast<vtkIdType>(vertexOfPoint.size()); ++i)
  {
    int& label = labels[vertexOfPoint[i]];
    label = std::max(label, static_cast<int>(selection->GetComponent(this->InputPoints[i], 0)));
  }
  return labels;
}

void SurfaceAdapter::IndexRegion(const le::EditRegion& region)
{
  const auto& vertexOfPoint = this->Mesh->GetVertexOfPoint();
  const vtkIdType numberOfPoints = static_cast<vtkIdType>(vertexOfPoint.size());
  this->RowOfVertex.assign(this->Mesh->GetNumberOfVertices(), -1);
  for (int k = 0; k < region.GetNumberOfVertices(); ++k)
  {
    this->RowOfVertex[region.Vertices[k]] = k;
  }
  MovedPoints& moved = this->RegionPoints;
  moved = MovedPoints();
  for (vtkIdType i = 0; i < numberOfPoints; ++i)
  {
    const int k = this->RowOfVertex[vertexOfPoint[i]];
    if (k >= 0)
    {
      moved.Ids.push_back(this->InputPoints[i]);
      moved.Rows.push_back(k);
      moved.Roles.push_back(static_cast<signed char>(region.Roles[k]));
    }
  }
}

void SurfaceAdapter::AddFollowers(vtkPolyData* input)
{
  MovedPoints& moved = this->RegionPoints;
  const vtkIdType n = input->GetNumberOfPoints();
  std::vector<int> movedIndex(n, -1); // -1: a point no polygon uses; -2: used, not moved
  VisitPolygons(input, [&](vtkIdType size, const vtkIdType* ids) {
    std::for_each(ids, ids + size, [&](vtkIdType id) { movedIndex[id] = -2; });
  });
  if (moved.Ids.empty() || std::find(movedIndex.begin(), movedIndex.end(), -1) == movedIndex.end())
  {
    return;
  }
  for (std::size_t k = 0; k < moved.Ids.size(); ++k)
  {
    movedIndex[moved.Ids[k]] = static_cast<int>(k);
  }
  // Each unused point takes the displacement of the used point nearest it, if the edit moves it.
  vtkNew<vtkPoints> used;
  used->SetDataTypeToDouble();
  std::vector<vtkIdType> usedIds;
  for (vtkIdType id = 0; id < n; ++id)
  {
    if (movedIndex[id] != -1)
    {
      used->InsertNextPoint(input->GetPoint(id));
      usedIds.push_back(id);
    }
  }
  vtkNew<vtkPolyData> surface;
  surface->SetPoints(used);
  vtkNew<vtkStaticPointLocator> locator;
  locator->SetDataSet(surface);
  locator->BuildLocator();
  moved.Offsets.assign(moved.Ids.size(), le::Vector3::Zero());
  for (vtkIdType id = 0; id < n; ++id)
  {
    if (movedIndex[id] != -1)
    {
      continue;
    }
    double p[3], q[3];
    input->GetPoint(id, p);
    const vtkIdType nearest = usedIds[locator->FindClosestPoint(p)];
    const int k = movedIndex[nearest];
    if (k < 0)
    {
      continue; // nearest to a part the edit leaves
    }
    input->GetPoint(nearest, q);
    moved.Ids.push_back(id);
    moved.Rows.push_back(moved.Rows[k]);
    moved.Roles.push_back(moved.Roles[k]);
    moved.Offsets.emplace_back(p[0] - q[0], p[1] - q[1], p[2] - q[2]);
  }
}

OutputEdit SurfaceAdapter::GetEdit(const le::Positions& solution,
  const NormalRefresher* normals, std::uint64_t regionVersion) const
{
  OutputEdit edit;
  edit.Moved = &this->RegionPoints;
  edit.Solution = &solution;
  edit.Center = this->Center;
  edit.Scale = this->Scale;
  edit.Normals = normals;
  edit.VertexRest = &this->Mesh->GetPositions();
  edit.VertexRows = &this->RowOfVertex;
  edit.RegionVersion = regionVersion;
  return edit;
}
}
}
