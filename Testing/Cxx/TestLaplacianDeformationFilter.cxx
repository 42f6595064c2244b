// Tests of vtkLaplacianDeformationFilter: behaviour, caching, pass-through and bad input.
#include "FilterTestHelpers.h"

#include "vtkCallbackCommand.h"
#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkCommand.h"
#include "vtkDoubleArray.h"
#include "vtkFloatArray.h"
#include "vtkInformation.h"
#include "vtkIntArray.h"
#include "vtkNew.h"
#include "vtkOBJReader.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPolyDataNormals.h"
#include "vtkSmartPointer.h"
#include "vtkSphereSource.h"
#include "vtkTransform.h"
#include "vtkTriangle.h"
#include "vtkSignedCharArray.h"
#include "vtkIdList.h"
#include "vtkIdTypeArray.h"
#include "vtkSelection.h"
#include "vtkSelectionNode.h"

#include "vtkMath.h"
#include "vtkMatrix4x4.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <functional>
#include <map>

#include <cmath>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>

namespace
{
vtkSignedCharArray* Roles(vtkPolyData* output)
{
  return vtkSignedCharArray::SafeDownCast(output->GetPointData()->GetArray("EditRole"));
}
}

TEST(Filter, IdentityReproducesTheInput)
{
  auto input = BumpyPlane();
  for (int order = 1; order <= 2; ++order)
  {
    for (int weights = 0; weights <= 1; ++weights)
    {
      auto filter = PlaneEdit(input);
      filter->SetOperatorOrder(order);
      filter->SetLaplacianWeights(weights);
      filter->Update();
      EXPECT_LT(MaxPointDistance(input, filter->GetOutput()), 1e-9 * Diagonal(input))
        << "order " << order << " weights " << weights;
      EXPECT_GT(filter->GetNumberOfROIVertices(), 0);
    }
  }
}

TEST(Filter, ACommitKeepsTheEditedShapeToFullPrecisionInEveryMode)
{
  // The committed rest shape is the output as it was, in the input's precision: a commit once
  // stored double coordinates as float and moved every edited point by about 3e-8.
  auto input = BumpyPlane();
  ASSERT_EQ(input->GetPoints()->GetDataType(), VTK_DOUBLE);
  for (int mode : { vtkLaplacianDeformationFilter::ROTATION_NONE,
         vtkLaplacianDeformationFilter::ROTATION_EXPLICIT,
         vtkLaplacianDeformationFilter::ROTATION_IMPLICIT,
         vtkLaplacianDeformationFilter::ROTATION_AS_RIGID_AS_POSSIBLE })
  {
    auto filter = PlaneEdit(input);
    filter->SetRotationMode(mode);
    filter->SetHandleTranslation(0.0, 0.0, 0.15);
    filter->Update();
    vtkNew<vtkPolyData> edited;
    edited->DeepCopy(filter->GetOutput());
    filter->CommitEdit();
    filter->Update();
    EXPECT_EQ(filter->GetOutput()->GetPoints()->GetDataType(), VTK_DOUBLE) << "mode " << mode;
    EXPECT_LT(MaxPointDistance(edited, filter->GetOutput()), 1e-9 * Diagonal(input))
      << "mode " << mode;
  }
}

TEST(Filter, MovesHandleAndLeavesOutsideBitIdentical)
{
  auto input = BumpyPlane();
  auto filter = PlaneEdit(input);
  filter->SetHandleTransform(Translation(0.0, 0.05, 0.2));
  filter->Update();
  vtkPolyData* output = filter->GetOutput();
  vtkSignedCharArray* roles = Roles(output);
  ASSERT_NE(roles, nullptr);
  int handles = 0, fixed = 0, anchors = 0, free = 0;
  for (vtkIdType i = 0; i < input->GetNumberOfPoints(); ++i)
  {
    double p[3], q[3];
    input->GetPoint(i, p);
    output->GetPoint(i, q);
    switch (roles->GetValue(i))
    {
      case vtkLaplacianDeformationFilter::ROLE_FIXED:
        ++fixed;
        ASSERT_TRUE(p[0] == q[0] && p[1] == q[1] && p[2] == q[2]) << "point " << i;
        break;
      case vtkLaplacianDeformationFilter::ROLE_HANDLE:
        ++handles;
        EXPECT_LT(std::sqrt(vtkMath::Distance2BetweenPoints(
                    q, std::array<double, 3>{ p[0], p[1] + 0.05, p[2] + 0.2 }.data())),
          1e-3 * Diagonal(input));
        break;
      case vtkLaplacianDeformationFilter::ROLE_ANCHOR:
        ++anchors;
        break;
      default:
        ++free;
    }
  }
  EXPECT_GT(handles, 0);
  EXPECT_GT(fixed, 0);
  EXPECT_GT(anchors, 0);
  EXPECT_GT(free, 0);
  EXPECT_EQ(handles, filter->GetNumberOfHandleVertices());
  EXPECT_EQ(handles + anchors + free, filter->GetNumberOfROIVertices());
}

TEST(Filter, ReusesTheFactorizationWhileOnlyTheHandleMoves)
{
  auto input = BumpyPlane();
  auto filter = PlaneEdit(input);
  vtkNew<vtkTransform> transform;
  filter->SetHandleTransform(transform);
  filter->Update();
  ASSERT_EQ(filter->GetNumberOfFactorizations(), 1);
  double previousZ = 0.0;
  for (int move = 1; move <= 5; ++move)
  {
    transform->Identity();
    transform->Translate(0, 0, 0.04 * move);
    transform->RotateZ(3.0 * move);
    filter->Update();
    double p[3];
    filter->GetOutput()->GetPoint(40 * 61 + 30, p); // near the handle
    EXPECT_GT(p[2], previousZ);
    previousZ = p[2];
  }
  EXPECT_EQ(filter->GetNumberOfFactorizations(), 1);

  // Everything that changes the matrix refactors.
  int expected = 1;
  auto expectRefactor = [&](const char* what) {
    filter->Update();
    EXPECT_EQ(filter->GetNumberOfFactorizations(), ++expected) << what;
  };
  filter->SetROIRadius(0.3);
  expectRefactor("ROI radius");
  filter->SetHandleCenter(0.4, 0.5, 0.0);
  expectRefactor("handle centre");
  filter->SetLaplacianWeightsToCotangent();
  expectRefactor("weights");
  filter->SetOperatorOrder(2);
  expectRefactor("order");
  input->GetPoints()->Modified();
  expectRefactor("mesh");
  filter->SetSolverToSimplicialLDLT();
  expectRefactor("solver");
  filter->Update();
  EXPECT_EQ(filter->GetNumberOfFactorizations(), expected) << "no change, no refactor";
}

