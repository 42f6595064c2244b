// The output written in place: a move writes only its region and the normals around it, an
// array held elsewhere is never written (copy on write), and moves, new regions and new inputs
// after in-place writes give what a fresh filter gives. The drag preview: refused unless only the
// handle's motion changed, its moving part is what an update of the same motion writes, and it
// leaves the output alone.
#include "FilterTestHelpers.h"
#include "vtkLaplacianDragPreview.h"

#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkIdFilter.h"
#include "vtkIdList.h"
#include "vtkPassThrough.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyDataNormals.h"
#include "vtkSignedCharArray.h"
#include "vtkSphereSource.h"

#include <gtest/gtest.h>

#include <set>

using namespace FilterTestHelpers;

namespace
{
// A sphere with point and cell normals, of about 2 * resolution^2 points.
vtkSmartPointer<vtkPolyData> SphereWithNormals(int resolution = 80)
{
  vtkNew<vtkSphereSource> sphere;
  sphere->SetThetaResolution(2 * resolution);
  sphere->SetPhiResolution(resolution);
  vtkNew<vtkPolyDataNormals> normals;
  normals->SetInputConnection(sphere->GetOutputPort());
  normals->ComputeCellNormalsOn();
  normals->SplittingOff();
  normals->Update();
  return normals->GetOutput();
}

vtkSmartPointer<vtkLaplacianDeformationFilter> SphereEdit(vtkPolyData* input, int mode)
{
  auto filter = vtkSmartPointer<vtkLaplacianDeformationFilter>::New();
  filter->SetInputData(input);
  filter->SetHandleCenter(0.5, 0.0, 0.0);
  filter->SetHandleRadius(0.05);
  filter->SetROIRadius(0.3);
  filter->SetRotationMode(mode);
  return filter;
}

// An edit of `input` updated with the handle moved by (x, y, 0).
vtkSmartPointer<vtkLaplacianDeformationFilter> MovedEdit(
  vtkPolyData* input, double x, double y = 0.0, int mode = vtkLaplacianDeformationFilter::ROTATION_NONE)
{
  auto filter = SphereEdit(input, mode);
  filter->SetHandleTranslation(x, y, 0.0);
  filter->Update();
  return filter;
}

vtkSmartPointer<vtkPolyData> Snapshot(vtkPolyData* data)
{
  auto copy = vtkSmartPointer<vtkPolyData>::New();
  copy->DeepCopy(data);
  return copy;
}

bool SameTuple(vtkDataArray* a, vtkDataArray* b, vtkIdType i)
{
  for (int c = 0; c < a->GetNumberOfComponents(); ++c)
  {
    if (a->GetComponent(i, c) != b->GetComponent(i, c))
    {
      return false;
    }
  }
  return true;
}

double MaxDifference(vtkDataArray* a, vtkDataArray* b)
{
  double worst = 0.0;
  for (vtkIdType i = 0; i < a->GetNumberOfTuples(); ++i)
  {
    for (int c = 0; c < a->GetNumberOfComponents(); ++c)
    {
      worst = std::max(worst, std::abs(a->GetComponent(i, c) - b->GetComponent(i, c)));
    }
  }
  return worst;
}

// The points of the region (EditRole not fixed) and their one-ring.
std::set<vtkIdType> RegionAndRing(vtkPolyData* output)
{
  vtkDataArray* roles = output->GetPointData()->GetArray("EditRole");
  output->BuildLinks();
  std::set<vtkIdType> near;
  vtkNew<vtkIdList> cells;
  for (vtkIdType i = 0; i < output->GetNumberOfPoints(); ++i)
  {
    if (roles->GetTuple1(i) == vtkLaplacianDeformationFilter::ROLE_FIXED)
    {
      continue;
    }
    output->GetPointCells(i, cells);
    for (vtkIdType c = 0; c < cells->GetNumberOfIds(); ++c)
    {
      vtkIdType size;
      const vtkIdType* corners;
      output->GetCellPoints(cells->GetId(c), size, corners);
      near.insert(corners, corners + size);
    }
  }
  return near;
}

// Points, normals and roles of two outputs agree to `tolerance` (points, of the diagonal).
void ExpectSameOutput(vtkPolyData* a, vtkPolyData* b, double tolerance)
{
  EXPECT_LE(MaxPointDistance(a, b), tolerance * Diagonal(a));
  EXPECT_LE(MaxDifference(a->GetPointData()->GetNormals(), b->GetPointData()->GetNormals()), 1e-9);
  EXPECT_LE(MaxDifference(a->GetCellData()->GetNormals(), b->GetCellData()->GetNormals()), 1e-9);
  EXPECT_EQ(MaxDifference(a->GetPointData()->GetArray("EditRole"),
              b->GetPointData()->GetArray("EditRole")),
    0.0);
}
}

