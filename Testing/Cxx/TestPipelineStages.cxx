// Each stage of the edit pipeline on its own, from plain data: a few hand-built polygons, no
// filter around them. The filters' tests cover the stages together.
#include "EditPipeline.h"
#include "BumpyPlane.h"
#include "FilterTestHelpers.h"
#include "FoldGuard.h"
#include "HandleMaps.h"
#include "HandleMotion.h"
#include "LandmarkBinder.h"
#include "LandmarkSource.h"
#include "NormalRefresher.h"
#include "OutputArray.h"
#include "OutputWriter.h"
#include "PreviewParts.h"
#include "RegionSelector.h"
#include "RestShape.h"
#include "SMPFor.h"
#include "SolverSettings.h"
#include "SurfaceAdapter.h"
#include "ThreadPool.h"

#include "vtkCellArray.h"
#include "vtkDoubleArray.h"
#include "vtkErrorCode.h"
#include "vtkFloatArray.h"
#include "vtkInformation.h"
#include "vtkIntArray.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPolyDataAlgorithm.h"
#include "vtkPolyDataNormals.h"
#include "vtkSMPTools.h"
#include "vtkSmartPointer.h"
#include "vtkTransform.h"
#include "vtkVersionMacros.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <functional>
#include <limits>
#include <mutex>
#include <set>
#include <string>
#include <thread>
#include <vector>

namespace le = LaplacianEditing;
namespace lep = LaplacianEditing::Pipeline;

namespace
{
// The ranges `array` keeps (whole and finite, of each component and of the magnitude) are those
// a copy that caches none computes.
void ExpectFreshRanges(vtkDataArray* array, const std::string& when)
{
  const vtkSmartPointer<vtkDataArray> fresh = vtk::TakeSmartPointer(array->NewInstance());
  fresh->DeepCopy(array);
  for (int c = -1; c < 3; ++c)
  {
    double kept[2], computed[2];
    array->GetRange(kept, c);
    fresh->GetRange(computed, c);
    EXPECT_EQ(kept[0], computed[0]) << when << ", component " << c;
    EXPECT_EQ(kept[1], computed[1]) << when << ", component " << c;
    array->GetFiniteRange(kept, c);
    fresh->GetFiniteRange(computed, c);
    EXPECT_EQ(kept[0], computed[0]) << when << ", finite component " << c;
    EXPECT_EQ(kept[1], computed[1]) << when << ", finite component " << c;
  }
}

// An n x n grid of unit squares, each split into two triangles, at height z = 0, with point
// normals; `offset` moves it along x.
vtkSmartPointer<vtkPolyData> Grid(int n, double offset = 0.0)
{
  BumpyPlaneShape flat;
  flat.Resolution = n;
  flat.BumpsPerSide = 0;
  vtkSmartPointer<vtkPolyData> grid = flat.Make();
  vtkPoints* points = grid->GetPoints();
  vtkNew<vtkFloatArray> normals;
  normals->SetName("Normals");
  normals->SetNumberOfComponents(3);
  for (vtkIdType p = 0; p < grid->GetNumberOfPoints(); ++p)
  {
    const double* x = points->GetPoint(p);
    points->SetPoint(p, n * x[0] + offset, n * x[1], 0.0);
    normals->InsertNextTuple3(0.0, 0.0, 1.0);
  }
  grid->GetPointData()->SetNormals(normals);
  return grid;
}

// A surface adapter over the whole of `input`, with a region of the vertices within `roi` of the
// grid's centre, the inner ones moved to `lift`.
struct AdaptedGrid
{
  vtkSmartPointer<vtkPolyData> Input;
  lep::SurfaceAdapter Surface;
  le::EditRegion Region;
  le::Positions Solution;

  AdaptedGrid(int n, double roi, double lift)
    : Input(Grid(n))
  {
    bool rebuilt = false;
    EXPECT_EQ(this->Surface.Update(this->Input, true, lep::Reach(), rebuilt), "");
    const le::SurfaceMesh& mesh = *this->Surface.GetMesh();
    const le::Vector3 center = this->Surface.Normalize(std::vector<double>{ n / 2.0, n / 2.0, 0.0 }.data());
    for (int v = 0; v < mesh.GetNumberOfVertices(); ++v)
    {
      const double d = (mesh.GetPositions()[v] - center).norm() / this->Surface.GetScale();
      if (d <= roi)
      {
        this->Region.Vertices.push_back(v);
        this->Region.Roles.push_back(d <= 1.0 ? le::VertexRole::Handle : le::VertexRole::Free);
      }
    }
    this->Surface.IndexRegion(this->Region);
    this->Solution.resize(this->Region.GetNumberOfVertices(), 3);
    for (int k = 0; k < this->Region.GetNumberOfVertices(); ++k)
    {
      const bool handle = this->Region.Roles[k] == le::VertexRole::Handle;
      this->Solution.row(k) = mesh.GetPositions()[this->Region.Vertices[k]].transpose();
      this->Solution(k, 2) += handle ? lift * this->Surface.GetScale() : 0.0;
    }
  }
};

// A source of a labelled region (labels of an integer array) whose handle group moves by a
// translation; it can fail at will.
class LabelledSource : public lep::EditSource
{
public:
  vtkDataArray* Labels = nullptr;
  double Translation[3] = { 0.0, 0.0, 0.0 };
  std::string Error;
  int RegionsSelected = 0;