TEST(Filter, SmoothedRotationsKeepTheRestMeetTheHandleAndLeaveTheOutside)
{
  // RotationSmoothing in the ARAP mode: nothing moved gives the input back (1e-9 of the
  // diagonal), the handle lands, the outside stays bit for bit, the weight refactors once and
  // drags reuse that factor, the same edit comes back after a drag and a change of weight
  // (each run to convergence, 1e-6 of the diagonal), and the result differs from plain ARAP's.
  auto input = BumpyPlane();
  auto filter = PlaneEdit(input);
  filter->SetRotationModeToAsRigidAsPossible();
  filter->SetRotationSmoothing(0.02);
  filter->SetARAPIterations(5000);
  filter->SetConvergence(1e-10);
  filter->Update();
  EXPECT_LT(MaxPointDistance(input, filter->GetOutput()), 1e-9 * Diagonal(input));
  vtkNew<vtkTransform> transform;
  transform->Translate(0.0, 0.05, 0.2);
  transform->RotateX(30.0);
  filter->SetHandleTransform(transform);
  filter->Update();
  vtkNew<vtkPolyData> smoothed;
  smoothed->DeepCopy(filter->GetOutput());
  vtkSignedCharArray* roles = Roles(smoothed);
  ASSERT_NE(roles, nullptr);
  for (vtkIdType i = 0; i < input->GetNumberOfPoints(); ++i)
  {
    double p[3], q[3], target[3];
    input->GetPoint(i, p);
    smoothed->GetPoint(i, q);
    if (roles->GetValue(i) == vtkLaplacianDeformationFilter::ROLE_FIXED)
    {
      ASSERT_TRUE(p[0] == q[0] && p[1] == q[1] && p[2] == q[2]) << "point " << i;
    }
    else if (roles->GetValue(i) == vtkLaplacianDeformationFilter::ROLE_HANDLE)
    {
      transform->TransformPoint(p, target);
      EXPECT_LT(std::sqrt(vtkMath::Distance2BetweenPoints(q, target)), 1e-9 * Diagonal(input));
    }
  }
  EXPECT_EQ(filter->GetNumberOfFactorizations(), 1);
  filter->DraggingOn();
  for (int move = 1; move <= 3; ++move)
  {
    transform->Translate(0.0, 0.0, 0.01);
    filter->Update();
  }
  filter->DraggingOff();
  filter->Update();
  EXPECT_EQ(filter->GetNumberOfFactorizations(), 1) << "drags reuse the factor";
  filter->SetRotationSmoothing(0.0);
  filter->Update();
  EXPECT_EQ(filter->GetNumberOfFactorizations(), 2) << "the weight refactors";
  filter->SetRotationSmoothing(0.02);
  transform->Translate(0.0, 0.0, -0.03);
  filter->Update();
  EXPECT_LT(MaxPointDistance(smoothed, filter->GetOutput()), 1e-6 * Diagonal(input)) << "the same edit again";
  filter->SetRotationSmoothing(0.0);
  filter->Update();
  const double apart = MaxPointDistance(smoothed, filter->GetOutput()) / Diagonal(input);
  std::printf("smoothed rotations against plain ARAP: %.2e of the diagonal apart\n", apart);
  EXPECT_GT(apart, 1e-3);
}

namespace
{
// The plane's ARAP edit, run to convergence, its region made large (a proxy of about 800
// nodes) when it has more than `largeRegion` vertices (0: never).
vtkSmartPointer<vtkLaplacianDeformationFilter> ConvergedArapEdit(vtkPolyData* input, int largeRegion)
{
  auto filter = PlaneEdit(input);
  filter->SetRotationModeToAsRigidAsPossible();
  filter->SetLargeRegionVertices(largeRegion);
  filter->SetProxyNodes(800);
  filter->SetARAPIterations(5000);
  filter->SetConvergence(1e-10);
  return filter;
}

// `output` is a valid edit of `input` whose handle moved by (dx, 0, dz): its fixed points bit
// for bit, its handle points at their targets to 1e-9 of the diagonal.
void ExpectTranslatedEdit(vtkPolyData* input, vtkPolyData* output, double dx, double dz)
{
  vtkSignedCharArray* roles = Roles(output);
  ASSERT_NE(roles, nullptr);
  for (vtkIdType i = 0; i < input->GetNumberOfPoints(); ++i)
  {
    double p[3], q[3];
    input->GetPoint(i, p);
    output->GetPoint(i, q);
    if (roles->GetValue(i) == vtkLaplacianDeformationFilter::ROLE_FIXED)
    {
      ASSERT_TRUE(p[0] == q[0] && p[1] == q[1] && p[2] == q[2]) << "point " << i;
    }
    else if (roles->GetValue(i) == vtkLaplacianDeformationFilter::ROLE_HANDLE)
    {
      const double target[3] = { p[0] + dx, p[1], p[2] + dz };
      ASSERT_LT(std::sqrt(vtkMath::Distance2BetweenPoints(q, target)), 1e-9 * Diagonal(input));
    }
  }
}
}