TEST(InPlace, AMoveWritesOnlyItsRegionAndTheNormalsOfItsRing)
{
  auto input = SphereWithNormals();
  auto filter = MovedEdit(input, 0.02);
  vtkPolyData* output = filter->GetOutput();
  vtkDataArray* points = output->GetPoints()->GetData();
  const vtkIdType copies = filter->GetNumberOfOutputCopies();
  EXPECT_EQ(copies, 4); // points, point and cell normals, roles: once per region
  auto before = Snapshot(output);
  const std::set<vtkIdType> near = RegionAndRing(output);
  ASSERT_LT(near.size(), static_cast<std::size_t>(input->GetNumberOfPoints() / 4));

  filter->SetHandleTranslation(0.05, 0.03, 0.0);
  filter->Update();
  EXPECT_EQ(output->GetPoints()->GetData(), points) << "the points were not written in place";
  EXPECT_EQ(filter->GetNumberOfOutputCopies(), copies) << "a move copied a whole array";
  vtkDataArray* roles = output->GetPointData()->GetArray("EditRole");
  int moved = 0;
  for (vtkIdType i = 0; i < input->GetNumberOfPoints(); ++i)
  {
    const bool fixed = roles->GetTuple1(i) == vtkLaplacianDeformationFilter::ROLE_FIXED;
    const bool changed = !SameTuple(output->GetPoints()->GetData(), before->GetPoints()->GetData(), i);
    moved += changed;
    EXPECT_FALSE(changed && fixed) << "fixed point " << i << " moved";
    double p[3], q[3];
    input->GetPoint(i, p);
    output->GetPoint(i, q);
    EXPECT_TRUE(!fixed || (p[0] == q[0] && p[1] == q[1] && p[2] == q[2])) << "point " << i;
    const bool normalChanged =
      !SameTuple(output->GetPointData()->GetNormals(), before->GetPointData()->GetNormals(), i);
    EXPECT_FALSE(normalChanged && !near.count(i)) << "the normal of point " << i << " changed";
  }
  EXPECT_GT(moved, 0);
}

