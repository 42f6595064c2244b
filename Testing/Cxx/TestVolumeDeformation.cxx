// vtkLaplacianVolumeDeformationFilter: the volume follows its boundary's edit without inverting a
// cell. Inverted cells are counted by VTK's vtkMeshQuality (Verdict), not by the filter's own
// measure. The tetrahedral meshes are tetgen's, made here and cached in the build's temporary folder.
#include "FilterTestHelpers.h"
#include "VolumeMeshes.h"

#include "vtkLaplacianLandmarkWarp.h"
#include "vtkLaplacianVolumeDeformationFilter.h"

#include "vtkCallbackCommand.h"
#include "vtkCellData.h"
#include "vtkCommand.h"
#include "vtkDoubleArray.h"
#include "vtkErrorCode.h"
#include "vtkFieldData.h"
#include "vtkFloatArray.h"
#include "vtkIntArray.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkTransform.h"
#include "vtkUnsignedCharArray.h"
#include "vtkUnstructuredGrid.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>
#include <tuple>
#include <vector>

namespace
{
using Filter = vtkLaplacianVolumeDeformationFilter;
using FilterTestHelpers::ErrorCatcher;

const std::string TemporaryDir = LAPLACIAN_EDITING_TEMPORARY_DIR;

// A beam 8 long, 1 by 1 across, of 40 x 5 x 5 hexahedra, with a point and a cell array.
vtkSmartPointer<vtkUnstructuredGrid> Beam()
{
  vtkSmartPointer<vtkUnstructuredGrid> beam = VolumeMeshes::HexBeam(40, 5, 5, 8.0);
  vtkNew<vtkDoubleArray> temperature;
  temperature->SetName("Temperature");
  for (vtkIdType i = 0; i < beam->GetNumberOfPoints(); ++i)
  {
    temperature->InsertNextValue(beam->GetPoint(i)[0]);
  }
  beam->GetPointData()->AddArray(temperature);
  vtkNew<vtkIntArray> material;
  material->SetName("Material");
  for (vtkIdType i = 0; i < beam->GetNumberOfCells(); ++i)
  {
    material->InsertNextValue(static_cast<int>(i % 3));
  }
  beam->GetCellData()->AddArray(material);
  return beam;
}

// An edit of the beam's end x = 8: handle radius 0.3, region 3.
vtkSmartPointer<Filter> BeamEdit(vtkUnstructuredGrid* beam)
{
  auto filter = vtkSmartPointer<Filter>::New();
  filter->SetInputData(beam);
  filter->SetHandleCenter(8.0, 0.5, 0.5);
  filter->SetHandleRadius(0.3);
  filter->SetROIRadius(3.0);
  filter->SetRotationModeToAsRigidAsPossible();
  return filter;
}

// The transform that turns by `degrees` about the y axis through `center`, then moves by `lift`.
vtkSmartPointer<vtkTransform> Turn(const double center[3], double degrees, const double lift[3])
{
  auto transform = vtkSmartPointer<vtkTransform>::New();
  transform->PostMultiply();
  transform->Translate(-center[0], -center[1], -center[2]);
  transform->RotateY(degrees);
  transform->Translate(center);
  transform->Translate(lift);
  return transform;
}

bool SamePoint(vtkPoints* a, vtkPoints* b, vtkIdType id)
{
  double p[3], q[3];
  a->GetPoint(id, p);
  b->GetPoint(id, q);
  return p[0] == q[0] && p[1] == q[1] && p[2] == q[2];
}

// The beam's edit dragged to a 30-degree turn and released: its next update settles.
vtkSmartPointer<Filter> ReleasedBeamDrag(vtkUnstructuredGrid* beam)
{
  vtkSmartPointer<Filter> filter = BeamEdit(beam);
  const double lift[3] = { 0.0, 0.0, 0.3 };
  filter->DraggingOn();
  filter->SetHandleTransform(Turn(filter->GetHandleCenter(), -30.0, lift));
  filter->Update();
  filter->DraggingOff();
  return filter;
}

// A new grab and its release: the release settles in full.
void GrabAndRelease(Filter* filter)
{
  filter->DraggingOn();
  filter->Update();
  filter->DraggingOff();
  filter->Update();
}

double Distance(const double a[3], const double b[3])
{
  return std::sqrt(vtkMath::Distance2BetweenPoints(a, b));
}

// The largest distance between the same point of two point sets of the same points.
double LargestDistance(vtkPointSet* a, vtkPointSet* b)
{
  double largest = 0.0;
  for (vtkIdType i = 0; i < a->GetNumberOfPoints(); ++i)
  {
    largest = std::max(largest, Distance(a->GetPoint(i), b->GetPoint(i)));
  }
  return largest;
}

// A settle the time limit cut ends where the uncut one does: settled, every target met, no
// cell inverted; returns the largest distance from the uncut settle's points.
double ExpectSettledAs(Filter* filter, Filter* uncut)
{
  EXPECT_EQ(filter->GetSettling(), 0);
  EXPECT_EQ(filter->GetLargestTargetMiss(), 0.0);
  EXPECT_EQ(VolumeMeshes::Measure(filter->GetOutput()).Inverted, 0);
  return LargestDistance(filter->GetOutput(), uncut->GetOutput());
}

// Every point farther than `radius` from `center` keeps its coordinates exactly; returns how
// many points that covers.
vtkIdType ExpectFarPointsUntouched(
  vtkUnstructuredGrid* input, vtkUnstructuredGrid* output, const double center[3], double radius)
{
  vtkIdType far = 0;
  for (vtkIdType i = 0; i < input->GetNumberOfPoints(); ++i)
  {
    if (Distance(input->GetPoint(i), center) > radius)
    {
      ++far;
      EXPECT_TRUE(SamePoint(input->GetPoints(), output->GetPoints(), i)) << "point " << i;
    }
  }
  return far;
}

vtkSmartPointer<vtkUnstructuredGrid> TetgenMesh(const std::string& name)
{
  std::string error;
  vtkSmartPointer<vtkUnstructuredGrid> grid = VolumeMeshes::Tetrahedralize(
    FilterTestHelpers::DataDir + "/" + name + ".obj", TemporaryDir, name, "pq1.4a0.0005", error);
  EXPECT_TRUE(grid) << error;
  return grid;
}
}