TEST(Filter, ALargeRegionDragsOnAProxyAndSettlesAsTheFactoredEditDoes)
{
  // A 9.6k-vertex region made large (LargeRegionVertices 1000, a proxy of about 800 nodes).
  // Required: nothing moved gives the input back (1e-9 of the diagonal); at every drag step
  // the handle lands (1e-9), the outside stays bit for bit, no triangle of the region turns
  // over (its normal against the rest's, which the 30-degree turn keeps positive), and the
  // point data pass through; the release, run to convergence, lands on the factored edit's
  // converged shape (1e-4 of the diagonal).
  auto input = BumpyPlane(160);
  vtkNew<vtkFloatArray> temperature;
  temperature->SetName("Temperature");
  temperature->SetNumberOfTuples(input->GetNumberOfPoints());
  temperature->FillValue(36.6f);
  input->GetPointData()->AddArray(temperature);
  auto factored = ConvergedArapEdit(input, 0);
  auto large = ConvergedArapEdit(input, 1000);
  large->Update();
  ASSERT_GT(large->GetNumberOfROIVertices(), 9000);
  EXPECT_LT(MaxPointDistance(input, large->GetOutput()), 1e-9 * Diagonal(input));

  vtkNew<vtkTransform> transform;
  large->SetHandleTransform(transform);
  factored->SetHandleTransform(transform);
  large->DraggingOn();
  for (int step = 1; step <= 6; ++step)
  {
    transform->Identity();
    transform->Translate(0.5, 0.5, 0.03 * step);
    transform->RotateY(5.0 * step);
    transform->Translate(-0.5, -0.5, 0.0);
    large->Update();
    vtkPolyData* output = large->GetOutput();
    vtkSignedCharArray* roles = Roles(output);
    ASSERT_NE(roles, nullptr);
    ASSERT_NE(output->GetPointData()->GetArray("Temperature"), nullptr);
    for (vtkIdType i = 0; i < input->GetNumberOfPoints(); ++i)
    {
      double p[3], q[3], target[3];
      input->GetPoint(i, p);
      output->GetPoint(i, q);
      if (roles->GetValue(i) == vtkLaplacianDeformationFilter::ROLE_FIXED)
      {
        ASSERT_TRUE(p[0] == q[0] && p[1] == q[1] && p[2] == q[2]) << "point " << i;
      }
      else if (roles->GetValue(i) == vtkLaplacianDeformationFilter::ROLE_HANDLE)
      {
        transform->TransformPoint(p, target);
        ASSERT_LT(std::sqrt(vtkMath::Distance2BetweenPoints(q, target)), 1e-9 * Diagonal(input));
      }
    }
    const vtkIdType* cell = nullptr;
    vtkIdType size = 0;
    for (vtkIdType c = 0; c < input->GetNumberOfPolys(); ++c)
    {
      input->GetPolys()->GetCellAtId(c, size, cell);
      double rest[3][3], moved[3][3];
      for (int k = 0; k < 3; ++k)
      {
        input->GetPoint(cell[k], rest[k]);
        output->GetPoint(cell[k], moved[k]);
      }
      double restNormal[3], movedNormal[3];
      vtkTriangle::ComputeNormalDirection(rest[0], rest[1], rest[2], restNormal);
      vtkTriangle::ComputeNormalDirection(moved[0], moved[1], moved[2], movedNormal);
      ASSERT_GT(vtkMath::Dot(restNormal, movedNormal), 0.0) << "triangle " << c << ", step " << step;
    }
  }
  large->DraggingOff();
  large->Update();
  factored->Update();
  const double apart = MaxPointDistance(factored->GetOutput(), large->GetOutput()) / Diagonal(input);
  std::printf("released large region: %.2e of the diagonal from the factored edit\n", apart);
  EXPECT_LT(apart, 1e-4);
}

TEST(Filter, ALargeRegionsSettleReportsProgressStopsWhereAbortedAndConvergesOnTheNextRelease)
{
  // A 9.6k-vertex region made large, settled, dragged to another pose, and released with an
  // observer that aborts after the third iteration's progress event. Required: progress events
  // in (0.9, 1), increasing, one an iteration; the abort ends the settle there, and the output
  // is that iterate, a valid edit (the handle met to 1e-9 of the diagonal, the outside bit for
  // bit, the edit not lost); a new grab and release then settle to the factored edit's
  // converged shape (1e-4).
  auto input = BumpyPlane(160);
  auto factored = ConvergedArapEdit(input, 0);
  auto large = ConvergedArapEdit(input, 1000);
  large->SetHandleTransform(Translation(-0.1, 0.05, 0.05));
  large->Update();
  for (vtkLaplacianDeformationFilter* filter : { factored.Get(), large.Get() })
  {
    filter->SetHandleTransform(Translation(0.05, 0.0, 0.15));
  }
  large->DraggingOn();
  large->Update();
  large->DraggingOff();

  std::vector<double> progress;
  vtkNew<vtkCallbackCommand> observer;
  observer->SetClientData(&progress);
  observer->SetCallback([](vtkObject* caller, unsigned long, void* client, void* data) {
    auto& seen = *static_cast<std::vector<double>*>(client);
    const double done = *static_cast<double*>(data);
    if (done > 0.9 && done < 1.0)
    {
      seen.push_back(done);
      if (seen.size() == 3)
      {
        static_cast<vtkAlgorithm*>(caller)->AbortExecuteOn();
      }
    }
  });
  const unsigned long tag = large->AddObserver(vtkCommand::ProgressEvent, observer);
  large->Update();
  large->RemoveObserver(tag);
  large->AbortExecuteOff();
  ASSERT_EQ(progress.size(), 3u);
  EXPECT_TRUE(std::is_sorted(progress.begin(), progress.end()));
  EXPECT_EQ(large->GetNumberOfARAPIterations(), 3);
  vtkPolyData* stopped = large->GetOutput();
  ExpectTranslatedEdit(input, stopped, 0.05, 0.15);
  if (::testing::Test::HasFatalFailure())
  {
    return;
  }
  EXPECT_GT(MaxPointDistance(input, stopped), 0.1);

  large->DraggingOn(); // a new grab, then its release
  large->Update();
  large->DraggingOff();
  large->Update();
  factored->Update();
  const double apart = MaxPointDistance(factored->GetOutput(), large->GetOutput()) / Diagonal(input);
  std::printf("released after an aborted settle: %.2e of the diagonal from the factored edit\n", apart);
  EXPECT_LT(apart, 1e-4);
}

TEST(Filter, ALargeRegionsSettleSplitByATimeLimitEndsOnTheUncutSettlesShape)
{
  // The 9.6k-vertex region made large, dragged and released twice over: once settled in one
  // update (12 Newton steps), once with a SettleTimeLimit that every step reaches, continued
  // update by update while GetSettling(). Required: one step an update, as many as the uncut
  // settle's; each update's output a valid edit (the handle met to 1e-9 of the diagonal, the
  // outside bit for bit); progress increasing over the whole settle, within (0.9, 1]; the
  // last output the uncut settle's (1e-12 of the diagonal: the same iterates); and
  // ContinueSettling() leaves a filter that is not settling unmodified.
  auto input = BumpyPlane(160);
  vtkSmartPointer<vtkLaplacianDeformationFilter> filters[2];
  for (auto& filter : filters)
  {
    filter = ConvergedArapEdit(input, 1000);
    filter->SetARAPIterations(12);
    filter->SetHandleTransform(Translation(-0.1, 0.05, 0.05));
    filter->Update();
    filter->SetHandleTransform(Translation(0.05, 0.0, 0.15));
    filter->DraggingOn();
    filter->Update();
    filter->DraggingOff();
  }
  vtkLaplacianDeformationFilter* uncut = filters[0];
  vtkLaplacianDeformationFilter* cut = filters[1];
  uncut->Update();
  EXPECT_FALSE(uncut->GetSettling());
  const int steps = uncut->GetNumberOfARAPIterations();
  ASSERT_GT(steps, 2);

  std::vector<double> progress;
  vtkNew<vtkCallbackCommand> observer;
  observer->SetClientData(&progress);
  observer->SetCallback([](vtkObject*, unsigned long, void* client, void* data) {
    const double done = *static_cast<double*>(data);
    if (done > 0.9 && done < 1.0) // the settle's, where each update also reports its end, 1
    {
      static_cast<std::vector<double>*>(client)->push_back(done);
    }
  });
  cut->AddObserver(vtkCommand::ProgressEvent, observer);
  cut->SetSettleTimeLimit(1e-9);
  int updates = 0;
  do
  {
    cut->ContinueSettling();
    cut->Update();
    ++updates;
    ASSERT_EQ(cut->GetNumberOfARAPIterations(), 1) << "update " << updates;
    ExpectTranslatedEdit(input, cut->GetOutput(), 0.05, 0.15);
    if (::testing::Test::HasFatalFailure())
    {
      return;
    }
  } while (cut->GetSettling() && updates <= steps);
  EXPECT_EQ(updates, steps);
  EXPECT_GE(static_cast<int>(progress.size()), steps - 1) << "one event a step";
  EXPECT_TRUE(std::is_sorted(progress.begin(), progress.end()));
  const double apart = MaxPointDistance(uncut->GetOutput(), cut->GetOutput()) / Diagonal(input);
  std::printf("a settle cut into %d updates: %.2e of the diagonal from the uncut one\n", updates, apart);
  EXPECT_LT(apart, 1e-12);
  const vtkMTimeType before = cut->GetMTime();
  cut->ContinueSettling();
  EXPECT_EQ(cut->GetMTime(), before);
}