  std::string ChooseRegion(
    vtkPolyData* rest, const lep::SurfaceAdapter& surface, lep::RegionChoice& region) override
  {
    region.Request.Selection = le::RegionRequest::Kind::Labeled;
    region.Request.LabelsVersion = this->Labels->GetMTime();
    vtkDataArray* labels = this->Labels;
    region.Labels = [&surface, labels] { return surface.VertexLabels(labels); };
    (void)rest;
    return this->Error;
  }
  void RegionSelected(const le::RegionRequest&, const le::EditRegion&,
    const lep::SurfaceAdapter&) override
  {
    ++this->RegionsSelected;
  }
  std::string ChooseMotions(const lep::SurfaceAdapter& surface, const le::EditRegion& region,
    lep::EditMotions& motions) override
  {
    vtkNew<vtkTransform> move;
    move->Translate(this->Translation);
    motions.Maps.assign(region.NumberOfHandleGroups, surface.NormalizedMap(move));
    return {};
  }
};

// Labels on a grid: the handle at the middle column's points, the ROI around, fixed beyond.
vtkSmartPointer<vtkIntArray> GridLabels(vtkPolyData* grid, int n)
{
  auto labels = vtkSmartPointer<vtkIntArray>::New();
  labels->SetName("Labels");
  for (vtkIdType p = 0; p < grid->GetNumberOfPoints(); ++p)
  {
    const double* x = grid->GetPoint(p);
    const double d = std::max(std::abs(x[0] - n / 2.0), std::abs(x[1] - n / 2.0));
    labels->InsertNextValue(d < 0.5 ? 2 : (d < n / 2.0 - 0.5 ? 1 : 0));
  }
  return labels;
}
}

TEST(SurfaceAdapter, RefusesWhatNoEditorTakes)
{
  vtkNew<vtkPolyData> empty;
  EXPECT_NE(lep::SurfaceAdapter::CheckSurface(empty).find("empty"), std::string::npos);
  vtkNew<vtkPolyData> lines;
  lines->SetPoints(Grid(1)->GetPoints());
  EXPECT_NE(lep::SurfaceAdapter::CheckSurface(lines).find("no polygons"), std::string::npos);
  EXPECT_EQ(lep::SurfaceAdapter::CheckSurface(Grid(2)), "");

  auto grid = Grid(2);
  grid->GetPoints()->SetPoint(4, std::numeric_limits<double>::quiet_NaN(), 0.0, 0.0);
  lep::SurfaceAdapter surface;
  EXPECT_NE(surface.Build(grid, true, lep::Reach()).find("Point 4"), std::string::npos);
}

TEST(SurfaceAdapter, WeldsSeamsInAUnitFrameAndKeepsToItsReach)
{
  // Two grids side by side sharing an edge's positions but not its points: a seam.
  auto left = Grid(2), right = Grid(2, 2.0);
  vtkNew<vtkPolyData> both;
  vtkNew<vtkPoints> points;
  vtkNew<vtkCellArray> triangles;
  for (vtkPolyData* part : { left.Get(), right.Get() })
  {
    const vtkIdType first = points->GetNumberOfPoints();
    for (vtkIdType p = 0; p < part->GetNumberOfPoints(); ++p)
    {
      points->InsertNextPoint(part->GetPoint(p));
    }
    vtkIdType size;
    const vtkIdType* ids;
    for (part->GetPolys()->InitTraversal(); part->GetPolys()->GetNextCell(size, ids);)
    {
      const vtkIdType shifted[3] = { ids[0] + first, ids[1] + first, ids[2] + first };
      triangles->InsertNextCell(3, shifted);
    }
  }
  both->SetPoints(points);
  both->SetPolys(triangles);

  lep::SurfaceAdapter surface;
  bool rebuilt = false;
  ASSERT_EQ(surface.Update(both, true, lep::Reach(), rebuilt), "");
  EXPECT_TRUE(rebuilt);
  EXPECT_EQ(surface.GetMesh()->GetNumberOfVertices(), 18 - 3) << "the seam's three points weld";
  EXPECT_NEAR(1.0 / surface.GetScale(), std::hypot(4.0, 2.0), 1e-12) << "a unit diagonal";
  ASSERT_EQ(surface.Update(both, true, lep::Reach(), rebuilt), "");
  EXPECT_FALSE(rebuilt) << "the same content, merge flag and reach";
  ASSERT_EQ(surface.Update(both, false, lep::Reach(), rebuilt), "");
  EXPECT_EQ(surface.GetMesh()->GetNumberOfVertices(), 18) << "unwelded";

  // A reach around the left grid's corner keeps the polygons there and the ring of polygons
  // around them, nothing of the right grid.
  lep::Reach reach;
  reach.Seeds.push_back({ 0.0, 0.0, 0.0 });
  reach.Margin = 0.5;
  ASSERT_EQ(surface.Update(both, true, reach, rebuilt), "");
  EXPECT_GT(surface.GetInputPoints().size(), 3u);
  for (vtkIdType id : surface.GetInputPoints())
  {
    EXPECT_LT(id, 9) << "nothing of the right grid";
  }
}

TEST(SurfaceAdapter, MapsTransformsIntoItsFrameAndIndexesTheRegion)
{
  AdaptedGrid grid(4, 1.6, 0.5);
  vtkNew<vtkTransform> transform;
  transform->Translate(1.0, -2.0, 0.5);
  transform->RotateZ(30.0);
  const le::AffineMap map = grid.Surface.NormalizedMap(transform);
  const double p[3] = { 3.0, 1.0, 0.0 };
  double moved[3];
  transform->TransformPoint(p, moved);
  const le::Vector3 expected = grid.Surface.Normalize(moved);
  const le::Vector3 mapped = map.leftCols<3>() * grid.Surface.Normalize(p) + map.col(3);
  EXPECT_LT((mapped - expected).norm(), 1e-14);

  const lep::MovedPoints& moved_points = grid.Surface.GetRegionPoints();
  EXPECT_EQ(moved_points.Ids.size(), static_cast<std::size_t>(grid.Region.GetNumberOfVertices()));
  for (std::size_t i = 0; i < moved_points.Ids.size(); ++i)
  {
    const double* x = grid.Input->GetPoint(moved_points.Ids[i]);
    EXPECT_LE(std::hypot(x[0] - 2.0, x[1] - 2.0), 1.6 + 1e-12);
  }
}