TEST(VolumeDeformation, NothingMovedGivesTheInputBack)
{
  vtkSmartPointer<vtkUnstructuredGrid> beam = Beam();
  vtkSmartPointer<Filter> filter = BeamEdit(beam);
  filter->Update();
  vtkUnstructuredGrid* output = filter->GetOutput();
  ASSERT_EQ(output->GetNumberOfPoints(), beam->GetNumberOfPoints());
  EXPECT_EQ(MaxPointDistance(beam, output), 0.0);
  // A cube's corners are right angles: every scaled Jacobian is 1.
  vtkDataArray* quality = output->GetCellData()->GetArray("ScaledJacobian");
  ASSERT_NE(quality, nullptr);
  EXPECT_NEAR(quality->GetRange()[0], 1.0, 1e-6);
  vtkDataArray* failed = output->GetCellData()->GetArray("EditFailed");
  ASSERT_NE(failed, nullptr);
  EXPECT_EQ(failed->GetRange()[1], 0.0);
}

TEST(VolumeDeformation, PassesPointCellAndFieldDataThrough)
{
  vtkSmartPointer<vtkUnstructuredGrid> beam = Beam();
  vtkNew<vtkIntArray> note;
  note->SetName("Note");
  note->InsertNextValue(7);
  beam->GetFieldData()->AddArray(note);
  vtkSmartPointer<Filter> filter = BeamEdit(beam);
  const double lift[3] = { 0.0, 0.0, 1.0 };
  filter->SetHandleTransform(Turn(filter->GetHandleCenter(), 30.0, lift));
  filter->Update();
  vtkUnstructuredGrid* output = filter->GetOutput();
  EXPECT_EQ(output->GetPointData()->GetArray("Temperature"), beam->GetPointData()->GetArray("Temperature"));
  EXPECT_EQ(output->GetCellData()->GetArray("Material"), beam->GetCellData()->GetArray("Material"));
  EXPECT_EQ(output->GetFieldData()->GetArray("Note"), note.Get());
  EXPECT_EQ(output->GetNumberOfCells(), beam->GetNumberOfCells());
  EXPECT_GT(filter->GetNumberOfZonePoints(), 0);
}

TEST(VolumeDeformation, RigidMotionOfTheWholeRegionIsReproduced)
{
  // The whole boundary in the region, both ends handles turned by one rotation: the volume,
  // interior included, turns rigidly.
  vtkSmartPointer<vtkUnstructuredGrid> beam = Beam();
  vtkNew<vtkIntArray> labels;
  labels->SetName("Selection");
  for (vtkIdType i = 0; i < beam->GetNumberOfPoints(); ++i)
  {
    const double x = beam->GetPoint(i)[0];
    labels->InsertNextValue(x < 1.0 ? 2 : (x > 7.0 ? 3 : 1));
  }
  beam->GetPointData()->AddArray(labels);
  vtkNew<Filter> filter;
  filter->SetInputData(beam);
  filter->SetSelectionModeToArray();
  filter->SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, "Selection");
  filter->SetRotationModeToAsRigidAsPossible();
  const double center[3] = { 4.0, 0.5, 0.5 }, lift[3] = { 0.5, 1.0, 0.0 };
  vtkSmartPointer<vtkTransform> rigid = Turn(center, 40.0, lift);
  filter->SetHandleTransform(0, rigid);
  filter->SetHandleTransform(1, rigid);
  filter->Update();
  vtkUnstructuredGrid* output = filter->GetOutput();
  double worst = 0.0;
  for (vtkIdType i = 0; i < beam->GetNumberOfPoints(); ++i)
  {
    double expected[3];
    rigid->TransformPoint(beam->GetPoint(i), expected);
    worst = std::max(worst, Distance(expected, output->GetPoint(i)));
  }
  std::printf("rigid turn of the whole beam: largest error %.2e of the diagonal\n",
    worst / beam->GetLength());
  EXPECT_LT(worst, 2e-5 * beam->GetLength());
  EXPECT_EQ(VolumeMeshes::Measure(output).Inverted, 0);
}

TEST(VolumeDeformation, HexBeamBendLeavesNoInvertedCell)
{
  vtkSmartPointer<vtkUnstructuredGrid> beam = Beam();
  vtkSmartPointer<Filter> filter = BeamEdit(beam);
  const double lift[3] = { 0.0, 0.0, 1.5 };
  filter->SetHandleTransform(Turn(filter->GetHandleCenter(), -90.0, lift));
  filter->Update();
  vtkUnstructuredGrid* output = filter->GetOutput();
  const VolumeMeshes::Validity validity = VolumeMeshes::Measure(output);
  std::printf("beam bent 90 degrees: %d iterations, smallest scaled Jacobian %.3f\n",
    filter->GetNumberOfVolumeIterations(), validity.SmallestScaledJacobian);
  EXPECT_EQ(validity.Inverted, 0);
  EXPECT_EQ(filter->GetNumberOfFailedCells(), 0);
  EXPECT_EQ(filter->GetLargestTargetMiss(), 0.0);
  // The filter's ScaledJacobian: Verdict's, to the float it is stored in.
  EXPECT_LT(validity.LargestReportedQualityError, 1e-6);
  // The zone reaches the region's radius from the region: beyond twice the region, at rest.
  const double radius = 3.0 * (1.0 + std::pow(2.0, filter->GetNumberOfZoneGrowths()));
  EXPECT_GT(ExpectFarPointsUntouched(beam, output, filter->GetHandleCenter(), radius), 0);
}

class TetgenBend : public ::testing::TestWithParam<std::tuple<std::string, double>>
{
};

namespace
{
// The edits: the handle on the boundary point farthest from the centroid (radius 0.03
// of the diagonal), region 0.3, as rigid as possible.
vtkSmartPointer<Filter> TetgenEdit(vtkUnstructuredGrid* mesh, const VolumeMeshes::Edit& edit)
{
  vtkNew<Filter> filter;
  filter->SetInputData(mesh);
  filter->SetRadiusUnitsToDiagonalFraction();
  filter->SetHandleCenter(edit.Center);
  filter->SetHandleRadius(0.03);
  filter->SetROIRadius(0.3);
  filter->SetRotationModeToAsRigidAsPossible();
  return filter;
}
}