TEST(Filter, SolversAgree)
{
  if (!vtkLaplacianDeformationFilter::IsCholmodAvailable())
  {
    GTEST_SKIP() << "built without CHOLMOD";
  }
  auto input = BumpyPlane();
  vtkSmartPointer<vtkPolyData> results[2];
  for (int solver = 0; solver <= 1; ++solver)
  {
    auto filter = PlaneEdit(input);
    filter->SetSolver(solver);
    filter->SetOperatorOrder(2);
    filter->SetHandleTransform(Translation(0.1, 0, 0.2));
    filter->Update();
    results[solver] = filter->GetOutput();
  }
  EXPECT_LT(MaxPointDistance(results[0], results[1]), 1e-8 * Diagonal(input));
}

TEST(Filter, PassesDataThroughAndRecomputesNormals)
{
  auto input = BumpyPlane();
  vtkNew<vtkPolyDataNormals> normals;
  normals->SetInputData(input);
  normals->SplittingOff();
  normals->ComputeCellNormalsOn();
  normals->Update();
  vtkNew<vtkPolyData> withData;
  withData->DeepCopy(normals->GetOutput());
  vtkNew<vtkIntArray> pointIds;
  pointIds->SetName("PointIds");
  vtkNew<vtkDoubleArray> cellValues;
  cellValues->SetName("CellValues");
  for (vtkIdType i = 0; i < withData->GetNumberOfPoints(); ++i)
  {
    pointIds->InsertNextValue(static_cast<int>(i));
  }
  for (vtkIdType i = 0; i < withData->GetNumberOfCells(); ++i)
  {
    cellValues->InsertNextValue(0.5 * i);
  }
  withData->GetPointData()->AddArray(pointIds);
  withData->GetCellData()->AddArray(cellValues);

  auto filter = PlaneEdit(withData);
  filter->SetHandleTransform(Translation(0, 0, 0.25));
  filter->Update();
  vtkPolyData* output = filter->GetOutput();
  EXPECT_EQ(output->GetNumberOfPoints(), withData->GetNumberOfPoints());
  EXPECT_EQ(output->GetNumberOfCells(), withData->GetNumberOfCells());
  EXPECT_EQ(output->GetPointData()->GetArray("PointIds"), pointIds.Get());
  EXPECT_EQ(output->GetCellData()->GetArray("CellValues"), cellValues.Get());

  // Normals follow the moved surface: compare with normals computed afresh on the output.
  vtkNew<vtkPolyDataNormals> fresh;
  vtkNew<vtkPolyData> bare;
  bare->SetPoints(output->GetPoints());
  bare->SetPolys(output->GetPolys());
  fresh->SetInputData(bare);
  fresh->SplittingOff();
  fresh->ComputeCellNormalsOn();
  fresh->Update();
  for (auto [ours, reference] :
    { std::make_pair(output->GetPointData()->GetNormals(), fresh->GetOutput()->GetPointData()->GetNormals()),
      std::make_pair(output->GetCellData()->GetNormals(), fresh->GetOutput()->GetCellData()->GetNormals()) })
  {
    ASSERT_NE(ours, nullptr);
    ASSERT_EQ(ours->GetNumberOfTuples(), reference->GetNumberOfTuples());
    double worstAngle = 0.0;
    for (vtkIdType i = 0; i < ours->GetNumberOfTuples(); ++i)
    {
      double a[3], b[3];
      ours->GetTuple(i, a);
      reference->GetTuple(i, b);
      worstAngle = std::max(worstAngle, std::acos(std::min(1.0, vtkMath::Dot(a, b))));
    }
    // vtkPolyDataNormals weights faces differently; both agree to a few degrees.
    EXPECT_LT(vtkMath::DegreesFromRadians(worstAngle), 5.0);
  }
}

namespace
{
// A bumpy plane labelled for array selection: the ROI in the middle, handle group 0 (label 2)
// left of the centre and group 1 (label 3) right of it.
vtkSmartPointer<vtkPolyData> TwoHandleGroupsPlane()
{
  auto input = BumpyPlane(40);
  vtkNew<vtkIntArray> selection;
  selection->SetName("Selection");
  for (vtkIdType i = 0; i < input->GetNumberOfPoints(); ++i)
  {
    double p[3];
    input->GetPoint(i, p);
    int label = (p[0] > 0.1 && p[0] < 0.9 && p[1] > 0.1 && p[1] < 0.9) ? 1 : 0;
    if (std::abs(p[1] - 0.5) < 0.06 && std::abs(p[0] - 0.3) < 0.06)
    {
      label = 2;
    }
    if (std::abs(p[1] - 0.5) < 0.06 && std::abs(p[0] - 0.7) < 0.06)
    {
      label = 3;
    }
    selection->InsertNextValue(label);
  }
  input->GetPointData()->AddArray(selection);
  return input;
}

vtkSmartPointer<vtkLaplacianDeformationFilter> ArrayEdit(vtkPolyData* input)
{
  auto filter = vtkSmartPointer<vtkLaplacianDeformationFilter>::New();
  filter->SetInputData(input);
  filter->SetSelectionModeToArray();
  filter->SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, "Selection");
  return filter;
}
}

TEST(Filter, SelectsByArrayWithSeveralHandleGroups)
{
  auto input = TwoHandleGroupsPlane();
  auto* selection = vtkIntArray::SafeDownCast(input->GetPointData()->GetArray("Selection"));
  auto filter = ArrayEdit(input);
  filter->SetHandleTransform(0, Translation(0, 0, 0.2));
  filter->SetHandleTransform(1, Translation(0, 0, -0.1));
  filter->Update();
  vtkPolyData* output = filter->GetOutput();
  for (vtkIdType i = 0; i < input->GetNumberOfPoints(); ++i)
  {
    double p[3], q[3];
    input->GetPoint(i, p);
    output->GetPoint(i, q);
    const int label = selection->GetValue(i);
    if (label == 0)
    {
      ASSERT_EQ(p[2], q[2]);
    }
    else if (label >= 2)
    {
      EXPECT_NEAR(q[2] - p[2], label == 2 ? 0.2 : -0.1, 1e-3 * Diagonal(input));
    }
  }
  EXPECT_EQ(filter->GetNumberOfHandleTransforms(), 2);
}