TEST(RegionSelector, ChecksLabelsAndBoundsTheReach)
{
  lep::RegionSelector selector;
  auto grid = Grid(4);
  auto label = [](vtkPolyData*, vtkSelection*) { return vtkSmartPointer<vtkIntArray>(); };
  EXPECT_NE(selector.SelectLabels(grid, nullptr, true, nullptr, label).find("no such point array"),
    std::string::npos);
  vtkNew<vtkDoubleArray> real;
  real->SetName("Real");
  real->SetNumberOfTuples(grid->GetNumberOfPoints());
  EXPECT_NE(selector.SelectLabels(grid, nullptr, true, real, label).find("integer array"),
    std::string::npos);
  EXPECT_EQ(selector.SelectLabels(grid, nullptr, false, nullptr, label), "");
  EXPECT_EQ(selector.GetLabels(), nullptr) << "geodesic discs";

  lep::RegionParameters parameters;
  parameters.HandleCenter[0] = parameters.HandleCenter[1] = 2.0;
  parameters.HandleRadius = 0.5;
  parameters.ROIRadius = 1.5;
  const lep::Reach& reach = selector.ComputeReach(grid, parameters);
  ASSERT_EQ(reach.Seeds.size(), 1u);
  // The handle centre is a vertex: the ROI and the default smoothing support, 10% wider.
  EXPECT_NEAR(reach.Margin, 1.1 * (1.5 + 0.2 * 1.5), 1e-12);
  lep::Reach none;
  lep::RegionSelector::SetMargin(none, parameters, false, 0.0, 0.0);
  EXPECT_LT(none.Margin, 0.0) << "no seeds: everything";

  lep::SurfaceAdapter surface;
  bool rebuilt = false;
  ASSERT_EQ(surface.Update(grid, true, reach, rebuilt), "");
  const le::RegionRequest request = selector.Request(grid, surface, parameters);
  EXPECT_EQ(request.Selection, le::RegionRequest::Kind::Geodesic);
  EXPECT_LT((surface.Denormalize(surface.GetMesh()->GetPositions()[request.CenterVertex]) -
              le::Vector3(2.0, 2.0, 0.0)).norm(), 1e-12);
  EXPECT_NEAR(request.ROIRadius, 1.5 * surface.GetScale(), 1e-15);
}

TEST(HandleMotion, AnglesAndMatricesRoundTripInOneConvention)
{
  for (const auto& angles : std::vector<std::array<double, 3>>{
         { 10.0, 20.0, 30.0 }, { -170.0, 45.0, 100.0 }, { 0.0, -80.0, 5.0 } })
  {
    double matrix[3][3], back[3];
    lep::HandleMotion::RotationMatrix(angles.data(), matrix);
    lep::HandleMotion::Angles(matrix, back);
    for (int a = 0; a < 3; ++a)
    {
      EXPECT_NEAR(back[a], angles[a], 1e-10);
    }
    // R = Rz Ry Rx: the x rotation comes first.
    vtkNew<vtkTransform> expected;
    expected->RotateZ(angles[2]);
    expected->RotateY(angles[1]);
    expected->RotateX(angles[0]);
    for (int r = 0; r < 3; ++r)
    {
      for (int c = 0; c < 3; ++c)
      {
        EXPECT_NEAR(matrix[r][c], expected->GetMatrix()->GetElement(r, c), 1e-14);
      }
    }
  }
  // About a centre, then translated: the centre goes to centre + translation.
  const double center[3] = { 1.0, 2.0, 3.0 }, rotation[3] = { 0.0, 0.0, 90.0 },
               translation[3] = { 0.5, 0.0, 0.0 };
  double moved[3];
  lep::HandleMotion::Transform(center, rotation, translation)->TransformPoint(center, moved);
  EXPECT_NEAR(moved[0], 1.5, 1e-14);
  EXPECT_NEAR(moved[1], 2.0, 1e-14);
}

TEST(HandleMaps, SaysWhatChangedAndMapsEachGroup)
{
  lep::HandleMaps handles;
  vtkNew<vtkTransform> lift;
  lift->Translate(0.0, 0.0, 1.0);
  EXPECT_TRUE(handles.SetTransform(1, lift));
  EXPECT_FALSE(handles.SetTransform(1, lift)) << "the same transform";
  EXPECT_EQ(handles.GetNumberOfTransforms(), 2);
  EXPECT_TRUE(handles.SetMotion(2, { 0.0, 1.0, 0.0, 0.0, 0.0, 0.0 }));
  EXPECT_FALSE(handles.SetMotion(2, { 0.0, 1.0, 0.0, 0.0, 0.0, 0.0 }));

  AdaptedGrid grid(4, 1.6, 0.0);
  le::EditRegion region = grid.Region;
  region.NumberOfHandleGroups = 3;
  region.HandleGroups.assign(region.GetNumberOfVertices(), -1);
  int group = 0;
  for (int k = 0; k < region.GetNumberOfVertices(); ++k)
  {
    if (region.Roles[k] == le::VertexRole::Handle)
    {
      region.HandleGroups[k] = group++ % 3;
    }
  }
  handles.FindGroupCenters(region, grid.Surface);
  EXPECT_NE(handles.GetGroupCenter(2), nullptr);
  EXPECT_EQ(handles.GetGroupCenter(3), nullptr);
  const double center[3] = { 2.0, 2.0, 0.0 }, rotation[3] = { 0.0, 0.0, 0.0 },
               translation[3] = { 1.0, 0.0, 0.0 };
  const std::vector<le::AffineMap> maps = handles.Maps(3, grid.Surface, center, rotation, translation);
  ASSERT_EQ(maps.size(), 3u);
  const double s = grid.Surface.GetScale();
  EXPECT_NEAR(maps[0](0, 3), s, 1e-14) << "group 0: the motion properties";
  EXPECT_NEAR(maps[1](2, 3), s, 1e-14) << "group 1: its transform";
  EXPECT_NEAR(maps[2](1, 3), s, 1e-14) << "group 2: its motion";
  EXPECT_TRUE(handles.RemoveAllTransforms());
  EXPECT_FALSE(handles.RemoveAllTransforms());
}