TEST_P(TetgenBend, NoInvertedCellAndTheBoundaryMet)
{
  // The edits: the handle on the boundary point farthest from the centroid (radius
  // 0.03 of the diagonal), region 0.3, turned about the axis across, lifted 0.1 of the
  // diagonal the way it turns.
  const auto [name, degrees] = GetParam();
  vtkSmartPointer<vtkUnstructuredGrid> mesh = TetgenMesh(name);
  ASSERT_TRUE(mesh);
  const VolumeMeshes::Edit edit = VolumeMeshes::FarEdit(mesh, degrees, 0.1);
  vtkSmartPointer<Filter> filter = TetgenEdit(mesh, edit);
  filter->SetHandleTransform(edit.At(1.0));
  filter->Update();
  vtkUnstructuredGrid* output = filter->GetOutput();
  const VolumeMeshes::Validity validity = VolumeMeshes::Measure(output);
  std::printf("%s turned %.0f degrees: %d tetrahedra in the zone, %d iterations, smallest "
              "scaled Jacobian %.4f\n",
    name.c_str(), degrees, filter->GetNumberOfZoneTetrahedra(), filter->GetNumberOfVolumeIterations(),
    validity.SmallestScaledJacobian);
  EXPECT_EQ(validity.Inverted, 0);
  EXPECT_EQ(filter->GetNumberOfFailedCells(), 0);
  // The ScaledJacobian array is Verdict's, to the float it is stored in.
  EXPECT_LT(validity.LargestReportedQualityError, 1e-6);
  // The boundary is the surface filter's edit, exactly.
  vtkPoints* surface = filter->GetSurfaceFilter()->GetOutput()->GetPoints();
  vtkIdType moved = 0;
  for (vtkIdType i = 0; i < mesh->GetNumberOfPoints(); ++i)
  {
    if (!SamePoint(surface, mesh->GetPoints(), i))
    {
      ++moved;
      ASSERT_TRUE(SamePoint(surface, output->GetPoints(), i)) << "boundary point " << i;
    }
  }
  EXPECT_GT(moved, 0);
  const double radius =
    mesh->GetLength() * 0.3 * (1.0 + std::pow(2.0, filter->GetNumberOfZoneGrowths()));
  EXPECT_GT(ExpectFarPointsUntouched(mesh, output, edit.Center, radius), 0);
}

// The same edits dragged in ten steps: the deformation graph takes every step (its repairs
// included), no cell inverts, the boundary is the surface's edit at every step, and the drag's
// end lies about as near the settled volume as the injective iteration's drag (measured: 0.0028
// and 0.0025 of the diagonal on spot, 0.0013 and 0.0047 on homer, on average).
TEST_P(TetgenBend, DraggedByTheGraphNoCellInvertsAndTheInteriorLagsLittle)
{
  const auto [name, degrees] = GetParam();
  vtkSmartPointer<vtkUnstructuredGrid> mesh = TetgenMesh(name);
  ASSERT_TRUE(mesh);
  const VolumeMeshes::Edit edit = VolumeMeshes::FarEdit(mesh, degrees, 0.1);
  auto lag = [&](bool graph) {
    vtkSmartPointer<Filter> filter = TetgenEdit(mesh, edit);
    filter->SetDragGraph(graph);
    filter->DraggingOn();
    constexpr int Steps = 10;
    int byGraph = 0;
    for (int step = 1; step <= Steps; ++step)
    {
      filter->SetHandleTransform(edit.At(step / double(Steps)));
      filter->Update();
      const VolumeMeshes::Validity validity = VolumeMeshes::Measure(filter->GetOutput());
      EXPECT_EQ(validity.Inverted, 0) << "step " << step;
      EXPECT_LT(validity.LargestReportedQualityError, 1e-6) << "step " << step;
      byGraph += filter->GetNumberOfGraphNodes() > 0;
      if (graph)
      {
        EXPECT_EQ(filter->GetLargestTargetMiss(), 0.0) << "step " << step;
      }
    }
    EXPECT_EQ(byGraph, graph ? Steps : 0);
    vtkNew<vtkUnstructuredGrid> dragged;
    dragged->DeepCopy(filter->GetOutput());
    filter->DraggingOff();
    filter->Update();
    EXPECT_EQ(filter->GetLargestTargetMiss(), 0.0);
    EXPECT_EQ(VolumeMeshes::Measure(filter->GetOutput()).Inverted, 0);
    // The mean distance of the points the release moved from their place at the drag's end
    // (the largest is the boundary's: the surface's release goes on from its drag's end).
    double sum = 0.0;
    int moved = 0;
    for (vtkIdType i = 0; i < mesh->GetNumberOfPoints(); ++i)
    {
      double a[3], b[3], r[3];
      dragged->GetPoint(i, a);
      filter->GetOutput()->GetPoint(i, b);
      mesh->GetPoint(i, r);
      if (Distance(b, r) > 0.0)
      {
        sum += Distance(a, b);
        ++moved;
      }
    }
    return sum / std::max(1, moved) / mesh->GetLength();
  };
  const double byGraph = lag(true);
  const double byIterations = lag(false);
  std::printf("%s dragged %.0f degrees in ten steps: the drag's end %.4f of the diagonal from the "
              "settled volume by the graph, %.4f by the injective iteration\n",
    name.c_str(), degrees, byGraph, byIterations);
  EXPECT_LT(byGraph, 1.25 * byIterations);
  EXPECT_LT(byGraph, 0.005);
}

INSTANTIATE_TEST_SUITE_P(Meshes, TetgenBend,
  ::testing::Values(std::make_tuple(std::string("spot"), 90.0), std::make_tuple(std::string("homer"), 60.0)),
  [](const ::testing::TestParamInfo<TetgenBend::ParamType>& info) {
    return std::get<0>(info.param);
  });

TEST(VolumeDeformation, MixedCellsBend)
{
  // The beam's far half in wedges (each hexahedron split across a diagonal), a pyramid cap
  // would not share faces: wedges and hexahedra meet on quadrilaterals.
  vtkSmartPointer<vtkUnstructuredGrid> hexes = Beam();
  vtkNew<vtkUnstructuredGrid> mixed;
  mixed->SetPoints(hexes->GetPoints());
  for (vtkIdType cell = 0; cell < hexes->GetNumberOfCells(); ++cell)
  {
    vtkIdType count;
    const vtkIdType* p;
    hexes->GetCellPoints(cell, count, p);
    if (hexes->GetPoint(p[0])[0] < 4.0)
    {
      mixed->InsertNextCell(VTK_HEXAHEDRON, 8, p);
      continue;
    }
    // Split along the diagonal 0-2 of the bottom face (and 4-6 of the top).
    const vtkIdType first[6] = { p[0], p[1], p[2], p[4], p[5], p[6] };
    const vtkIdType second[6] = { p[0], p[2], p[3], p[4], p[6], p[7] };
    mixed->InsertNextCell(VTK_WEDGE, 6, first);
    mixed->InsertNextCell(VTK_WEDGE, 6, second);
  }
  vtkSmartPointer<Filter> filter = BeamEdit(mixed);
  const double lift[3] = { 0.0, 0.0, 1.0 };
  filter->SetHandleTransform(Turn(filter->GetHandleCenter(), -60.0, lift));
  filter->Update();
  EXPECT_EQ(filter->GetErrorCode(), 0);
  EXPECT_EQ(filter->GetNumberOfFailedCells(), 0);
  EXPECT_GT(filter->GetOutput()->GetCellData()->GetArray("ScaledJacobian")->GetRange()[0], 0.0);
  EXPECT_GT(filter->GetNumberOfZonePoints(), 0);
}

