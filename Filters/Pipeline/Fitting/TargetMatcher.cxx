#include "TargetMatcher.h"

#include "SMPFor.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkDoubleArray.h"
#include "vtkGenericCell.h"
#include "vtkIdList.h"
#include "vtkMath.h"
#include "vtkPointData.h"
#include "vtkPointSet.h"
#include "vtkPolyData.h"
#include "vtkPolyDataNormals.h"
#include "vtkStaticCellLocator.h"
#include "vtkStaticPointLocator.h"

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <thread>
#include <unordered_map>

namespace LaplacianEditing
{
namespace Pipeline
{
namespace
{
// Match's threads, each with its own cell locator (a few tens of MB each on a million triangles).
std::size_t MatchThreads()
{
  return std::min<std::size_t>(std::max(1u, std::thread::hardware_concurrency()), 8);
}

// A match on a rim triangle whose offset leans more than this (a sine) from the normal lies
// beyond the rim.
constexpr double RimSlant = 0.1;

// Nearer the target than this fraction of its diagonal, a point is on it.
constexpr double OnSurfaceFraction = 1e-6;

// A closest point with a barycentric weight below this lies on the triangle's edge or vertex.
constexpr double OnEdgeWeight = 1e-9;

// A cloud's normal at a point is the direction of least spread of its nearest points.
constexpr int CloudNeighbours = 12;

vtkSmartPointer<vtkDataArray> CloudNormals(vtkPointSet* cloud, vtkStaticPointLocator* locator)
{
  auto normals = vtkSmartPointer<vtkDoubleArray>::New();
  normals->SetNumberOfComponents(3);
  normals->SetNumberOfTuples(cloud->GetNumberOfPoints());
  vtkNew<vtkIdList> near;
  for (vtkIdType i = 0; i < cloud->GetNumberOfPoints(); ++i)
  {
    double p[3];
    cloud->GetPoint(i, p);
    locator->FindClosestNPoints(CloudNeighbours, p, near);
    Eigen::Vector3d mean = Eigen::Vector3d::Zero();
    std::vector<Eigen::Vector3d> points(near->GetNumberOfIds());
    for (vtkIdType k = 0; k < near->GetNumberOfIds(); ++k)
    {
      cloud->GetPoint(near->GetId(k), points[k].data());
      mean += points[k];
    }
    mean /= std::max<double>(1.0, static_cast<double>(points.size()));
    Eigen::Matrix3d spread = Eigen::Matrix3d::Zero();
    for (const Eigen::Vector3d& q : points)
    {
      spread += (q - mean) * (q - mean).transpose();
    }
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(spread);
    const Eigen::Vector3d normal = solver.eigenvectors().col(0); // the smallest eigenvalue's
    normals->SetTuple(i, normal.data());
  }
  return normals;
}

// The barycentric weights of `p` (in the triangle's plane) on the corners a, b, c.
void Barycentric(const double p[3], const double a[3], const double b[3], const double c[3],
  double weights[3])
{
  double ab[3], ac[3], ap[3];
  vtkMath::Subtract(b, a, ab);
  vtkMath::Subtract(c, a, ac);
  vtkMath::Subtract(p, a, ap);
  const double d00 = vtkMath::Dot(ab, ab), d01 = vtkMath::Dot(ab, ac), d11 = vtkMath::Dot(ac, ac);
  const double d20 = vtkMath::Dot(ap, ab), d21 = vtkMath::Dot(ap, ac);
  const double determinant = d00 * d11 - d01 * d01;
  if (determinant <= 0.0)
  {
    weights[0] = weights[1] = weights[2] = 1.0 / 3.0;
    return;
  }
  weights[1] = (d11 * d20 - d01 * d21) / determinant;
  weights[2] = (d00 * d21 - d01 * d20) / determinant;
  weights[0] = 1.0 - weights[1] - weights[2];
}

// The template's shape with its point normals, as it lies now (its own orientation).
vtkSmartPointer<vtkPolyData> WithPointNormals(vtkPolyData* shape)
{
  vtkNew<vtkPolyDataNormals> normals;
  normals->SetInputData(shape);
  normals->SplittingOff();
  normals->ConsistencyOff();
  normals->AutoOrientNormalsOff();
  normals->Update();
  return normals->GetOutput();
}

// The triangles with a corner on an edge that only one triangle has: a hole's rim, or the
// target's border.
std::vector<char> RimTriangles(vtkPolyData* surface)
{
  std::unordered_map<std::uint64_t, int> edges;
  auto key = [](vtkIdType a, vtkIdType b) {
    return (static_cast<std::uint64_t>(std::min(a, b)) << 32) | static_cast<std::uint64_t>(std::max(a, b));
  };
  const vtkIdType cells = surface->GetNumberOfCells();
  vtkIdType count = 0;
  const vtkIdType* ids = nullptr;
  for (vtkIdType c = 0; c < cells; ++c)
  {
    surface->GetCellPoints(c, count, ids);
    for (vtkIdType k = 0; k < count; ++k)
    {
      ++edges[key(ids[k], ids[(k + 1) % count])];
    }
  }
  std::vector<char> onRim(surface->GetNumberOfPoints(), 0);
  for (const auto& edge : edges)
  {
    if (edge.second == 1)
    {
      onRim[edge.first >> 32] = 1;
      onRim[edge.first & 0xffffffffu] = 1;
    }
  }
  std::vector<char> rim(cells, 0);
  for (vtkIdType c = 0; c < cells; ++c)
  {
    surface->GetCellPoints(c, count, ids);
    for (vtkIdType k = 0; k < count; ++k)
    {
      rim[c] = rim[c] || onRim[ids[k]];
    }
  }
  return rim;
}
}

TargetMatcher::TargetMatcher() = default;
TargetMatcher::~TargetMatcher() = default;

std::string TargetMatcher::SetTarget(vtkPointSet* target)
{
  this->Surface = nullptr;
  this->Cloud = nullptr;
  if (!target || target->GetNumberOfPoints() == 0)
  {
    return "The target (input port 1) has no points.";
  }
  for (vtkIdType i = 0; i < target->GetNumberOfPoints(); ++i)
  {
    double p[3];
    target->GetPoint(i, p);
    if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2]))
    {
      return "Target point " + std::to_string(i) + " has a NaN or infinite coordinate.";
    }
  }
  auto* polyData = vtkPolyData::SafeDownCast(target);
  if (polyData && polyData->GetNumberOfPolys() > 0)
  {
    if (polyData->GetPolys()->IsHomogeneous() != 3)
    {
      return "The target's polygons must all be triangles (run vtkTriangleFilter on it).";
    }
    vtkNew<vtkPolyData> triangles;
    triangles->SetPoints(polyData->GetPoints());
    triangles->SetPolys(polyData->GetPolys());
    vtkNew<vtkPolyDataNormals> normals;
    normals->SetInputData(triangles);
    normals->ComputeCellNormalsOn();
    normals->ComputePointNormalsOn();
    normals->SplittingOff();
    normals->Update();
    this->Surface = normals->GetOutput();
    this->FaceNormals = this->Surface->GetCellData()->GetNormals();
    this->Normals = this->Surface->GetPointData()->GetNormals();
    this->RimCells = RimTriangles(this->Surface);
    this->OnSurface = OnSurfaceFraction * this->Surface->GetLength();
    // Match's threads read the corners from here and the cells through the locator, whose
    // structures are built once on this thread.
    this->Corners.resize(this->Surface->GetNumberOfCells());
    vtkIdType count = 0;
    const vtkIdType* corners = nullptr;
    for (vtkIdType c = 0; c < this->Surface->GetNumberOfCells(); ++c)
    {
      this->Surface->GetCellPoints(c, count, corners);
      std::copy(corners, corners + 3, this->Corners[c].begin());
    }
    this->Surface->BuildLinks();
    this->Cells.resize(MatchThreads());
    for (auto& locator : this->Cells)
    {
      locator = vtkSmartPointer<vtkStaticCellLocator>::New();
      locator->SetDataSet(this->Surface);
      locator->BuildLocator();
    }
    return {};
  }
  // Points alone: a cloud (a surface's vertices without its triangles count as one).
  this->Cloud = target;
  this->CloudOriented = false;
  this->Points->SetDataSet(target);
  this->Points->BuildLocator();
  this->Normals = CloudNormals(target, this->Points);
  return {};
}