TEST(RestShape, CommitsUndoesAndForgetsOnNewContent)
{
  lep::RestShape rest;
  auto input = Grid(2);
  EXPECT_EQ(rest.Get(input), input.Get());
  vtkNew<vtkPoints> edited;
  edited->DeepCopy(input->GetPoints());
  edited->SetPoint(4, 1.0, 1.0, 0.5);
  rest.Commit(edited);
  edited->SetPoint(4, 9.0, 9.0, 9.0); // the commit took a copy
  vtkPolyData* committed = rest.Get(input);
  EXPECT_NE(committed, input.Get());
  EXPECT_EQ(committed->GetPoint(4)[2], 0.5);
  EXPECT_EQ(committed->GetPolys(), input->GetPolys()) << "the input's cells, shared";
  double point[3];
  ASSERT_TRUE(rest.GetPoint(input, 4, point));
  EXPECT_EQ(point[2], 0.5);
  EXPECT_FALSE(rest.GetPoint(input, 99, point));
  EXPECT_TRUE(rest.Undo());
  EXPECT_FALSE(rest.Undo());
  rest.Commit(edited);
  input->GetPoints()->Modified();
  EXPECT_EQ(rest.Get(input), input.Get()) << "new content forgets the commits";
  EXPECT_EQ(rest.GetNumberOfCommits(), 0);
}

TEST(OutputArray, WritesItsTuplesInPlaceAndCopiesOnWrite)
{
  vtkNew<vtkDoubleArray> rest;
  rest->SetNumberOfValues(10);
  for (vtkIdType i = 0; i < 10; ++i)
  {
    rest->SetValue(i, i);
  }
  lep::OutputArray output;
  const std::vector<vtkIdType> ids = { 2, 5 };
  int writes = 0;
  auto write = [&](vtkDataArray* array) {
    ++writes;
    for (vtkIdType id : ids)
    {
      array->SetTuple1(id, -1.0);
    }
  };
  EXPECT_EQ(output.Update(rest, {}, 1, write), rest.Get()) << "nothing moved: the rest itself";
  vtkDataArray* first = output.Update(rest, ids, 1, write);
  EXPECT_NE(first, rest.Get());
  EXPECT_EQ(first->GetTuple1(5), -1.0);
  EXPECT_EQ(first->GetTuple1(4), 4.0);
  EXPECT_EQ(rest->GetValue(5), 5.0) << "the rest is never written";
  EXPECT_EQ(output.Update(rest, ids, 1, write), first) << "the same key: untouched";
  EXPECT_EQ(writes, 1);
  EXPECT_EQ(output.Update(rest, ids, 2, write), first) << "a new key: written in place";
  EXPECT_EQ(output.GetNumberOfCopies(), 1);
  vtkSmartPointer<vtkDataArray> held = first; // someone else holds it
  vtkDataArray* second = output.Update(rest, ids, 3, write);
  EXPECT_NE(second, first) << "copy on write";
  EXPECT_EQ(output.GetNumberOfCopies(), 2);
}

TEST(OutputArray, KeepsTheRangesVTKCachesRightWithoutAPassOverTheArray)
{
  // A ramp of 3-component tuples; each update writes tuple 5, whose value sets or leaves the
  // extremes. The ranges VTK caches must be those of the array, carried over where the written
  // tuple held no extreme (ParaView asks for them after every update).
  vtkNew<vtkDoubleArray> rest;
  rest->SetNumberOfComponents(3);
  rest->SetNumberOfTuples(100);
  for (vtkIdType i = 0; i < 100; ++i)
  {
    rest->SetTuple3(i, i, -i, 0.5 * i);
  }
  lep::OutputArray output;
  double value = 0.0;
  vtkIdType at = 5;
  auto write = [&](vtkDataArray* array) { array->SetTuple3(at, value, -value, 0.5 * value); };
  auto expectCarried = [](vtkDataArray* array, const char* when) {
    EXPECT_TRUE(array->GetInformation()->Has(vtkAbstractArray::PER_COMPONENT()))
      << when << ": carried over, not dropped";
  };
  value = 7.0;
  double restRange[2];
  rest->GetRange(restRange, 0); // the rest's cache, which a fresh copy takes
  vtkDataArray* array = output.Update(rest, { 5 }, 1, write);
  expectCarried(array, "after the copy");
  ExpectFreshRanges(array, "after the copy");
  value = 500.0; // beyond every extreme: a new maximum, the minima kept
  ASSERT_EQ(output.Update(rest, { 5 }, 2, write), array);
  expectCarried(array, "after a write beyond the range");
  ExpectFreshRanges(array, "after a write beyond the range");
  value = 3.0; // the written tuple held the maxima: the other tuples' extremes, measured once
  ASSERT_EQ(output.Update(rest, { 5 }, 3, write), array);
  expectCarried(array, "after a write back inside the range");
  ExpectFreshRanges(array, "after a write back inside the range");
  value = -1000.0;
  at = 6;
  ASSERT_EQ(output.Update(rest, { 6 }, 4, write), array); // tuple 5 back to rest, 6 written
  ExpectFreshRanges(array, "after a write elsewhere");
  value = 0.0; // tuple 6 held the minimum of component 0
  ASSERT_EQ(output.Update(rest, { 6 }, 5, write), array);
  expectCarried(array, "after a write that moves an extreme inside again");
  ExpectFreshRanges(array, "after a write that moves an extreme inside again");
  // Values that are not finite: the plain and the finite ranges part.
  value = std::numeric_limits<double>::infinity();
  ASSERT_EQ(output.Update(rest, { 6 }, 6, write), array);
  ExpectFreshRanges(array, "after an infinite write");
  value = std::numeric_limits<double>::quiet_NaN();
  ASSERT_EQ(output.Update(rest, { 6 }, 7, write), array);
  ExpectFreshRanges(array, "after a NaN write");
  value = 2.0;
  ASSERT_EQ(output.Update(rest, { 6 }, 8, write), array);
  ExpectFreshRanges(array, "after a finite write again");
}