TEST(VolumeDeformation, DragReusesTheZoneAndTheReleaseSettles)
{
  vtkSmartPointer<vtkUnstructuredGrid> beam = Beam();
  vtkSmartPointer<Filter> filter = BeamEdit(beam);
  const double lift[3] = { 0.0, 0.0, 0.3 };
  filter->SetHandleTransform(Turn(filter->GetHandleCenter(), -5.0, lift));
  filter->Update();
  filter->DraggingOn();
  for (int step = 2; step <= 6; ++step)
  {
    filter->SetHandleTransform(Turn(filter->GetHandleCenter(), -5.0 * step, lift));
    filter->Update();
    // The first drag step builds the zone's deformation graph; the others reuse it.
    if (step > 2)
    {
      EXPECT_EQ(filter->GetVolumeSetupTime(), 0.0) << "step " << step;
    }
    EXPECT_EQ(filter->GetNumberOfVolumeFactorizations(), 0) << "step " << step;
    // The graph takes the step: no iteration of the interior's solve, the boundary met.
    EXPECT_GT(filter->GetNumberOfGraphNodes(), 0) << "step " << step;
    EXPECT_EQ(filter->GetNumberOfVolumeIterations(), 0) << "step " << step;
    EXPECT_EQ(filter->GetLargestTargetMiss(), 0.0) << "step " << step;
    const VolumeMeshes::Validity validity = VolumeMeshes::Measure(filter->GetOutput());
    EXPECT_EQ(validity.Inverted, 0);
    // A drag step's ScaledJacobian (the batched pass): Verdict's, to the float it is stored in.
    EXPECT_LT(validity.LargestReportedQualityError, 1e-6);
  }
  filter->DraggingOff();
  filter->Update();
  EXPECT_GT(filter->GetNumberOfVolumeIterations(), filter->GetDragVolumeIterations());
  EXPECT_EQ(filter->GetLargestTargetMiss(), 0.0);
}

// A release starts at the drag's end, near its targets: the pull is stiff from the start, where a
// settle from rest tightens it in stages (and at 1M tetrahedra, a release that did the same left
// targets a little short and grew its zone: 37 s against 6.8 s, volumes.md).
TEST(VolumeDeformation, AReleaseSettlesFromTheDragsEndOnTheDragsFactor)
{
  vtkSmartPointer<vtkUnstructuredGrid> beam = Beam();
  const double lift[3] = { 0.0, 0.0, 0.3 };
  vtkSmartPointer<Filter> fromRest = BeamEdit(beam);
  fromRest->SetHandleTransform(Turn(fromRest->GetHandleCenter(), -40.0, lift));
  fromRest->Update();
  vtkSmartPointer<Filter> dragged = BeamEdit(beam);
  dragged->DraggingOn();
  for (int step = 1; step <= 8; ++step)
  {
    dragged->SetHandleTransform(Turn(dragged->GetHandleCenter(), -5.0 * step, lift));
    dragged->Update();
  }
  dragged->DraggingOff();
  dragged->Update();
  for (Filter* filter : { fromRest.Get(), dragged.Get() })
  {
    EXPECT_EQ(filter->GetLargestTargetMiss(), 0.0);
    EXPECT_EQ(filter->GetNumberOfZoneGrowths(), 0);
    EXPECT_EQ(VolumeMeshes::Measure(filter->GetOutput()).Inverted, 0);
  }
  EXPECT_LT(dragged->GetNumberOfVolumeIterations(), fromRest->GetNumberOfVolumeIterations());
  // From rest, a factorization a stage (three) at least; the drag's factor serves the release,
  // refactored only where a stalled step reweights it.
  EXPECT_GE(fromRest->GetNumberOfVolumeFactorizations(), 3);
  EXPECT_LT(dragged->GetNumberOfVolumeFactorizations(), fromRest->GetNumberOfVolumeFactorizations());
}

TEST(VolumeDeformation, ADragStepsWorkFollowsTheRegionNotTheMesh)
{
  // The same edit of a beam's end on a beam of 40 cells and on one of 160, as fine, four times
  // as long: a drag step solves the same zone and moves the same number of points on both.
  auto dragStep = [](int cells) {
    vtkSmartPointer<vtkUnstructuredGrid> beam = VolumeMeshes::HexBeam(cells, 5, 5, 0.2 * cells);
    vtkNew<Filter> filter;
    filter->SetInputData(beam);
    filter->SetHandleCenter(0.2 * cells, 0.5, 0.5);
    filter->SetHandleRadius(0.31); // radii between grid distances: no ties
    filter->SetROIRadius(3.05);
    filter->SetRotationModeToAsRigidAsPossible();
    const double lift[3] = { 0.0, 0.0, 0.2 };
    filter->SetHandleTransform(Turn(filter->GetHandleCenter(), -5.0, lift));
    filter->Update();
    filter->DraggingOn();
    filter->SetHandleTransform(Turn(filter->GetHandleCenter(), -10.0, lift));
    filter->Update();
    vtkIdType moved = 0;
    for (vtkIdType i = 0; i < beam->GetNumberOfPoints(); ++i)
    {
      double rest[3], now[3];
      beam->GetPoint(i, rest);
      filter->GetOutput()->GetPoint(i, now);
      moved += Distance(rest, now) > 0.0;
    }
    EXPECT_EQ(VolumeMeshes::Measure(filter->GetOutput()).Inverted, 0);
    return std::make_tuple(filter->GetNumberOfZonePoints(), moved, beam->GetNumberOfPoints());
  };
  const auto [shortZone, shortMoved, shortPoints] = dragStep(40);
  const auto [longZone, longMoved, longPoints] = dragStep(160);
  std::printf("zone points %d and %d, points moved %lld and %lld, of %lld and %lld\n", shortZone,
    longZone, static_cast<long long>(shortMoved), static_cast<long long>(longMoved),
    static_cast<long long>(shortPoints), static_cast<long long>(longPoints));
  EXPECT_GT(shortMoved, 0);
  EXPECT_EQ(longZone, shortZone);
  EXPECT_EQ(longMoved, shortMoved);
  EXPECT_LT(longZone, longPoints / 3);
}