void TargetMatcher::Closest(
  const double point[3], double closest[3], double normal[3], bool& rim, std::size_t locator) const
{
  if (this->Surface)
  {
    thread_local vtkNew<vtkGenericCell> cell;
    vtkIdType cellId = -1;
    int subId = 0;
    double squared = 0.0;
    this->Cells[locator]->FindClosestPoint(point, closest, cell, cellId, subId, squared);
    double weights[3]; // the closest point's on the cell's corners
    this->CornerWeights(cellId, closest, weights);
    cellId = this->FirstOfEquallyNear(point, cellId, closest, squared, weights, cell);
    // Beyond a rim, the closest point is on the rim's edge, off the perpendicular: the point lies
    // where the target has no surface. On a rim triangle's face it is a match like any other.
    double face[3];
    this->FaceNormals->GetTuple(cellId, face);
    double offset[3] = { point[0] - closest[0], point[1] - closest[1], point[2] - closest[2] };
    const double along = vtkMath::Dot(offset, face);
    double across[3] = { offset[0] - along * face[0], offset[1] - along * face[1],
      offset[2] - along * face[2] };
    rim = this->RimCells[cellId] != 0 && vtkMath::Norm(offset) > this->OnSurface &&
      vtkMath::Norm(across) > RimSlant * vtkMath::Norm(offset);
    // The normal to match with: the corners' normals, interpolated, smoother than the face's on
    // a noisy scan.
    const std::array<vtkIdType, 3>& corners = this->Corners[cellId];
    double cornerNormal[3];
    normal[0] = normal[1] = normal[2] = 0.0;
    for (int k = 0; k < 3; ++k)
    {
      this->Normals->GetTuple(corners[k], cornerNormal);
      for (int j = 0; j < 3; ++j)
      {
        normal[j] += weights[k] * cornerNormal[j];
      }
    }
    if (vtkMath::Normalize(normal) == 0.0)
    {
      std::copy(face, face + 3, normal);
    }
    return;
  }
  const vtkIdType nearest = this->Points->FindClosestPoint(point);
  this->Cloud->GetPoint(nearest, closest);
  this->Normals->GetTuple(nearest, normal);
  rim = false;
}