TEST(Filter, MovesFurtherHandleGroupsByProperties)
{
  // Group 1 turned 30 degrees about z through its rest centroid and lowered, by the property
  // form ParaView and pvpython use, must equal the same motion given as a transform object.
  auto input = TwoHandleGroupsPlane();
  auto byMotion = ArrayEdit(input);
  byMotion->SetHandleTranslation(0.0, 0.0, 0.2);
  byMotion->SetHandleGroupMotion(1, 0.0, 0.0, -0.1, 0.0, 0.0, 30.0);
  byMotion->Update();
  double center[3], motion[6];
  ASSERT_TRUE(byMotion->GetHandleGroupCenter(1, center));
  ASSERT_TRUE(byMotion->GetHandleGroupMotion(1, motion));
  EXPECT_EQ(motion[5], 30.0);
  EXPECT_FALSE(byMotion->GetHandleGroupMotion(2, motion));
  // The forms ParaView's panel reads through its client-server layer.
  EXPECT_EQ(byMotion->GetNumberOfHandleGroups(), 2);
  const double* returned = byMotion->GetHandleGroupCenter(1);
  EXPECT_TRUE(std::equal(center, center + 3, returned));
  EXPECT_FALSE(byMotion->GetHandleGroupCenter(2, center));
  EXPECT_EQ(byMotion->GetHandleGroupCenter(2)[0], 0.0);

  vtkNew<vtkTransform> turn;
  turn->PostMultiply();
  turn->Translate(-center[0], -center[1], -center[2]);
  turn->RotateZ(30.0);
  turn->Translate(center);
  turn->Translate(0.0, 0.0, -0.1);
  auto byTransform = ArrayEdit(input);
  byTransform->SetHandleTranslation(0.0, 0.0, 0.2);
  byTransform->SetHandleTransform(1, turn);
  byTransform->Update();
  EXPECT_LT(MaxPointDistance(byMotion->GetOutput(), byTransform->GetOutput()), 1e-12);

  auto* selection = vtkIntArray::SafeDownCast(input->GetPointData()->GetArray("Selection"));
  int handleVertices = 0;
  for (vtkIdType i = 0; i < input->GetNumberOfPoints(); ++i)
  {
    if (selection->GetValue(i) == 3)
    {
      double p[3], q[3], target[3];
      input->GetPoint(i, p);
      byMotion->GetOutput()->GetPoint(i, q);
      turn->TransformPoint(p, target);
      EXPECT_LT(std::sqrt(vtkMath::Distance2BetweenPoints(q, target)), 1e-3 * Diagonal(input));
      ++handleVertices;
    }
  }
  EXPECT_GT(handleVertices, 10);

  // A transform object wins over a motion; a commit sets the motions back to rest.
  byTransform->SetHandleGroupMotion(1, 0.0, 0.0, 0.3, 0.0, 0.0, 0.0);
  byTransform->Update();
  EXPECT_LT(MaxPointDistance(byMotion->GetOutput(), byTransform->GetOutput()), 1e-12);
  vtkNew<vtkPolyData> edited;
  edited->DeepCopy(byMotion->GetOutput());
  byMotion->CommitEdit();
  EXPECT_EQ(byMotion->GetNumberOfHandleGroupMotions(), 0);
  byMotion->Update();
  EXPECT_LT(MaxPointDistance(byMotion->GetOutput(), edited), 1e-9 * Diagonal(input));

  // Group 0 moves by HandleTranslation and HandleRotation, not by a motion.
  ErrorCatcher errors(byMotion);
  byMotion->SetHandleGroupMotion(0, 0.0, 0.0, 0.1, 0.0, 0.0, 0.0);
  EXPECT_NE(errors.Messages.find("group 0 moves with HandleTranslation"), std::string::npos);
  EXPECT_EQ(byMotion->GetNumberOfHandleGroupMotions(), 0);
}

TEST(Filter, EditsTheCactusFromItsSelAndDefFiles)
{
  // The Botsch & Sorkine benchmark format: OFF mesh, .sel roles, .def handle transform.
  std::ifstream off(DataDir + "/cactus.off"), sel(DataDir + "/cactus.sel"),
    def(DataDir + "/cactus.def");
  ASSERT_TRUE(off && sel && def) << "missing cactus files in " << DataDir;
  std::string header, line;
  int nv, nf, ne;
  off >> header >> nv >> nf >> ne;
  vtkNew<vtkPoints> points;
  for (int i = 0; i < nv; ++i)
  {
    double p[3];
    off >> p[0] >> p[1] >> p[2];
    std::getline(off, line); // colour
    points->InsertNextPoint(p);
  }
  vtkNew<vtkCellArray> polys;
  for (int i = 0; i < nf; ++i)
  {
    int n;
    vtkIdType ids[3];
    off >> n >> ids[0] >> ids[1] >> ids[2];
    std::getline(off, line);
    polys->InsertNextCell(3, ids);
  }
  vtkNew<vtkIntArray> labels;
  labels->SetName("Selection");
  while (std::getline(sel, line))
  {
    if (!line.empty() && line[0] != '#')
    {
      labels->InsertNextValue(std::stoi(line));
    }
  }
  ASSERT_EQ(labels->GetNumberOfTuples(), nv);
  vtkNew<vtkMatrix4x4> matrix;
  std::getline(def, line);
  for (int r = 0; r < 4; ++r)
  {
    for (int c = 0; c < 4; ++c)
    {
      double value;
      def >> value;
      matrix->SetElement(r, c, value);
    }
  }
  vtkNew<vtkPolyData> cactus;
  cactus->SetPoints(points);
  cactus->SetPolys(polys);
  cactus->GetPointData()->AddArray(labels);

  vtkNew<vtkTransform> transform;
  transform->SetMatrix(matrix);
  vtkNew<vtkLaplacianDeformationFilter> filter;
  filter->SetInputData(cactus);
  filter->SetSelectionModeToArray();
  filter->SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, "Selection");
  filter->SetHandleTransform(transform);
  filter->Update();
  vtkPolyData* output = filter->GetOutput();
  for (vtkIdType i = 0; i < nv; ++i)
  {
    double p[3], q[3], target[3];
    cactus->GetPoint(i, p);
    output->GetPoint(i, q);
    if (labels->GetValue(i) == 0)
    {
      ASSERT_TRUE(p[0] == q[0] && p[1] == q[1] && p[2] == q[2]);
    }
    else if (labels->GetValue(i) == 2)
    {
      transform->TransformPoint(p, target);
      EXPECT_LT(std::sqrt(vtkMath::Distance2BetweenPoints(q, target)), 1e-3 * Diagonal(cactus));
    }
  }
}