TEST(VolumeDeformation, SettleReportsProgressStopsWhereAbortedAndTheNextReleaseSettles)
{
  // The beam dragged and released with an observer that aborts after the settle's third
  // iteration. Required: progress events in (0.4, 0.9), increasing, one an iteration; the abort
  // ends the settle there with every cell positive; a new grab and release settle in full. The
  // boundary's own settle reports first, in (0.1, 0.4).
  vtkSmartPointer<vtkUnstructuredGrid> beam = Beam();
  vtkSmartPointer<Filter> filter = ReleasedBeamDrag(beam);
  struct Progress
  {
    std::vector<double> Boundary, Volume;
  } progress;
  vtkNew<vtkCallbackCommand> observer;
  observer->SetClientData(&progress);
  observer->SetCallback([](vtkObject* caller, unsigned long, void* client, void* data) {
    auto& seen = *static_cast<Progress*>(client);
    const double done = *static_cast<double*>(data);
    if (done > 0.1 && done < 0.4)
    {
      seen.Boundary.push_back(done);
    }
    if (done > 0.4 && done < 0.9)
    {
      seen.Volume.push_back(done);
      if (seen.Volume.size() == 3)
      {
        static_cast<vtkAlgorithm*>(caller)->AbortExecuteOn();
      }
    }
  });
  const unsigned long tag = filter->AddObserver(vtkCommand::ProgressEvent, observer);
  filter->Update();
  filter->RemoveObserver(tag);
  filter->AbortExecuteOff();
  EXPECT_GT(progress.Boundary.size(), 1u) << "the boundary's settle reports as the filter's";
  ASSERT_EQ(progress.Volume.size(), 3u);
  EXPECT_TRUE(std::is_sorted(progress.Volume.begin(), progress.Volume.end()));
  EXPECT_EQ(filter->GetNumberOfVolumeIterations(), 3);
  const VolumeMeshes::Validity stopped = VolumeMeshes::Measure(filter->GetOutput());
  EXPECT_EQ(stopped.Inverted, 0);
  EXPECT_EQ(filter->GetOutput()->GetNumberOfPoints(), beam->GetNumberOfPoints());

  // The release settles (more than a drag step's iterations, every target met) from the new
  // drag's end, which started where the abort left the volume.
  GrabAndRelease(filter);
  EXPECT_GT(filter->GetNumberOfVolumeIterations(), filter->GetDragVolumeIterations());
  EXPECT_EQ(filter->GetLargestTargetMiss(), 0.0);
  EXPECT_EQ(VolumeMeshes::Measure(filter->GetOutput()).Inverted, 0);
}

namespace
{
// The beam's drag released twice, in ARAP or in rotation mode None: in full, and with a time
// limit that every iteration reaches (1 ns), continued update by update (ContinueSettling)
// until it is done, as the ParaView panel does. Checks that every update's volume has every
// cell positive, and that the split settle ends with every target met. Returns the split
// settle's updates, those in which the boundary's settle was cut, the interior's settle
// iterations in all, with the uncut's, and the largest distance of a point from the uncut
// settle's, as a share of the beam's length.
struct SplitSettle
{
  int Updates = 0, BoundaryUpdates = 0, Iterations = 0, UncutIterations = 0;
  double Distance = 0.0;
};

SplitSettle SettleSplitByATimeLimit(bool rigid, bool fromDrag = true)
{
  vtkSmartPointer<vtkUnstructuredGrid> beam = Beam();
  auto released = [&]() {
    vtkSmartPointer<Filter> filter = BeamEdit(beam);
    rigid ? filter->SetRotationModeToAsRigidAsPossible() : filter->SetRotationModeToNone();
    const double lift[3] = { 0.0, 0.0, 0.3 };
    filter->SetHandleTransform(Turn(filter->GetHandleCenter(), -30.0, lift));
    if (fromDrag)
    {
      filter->DraggingOn();
      filter->Update();
      filter->DraggingOff();
    }
    return filter;
  };
  SplitSettle split;
  vtkSmartPointer<Filter> uncut = released();
  uncut->Update();
  EXPECT_EQ(uncut->GetSettling(), 0);
  split.UncutIterations = uncut->GetNumberOfVolumeIterations();

  vtkSmartPointer<Filter> filter = released();
  filter->SetSettleTimeLimit(1e-9);
  filter->Update();
  for (split.Updates = 1; filter->GetSettling() && split.Updates < 1000; ++split.Updates)
  {
    EXPECT_EQ(VolumeMeshes::Measure(filter->GetOutput()).Inverted, 0) << "update " << split.Updates;
    if (filter->GetSurfaceFilter()->GetSettling())
    {
      ++split.BoundaryUpdates; // the interior followed as a drag step: by its graph, or iterations
      EXPECT_EQ(filter->GetNumberOfVolumeIterations(),
        filter->GetNumberOfGraphNodes() > 0 ? 0 : filter->GetDragVolumeIterations());
    }
    else
    {
      split.Iterations += filter->GetNumberOfVolumeIterations();
      EXPECT_EQ(filter->GetNumberOfVolumeIterations(), 1) << "update " << split.Updates;
    }
    filter->ContinueSettling();
    filter->Update();
  }
  split.Iterations += filter->GetNumberOfVolumeIterations();
  const double largest = ExpectSettledAs(filter, uncut);
  std::printf("%s%s: %d updates, %d of them the boundary's; the interior's settle %d iterations "
              "against the uncut's %d; %.3g of the beam's length from the uncut settle\n",
    rigid ? "ARAP" : "None", fromDrag ? "" : " from rest", split.Updates, split.BoundaryUpdates, split.Iterations,
    split.UncutIterations, largest / 8.0);
  split.Distance = largest / 8.0;

  // Without the limit, a release settles in one update.
  filter->SetSettleTimeLimit(0.0);
  GrabAndRelease(filter);
  EXPECT_EQ(filter->GetSettling(), 0);
  return split;
}
}

TEST(VolumeDeformation, ABoundarySettleSplitByATimeLimitEndsOnTheUncutSettlesShape)
{
  // ARAP: the boundary's settle is cut at every iteration, the interior following it as a drag
  // step does, then settling: a path of its own, ending within 1e-4 of the beam's length.
  const SplitSettle split = SettleSplitByATimeLimit(true);
  EXPECT_GT(split.BoundaryUpdates, 1);
  EXPECT_LT(split.Distance, 1e-4);
}

TEST(VolumeDeformation, AnInteriorSettleSplitByATimeLimitEndsOnTheUncutSettlesShapeToTheBit)
{
  // Rotation mode None solves the boundary at once: the interior's settle is cut at every
  // iteration and goes on where it stopped (its stage, momentum and iterate), so that it takes
  // the uncut settle's iterations and ends on its shape to the bit.
  const SplitSettle split = SettleSplitByATimeLimit(false);
  EXPECT_EQ(split.BoundaryUpdates, 0);
  EXPECT_GT(split.Updates, 2);
  EXPECT_EQ(split.Iterations, split.UncutIterations);
  EXPECT_EQ(split.Distance, 0.0);
}

TEST(VolumeDeformation, ASettleFromRestSplitByATimeLimitEndsOnTheUncutSettlesShapeToTheBit)
{
  // The same edit settled from rest, without a drag: the interior's settle runs its stages of
  // a loosening pull, and a cut at every iteration goes on in the stage it stopped in.
  const SplitSettle split = SettleSplitByATimeLimit(false, false);
  EXPECT_GT(split.Updates, 2);
  EXPECT_EQ(split.Iterations, split.UncutIterations);
  EXPECT_EQ(split.Distance, 0.0);
}

