// Results a user would call wrong, measured on real meshes (../shared/data): free parts that
// run ahead of the handle, regions that swell, second-order edits that blow up, anchors far from
// the fixed part. Each case states its tolerance and what was measured.
#include "ReferenceEdits.h"

#include "vtkMatrix4x4.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <deque>
#include <limits>

using Filter = vtkLaplacianDeformationFilter;
namespace le = LaplacianEditing;

namespace
{
const std::string Data = LAPLACIAN_EDITING_DATA_DIR;

struct Result
{
  le::EditMeasures Measures;
  double FreeMotionRatio = 0.0;
  vtkSmartPointer<vtkPolyData> Output;
};

Result RunEdit(const ReferenceEdits::Edit& edit, int mode, int iterations = 1, int order = 1,
  double padding = 0.1, bool straighten = true)
{
  vtkNew<Filter> filter;
  ReferenceEdits::Configure(edit, filter);
  filter->SetRotationMode(mode);
  filter->SetNumberOfIterations(iterations);
  filter->SetOperatorOrder(order);
  filter->SetAnchorPadding(padding);
  filter->SetPreserveDetailScale(straighten);
  filter->SetHandleTransform(const_cast<vtkTransform*>(edit.Handle.Get()));
  filter->Update();
  const ReferenceEdits::Measured measured(edit.Mesh, edit.Labels);
  const auto deformed = ReferenceEdits::PointsOf(filter->GetOutput());
  Result result;
  result.Measures = le::MeasureEdit(measured.Mesh, measured.Region, deformed);
  result.FreeMotionRatio = measured.FreeMotionRatio(deformed, edit.Labels);
  result.Output = filter->GetOutput();
  return result;
}

const int Modes[] = { Filter::ROTATION_NONE, Filter::ROTATION_EXPLICIT, Filter::ROTATION_IMPLICIT,
  Filter::ROTATION_AS_RIGID_AS_POSSIBLE };
const char* ModeNames[] = { "none", "explicit", "implicit", "arap" };
}

TEST(EditQuality, FreePartsDoNotRunAheadOfTheHandle)
{
  // Armadillo's hand, the handle at a fingertip moved by 0.01 of the diagonal. Required in every
  // mode: no vertex outside the handle moves more than 1.2 times as far as the handle (measured
  // before the fix: implicit 2.7, a neighbouring finger swelling into a horn; after: 0.98, as
  // CGAL's ARAP).
  ReferenceEdits::Edit edit;
  ASSERT_TRUE(ReferenceEdits::LoadArmadilloHand(Data, edit));
  for (int m = 0; m < 4; ++m)
  {
    const Result result = RunEdit(edit, Modes[m]);
    std::printf("armadillo %-8s free motion %.2f of the handle's\n", ModeNames[m],
      result.FreeMotionRatio);
    EXPECT_LE(result.FreeMotionRatio, 1.2) << ModeNames[m];
  }
}

TEST(EditQuality, TheCactusKeepsItsArea)
{
  // The cactus's 70-degree turn. Required: the region's area within 15% of the rest area in
  // every mode with its defaults (measured before the fixes: implicit 3.2 times the area, then
  // 1.23 with linearized rotations alone; with the default rigid step 1.02). The linear implicit
  // method (PreserveDetailScale off) lengthens details by about 1 + angle^2 / 2: its documented
  // 1.23 is bounded here at 1.3.
  ReferenceEdits::Edit edit;
  ASSERT_TRUE(ReferenceEdits::LoadCactus(Data, edit));
  for (int m = 0; m < 4; ++m)
  {
    for (int linear = 0; linear <= (Modes[m] == Filter::ROTATION_IMPLICIT ? 1 : 0); ++linear)
    {
      const double area = RunEdit(edit, Modes[m], 1, 1, 0.1, !linear).Measures.AreaRatio;
      std::printf("cactus %-8s%s area ratio %.3f\n", ModeNames[m], linear ? " linear" : "", area);
      EXPECT_LE(area, linear ? 1.3 : 1.15) << ModeNames[m] << " linear " << linear;
      EXPECT_GE(area, 0.85) << ModeNames[m] << " linear " << linear;
    }
  }
}