TEST(InPlace, AnArrayHeldElsewhereIsNeverWritten)
{
  auto input = SphereWithNormals();
  auto filter = MovedEdit(input, 0.02);
  vtkPolyData* output = filter->GetOutput();
  // A caller keeps the points, and a shallow copy (which shares every array).
  vtkSmartPointer<vtkPoints> heldPoints = output->GetPoints();
  vtkNew<vtkPolyData> kept;
  kept->ShallowCopy(output);
  auto before = Snapshot(output);
  const vtkIdType copies = filter->GetNumberOfOutputCopies();

  filter->SetHandleTranslation(0.06, 0.0, 0.0);
  filter->Update();
  EXPECT_NE(output->GetPoints(), heldPoints.Get());
  EXPECT_EQ(MaxPointDistance(kept, before), 0.0);
  EXPECT_EQ(MaxDifference(heldPoints->GetData(), before->GetPoints()->GetData()), 0.0);
  EXPECT_EQ(MaxDifference(kept->GetPointData()->GetNormals(), before->GetPointData()->GetNormals()), 0.0);
  EXPECT_EQ(MaxDifference(kept->GetCellData()->GetNormals(), before->GetCellData()->GetNormals()), 0.0);
  EXPECT_GT(MaxPointDistance(output, before), 0.01);
  // Points and normals were copied once; the roles did not change, so nothing was written.
  EXPECT_EQ(filter->GetNumberOfOutputCopies(), copies + 3);

  // From then on the new arrays are written in place, while the old ones stay held.
  filter->SetHandleTranslation(0.07, 0.0, 0.0);
  filter->Update();
  EXPECT_EQ(filter->GetNumberOfOutputCopies(), copies + 3);
  EXPECT_EQ(MaxPointDistance(kept, before), 0.0);
  ExpectSameOutput(output, MovedEdit(input, 0.07)->GetOutput(), 1e-12);
}

TEST(InPlace, ADownstreamOutputIsRecomputedNotCopied)
{
  // A filter downstream shares the output's arrays until the next update recomputes it (as
  // ParaView's pass-through filter after every source): the moves still write in place.
  auto input = SphereWithNormals();
  auto filter = SphereEdit(input, vtkLaplacianDeformationFilter::ROTATION_NONE);
  vtkNew<vtkPassThrough> downstream;
  downstream->SetInputConnection(filter->GetOutputPort());
  for (int move = 1; move <= 6; ++move)
  {
    filter->SetHandleTranslation(0.01 * move, 0.0, 0.0);
    downstream->Update();
    ExpectSameOutput(vtkPolyData::SafeDownCast(downstream->GetOutput()),
      MovedEdit(input, 0.01 * move)->GetOutput(), 1e-12);
  }
  EXPECT_EQ(filter->GetNumberOfOutputCopies(), 4); // the first region's, once per array
}

TEST(InPlace, AConsumerThatKeepsACopyMakesTheMovesAlternateTwoBuffers)
{
  // A consumer that keeps a shallow copy of the last output until the next one arrives (a
  // renderer's cache, ParaView's representations): that copy is never written, and each move
  // writes the buffer it no longer holds.
  auto input = SphereWithNormals();
  auto filter = SphereEdit(input, vtkLaplacianDeformationFilter::ROTATION_NONE);
  vtkNew<vtkPolyData> cache;
  for (int move = 1; move <= 6; ++move)
  {
    filter->SetHandleTranslation(0.01 * move, 0.0, 0.0);
    filter->Update();
    auto kept = Snapshot(cache);
    cache->ShallowCopy(filter->GetOutput());
    ExpectSameOutput(cache, MovedEdit(input, 0.01 * move)->GetOutput(), 1e-12);
    if (move > 1)
    {
      EXPECT_EQ(MaxPointDistance(kept, MovedEdit(input, 0.01 * (move - 1))->GetOutput()), 0.0)
        << "the cache of move " << move - 1 << " was written";
    }
  }
  // The first region copies each array once, the second buffer of points and normals once more.
  EXPECT_EQ(filter->GetNumberOfOutputCopies(), 4 + 3);
}