TEST(Filter, EditsAcrossTextureSeams)
{
  // spot.obj: 2,930 vertices read as 17,568 points split at texture seams. Coincident points
  // must move together, so the edit leaves no crack.
  vtkNew<vtkOBJReader> reader;
  reader->SetFileName((DataDir + "/spot.obj").c_str());
  reader->Update();
  vtkPolyData* spot = reader->GetOutput();
  ASSERT_GT(spot->GetNumberOfPoints(), 10000);
  vtkNew<vtkLaplacianDeformationFilter> filter;
  filter->SetInputData(spot);
  double p[3];
  spot->GetPoint(0, p);
  filter->SetHandleCenter(p);
  filter->SetHandleRadius(0.05 * spot->GetLength());
  filter->SetROIRadius(0.3 * spot->GetLength());
  filter->SetHandleTransform(Translation(0, 0.1 * spot->GetLength(), 0));
  filter->Update();
  vtkPolyData* output = filter->GetOutput();
  EXPECT_GT(filter->GetNumberOfROIVertices(), 200);
  // Group points by input position; each group must share one output position.
  std::map<std::array<double, 3>, std::array<double, 3>> moved;
  int groupsChecked = 0;
  for (vtkIdType i = 0; i < spot->GetNumberOfPoints(); ++i)
  {
    std::array<double, 3> in, out;
    spot->GetPoint(i, in.data());
    output->GetPoint(i, out.data());
    auto [it, inserted] = moved.emplace(in, out);
    if (!inserted)
    {
      ASSERT_EQ(it->second, out) << "point " << i << " split from its seam twin";
      ++groupsChecked;
    }
  }
  EXPECT_GT(groupsChecked, 1000);
}

TEST(Filter, ReportsProgress)
{
  auto filter = PlaneEdit(BumpyPlane());
  std::vector<double> progress;
  vtkNew<vtkCallbackCommand> callback;
  callback->SetClientData(&progress);
  callback->SetCallback([](vtkObject* caller, unsigned long, void* data, void*) {
    static_cast<std::vector<double>*>(data)->push_back(
      static_cast<vtkAlgorithm*>(caller)->GetProgress());
  });
  filter->AddObserver(vtkCommand::ProgressEvent, callback);
  filter->Update();
  // After each stage: graph, region, rotation model, solve, output.
  ASSERT_GE(progress.size(), 5u);
  EXPECT_TRUE(std::is_sorted(progress.begin(), progress.end()));
  EXPECT_EQ(progress.back(), 1.0);
}

// Each bad input: a clear error, and the output is the input unchanged.
struct BadInput
{
  const char* Name;
  std::function<void(vtkPolyData*, vtkLaplacianDeformationFilter*)> Spoil;
  const char* Message;
};

void PrintTo(const BadInput& bad, std::ostream* os)
{
  *os << bad.Name;
}

class FilterBadInput : public ::testing::TestWithParam<BadInput>
{
};

TEST_P(FilterBadInput, ReportsAnErrorAndPassesTheInputThrough)
{
  const BadInput& bad = GetParam();
  auto input = BumpyPlane(20);
  auto filter = PlaneEdit(input);
  bad.Spoil(input, filter);
  filter->SetHandleTransform(Translation(0, 0, 0.3));
  ErrorCatcher errors(filter);
  filter->Update();
  EXPECT_NE(errors.Messages.find(bad.Message), std::string::npos)
    << bad.Name << ": got '" << errors.Messages << "'";
  vtkPolyData* output = filter->GetOutput();
  EXPECT_EQ(output->GetNumberOfPoints(), input->GetNumberOfPoints());
  EXPECT_EQ(output->GetNumberOfCells(), input->GetNumberOfCells());
  if (input->GetNumberOfPoints() > 0)
  {
    EXPECT_EQ(output->GetPoints()->GetData(), input->GetPoints()->GetData());
  }
}

namespace
{
// An index selection of points or cells, as ParaView's "Copy Active Selection" gives.
vtkSmartPointer<vtkSelection> IdSelection(const std::vector<vtkIdType>& ids, int field)
{
  vtkNew<vtkIdTypeArray> list;
  for (vtkIdType id : ids)
  {
    list->InsertNextValue(id);
  }
  vtkNew<vtkSelectionNode> node;
  node->SetContentType(vtkSelectionNode::INDICES);
  node->SetFieldType(field);
  node->SetSelectionList(list);
  auto selection = vtkSmartPointer<vtkSelection>::New();
  selection->AddNode(node);
  return selection;
}

void AddSelection(vtkPolyData* input, vtkDataArray* array, vtkLaplacianDeformationFilter* filter)
{
  array->SetName("Selection");
  array->SetNumberOfComponents(1);
  array->SetNumberOfTuples(input->GetNumberOfPoints());
  array->Fill(1);
  input->GetPointData()->AddArray(array);
  filter->SetSelectionModeToArray();
  filter->SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, "Selection");
}
}