TEST(VolumeDeformation, ALimitOnTheSurfaceFilterAloneCutsOnlyTheBoundarysSettle)
{
  // A handle widget paired with the surface filter continues the surface's settle only: with
  // the limit set there, the interior follows the boundary's steps and then settles in full,
  // so that the volume ends settled, every target met, near the uncut settle.
  vtkSmartPointer<vtkUnstructuredGrid> beam = Beam();
  vtkSmartPointer<Filter> uncut = ReleasedBeamDrag(beam);
  uncut->Update();
  vtkSmartPointer<Filter> filter = ReleasedBeamDrag(beam);
  vtkLaplacianDeformationFilter* surface = filter->GetSurfaceFilter();
  surface->SetSettleTimeLimit(1e-9);
  EXPECT_EQ(filter->GetSettleTimeLimit(), 0.0);
  filter->Update();
  int updates = 1;
  for (; surface->GetSettling() && updates < 1000; ++updates)
  {
    EXPECT_EQ(VolumeMeshes::Measure(filter->GetOutput()).Inverted, 0) << "update " << updates;
    surface->ContinueSettling(); // what the widget does
    filter->Update();
  }
  EXPECT_GT(updates, 2);
  const double largest = ExpectSettledAs(filter, uncut);
  EXPECT_LT(largest / 8.0, 1e-4);
}

TEST(VolumeDeformation, AnAbortDuringTheBoundarysSettleEndsTheUpdateAtAValidVolume)
{
  // Aborted at the boundary's first settle event (its edit's last tenth, (0.37, 0.4) of the
  // filter's progress): the boundary's settle ends there, the volume's after its first iteration, every cell positive; the surface filter is free for the next
  // update, and a new grab and release settle in full.
  vtkSmartPointer<vtkUnstructuredGrid> beam = Beam();
  vtkSmartPointer<Filter> filter = ReleasedBeamDrag(beam);
  vtkNew<vtkCallbackCommand> observer;
  observer->SetCallback([](vtkObject* caller, unsigned long, void*, void* data) {
    const double done = *static_cast<double*>(data);
    if (done > 0.37 && done < 0.4)
    {
      static_cast<vtkAlgorithm*>(caller)->AbortExecuteOn();
    }
  });
  const unsigned long tag = filter->AddObserver(vtkCommand::ProgressEvent, observer);
  filter->Update();
  filter->RemoveObserver(tag);
  filter->AbortExecuteOff();
  EXPECT_EQ(filter->GetSurfaceFilter()->GetAbortExecute(), 0);
  EXPECT_EQ(filter->GetSurfaceFilter()->GetNumberOfARAPIterations(), 1);
  EXPECT_EQ(filter->GetNumberOfVolumeIterations(), 1);
  EXPECT_EQ(VolumeMeshes::Measure(filter->GetOutput()).Inverted, 0);

  GrabAndRelease(filter);
  EXPECT_GT(filter->GetSurfaceFilter()->GetNumberOfARAPIterations(), 1);
  EXPECT_EQ(filter->GetLargestTargetMiss(), 0.0);
  EXPECT_EQ(VolumeMeshes::Measure(filter->GetOutput()).Inverted, 0);
}

TEST(VolumeDeformation, UnreachableBoundaryIsReportedNotInverted)
{
  // The end pushed back through the beam: the boundary's edit folds onto itself, and no
  // interior without inverted cells fills it.
  vtkSmartPointer<vtkUnstructuredGrid> beam = Beam();
  vtkSmartPointer<Filter> filter = BeamEdit(beam);
  filter->SetHandleTranslation(-6.0, 0.0, 0.0);
  ErrorCatcher warnings(filter, vtkCommand::WarningEvent);
  filter->Update();
  vtkUnstructuredGrid* output = filter->GetOutput();
  EXPECT_GT(filter->GetNumberOfFailedCells(), 0);
  EXPECT_NE(warnings.Messages.find("could not follow the edit"), std::string::npos)
    << warnings.Messages;
  EXPECT_EQ(warnings.Messages.find("sliver"), std::string::npos) << "the cells are cubes";
  EXPECT_EQ(VolumeMeshes::Measure(output).Inverted, 0);
  vtkDataArray* failed = output->GetCellData()->GetArray("EditFailed");
  double marked = 0.0;
  for (vtkIdType i = 0; i < failed->GetNumberOfTuples(); ++i)
  {
    marked += failed->GetTuple1(i);
  }
  EXPECT_EQ(marked, filter->GetNumberOfFailedCells());
}

TEST(VolumeDeformation, TheFailureWarningCountsSlivers)
{
  vtkSmartPointer<vtkUnstructuredGrid> beam = Beam();
  // Sheared by x += 12 (y - 0.4), every cell's corners have a scaled Jacobian of 1 / sqrt(145),
  // about 0.083: each failed cell is a sliver at rest. The handle's row y = 0.4 stays in place.
  vtkPoints* points = beam->GetPoints();
  for (vtkIdType i = 0; i < points->GetNumberOfPoints(); ++i)
  {
    double p[3];
    points->GetPoint(i, p);
    p[0] += 12.0 * (p[1] - 0.4);
    points->SetPoint(i, p);
  }
  vtkSmartPointer<Filter> filter = BeamEdit(beam);
  filter->SetHandleCenter(8.0, 0.4, 0.4);
  filter->SetHandleTranslation(-6.0, 0.0, 0.0);
  ErrorCatcher warnings(filter, vtkCommand::WarningEvent);
  filter->Update();
  ASSERT_GT(filter->GetNumberOfFailedCells(), 0);
  const std::string counted =
    std::to_string(filter->GetNumberOfFailedCells()) + " of them were slivers at rest";
  EXPECT_NE(warnings.Messages.find(counted), std::string::npos) << warnings.Messages;
  EXPECT_EQ(VolumeMeshes::Measure(filter->GetOutput()).Inverted, 0);
}