TEST(EditQuality, TheImplicitRigidStepStraightensTheTwist)
{
  // The bunny's ear turned 120 degrees about its axis, implicit mode. Required: the default rigid
  // step lowers the ARAP energy of the linear result by at least a quarter and keeps the area
  // within 15% (measured: energy 0.0299 -> 0.0190, area 1.08 -> 1.03).
  ReferenceEdits::Edit edit;
  ASSERT_TRUE(ReferenceEdits::LoadTwist(Data, edit));
  const Result linear = RunEdit(edit, Filter::ROTATION_IMPLICIT, 1, 1, 0.1, false);
  const Result straightened = RunEdit(edit, Filter::ROTATION_IMPLICIT);
  std::printf("twist implicit energy %.4f -> %.4f, area %.3f -> %.3f\n", linear.Measures.Energy,
    straightened.Measures.Energy, linear.Measures.AreaRatio, straightened.Measures.AreaRatio);
  EXPECT_LE(straightened.Measures.Energy, 0.75 * linear.Measures.Energy);
  EXPECT_NEAR(straightened.Measures.AreaRatio, 1.0, 0.15);
}

TEST(EditQuality, SecondOrderWithoutPaddingDoesNotBlowUp)
{
  // Order 2 with no anchor padding, on the cactus and on the bunny's ear bent over by 60
  // degrees. Required in none and explicit mode (one and five iterations): the area within 15%,
  // and an ARAP energy no worse than first order's in the same mode, with 5% slack (measured
  // before the fix: explicit five iterations multiplied the cactus's area by 30).
  ReferenceEdits::Edit cactus, ear;
  ASSERT_TRUE(ReferenceEdits::LoadCactus(Data, cactus));
  ASSERT_TRUE(ReferenceEdits::LoadTwist(Data, ear, 60.0, true));
  for (const ReferenceEdits::Edit* edit : { &cactus, &ear })
  {
    for (const auto& [mode, iterations] : { std::pair<int, int>{ Filter::ROTATION_NONE, 1 },
           { Filter::ROTATION_EXPLICIT, 1 }, { Filter::ROTATION_EXPLICIT, 5 } })
    {
      const Result first = RunEdit(*edit, mode, iterations, 1, 0.0);
      const Result second = RunEdit(*edit, mode, iterations, 2, 0.0);
      std::printf("%s mode %d k %d: order 1 area %.3f energy %.4f, order 2 area %.3f energy %.4f\n",
        edit == &cactus ? "cactus" : "ear", mode, iterations, first.Measures.AreaRatio,
        first.Measures.Energy, second.Measures.AreaRatio, second.Measures.Energy);
      EXPECT_NEAR(second.Measures.AreaRatio, 1.0, 0.15) << mode << " k " << iterations;
      EXPECT_LE(second.Measures.Energy, 1.05 * first.Measures.Energy) << mode << " k " << iterations;
    }
  }
}

TEST(EditQuality, ArrayAnchorsLineTheFixedPart)
{
  // The cactus's array selection with the default padding. Required: every anchor within three
  // edges of a fixed vertex (before the fix, the padding was measured from the handle and pinned
  // the tip of a side arm), and every ROI vertex farther than that moves (more than 1% of the
  // handle's mean displacement).
  ReferenceEdits::Edit edit;
  ASSERT_TRUE(ReferenceEdits::LoadCactus(Data, edit));
  const Result result = RunEdit(edit, Filter::ROTATION_EXPLICIT);
  const ReferenceEdits::Measured measured(edit.Mesh, edit.Labels);
  const le::SurfaceMesh& mesh = measured.Mesh;
  // Edges from the fixed part, breadth first.
  std::vector<int> hops(mesh.GetNumberOfVertices(), -1);
  std::deque<int> queue;
  for (int v = 0; v < mesh.GetNumberOfVertices(); ++v)
  {
    if (edit.Labels->GetValue(v) == 0)
    {
      hops[v] = 0;
      queue.push_back(v);
    }
  }
  while (!queue.empty())
  {
    const int v = queue.front();
    queue.pop_front();
    for (const int* w = mesh.NeighborsBegin(v); w != mesh.NeighborsEnd(v); ++w)
    {
      if (hops[*w] < 0)
      {
        hops[*w] = hops[v] + 1;
        queue.push_back(*w);
      }
    }
  }
  vtkDataArray* roles = result.Output->GetPointData()->GetArray("EditRole");
  const auto deformed = ReferenceEdits::PointsOf(result.Output);
  double handleMove = 0.0;
  int handles = 0, anchors = 0, pinned = 0;
  for (int v : measured.Region)
  {
    const double move = (deformed[v] - mesh.GetPositions()[v]).norm();
    if (edit.Labels->GetValue(v) == 2)
    {
      handleMove += move;
      ++handles;
    }
  }
  handleMove /= std::max(handles, 1);
  for (int v : measured.Region)
  {
    const double move = (deformed[v] - mesh.GetPositions()[v]).norm();
    if (static_cast<int>(roles->GetTuple1(v)) == Filter::ROLE_ANCHOR)
    {
      ++anchors;
      EXPECT_LE(hops[v], 3) << "anchor " << v;
    }
    else if (hops[v] > 3 && move < 0.01 * handleMove)
    {
      ++pinned;
    }
  }
  std::printf("cactus: %d anchors, %d ROI vertices away from the fixed part left at rest\n",
    anchors, pinned);
  EXPECT_GT(anchors, 0);
  EXPECT_EQ(pinned, 0);
}