TEST(OutputArray, KeepsTheRangesItsWriterMeasured)
{
  // A drag's writes: the same 3,000 of 40,000 float tuples each time, written by SetTuples,
  // which measures them as it writes them (two chunks' worth of SMP ranges at least). Required:
  // after every write the ranges VTK caches are those of the array as stored (float), with
  // values beyond the extremes, back inside them, infinite and NaN.
  vtkNew<vtkFloatArray> rest;
  rest->SetNumberOfComponents(3);
  rest->SetNumberOfTuples(40000);
  for (vtkIdType i = 0; i < 40000; ++i)
  {
    rest->SetTuple3(i, 1e-3 * i, -2e-3 * i, std::sin(1e-3 * i));
  }
  std::vector<vtkIdType> ids;
  for (vtkIdType i = 100; i < 40000; i += 13)
  {
    ids.push_back(i);
  }
  lep::OutputArray output;
  double offset = 0.0;
  auto write = [&](vtkDataArray* array) {
    lep::OutputArray::SetTuples<3>(array, ids, [&](vtkIdType i, double* p) {
      p[0] = 1e-3 * ids[i] + offset + 1e-9; // rounded as a float stores it
      p[1] = -2e-3 * ids[i] * (1.0 + offset);
      p[2] = i == 7 ? offset : 0.5;
    }, output.WriteExtremes());
  };
  double range[2];
  rest->GetRange(range, 0);
  rest->GetFiniteRange(range, 0);
  vtkDataArray* array = nullptr;
  const double inf = std::numeric_limits<double>::infinity();
  std::uint64_t key = 0;
  for (double value : { 0.0, 0.25, 100.0, -3.0, inf, -inf, std::nan(""), 2.0, 0.0 })
  {
    offset = value;
    vtkDataArray* written = output.Update(rest, ids, ++key, write);
    ASSERT_TRUE(!array || written == array) << "written in place";
    array = written;
    ExpectFreshRanges(array, "after a write of " + std::to_string(value));
  }
}

TEST(OutputArray, KeepsThePointsRangesThroughTheirModified)
{
  // vtkPoints::Modified marks its array modified too (from VTK 9.2), which drops the cache: the
  // ranges are set after it. A sphere's pole lifted, its maximum among the written points.
  vtkNew<vtkPoints> rest;
  rest->SetDataTypeToDouble();
  for (int i = 0; i <= 20; ++i)
  {
    rest->InsertNextPoint(std::cos(0.1 * i), 0.0, std::sin(0.1 * i));
  }
  lep::OutputArray output;
  double lift = 0.0;
  auto write = [&](vtkDataArray* array) { array->SetTuple3(15, std::cos(1.5), 0.0, std::sin(1.5) + lift); };
  vtkPoints* points = nullptr;
  for (int update = 1; update <= 3; ++update)
  {
    lift = 0.1 * update;
    points = output.Update(rest, { 14, 15, 16 }, update, write);
    EXPECT_TRUE(points->GetData()->GetInformation()->Has(vtkAbstractArray::PER_COMPONENT()) ||
      update == 1)
      << "update " << update << ": the ranges stay cached";
    double z[2];
    points->GetData()->GetRange(z, 2); // as ParaView's data information would, caching them
    EXPECT_EQ(z[1], std::sin(1.5) + lift) << "update " << update;
    // The bounds are the cached ranges, which are the points' own.
    double bounds[6], exact[6] = { VTK_DOUBLE_MAX, VTK_DOUBLE_MIN, VTK_DOUBLE_MAX, VTK_DOUBLE_MIN,
      VTK_DOUBLE_MAX, VTK_DOUBLE_MIN };
    points->GetBounds(bounds);
    for (vtkIdType i = 0; i < points->GetNumberOfPoints(); ++i)
    {
      for (int c = 0; c < 3; ++c)
      {
        exact[2 * c] = std::min(exact[2 * c], points->GetPoint(i)[c]);
        exact[2 * c + 1] = std::max(exact[2 * c + 1], points->GetPoint(i)[c]);
      }
    }
    for (int k = 0; k < 6; ++k)
    {
      EXPECT_EQ(bounds[k], exact[k]) << "update " << update << ", bound " << k;
    }
  }
}

TEST(OutputWriter, WritesOnlyTheRegionAndItsRoles)
{
  AdaptedGrid grid(4, 1.6, 0.5);
  vtkNew<vtkPolyData> output;
  output->ShallowCopy(grid.Input);
  lep::OutputWriter writer;
  lep::NormalRefresher normals;
  normals.Index(grid.Input, grid.Surface);
  const lep::OutputEdit edit = grid.Surface.GetEdit(grid.Solution, &normals, 1);
  writer.Write(grid.Input, output, &edit, lep::OutputOptions{ true });
  vtkDataArray* roles = output->GetPointData()->GetArray("EditRole");
  ASSERT_NE(roles, nullptr);
  int handles = 0;
  for (vtkIdType p = 0; p < output->GetNumberOfPoints(); ++p)
  {
    const double* x = grid.Input->GetPoint(p);
    const double lifted = output->GetPoint(p)[2];
    const bool handle = std::hypot(x[0] - 2.0, x[1] - 2.0) <= 1.0;
    EXPECT_EQ(lifted, handle ? 0.5 : 0.0);
    EXPECT_EQ(roles->GetTuple1(p), handle ? 3.0 : (std::hypot(x[0] - 2.0, x[1] - 2.0) <= 1.6 ? 2.0 : 0.0));
    handles += handle;
  }
  EXPECT_GT(handles, 0);
  EXPECT_EQ(grid.Input->GetPoint(12)[2], 0.0) << "the input is never written";

  // Its normals are those of the moved surface, refreshed near the edit only.
  vtkNew<vtkPolyDataNormals> expected;
  expected->SetInputData(output);
  expected->ComputePointNormalsOn();
  expected->SplittingOff();
  expected->ConsistencyOff();
  expected->Update();
  vtkDataArray* refreshed = output->GetPointData()->GetNormals();
  vtkDataArray* recomputed = expected->GetOutput()->GetPointData()->GetNormals();
  for (vtkIdType p : normals.GetPointIds())
  {
    double a[3], b[3];
    refreshed->GetTuple(p, a);
    recomputed->GetTuple(p, b);
    EXPECT_GT(vtkMath::Dot(a, b), 0.99) << "point " << p;
  }

  writer.Write(grid.Input, output, nullptr, lep::OutputOptions{ true });
  EXPECT_EQ(output->GetPoints(), grid.Input->GetPoints()) << "nothing moved: the rest points";
}