TEST(VolumeDeformation, CommitMakesTheVolumeTheNextRest)
{
  vtkSmartPointer<vtkUnstructuredGrid> beam = Beam();
  vtkSmartPointer<Filter> filter = BeamEdit(beam);
  filter->SetHandleTranslation(0.0, 0.0, 1.0);
  filter->Update();
  vtkNew<vtkPoints> edited;
  edited->SetDataTypeToDouble();
  edited->DeepCopy(filter->GetOutput()->GetPoints());
  filter->CommitEdit();
  EXPECT_EQ(filter->GetNumberOfCommits(), 1);
  EXPECT_EQ(filter->GetHandleTranslation()[2], 0.0);
  filter->Update();
  vtkNew<vtkUnstructuredGrid> committed;
  committed->SetPoints(edited);
  EXPECT_EQ(MaxPointDistance(committed, filter->GetOutput()), 0.0) << "the committed volume at rest";
  // The next edit starts from the committed volume.
  filter->SetHandleTranslation(0.0, 0.0, 1.0);
  filter->Update();
  EXPECT_GT(filter->GetOutput()->GetBounds()[5], 2.5);
  EXPECT_EQ(VolumeMeshes::Measure(filter->GetOutput()).Inverted, 0);
  filter->SetHandleTranslation(0.0, 0.0, 0.0);
  EXPECT_TRUE(filter->UndoCommit());
  filter->Update();
  EXPECT_EQ(MaxPointDistance(beam, filter->GetOutput()), 0.0) << "the undo gives the rest back";
}

// Bad input: a clear error, and the input passed through.
struct BadGrid
{
  const char* Name;
  vtkSmartPointer<vtkUnstructuredGrid> (*Make)();
  const char* Message;
};

// What ctest's test names show of a case.
void PrintTo(const BadGrid& grid, std::ostream* os)
{
  *os << grid.Name;
}

class VolumeErrors : public ::testing::TestWithParam<BadGrid>
{
};

TEST_P(VolumeErrors, ReportsAndPassesTheInputThrough)
{
  vtkSmartPointer<vtkUnstructuredGrid> input = GetParam().Make();
  vtkNew<Filter> filter;
  filter->SetInputData(input);
  filter->SetHandleCenter(input->GetNumberOfPoints() ? input->GetPoint(0) : input->GetCenter());
  filter->SetHandleTranslation(0.0, 0.0, 0.5);
  ErrorCatcher errors(filter);
  filter->Update();
  EXPECT_NE(errors.Messages.find(GetParam().Message), std::string::npos) << errors.Messages;
  EXPECT_NE(filter->GetErrorCode(), 0);
  vtkUnstructuredGrid* output = filter->GetOutput();
  EXPECT_EQ(output->GetNumberOfPoints(), input->GetNumberOfPoints());
  EXPECT_EQ(output->GetNumberOfCells(), input->GetNumberOfCells());
  EXPECT_EQ(output->GetPoints(), input->GetPoints());
}

namespace
{
vtkSmartPointer<vtkUnstructuredGrid> Empty()
{
  return vtkSmartPointer<vtkUnstructuredGrid>::New();
}

vtkSmartPointer<vtkUnstructuredGrid> TrianglesOnly()
{
  auto grid = vtkSmartPointer<vtkUnstructuredGrid>::New();
  vtkNew<vtkPoints> points;
  points->InsertNextPoint(0, 0, 0);
  points->InsertNextPoint(1, 0, 0);
  points->InsertNextPoint(0, 1, 0);
  grid->SetPoints(points);
  const vtkIdType triangle[3] = { 0, 1, 2 };
  grid->InsertNextCell(VTK_TRIANGLE, 3, triangle);
  return grid;
}

vtkSmartPointer<vtkUnstructuredGrid> QuadraticTetrahedron()
{
  auto grid = vtkSmartPointer<vtkUnstructuredGrid>::New();
  vtkNew<vtkPoints> points;
  const double corners[4][3] = { { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 }, { 0, 0, 1 } };
  const int edges[6][2] = { { 0, 1 }, { 1, 2 }, { 2, 0 }, { 0, 3 }, { 1, 3 }, { 2, 3 } };
  for (const auto& c : corners)
  {
    points->InsertNextPoint(c);
  }
  for (const auto& e : edges)
  {
    points->InsertNextPoint((corners[e[0]][0] + corners[e[1]][0]) / 2,
      (corners[e[0]][1] + corners[e[1]][1]) / 2, (corners[e[0]][2] + corners[e[1]][2]) / 2);
  }
  grid->SetPoints(points);
  const vtkIdType ids[10] = { 0, 1, 2, 3, 4, 5, 6, 7, 8, 9 };
  grid->InsertNextCell(VTK_QUADRATIC_TETRA, 10, ids);
  return grid;
}

vtkSmartPointer<vtkUnstructuredGrid> OneCellInverted()
{
  vtkSmartPointer<vtkUnstructuredGrid> beam = VolumeMeshes::HexBeam(6, 2, 2, 3.0);
  // Cell 7's top and bottom faces swapped: every corner of it turns inside out.
  vtkIdType count;
  const vtkIdType* p;
  beam->GetCellPoints(7, count, p);
  const vtkIdType swapped[8] = { p[4], p[5], p[6], p[7], p[0], p[1], p[2], p[3] };
  beam->ReplaceCell(7, 8, swapped);
  return beam;
}

vtkSmartPointer<vtkUnstructuredGrid> CubesSharingAnEdge()
{
  auto grid = vtkSmartPointer<vtkUnstructuredGrid>::New();
  vtkNew<vtkPoints> points;
  for (int k = 0; k <= 1; ++k)
  {
    for (int j = 0; j <= 2; ++j)
    {
      for (int i = 0; i <= 2; ++i)
      {
        points->InsertNextPoint(i, j, k);
      }
    }
  }
  grid->SetPoints(points);
  auto id = [](int i, int j, int k) { return static_cast<vtkIdType>(k * 9 + j * 3 + i); };
  for (auto [i, j] : { std::make_pair(0, 0), std::make_pair(1, 1) })
  {
    const vtkIdType hex[8] = { id(i, j, 0), id(i + 1, j, 0), id(i + 1, j + 1, 0), id(i, j + 1, 0),
      id(i, j, 1), id(i + 1, j, 1), id(i + 1, j + 1, 1), id(i, j + 1, 1) };
    grid->InsertNextCell(VTK_HEXAHEDRON, 8, hex);
  }
  return grid;
}

vtkSmartPointer<vtkUnstructuredGrid> NaNPoint()
{
  vtkSmartPointer<vtkUnstructuredGrid> beam = VolumeMeshes::HexBeam(4, 2, 2, 2.0);
  beam->GetPoints()->SetPoint(5, std::numeric_limits<double>::quiet_NaN(), 0.0, 0.0);
  return beam;
}
}

INSTANTIATE_TEST_SUITE_P(BadInput, VolumeErrors,
  ::testing::Values(BadGrid{ "Empty", &Empty, "empty" },
    BadGrid{ "NoVolumeCells", &TrianglesOnly, "no 3D cells" },
    BadGrid{ "NonLinear", &QuadraticTetrahedron, "non-linear cells" },
    BadGrid{ "InvertedAtRest", &OneCellInverted, "1 cell is flat or inverted at rest (the first is cell 7)" },
    BadGrid{ "NonManifold", &CubesSharingAnEdge, "not manifold" },
    BadGrid{ "NaN", &NaNPoint, "NaN" }),
  [](const ::testing::TestParamInfo<BadGrid>& info) { return std::string(info.param.Name); });