void TargetMatcher::CornerWeights(vtkIdType cellId, const double p[3], double weights[3]) const
{
  const std::array<vtkIdType, 3>& corners = this->Corners[cellId];
  double a[3], b[3], c[3];
  this->Surface->GetPoint(corners[0], a);
  this->Surface->GetPoint(corners[1], b);
  this->Surface->GetPoint(corners[2], c);
  Barycentric(p, a, b, c, weights);
}

vtkIdType TargetMatcher::FirstOfEquallyNear(const double point[3], vtkIdType cellId,
  double closest[3], double& squared, double weights[3], vtkGenericCell* cell) const
{
  const std::array<vtkIdType, 3>& corners = this->Corners[cellId];
  vtkIdType on[3]; // the corners of the vertex or edge the closest point lies on
  int onCount = 0;
  for (int k = 0; k < 3; ++k)
  {
    if (weights[k] > OnEdgeWeight)
    {
      on[onCount++] = corners[k];
    }
  }
  if (onCount == 3 || onCount == 0)
  {
    return cellId; // inside the triangle (or a degenerate one): no other is as near
  }
  vtkIdType count = 0;
  vtkIdType* around = nullptr;
  this->Surface->GetPointCells(on[0], count, around);
  vtkIdType best = cellId;
  for (vtkIdType k = 0; k < count; ++k)
  {
    const std::array<vtkIdType, 3>& other = this->Corners[around[k]];
    const bool shares = std::all_of(on, on + onCount,
      [&](vtkIdType v) { return std::find(other.begin(), other.end(), v) != other.end(); });
    if (!shares || around[k] == cellId)
    {
      continue;
    }
    double candidate[3], pcoords[3], cellWeights[3], candidateSquared = 0.0;
    int subId = 0;
    this->Surface->GetCell(around[k], cell);
    cell->EvaluatePosition(point, candidate, subId, pcoords, candidateSquared, cellWeights);
    if (candidateSquared < squared || (candidateSquared == squared && around[k] < best))
    {
      best = around[k];
      squared = candidateSquared;
      std::copy(candidate, candidate + 3, closest);
    }
  }
  if (best != cellId)
  {
    this->CornerWeights(best, closest, weights);
  }
  return best;
}

double TargetMatcher::DistanceTo(const double point[3]) const
{
  double closest[3], normal[3];
  bool rim = false;
  this->Closest(point, closest, normal, rim);
  return std::sqrt(vtkMath::Distance2BetweenPoints(point, closest));
}