TEST(PreviewParts, CutTheSurfaceIntoStillAndMovingParts)
{
  AdaptedGrid grid(6, 1.6, 0.5);
  vtkNew<vtkPolyData> output;
  output->ShallowCopy(grid.Input);
  lep::NormalRefresher normals;
  normals.Index(grid.Input, grid.Surface);
  const lep::OutputEdit edit = grid.Surface.GetEdit(grid.Solution, &normals, 7);
  lep::PreviewParts parts;
  EXPECT_FALSE(parts.IsBuiltFor(7));
  parts.Build(grid.Input, output, edit);
  EXPECT_TRUE(parts.IsBuiltFor(7));
  parts.Write(edit);
  vtkPolyData* still = parts.GetStillPart();
  vtkPolyData* moving = parts.GetMovingPart();
  EXPECT_EQ(still->GetNumberOfPolys() + moving->GetNumberOfPolys(), grid.Input->GetNumberOfPolys());
  EXPECT_LT(moving->GetNumberOfPoints(), grid.Input->GetNumberOfPoints());
  double top = 0.0;
  for (vtkIdType p = 0; p < moving->GetNumberOfPoints(); ++p)
  {
    top = std::max(top, moving->GetPoint(p)[2]);
  }
  EXPECT_EQ(top, 0.5) << "the moving part holds the solution";
  EXPECT_EQ(still->GetPoints(), grid.Input->GetPoints()) << "the still part is at rest";
  // Write caches the moving points' ranges; they are those computed afresh.
  vtkDataArray* positions = moving->GetPoints()->GetData();
  ASSERT_TRUE(positions->GetInformation()->Has(vtkAbstractArray::PER_COMPONENT()));
  vtkNew<vtkDoubleArray> copy;
  copy->SetNumberOfComponents(3);
  for (vtkIdType p = 0; p < positions->GetNumberOfTuples(); ++p)
  {
    copy->InsertNextTuple(positions->GetTuple(p));
  }
  for (int c = 0; c < 3; ++c)
  {
    double cached[2], fresh[2];
    positions->GetRange(cached, c);
    copy->GetRange(fresh, c);
    EXPECT_EQ(cached[0], fresh[0]) << "component " << c;
    EXPECT_EQ(cached[1], fresh[1]) << "component " << c;
  }
  EXPECT_EQ(positions->GetRange(2)[1], 0.5);
}

TEST(LandmarkBinder, BindsToTrianglesAndTurnsTargetsIntoTheCoresFrame)
{
  auto grid = Grid(2);
  lep::SurfaceAdapter surface;
  bool rebuilt = false;
  ASSERT_EQ(surface.Update(grid, true, lep::Reach(), rebuilt), "");
  vtkNew<vtkPoints> sources;
  sources->SetDataTypeToDouble();
  sources->InsertNextPoint(0.25, 0.5, 0.0); // inside a triangle
  sources->InsertNextPoint(2.0, 2.0, 0.1);  // above a corner
  lep::LandmarkBinder binder;
  bool rebound = false;
  ASSERT_EQ(binder.Update(sources, surface, 1.0, rebound), "");
  EXPECT_TRUE(rebound);
  EXPECT_NEAR(binder.GetDistances()[0], 0.0, 1e-14);
  EXPECT_NEAR(binder.GetDistances()[1], 0.1, 1e-14);
  ASSERT_EQ(binder.Update(sources, surface, 1.0, rebound), "");
  EXPECT_FALSE(rebound) << "the same landmarks and surface";
  EXPECT_NE(binder.Update(sources, surface, 0.05, rebound).find("lies on no component"),
    std::string::npos);

  ASSERT_EQ(binder.Update(sources, surface, 1.0, rebound), "");
  le::PointTargets targets;
  ASSERT_EQ(binder.Targets(sources, surface, targets), "");
  // Landmarks at their sources: each bound point's target is where it is.
  const le::Vector3 bound = surface.Normalize(std::vector<double>{ 0.25, 0.5, 0.0 }.data());
  EXPECT_LT((targets.Targets.row(0).transpose() - bound).norm(), 1e-14);
}

TEST(SolverSettings, TranslateTheFiltersPropertiesForTheCore)
{
  lep::SolverSettings settings;
  settings.RotationMode = static_cast<int>(le::RotationMode::AsRigidAsPossible);
  settings.ARAPIterations = 30;
  settings.DragARAPIterations = 2;
  settings.NormalSmoothingRadius = 2.0;
  EXPECT_FALSE(settings.System(100.0).LeastSquares) << "ARAP needs no least-squares system";
  EXPECT_EQ(settings.System(100.0).MaximumFactorBytes, 100.0 * 1048576.0);
  EXPECT_EQ(settings.Rotation(0.5, 0.1).Arap.MaximumIterations, 30);
  EXPECT_NEAR(settings.Rotation(0.5, 0.1).NormalSmoothingRadius, 0.2, 1e-15) << "mesh units";
  settings.NormalSmoothingRadius = 0.0;
  EXPECT_NEAR(settings.Rotation(0.5, 0.1).NormalSmoothingRadius, 0.1, 1e-15) << "0.2 of the region";
  settings.Dragging = true;
  EXPECT_EQ(settings.Rotation(0.5, 0.1).Arap.MaximumIterations, 2) << "a drag step";
  settings.Dragging = false;
  settings.Settle = true;
  EXPECT_EQ(settings.Rotation(0.5, 0.1).Arap.Tolerance, 0.0) << "the settle runs in full";
  EXPECT_GT(lep::SolverSettings::AutomaticFactorLimit(), 0.0);
}