namespace
{
// Landmarks on the beam's end corners: those of the end x = 8 moved by (0, dy, dz), those of the
// end x = 0 held.
void BeamEndLandmarks(double dy, double dz, vtkPoints* sources, vtkPoints* targets)
{
  for (double y : { 0.0, 1.0 })
  {
    for (double z : { 0.0, 1.0 })
    {
      sources->InsertNextPoint(8.0, y, z);
      targets->InsertNextPoint(8.0, y + dy, z + dz);
      sources->InsertNextPoint(0.0, y, z);
      targets->InsertNextPoint(0.0, y, z);
    }
  }
}
}

TEST(VolumeDeformation, LandmarkWarpTakesAVolume)
{
  // Landmarks on the beam's boundary: the end x = 8 lifted by 1.5, the end x = 0 held.
  vtkSmartPointer<vtkUnstructuredGrid> beam = Beam();
  vtkNew<vtkPoints> sources, targets;
  BeamEndLandmarks(0.0, 1.5, sources, targets);
  vtkNew<vtkLaplacianLandmarkWarp> warp;
  warp->SetInputData(beam);
  warp->SetSourceLandmarks(sources);
  warp->SetTargetLandmarks(targets);
  // The interior's settle reports its iterations as the volume filter's does (VolumeFollower),
  // after the surface's edit has reported its end.
  std::vector<double> progress;
  vtkNew<vtkCallbackCommand> observer;
  observer->SetClientData(&progress);
  observer->SetCallback([](vtkObject*, unsigned long, void* client, void* data) {
    static_cast<std::vector<double>*>(client)->push_back(*static_cast<double*>(data));
  });
  warp->AddObserver(vtkCommand::ProgressEvent, observer);
  warp->Update();
  const auto surfaceDone = std::find(progress.begin(), progress.end(), 1.0);
  EXPECT_GT(std::count_if(surfaceDone, progress.end(), [](double done) { return done > 0.9 && done < 1.0; }), 1);
  auto* output = vtkUnstructuredGrid::SafeDownCast(warp->GetOutput());
  ASSERT_NE(output, nullptr);
  EXPECT_LT(warp->GetMaximumLandmarkDistance(), 1e-6 * beam->GetLength());
  EXPECT_NE(output->GetFieldData()->GetArray("LandmarkDistance"), nullptr);
  EXPECT_NE(output->GetCellData()->GetArray("ScaledJacobian"), nullptr);
  EXPECT_EQ(output->GetCellData()->GetArray("Material"), beam->GetCellData()->GetArray("Material"));
  EXPECT_EQ(VolumeMeshes::Measure(output).Inverted, 0);
  // The interior follows: the beam's centre line at x = 6 rises with the boundary around it.
  int interior = 0;
  for (vtkIdType i = 0; i < beam->GetNumberOfPoints(); ++i)
  {
    const double* p = beam->GetPoint(i);
    if (p[0] == 6.0 && p[1] == 0.4 && p[2] == 0.4)
    {
      ++interior;
      EXPECT_GT(output->GetPoint(i)[2] - p[2], 0.2) << "interior point " << i;
    }
  }
  EXPECT_EQ(interior, 1);
}

TEST(VolumeDeformation, AWarpedVolumesSettleSplitByATimeLimitEndsSettled)
{
  // The landmark warp of a volume with a SettleTimeLimit that every step reaches, continued
  // update by update as the Landmark Drag panel does: the interior follows each step of the
  // boundary's settle as a drag step, every cell positive, and settles in full with the last
  // one, near the uncut warp's volume (1e-4 of the beam's length).
  vtkSmartPointer<vtkUnstructuredGrid> beam = Beam();
  vtkNew<vtkPoints> sources, targets;
  BeamEndLandmarks(1.0, 1.5, sources, targets);
  auto warped = [&](double limit) {
    auto warp = vtkSmartPointer<vtkLaplacianLandmarkWarp>::New();
    warp->SetInputData(beam);
    warp->SetSourceLandmarks(sources);
    warp->SetTargetLandmarks(targets);
    warp->SetSettleTimeLimit(limit);
    return warp;
  };
  auto uncut = warped(0.0);
  uncut->Update();
  auto cut = warped(1e-9);
  int updates = 0;
  do
  {
    cut->ContinueSettling();
    cut->Update();
    ++updates;
    ASSERT_EQ(cut->GetErrorCode(), vtkErrorCode::NoError);
    EXPECT_EQ(VolumeMeshes::Measure(vtkUnstructuredGrid::SafeDownCast(cut->GetOutput())).Inverted, 0)
      << "update " << updates;
  } while (cut->GetSettling() && updates < 1000);
  EXPECT_GT(updates, 2);
  EXPECT_LT(cut->GetMaximumLandmarkDistance(), 1e-6 * beam->GetLength());
  auto* cutGrid = vtkUnstructuredGrid::SafeDownCast(cut->GetOutput());
  auto* uncutGrid = vtkUnstructuredGrid::SafeDownCast(uncut->GetOutput());
  ASSERT_NE(cutGrid, nullptr);
  ASSERT_NE(uncutGrid, nullptr);
  const double largest = LargestDistance(cutGrid, uncutGrid);
  std::printf("a warped volume's settle in %d updates: %.2e of the beam's length from the uncut "
              "warp's\n", updates, largest / 8.0);
  EXPECT_LT(largest / 8.0, 1e-4);
}

TEST(VolumeDeformation, DisplacementOfTheVolumeAndOfAWarpedGrid)
{
  vtkSmartPointer<vtkUnstructuredGrid> beam = Beam();
  vtkSmartPointer<Filter> filter = BeamEdit(beam);
  filter->OutputDisplacementOn();
  filter->SetHandleTranslation(0.0, 0.0, 1.0);
  filter->Update();
  vtkNew<vtkLaplacianLandmarkWarp> warp;
  vtkNew<vtkPoints> sources, targets;
  sources->InsertNextPoint(8.0, 0.0, 0.0);
  targets->InsertNextPoint(8.0, 0.0, 0.5);
  sources->InsertNextPoint(0.0, 0.0, 0.0);
  targets->InsertNextPoint(0.0, 0.0, 0.0);
  warp->SetInputData(beam);
  warp->SetSourceLandmarks(sources);
  warp->SetTargetLandmarks(targets);
  warp->OutputDisplacementOn();
  warp->Update();
  for (vtkPointSet* output : { static_cast<vtkPointSet*>(filter->GetOutput()), vtkPointSet::SafeDownCast(warp->GetOutput()) })
  {
    EXPECT_GT(FilterTestHelpers::ExpectDisplacement(beam, output), 0.4);
  }
}