TEST(EditQuality, ArapEnergyFallsOnTheTwist)
{
  // The bunny's ear twisted 120 degrees, as rigid as possible with cotangent weights, k = 1 to
  // 12 iterations from the same start. Required: the energy never rises with k, and after 12
  // it is below a third of the best linear mode's here (explicit, five iterations; measured
  // 0.078 against 0.0127).
  ReferenceEdits::Edit edit;
  ASSERT_TRUE(ReferenceEdits::LoadTwist(Data, edit));
  double previous = std::numeric_limits<double>::infinity();
  for (int k = 1; k <= 12; ++k)
  {
    vtkNew<Filter> filter;
    ReferenceEdits::Configure(edit, filter);
    filter->SetRotationModeToAsRigidAsPossible();
    filter->SetLaplacianWeightsToCotangent();
    filter->SetARAPIterations(k);
    filter->SetConvergence(0.0);
    filter->SetHandleTransform(const_cast<vtkTransform*>(edit.Handle.Get()));
    filter->Update();
    const double energy = filter->GetARAPEnergy();
    EXPECT_LE(energy, previous * (1.0 + 1e-12)) << k << " iterations";
    previous = energy;
  }
  const double explicitEnergy = RunEdit(edit, Filter::ROTATION_EXPLICIT, 5).Measures.Energy;
  std::printf("twist: ARAP energy after 12 iterations %.4f, explicit k = 5 %.4f\n", previous,
    explicitEnergy);
  EXPECT_LT(3.0 * previous, explicitEnergy);
}

TEST(EditQuality, ArapComesWithinFivePercentOfConvergedOnALargeBend)
{
  // bumps.obj with its far strip turned 60 degrees across a 12k-vertex region, at the default
  // settings: a script's update after the setup, and the update that settles a drag of ten
  // steps (each capped at DragARAPIterations). Required: each within 5% of the energy converged
  // (1000 iterations, Convergence 1e-9). Measured 1.012 and 1.001. A test on the last
  // iteration alone, which a short Anderson step passes, stopped the same bend (cotangent
  // weights, EditQuality) at 1.11 times converged after 15 iterations, and the turn without
  // its lift at 1.70 after 7.
  ReferenceEdits::Edit edit;
  ASSERT_TRUE(ReferenceEdits::LoadBend(Data, edit));
  auto update = [&](bool drag, int iterations, double convergence) {
    vtkNew<Filter> filter;
    ReferenceEdits::Configure(edit, filter);
    filter->SetRotationModeToAsRigidAsPossible();
    filter->Update(); // the setup
    vtkNew<vtkTransform> handle;
    filter->SetHandleTransform(handle);
    filter->SetDragging(drag);
    for (int step = drag ? 1 : 10; step <= 10; ++step)
    {
      // The bend's map, a tenth of its way a step (matrices blended: the moves are small).
      vtkNew<vtkMatrix4x4> blend;
      for (int i = 0; i < 4; ++i)
      {
        for (int j = 0; j < 4; ++j)
        {
          blend->SetElement(i, j,
            (i == j ? 1.0 : 0.0) * (1.0 - step / 10.0) +
              edit.Handle->GetMatrix()->GetElement(i, j) * step / 10.0);
        }
      }
      handle->SetMatrix(blend);
      filter->Update();
    }
    filter->DraggingOff();
    filter->SetARAPIterations(iterations);
    filter->SetConvergence(convergence);
    filter->Update();
    return filter->GetARAPEnergy();
  };
  const double converged = update(false, 1000, 1e-9);
  const double script = update(false, 30, 1e-3) / converged;
  const double released = update(true, 30, 1e-3) / converged;
  std::printf("bend: a script's update %.4f of converged, a drag's release %.4f\n", script, released);
  EXPECT_LE(script, 1.05);
  EXPECT_LE(released, 1.05);
}