TEST(EditPipeline, RunsASourcesEditAndReportsThroughItsFilter)
{
  const int n = 8;
  auto grid = Grid(n);
  auto labels = GridLabels(grid, n);
  vtkNew<vtkPolyDataAlgorithm> filter;
  unsigned long code = vtkErrorCode::NoError;
  lep::EditPipeline pipeline(filter, [&code](unsigned long c) { code = c; });
  LabelledSource source;
  source.Labels = labels;
  source.Translation[2] = 0.5;
  vtkNew<vtkPolyData> output;
  output->ShallowCopy(grid);
  pipeline.BeginUpdate();
  ASSERT_TRUE(pipeline.Run(grid, output, source, lep::SolverSettings(), true, lep::OutputOptions{ true }));
  EXPECT_EQ(code, vtkErrorCode::NoError);
  EXPECT_EQ(source.RegionsSelected, 1);
  EXPECT_EQ(pipeline.GetEditor().GetNumberOfFactorizations(), 1);
  for (vtkIdType p = 0; p < grid->GetNumberOfPoints(); ++p)
  {
    const int label = labels->GetValue(p);
    const double z = output->GetPoint(p)[2];
    if (label == 0)
    {
      EXPECT_EQ(z, 0.0) << "fixed point " << p << " untouched";
    }
    if (label == 2)
    {
      EXPECT_NEAR(z, 0.5, 1e-3) << "handle point " << p;
    }
  }
  EXPECT_GT(pipeline.GetFacts().NumberOfROIVertices, 0);

  // A move only solves; a source's error is the filter's.
  source.Translation[2] = 0.25;
  pipeline.BeginUpdate();
  ASSERT_TRUE(pipeline.Run(grid, output, source, lep::SolverSettings(), true, lep::OutputOptions{ true }));
  EXPECT_EQ(source.RegionsSelected, 1);
  EXPECT_EQ(pipeline.GetEditor().GetNumberOfFactorizations(), 1);
  EXPECT_EQ(pipeline.GetFacts().SetupTime, 0.0);
  source.Error = "no region today";
  pipeline.BeginUpdate();
  ErrorCatcher errors(filter, vtkCommand::ErrorEvent);
  EXPECT_FALSE(pipeline.Run(grid, output, source, lep::SolverSettings(), true, lep::OutputOptions{ true }));
  EXPECT_NE(errors.Messages.find("no region today"), std::string::npos);
  EXPECT_EQ(code, vtkErrorCode::UserError);
}

TEST(EditPipeline, ResolvesNewMotionsOnTheSameFactorsAndRecordsNoDrag)
{
  const int n = 8;
  auto grid = Grid(n);
  auto labels = GridLabels(grid, n);
  vtkNew<vtkPolyDataAlgorithm> filter;
  lep::EditPipeline pipeline(filter, [](unsigned long) {});
  LabelledSource source;
  source.Labels = labels;
  ErrorCatcher errors(filter, vtkCommand::ErrorEvent);
  EXPECT_FALSE(pipeline.Resolve(source, lep::SolverSettings())) << "nothing solved yet";
  EXPECT_NE(errors.Messages.find("No edit to solve again"), std::string::npos);

  source.Translation[2] = 0.5;
  pipeline.BeginUpdate();
  ASSERT_TRUE(pipeline.Run(grid, nullptr, source, lep::SolverSettings(), true));
  source.Translation[2] = 0.2;
  source.Translation[0] = 0.1;
  ASSERT_TRUE(pipeline.Resolve(source, lep::SolverSettings()));
  EXPECT_EQ(pipeline.GetEditor().GetNumberOfFactorizations(), 1);
  EXPECT_EQ(source.RegionsSelected, 1);
  EXPECT_TRUE(pipeline.SetDragging(false)) << "a Resolve is no drag step the drag's end settles";

  // The same edit as a fresh pipeline solves it from the start.
  vtkNew<vtkPolyData> resolved, fresh;
  resolved->ShallowCopy(grid);
  const lep::OutputEdit edit = pipeline.GetEdit();
  pipeline.Write(grid, resolved, &edit, lep::OutputOptions{ true });
  lep::EditPipeline reference(filter, [](unsigned long) {});
  LabelledSource again;
  again.Labels = labels;
  std::copy(source.Translation, source.Translation + 3, again.Translation);
  fresh->ShallowCopy(grid);
  reference.BeginUpdate();
  ASSERT_TRUE(reference.Run(grid, fresh, again, lep::SolverSettings(), true, lep::OutputOptions{ true }));
  for (vtkIdType p = 0; p < grid->GetNumberOfPoints(); ++p)
  {
    for (int k = 0; k < 3; ++k)
    {
      EXPECT_NEAR(resolved->GetPoint(p)[k], fresh->GetPoint(p)[k], 1e-12) << "point " << p;
    }
  }
}

namespace
{
// How many times each index of [0, n) a loop's ranges reached, and whether one was out of it.
struct Coverage
{
  explicit Coverage(int n)
    : Hits(n)
  {
  }
  std::function<void(int, int)> Body(int n)
  {
    return [this, n](int first, int last) {
      this->Stray = this->Stray || first < 0 || last > n || first >= last;
      for (int i = std::max(first, 0); i < std::min(last, n); ++i)
      {
        ++this->Hits[i];
      }
    };
  }
  bool Once() const
  {
    return !this->Stray &&
      std::all_of(this->Hits.begin(), this->Hits.end(), [](const std::atomic<int>& h) { return h == 1; });
  }
  std::vector<std::atomic<int>> Hits;
  std::atomic<bool> Stray{ false };
};
}

namespace
{
// A 2 x 2 square of unit quads (two triangles each, facing +z) with an ear below its first
// edge: the triangle (1, 0, 9), its apex 9 at (0.3, -apexHeight).
vtkSmartPointer<vtkPolyData> SquareWithEar(double apexHeight)
{
  auto square = vtkSmartPointer<vtkPolyData>::New();
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  for (int j = 0; j < 3; ++j)
  {
    for (int i = 0; i < 3; ++i)
    {
      points->InsertNextPoint(i, j, 0.0);
    }
  }
  points->InsertNextPoint(0.3, -apexHeight, 0.0);
  vtkNew<vtkCellArray> triangles;
  for (vtkIdType a : { 0, 1, 3, 4 })
  {
    const vtkIdType lower[3] = { a, a + 1, a + 4 }, upper[3] = { a, a + 4, a + 3 };
    triangles->InsertNextCell(3, lower);
    triangles->InsertNextCell(3, upper);
  }
  const vtkIdType ear[3] = { 1, 0, 9 };
  triangles->InsertNextCell(3, ear);
  square->SetPoints(points);
  square->SetPolys(triangles);
  return square;
}

// `rest` turned by 90 degrees about x; `over`: point 9 reflected across the x axis first, the
// ear turned over.
vtkSmartPointer<vtkPolyData> Turned(vtkPolyData* rest, bool over)
{
  auto turned = vtkSmartPointer<vtkPolyData>::New();
  turned->DeepCopy(rest);
  for (vtkIdType i = 0; i < turned->GetNumberOfPoints(); ++i)
  {
    double p[3];
    turned->GetPoint(i, p);
    const double y = i == 9 && over ? -p[1] : p[1];
    turned->GetPoints()->SetPoint(i, p[0], -p[2], y);
  }
  return turned;
}
}