TEST(InPlace, NewRegionsAndInputsAfterInPlaceMovesMatchAFreshFilter)
{
  for (const int mode : { vtkLaplacianDeformationFilter::ROTATION_NONE,
         vtkLaplacianDeformationFilter::ROTATION_EXPLICIT,
         vtkLaplacianDeformationFilter::ROTATION_IMPLICIT })
  {
    SCOPED_TRACE(mode);
    auto input = SphereWithNormals();
    auto filter = SphereEdit(input, mode);
    for (int move = 1; move <= 3; ++move)
    {
      filter->SetHandleTranslation(0.02 * move, 0.01, 0.0);
      filter->Update();
    }
    // A new region: the handle elsewhere, a smaller ROI that leaves part of the old one.
    filter->SetHandleCenter(0.0, 0.5, 0.0);
    filter->SetROIRadius(0.25);
    filter->Update();
    auto fresh = SphereEdit(input, mode);
    fresh->SetHandleCenter(0.0, 0.5, 0.0);
    fresh->SetROIRadius(0.25);
    fresh->SetHandleTranslation(0.06, 0.01, 0.0);
    fresh->Update();
    ExpectSameOutput(filter->GetOutput(), fresh->GetOutput(), 1e-12);

    // New input content: the same mesh, shifted.
    auto shifted = Snapshot(input);
    for (vtkIdType i = 0; i < shifted->GetNumberOfPoints(); ++i)
    {
      double p[3];
      shifted->GetPoint(i, p);
      p[2] += 0.25;
      shifted->GetPoints()->SetPoint(i, p);
    }
    filter->SetInputData(shifted);
    filter->SetHandleCenter(0.5, 0.0, 0.25);
    filter->Update();
    auto freshShifted = SphereEdit(shifted, mode);
    freshShifted->SetHandleCenter(0.5, 0.0, 0.25);
    freshShifted->SetROIRadius(0.25);
    freshShifted->SetHandleTranslation(0.06, 0.01, 0.0);
    freshShifted->Update();
    ExpectSameOutput(filter->GetOutput(), freshShifted->GetOutput(), 1e-12);
  }
}

namespace
{
// The sphere with its point and cell ids as arrays, which the preview's parts carry along.
vtkSmartPointer<vtkPolyData> SphereWithIds()
{
  vtkNew<vtkIdFilter> ids;
  ids->SetInputData(SphereWithNormals());
  ids->SetPointIdsArrayName("PointIds");
  ids->SetCellIdsArrayName("CellIds");
  ids->Update();
  return vtkPolyData::SafeDownCast(ids->GetOutput());
}
}

TEST(Preview, IsRefusedUnlessOnlyTheHandleMotionChanged)
{
  auto input = SphereWithIds();
  auto filter = SphereEdit(input, vtkLaplacianDeformationFilter::ROTATION_NONE);
  vtkNew<vtkLaplacianDragPreview> preview;
  EXPECT_FALSE(preview->Update(0.01, 0, 0, 0, 0, 0)) << "without a filter";
  preview->SetFilter(filter);
  EXPECT_FALSE(preview->Update(0.01, 0, 0, 0, 0, 0)) << "before any update";
  filter->Update();
  EXPECT_TRUE(preview->Update(0.01, 0, 0, 0, 0, 0));
  filter->SetROIRadius(0.35);
  EXPECT_FALSE(preview->Update(0.01, 0, 0, 0, 0, 0)) << "after a new ROI radius";
  filter->Update();
  EXPECT_TRUE(preview->Update(0.02, 0, 0, 0, 0, 0));
  input->GetPoints()->Modified();
  EXPECT_FALSE(preview->Update(0.02, 0, 0, 0, 0, 0)) << "after new input content";
}