void TargetMatcher::OrientCloud(vtkPolyData* shape)
{
  if (this->Surface)
  {
    return;
  }
  vtkSmartPointer<vtkPolyData> normalized = WithPointNormals(shape);
  vtkDataArray* own = normalized->GetPointData()->GetNormals();
  vtkNew<vtkStaticPointLocator> nearest;
  nearest->SetDataSet(normalized);
  nearest->BuildLocator();
  for (vtkIdType i = 0; i < this->Cloud->GetNumberOfPoints(); ++i)
  {
    double p[3], normal[3], mine[3];
    this->Cloud->GetPoint(i, p);
    this->Normals->GetTuple(i, normal);
    own->GetTuple(nearest->FindClosestPoint(p), mine);
    if (vtkMath::Dot(normal, mine) < 0.0)
    {
      vtkMath::MultiplyScalar(normal, -1.0);
      this->Normals->SetTuple(i, normal);
    }
  }
  this->CloudOriented = true;
}

void TargetMatcher::Match(vtkPolyData* shape, const Criteria& criteria, Matches& matches,
  const std::vector<vtkIdType>* subset) const
{
  vtkSmartPointer<vtkPolyData> normalized = WithPointNormals(shape);
  vtkDataArray* own = normalized->GetPointData()->GetNormals();
  const vtkIdType n = shape->GetNumberOfPoints();
  matches.Targets.resize(n);
  matches.Normals.resize(n);
  matches.Landings.resize(n);
  matches.Distances.resize(n);
  matches.Trusted.assign(n, subset ? 0 : 1);
  std::vector<vtkIdType> all;
  if (!subset)
  {
    all.resize(n);
    std::iota(all.begin(), all.end(), vtkIdType(0));
  }
  const std::vector<vtkIdType>& ids = subset ? *subset : all;
  const vtkIdType count = static_cast<vtkIdType>(ids.size());
  std::vector<double> cosines(count, 1.0);
  std::vector<char> rims(count, 0);
  auto matchPoint = [&](vtkIdType row, std::size_t locator) {
    const vtkIdType i = ids[row];
    double p[3], closest[3], normal[3], mine[3];
    shape->GetPoint(i, p);
    bool rim = false;
    this->Closest(p, closest, normal, rim, locator);
    own->GetTuple(i, mine);
    const double along = (closest[0] - p[0]) * normal[0] + (closest[1] - p[1]) * normal[1] +
      (closest[2] - p[2]) * normal[2];
    for (int k = 0; k < 3; ++k)
    {
      matches.Targets[i][k] = p[k] + along * normal[k];
      matches.Normals[i][k] = normal[k];
      matches.Landings[i][k] = this->Surface ? closest[k] : matches.Targets[i][k];
    }
    matches.Distances[i] = std::sqrt(vtkMath::Distance2BetweenPoints(p, closest));
    cosines[row] = vtkMath::Dot(normal, mine);
    rims[row] = rim;
  };
  // The closest points are most of a fit's time: a part per thread, each with its own cell
  // locator (a cloud's point locator keeps no query state).
  const int parts = static_cast<int>(this->Surface ? this->Cells.size() : MatchThreads());
  SMPFor(0, parts, [&](int firstPart, int lastPart) {
    for (int part = firstPart; part < lastPart; ++part)
    {
      for (vtkIdType k = count * part / parts; k < count * (part + 1) / parts; ++k)
      {
        matchPoint(k, this->Surface ? part : 0);
      }
    }
  });
  const auto facing = std::count_if(cosines.begin(), cosines.end(), [](double c) { return c >= 0.0; });
  const auto opposed = static_cast<decltype(facing)>(count) - facing;
  // A surface's normals may point the other way than the template's all over (another
  // orientation); a cloud's sign is unknown point by point.
  const double sign = opposed > facing ? -1.0 : 1.0;
  for (vtkIdType k = 0; k < count; ++k)
  {
    const vtkIdType i = ids[k];
    const double cosine = this->Surface ? sign * cosines[k]
                                        : (this->CloudOriented ? cosines[k] : std::abs(cosines[k]));
    matches.Trusted[i] = matches.Distances[i] <= criteria.MaximumDistance && cosine >= criteria.MinimumCosine && !rims[k];
  }
}
}
}