TEST(FoldGuard, ASliverTurnedOverIsTurnedBackAndNothingElse)
{
  // The square turned rigidly at the guard's start, then its ear turned over. Required: the
  // sliver is mended, its apex where the turn takes its rest position (to 1e-12) and every
  // other point bit-identical; a fat triangle turned over is left to the guard's other checks
  // (not mended).
  auto rest = SquareWithEar(0.01);
  auto turned = Turned(rest, true);
  lep::FoldGuard guard;
  guard.Reset(rest->GetNumberOfPoints());
  guard.Remember(Turned(rest, false));
  vtkNew<vtkPolyData> before;
  before->DeepCopy(turned);
  EXPECT_EQ(guard.MendSlivers(rest, turned), 1);
  const double expected[3] = { 0.3, 0.0, -0.01 };
  double apex[3];
  turned->GetPoint(9, apex);
  EXPECT_LT(std::sqrt(vtkMath::Distance2BetweenPoints(apex, expected)), 1e-12);
  for (vtkIdType i = 0; i < 9; ++i)
  {
    double p[3], q[3];
    turned->GetPoint(i, p);
    before->GetPoint(i, q);
    EXPECT_TRUE(p[0] == q[0] && p[1] == q[1] && p[2] == q[2]) << "point " << i;
  }
  auto fat = SquareWithEar(1.0);
  auto fatTurned = Turned(fat, true);
  guard.Remember(Turned(fat, false));
  EXPECT_EQ(guard.MendSlivers(fat, fatTurned), 0);
}

TEST(ThreadPool, CoversEachIndexOnceOnItsOwnThreadsAgainAndAgain)
{
  lep::ThreadPool pool(2);
  ASSERT_EQ(pool.GetNumberOfThreads(), 2);
  for (const int n : { 0, 1, 2, 7, 1000, 100000 })
  {
    Coverage coverage(n);
    pool.For(0, n, coverage.Body(n));
    EXPECT_TRUE(coverage.Once()) << n << " indices";
  }
  // Chunks that take a while, so that both threads take some: over many loops, the same two
  // threads (the caller and one worker) run them all.
  std::mutex lock;
  std::set<std::thread::id> threads;
  for (int loop = 0; loop < 20; ++loop)
  {
    pool.For(0, 8, [&](int, int) {
      std::this_thread::sleep_for(std::chrono::milliseconds(1));
      std::lock_guard<std::mutex> guard(lock);
      threads.insert(std::this_thread::get_id());
    });
  }
  EXPECT_EQ(threads.size(), 2u) << "the loops ran on the pool's threads, started once";
  EXPECT_EQ(threads.count(std::this_thread::get_id()), 1u) << "the caller works too";
}

TEST(ThreadPool, RunsNestedAndConcurrentLoopsOnTheirCallers)
{
  lep::ThreadPool pool(3);
  // A loop inside a loop's body: the pool is busy, the inner loop runs on its caller.
  std::atomic<int> innerRuns{ 0 };
  std::atomic<bool> innerOnce{ true };
  pool.For(0, 12, [&](int first, int last) {
    for (int i = first; i < last; ++i)
    {
      Coverage inner(50);
      pool.For(0, 50, inner.Body(50));
      innerOnce = innerOnce && inner.Once();
      ++innerRuns;
    }
  });
  EXPECT_EQ(innerRuns, 12);
  EXPECT_TRUE(innerOnce);
  // Two threads calling at once: each loop covers its range once, whichever runs it.
  Coverage a(20000), b(20000);
  const std::function<void(int, int)> coverA = a.Body(20000), coverB = b.Body(20000);
  std::thread other([&] {
    for (int k = 0; k < 50; ++k)
    {
      pool.For(0, 400, [&](int first, int last) { coverA(400 * k + first, 400 * k + last); });
    }
  });
  for (int k = 0; k < 50; ++k)
  {
    pool.For(0, 400, [&](int first, int last) { coverB(400 * k + first, 400 * k + last); });
  }
  other.join();
  EXPECT_TRUE(a.Once());
  EXPECT_TRUE(b.Once());
}

TEST(SMPFor, RunsOnThreadsThatOutliveALoopWhereVTKWouldStartThem)
{
  // Where VTK's backend starts threads at every loop (STDThread before VTK 9.3; Sequential,
  // which ParaView's VTK runs by default), the loops take ThreadPool's. A thread that outlives
  // a loop counts the loops it has worked on; a thread started for one loop counts one.
  const std::string backend = vtkSMPTools::GetBackend();
  std::cout << "vtkSMPTools backend " << backend << "\n";
  if ((backend != "STDThread" && backend != "Sequential") || VTK_VERSION_NUMBER >= VTK_VERSION_CHECK(9, 3, 0) ||
    lep::ThreadPool::Shared().GetNumberOfThreads() < 2)
  {
    GTEST_SKIP() << "VTK's own threads run the loops here";
  }
  static thread_local int loopsWorked = 0;
  static thread_local int lastLoop = -1;
  std::atomic<int> mostByAWorker{ 0 };
  const std::thread::id caller = std::this_thread::get_id();
  for (int loop = 0; loop < 10; ++loop)
  {
    lep::SMPFor(0, 8, [&](int, int) {
      std::this_thread::sleep_for(std::chrono::milliseconds(1));
      if (lastLoop != loop)
      {
        lastLoop = loop;
        ++loopsWorked;
      }
      if (std::this_thread::get_id() != caller)
      {
        int most = mostByAWorker;
        while (loopsWorked > most && !mostByAWorker.compare_exchange_weak(most, loopsWorked))
        {
        }
      }
    });
  }
  EXPECT_GT(mostByAWorker, 1) << "a worker worked on more than one loop: started once";
}