TEST(Preview, TheMovingPartIsWhatAnUpdateOfTheSameMotionWrites)
{
  for (const int mode : { vtkLaplacianDeformationFilter::ROTATION_NONE,
         vtkLaplacianDeformationFilter::ROTATION_EXPLICIT,
         vtkLaplacianDeformationFilter::ROTATION_IMPLICIT })
  {
    SCOPED_TRACE(mode);
    auto input = SphereWithIds();
    auto filter = SphereEdit(input, mode);
    filter->Update();
    auto before = Snapshot(filter->GetOutput());
    const vtkMTimeType filterTime = filter->GetMTime();
    const vtkMTimeType outputTime = filter->GetOutput()->GetMTime();
    const double translation[3] = { 0.05, 0.02, 0.0 }, rotation[3] = { 0.0, 0.0, 20.0 };
    vtkNew<vtkLaplacianDragPreview> preview;
    preview->SetFilter(filter);
    ASSERT_TRUE(preview->Update(translation, rotation));

    // Neither the filter nor its output changed.
    EXPECT_EQ(filter->GetMTime(), filterTime);
    EXPECT_EQ(filter->GetOutput()->GetMTime(), outputTime);
    EXPECT_EQ(MaxPointDistance(filter->GetOutput(), before), 0.0);

    // Together, the parts hold each polygon once; the still part is at rest.
    vtkPolyData* still = preview->GetStillPart();
    vtkPolyData* moving = preview->GetMovingPart();
    EXPECT_EQ(still->GetNumberOfPolys() + moving->GetNumberOfPolys(), input->GetNumberOfPolys());
    EXPECT_GT(moving->GetNumberOfPolys(), 0);
    EXPECT_LT(moving->GetNumberOfPoints(), input->GetNumberOfPoints() / 4);
    EXPECT_EQ(MaxPointDistance(still, input), 0.0);
    vtkDataArray* scalars = filter->GetOutput()->GetPointData()->GetScalars();
    ASSERT_NE(scalars, nullptr);
    ASSERT_NE(still->GetPointData()->GetScalars(), nullptr) << "the still part is coloured alike";
    EXPECT_STREQ(still->GetPointData()->GetScalars()->GetName(), scalars->GetName());

    // The moving part's points, normals and arrays are the update's, by the input's ids.
    auto updated = SphereEdit(input, mode);
    updated->SetHandleTranslation(translation);
    updated->SetHandleRotation(rotation);
    updated->Update();
    vtkPolyData* expected = updated->GetOutput();
    vtkDataArray* ids = moving->GetPointData()->GetArray("PointIds");
    ASSERT_NE(ids, nullptr) << "the moving part carries the input's point arrays";
    ASSERT_NE(moving->GetCellData()->GetArray("CellIds"), nullptr);
    double worstPoint = 0.0, worstNormal = 0.0;
    for (vtkIdType i = 0; i < moving->GetNumberOfPoints(); ++i)
    {
      const auto id = static_cast<vtkIdType>(ids->GetTuple1(i));
      double p[3], q[3], n[3], m[3];
      moving->GetPoint(i, p);
      expected->GetPoint(id, q);
      worstPoint = std::max(worstPoint, std::sqrt(vtkMath::Distance2BetweenPoints(p, q)));
      moving->GetPointData()->GetNormals()->GetTuple(i, n);
      expected->GetPointData()->GetNormals()->GetTuple(id, m);
      worstNormal = std::max(worstNormal, std::sqrt(vtkMath::Distance2BetweenPoints(n, m)));
    }
    EXPECT_LE(worstPoint, 1e-12 * Diagonal(input));
    EXPECT_LE(worstNormal, 1e-9);

    // The next update solves and writes as a fresh filter does.
    filter->SetHandleTranslation(translation);
    filter->SetHandleRotation(rotation);
    filter->Update();
    ExpectSameOutput(filter->GetOutput(), expected, 1e-12);
  }
}

TEST(Displacement, IsTheOutputMinusTheInputAndOffByDefault)
{
  vtkSmartPointer<vtkPolyData> plane = FilterTestHelpers::BumpyPlane();
  vtkSmartPointer<vtkLaplacianDeformationFilter> filter = FilterTestHelpers::PlaneEdit(plane);
  filter->SetHandleTranslation(0.0, 0.0, 0.2);
  filter->Update();
  EXPECT_EQ(filter->GetOutput()->GetPointData()->GetArray("Displacement"), nullptr);
  filter->OutputDisplacementOn();
  for (double lift : { 0.2, 0.3 }) // the second move rewrites the first's array in place
  {
    filter->SetHandleTranslation(0.0, 0.1, lift);
    filter->Update();
    EXPECT_GT(FilterTestHelpers::ExpectDisplacement(plane, filter->GetOutput()), 0.1);
  }
}