INSTANTIATE_TEST_SUITE_P(Cases, FilterBadInput,
  ::testing::Values(
    BadInput{ "EmptyMesh", [](vtkPolyData* in, vtkLaplacianDeformationFilter*) { in->Initialize(); },
      "empty" },
    BadInput{ "LinesOnly",
      [](vtkPolyData* in, vtkLaplacianDeformationFilter*) {
        vtkNew<vtkCellArray> lines;
        const vtkIdType ids[2] = { 0, 1 };
        lines->InsertNextCell(2, ids);
        in->SetPolys(nullptr);
        in->SetLines(lines);
      },
      "no polygons" },
    BadInput{ "NaNCoordinate",
      [](vtkPolyData* in, vtkLaplacianDeformationFilter*) {
        in->GetPoints()->SetPoint(7, std::nan(""), 0, 0);
      },
      "NaN or infinite" },
    BadInput{ "InfiniteCoordinate",
      [](vtkPolyData* in, vtkLaplacianDeformationFilter*) {
        in->GetPoints()->SetPoint(7, 0, std::numeric_limits<double>::infinity(), 0);
      },
      "NaN or infinite" },
    BadInput{ "ZeroRadius",
      [](vtkPolyData*, vtkLaplacianDeformationFilter* f) { f->SetHandleRadius(0.0); },
      "must be positive" },
    BadInput{ "NegativeROIRadius",
      [](vtkPolyData*, vtkLaplacianDeformationFilter* f) { f->SetROIRadius(-1.0); },
      "must be positive" },
    BadInput{ "HandleOutsideROI",
      [](vtkPolyData*, vtkLaplacianDeformationFilter* f) {
        f->SetHandleRadius(0.4);
        f->SetROIRadius(0.3);
      },
      "handle reaches outside the region" },
    BadInput{ "ROIWithoutAnchorOrFixedVertex",
      [](vtkPolyData*, vtkLaplacianDeformationFilter* f) {
        f->SetROIRadius(100.0);
        f->SetAnchorPadding(0.0);
      },
      "no fixed vertex and no anchor" },
    BadInput{ "MissingSelectionArray",
      [](vtkPolyData*, vtkLaplacianDeformationFilter* f) {
        f->SetSelectionModeToArray();
        f->SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, "Nope");
      },
      "no such point array" },
    BadInput{ "FloatSelectionArray",
      [](vtkPolyData* in, vtkLaplacianDeformationFilter* f) {
        vtkNew<vtkFloatArray> array;
        AddSelection(in, array, f);
      },
      "must be an integer array" },
    BadInput{ "NoHandle",
      [](vtkPolyData* in, vtkLaplacianDeformationFilter* f) {
        vtkNew<vtkIntArray> array;
        AddSelection(in, array, f);
        array->SetValue(0, 0);
      },
      "no handle vertex" },
    BadInput{ "SelectionInputSelectsNothing",
      [](vtkPolyData*, vtkLaplacianDeformationFilter* f) {
        f->SetSelectionData(IdSelection({}, vtkSelectionNode::POINT));
      },
      "selects no point of the input" },
    BadInput{ "UnreferencedVertexInROI",
      [](vtkPolyData* in, vtkLaplacianDeformationFilter* f) {
        in->GetPoints()->InsertNextPoint(0.5, 0.5, 1.0);
        vtkNew<vtkIntArray> array;
        AddSelection(in, array, f);
        array->SetValue(0, 2);
        array->SetValue(1, 0);
      },
      "no triangle references" }),
  [](const auto& info) { return std::string(info.param.Name); });

TEST(Filter, IgnoresUnreferencedPointsOutsideTheROI)
{
  auto input = BumpyPlane(30);
  input->GetPoints()->InsertNextPoint(0.5, 0.5, 1.0);
  auto filter = PlaneEdit(input);
  filter->SetHandleTransform(Translation(0, 0, 0.2));
  ErrorCatcher errors(filter);
  filter->Update();
  EXPECT_EQ(errors.Messages, "");
  double q[3];
  filter->GetOutput()->GetPoint(input->GetNumberOfPoints() - 1, q);
  EXPECT_EQ(q[2], 1.0);
}

TEST(Filter, TriangulatesQuadsInternallyAndKeepsThem)
{
  vtkNew<vtkPoints> points;
  vtkNew<vtkCellArray> quads;
  const int n = 30;
  for (int j = 0; j <= n; ++j)
  {
    for (int i = 0; i <= n; ++i)
    {
      points->InsertNextPoint(static_cast<double>(i) / n, static_cast<double>(j) / n, 0.0);
    }
  }
  for (int j = 0; j < n; ++j)
  {
    for (int i = 0; i < n; ++i)
    {
      const vtkIdType a = j * (n + 1) + i;
      const vtkIdType ids[4] = { a, a + 1, a + n + 2, a + n + 1 };
      quads->InsertNextCell(4, ids);
    }
  }
  vtkNew<vtkPolyData> mesh;
  mesh->SetPoints(points);
  mesh->SetPolys(quads);
  auto filter = PlaneEdit(mesh);
  filter->SetHandleTransform(Translation(0, 0, 0.2));
  filter->Update();
  EXPECT_EQ(filter->GetOutput()->GetPolys()->GetMaxCellSize(), 4);
  double q[3];
  filter->GetOutput()->GetPoint(15 * (n + 1) + 15, q);
  EXPECT_NEAR(q[2], 0.2, 1e-3);
}

TEST(Filter, TranslationAndRotationPropertiesMatchTheTransform)
{
  // ParaView's properties: rotation about the handle centre (x, then y, then z), then a
  // translation. They give the edit the equivalent vtkTransform gives.
  auto input = BumpyPlane(40);
  auto byProperties = PlaneEdit(input);
  byProperties->SetHandleTranslation(0.05, -0.02, 0.2);
  byProperties->SetHandleRotation(10.0, -20.0, 30.0);
  byProperties->Update();
  vtkNew<vtkTransform> transform;
  transform->PostMultiply();
  transform->Translate(-0.5, -0.5, 0.0);
  transform->RotateX(10.0);
  transform->RotateY(-20.0);
  transform->RotateZ(30.0);
  transform->Translate(0.5, 0.5, 0.0);
  transform->Translate(0.05, -0.02, 0.2);
  auto byTransform = PlaneEdit(input);
  byTransform->SetHandleTransform(transform);
  byTransform->Update();
  EXPECT_LT(MaxPointDistance(byProperties->GetOutput(), byTransform->GetOutput()), 1e-12);
  EXPECT_GT(MaxPointDistance(input, byProperties->GetOutput()), 0.1);
}

namespace
{
// The array-mode edit of `rest` whose labels are the roles of `edited` (a handle stays a handle,
// the rest of the ROI is ROI), with the same handle centre and translation.
vtkSmartPointer<vtkLaplacianDeformationFilter> SameEditByArray(
  vtkPolyData* rest, vtkLaplacianDeformationFilter* edited)
{
  vtkNew<vtkPolyData> labeled;
  labeled->ShallowCopy(rest);
  vtkNew<vtkIntArray> labels;
  labels->SetName("Labels");
  labels->SetNumberOfTuples(rest->GetNumberOfPoints());
  vtkSignedCharArray* roles = Roles(edited->GetOutput());
  for (vtkIdType i = 0; i < rest->GetNumberOfPoints(); ++i)
  {
    const int role = roles->GetValue(i);
    labels->SetValue(i, role == vtkLaplacianDeformationFilter::ROLE_HANDLE ? 2 : (role ? 1 : 0));
  }
  labeled->GetPointData()->AddArray(labels);
  auto array = vtkSmartPointer<vtkLaplacianDeformationFilter>::New();
  array->SetInputData(labeled);
  array->SetSelectionModeToArray();
  array->SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, "Labels");
  array->SetHandleCenter(edited->GetHandleCenter());
  array->SetHandleTranslation(edited->GetHandleTranslation());
  array->Update();
  return array;
}
}

TEST(Filter, TheSurfaceGraphFollowsTheRegionNotTheInput)
{
  // A sphere of 250k points and a region of about 1% of it, selected geodesically and by
  // array: required, a surface graph under 4 times the ROI (the ROI, its rings and margin) both
  // ways.
  vtkNew<vtkSphereSource> source;
  source->SetThetaResolution(500);
  source->SetPhiResolution(500);
  source->Update();
  vtkPolyData* sphere = source->GetOutput();
  auto geodesic = vtkSmartPointer<vtkLaplacianDeformationFilter>::New();
  geodesic->SetInputData(sphere);
  geodesic->SetRadiusUnitsToDiagonalFraction();
  geodesic->SetHandleCenter(0.3, 0.0, 0.4); // on the sphere, away from its pole
  geodesic->SetHandleRadius(0.01);
  geodesic->SetROIRadius(0.05);
  geodesic->SetHandleTranslation(0.0, 0.0, 0.02);
  geodesic->Update();
  const int roi = geodesic->GetNumberOfROIVertices();
  EXPECT_GT(roi, 1000);
  EXPECT_LT(roi, sphere->GetNumberOfPoints() / 50);
  EXPECT_LT(geodesic->GetNumberOfSurfaceVertices(), 4 * roi);

  auto array = SameEditByArray(sphere, geodesic);
  EXPECT_EQ(array->GetNumberOfROIVertices(), roi);
  EXPECT_LT(array->GetNumberOfSurfaceVertices(), 4 * roi);
  EXPECT_EQ(array->GetNumberOfHandleVertices(), geodesic->GetNumberOfHandleVertices());
}

TEST(Filter, AHandleFromASelectionInputEditsAsTheSameArraySelection)
{
  // Points within 0.08 of a sphere point, selected by id on port 1: the handle is exactly
  // them, the ROI lies within ROIRadius of them, and the edit matches the array mode's with
  // the same labels (1e-9). Moves re-solve; a new selection selects again.
  vtkNew<vtkSphereSource> source;
  source->SetThetaResolution(80);
  source->SetPhiResolution(80);
  source->Update();
  vtkPolyData* sphere = source->GetOutput();
  const double center[3] = { 0.3, 0.0, 0.4 };
  std::vector<vtkIdType> ids;
  for (vtkIdType i = 0; i < sphere->GetNumberOfPoints(); ++i)
  {
    if (vtkMath::Distance2BetweenPoints(sphere->GetPoint(i), center) < 0.08 * 0.08)
    {
      ids.push_back(i);
    }
  }
  ASSERT_GT(ids.size(), 10u);
  auto selected = vtkSmartPointer<vtkLaplacianDeformationFilter>::New();
  selected->SetInputData(sphere);
  selected->SetSelectionData(IdSelection(ids, vtkSelectionNode::POINT));
  selected->SetHandleCenter(const_cast<double*>(center));
  selected->SetROIRadius(0.35);
  selected->SetHandleTranslation(0.0, 0.05, 0.1);
  ErrorCatcher errors(selected);
  selected->Update();
  EXPECT_EQ(errors.Messages, "");
  vtkSignedCharArray* roles = Roles(selected->GetOutput());
  std::vector<vtkIdType> handle;
  double farthest = 0.0;
  for (vtkIdType i = 0; i < sphere->GetNumberOfPoints(); ++i)
  {
    if (roles->GetValue(i) == vtkLaplacianDeformationFilter::ROLE_HANDLE)
    {
      handle.push_back(i);
    }
    if (roles->GetValue(i) != vtkLaplacianDeformationFilter::ROLE_FIXED)
    {
      double p[3], q[3], nearest = VTK_DOUBLE_MAX;
      sphere->GetPoint(i, p);
      for (vtkIdType id : ids)
      {
        sphere->GetPoint(id, q);
        nearest = std::min(nearest, vtkMath::Distance2BetweenPoints(p, q));
      }
      farthest = std::max(farthest, std::sqrt(nearest));
    }
  }
  EXPECT_EQ(handle, ids);
  EXPECT_GT(selected->GetNumberOfROIVertices(), 3 * static_cast<int>(ids.size()));
  EXPECT_LE(farthest, 0.35); // a straight line is never longer than the path on the surface
  EXPECT_GT(farthest, 0.25);

  auto array = SameEditByArray(sphere, selected);
  EXPECT_LT(MaxPointDistance(array->GetOutput(), selected->GetOutput()), 1e-9);

  const int factorizations = selected->GetNumberOfFactorizations();
  selected->SetHandleTranslation(0.0, 0.0, 0.2);
  selected->Update();
  EXPECT_EQ(selected->GetNumberOfFactorizations(), factorizations) << "a move only re-solves";
  ids.resize(ids.size() / 2);
  selected->SetSelectionData(IdSelection(ids, vtkSelectionNode::POINT));
  selected->Update();
  EXPECT_EQ(selected->GetNumberOfHandleVertices(), static_cast<int>(ids.size()));
  EXPECT_GT(selected->GetNumberOfFactorizations(), factorizations) << "a new selection selects again";
}

TEST(Filter, ASelectionAddressedToAnotherPieceSelectsNothingHere)
{
  // ParaView's selections of ids name the piece (PROCESS_ID) they address; a serial filter is
  // piece 0, and the parallel one labels each piece with the nodes addressed to it.
  auto input = BumpyPlane(20);
  auto filter = PlaneEdit(input);
  const vtkIdType cell = input->GetNumberOfCells() / 2;
  auto selection = IdSelection({ cell }, vtkSelectionNode::CELL);
  auto other = IdSelection({ 0, 1, 2 }, vtkSelectionNode::POINT);
  selection->GetNode(0)->GetProperties()->Set(vtkSelectionNode::PROCESS_ID(), 0);
  other->GetNode(0)->GetProperties()->Set(vtkSelectionNode::PROCESS_ID(), 1);
  selection->AddNode(other->GetNode(0));
  filter->SetSelectionData(selection);
  filter->Update();
  EXPECT_EQ(filter->GetNumberOfHandleVertices(), 3) << "the cell's corners, not points 0-2";
}

TEST(Filter, ASelectionOfCellsMakesTheirPointsTheHandle)
{
  auto input = BumpyPlane(20);
  auto filter = PlaneEdit(input);
  const vtkIdType cell = input->GetNumberOfCells() / 2;
  filter->SetSelectionData(IdSelection({ cell }, vtkSelectionNode::CELL));
  filter->SetHandleTransform(Translation(0, 0, 0.1));
  filter->Update();
  vtkNew<vtkIdList> corners;
  input->GetCellPoints(cell, corners);
  EXPECT_EQ(filter->GetNumberOfHandleVertices(), corners->GetNumberOfIds());
  vtkSignedCharArray* roles = Roles(filter->GetOutput());
  for (vtkIdType k = 0; k < corners->GetNumberOfIds(); ++k)
  {
    EXPECT_EQ(roles->GetValue(corners->GetId(k)), vtkLaplacianDeformationFilter::ROLE_HANDLE);
  }
}
