// Degenerate and hostile meshes, abort, memory bounds and concurrency: each case states what the
// filter does with it.
#include "FilterTestHelpers.h"

#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkIdList.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkSignedCharArray.h"

#include <gtest/gtest.h>

#include <thread>

namespace
{
using Filter = vtkLaplacianDeformationFilter;

// Every output coordinate is finite, handles sit on their targets (a translation by `lift`)
// and fixed points are bit-identical.
void ExpectSoundEdit(vtkPolyData* input, Filter* filter, const double lift[3])
{
  vtkPolyData* output = filter->GetOutput();
  ASSERT_EQ(output->GetNumberOfPoints(), input->GetNumberOfPoints());
  auto* roles = vtkSignedCharArray::SafeDownCast(output->GetPointData()->GetArray("EditRole"));
  ASSERT_NE(roles, nullptr);
  int handles = 0;
  for (vtkIdType i = 0; i < input->GetNumberOfPoints(); ++i)
  {
    double p[3], q[3];
    input->GetPoint(i, p);
    output->GetPoint(i, q);
    ASSERT_TRUE(std::isfinite(q[0]) && std::isfinite(q[1]) && std::isfinite(q[2])) << i;
    if (roles->GetValue(i) == Filter::ROLE_FIXED)
    {
      ASSERT_TRUE(p[0] == q[0] && p[1] == q[1] && p[2] == q[2]) << i;
    }
    else if (roles->GetValue(i) == Filter::ROLE_HANDLE)
    {
      ++handles;
      const double target[3] = { p[0] + lift[0], p[1] + lift[1], p[2] + lift[2] };
      EXPECT_LT(std::sqrt(vtkMath::Distance2BetweenPoints(q, target)), 1e-3 * Diagonal(input));
    }
  }
  EXPECT_GT(handles, 0);
}

// Updates the filter, expecting no error and a sound edit.
void ExpectCleanEdit(vtkPolyData* input, Filter* filter, const double lift[3])
{
  ErrorCatcher errors(filter);
  filter->Update();
  EXPECT_EQ(errors.Messages, "");
  ExpectSoundEdit(input, filter, lift);
}

vtkSmartPointer<Filter> Lifted(vtkPolyData* input, const double lift[3])
{
  auto filter = PlaneEdit(input);
  filter->SetHandleTransform(Translation(lift[0], lift[1], lift[2]));
  return filter;
}

const double Lift[3] = { 0.02, -0.01, 0.2 };

// The triangles of `mesh`, each with its own three points: an STL-style soup. With `rounding`,
// each copy is off by up to that much in each coordinate, as separately computed copies are.
vtkSmartPointer<vtkPolyData> Soup(vtkPolyData* mesh, double rounding = 0.0)
{
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  vtkNew<vtkCellArray> triangles;
  auto cells = vtk::TakeSmartPointer(mesh->GetPolys()->NewIterator());
  for (cells->GoToFirstCell(); !cells->IsDoneWithTraversal(); cells->GoToNextCell())
  {
    vtkIdType size;
    const vtkIdType* ids;
    cells->GetCurrentCell(size, ids);
    triangles->InsertNextCell(static_cast<int>(size));
    for (vtkIdType c = 0; c < size; ++c)
    {
      double p[3];
      mesh->GetPoint(ids[c], p);
      const vtkIdType copy = points->GetNumberOfPoints();
      for (int a = 0; a < 3; ++a)
      {
        p[a] += rounding * static_cast<double>((copy + a) % 3 - 1);
      }
      triangles->InsertCellPoint(points->InsertNextPoint(p));
    }
  }
  auto soup = vtkSmartPointer<vtkPolyData>::New();
  soup->SetPoints(points);
  soup->SetPolys(triangles);
  return soup;
}
}

TEST(Degenerate, ZeroAreaAndObtuseTrianglesWithCotangentWeights)
{
  // Collapse a few triangles to zero area (a point moved onto its neighbour's position makes
  // two triangles degenerate after merging) and squash a row into obtuse slivers.
  auto input = BumpyPlane(40);
  double p[3];
  input->GetPoint(20 * 41 + 21, p);
  input->GetPoints()->SetPoint(20 * 41 + 22, p);
  for (int i = 0; i <= 40; ++i)
  {
    input->GetPoint(15 * 41 + i, p);
    p[1] = input->GetPoint(14 * 41 + i)[1] + 1e-4;
    input->GetPoints()->SetPoint(15 * 41 + i, p);
  }
  for (int order = 1; order <= 2; ++order)
  {
    auto filter = Lifted(input, Lift);
    filter->SetLaplacianWeightsToCotangent();
    filter->SetOperatorOrder(order);
    filter->SetRotationModeToExplicit();
    ExpectCleanEdit(input, filter, Lift);
  }
}

namespace
{
// The soup of `welded` edits as `welded` does, point for point. The handle centre is off the
// grid's symmetries, so that its nearest vertex is not a tie that rounding could break.
void ExpectSoupEditsAsWelded(vtkPolyData* welded, vtkPolyData* soup)
{
  auto reference = Lifted(welded, Lift);
  reference->SetHandleCenter(0.505, 0.49, 0.0);
  reference->Update();
  auto merged = Lifted(soup, Lift);
  merged->SetHandleCenter(0.505, 0.49, 0.0);
  merged->Update();
  ExpectSoundEdit(soup, merged, Lift);
  auto cells = vtk::TakeSmartPointer(welded->GetPolys()->NewIterator());
  vtkIdType soupPoint = 0;
  double worst = 0.0;
  for (cells->GoToFirstCell(); !cells->IsDoneWithTraversal(); cells->GoToNextCell())
  {
    vtkIdType size;
    const vtkIdType* ids;
    cells->GetCurrentCell(size, ids);
    for (vtkIdType c = 0; c < size; ++c, ++soupPoint)
    {
      double a[3], b[3];
      reference->GetOutput()->GetPoint(ids[c], a);
      merged->GetOutput()->GetPoint(soupPoint, b);
      worst = std::max(worst, std::sqrt(vtkMath::Distance2BetweenPoints(a, b)));
    }
  }
  EXPECT_LT(worst, 1e-12 * Diagonal(welded));
}
}

TEST(Degenerate, TriangleSoupIsMergedIntoOneSurface)
{
  // The filter merges points at identical positions, so a soup edits exactly like the welded
  // mesh. Without merging every triangle is its own component, which the region would swallow
  // whole: that is refused with a message.
  auto welded = BumpyPlane(30);
  auto soup = Soup(welded);
  ExpectSoupEditsAsWelded(welded, soup);

  auto unmerged = Lifted(soup, Lift);
  unmerged->MergeCoincidentPointsOff();
  ErrorCatcher errors(unmerged);
  unmerged->Update();
  EXPECT_NE(errors.Messages.find("no fixed vertex and no anchor"), std::string::npos);
}

TEST(Degenerate, CopiesThatDifferByRoundingAreMergedToo)
{
  // The pieces of a parallel source, or charts computed one by one, repeat their seam points a
  // few ulps apart (ParaView's sphere pieces meet at sin(2 pi) = -2.4e-16 against 0). Exact
  // merging cut the edit at such a seam.
  auto welded = BumpyPlane(30);
  ExpectSoupEditsAsWelded(welded, Soup(welded, 1e-15));
}

TEST(Degenerate, NonManifoldEdgesAndVertices)
{
  // A fin of two triangles on an edge in the ROI (three triangles share that edge), and a
  // separate fan touching the plane at a single vertex (a bow tie). Both edit without error.
  auto input = BumpyPlane(30);
  vtkPoints* points = input->GetPoints();
  const vtkIdType a = 15 * 31 + 16, b = 15 * 31 + 17, touch = 12 * 31 + 12;
  const vtkIdType fin = points->InsertNextPoint(0.55, 0.5, 0.1);
  const vtkIdType finTop = points->InsertNextPoint(0.56, 0.52, 0.12);
  const vtkIdType fan1 = points->InsertNextPoint(0.4, 0.35, 0.1);
  const vtkIdType fan2 = points->InsertNextPoint(0.35, 0.4, 0.1);
  const vtkIdType fan3 = points->InsertNextPoint(0.3, 0.3, 0.15);
  const vtkIdType cells[][3] = { { a, b, fin }, { b, finTop, fin }, { touch, fan1, fan2 },
    { fan1, fan3, fan2 } };
  for (const auto& cell : cells)
  {
    input->GetPolys()->InsertNextCell(3, cell);
  }
  input->Modified();
  for (int mode : { Filter::ROTATION_NONE, Filter::ROTATION_EXPLICIT, Filter::ROTATION_IMPLICIT })
  {
    auto filter = Lifted(input, Lift);
    filter->SetRotationMode(mode);
    ExpectCleanEdit(input, filter, Lift);
  }
}

TEST(Degenerate, InconsistentlyOrientedFacesEditLikeOrientedOnes)
{
  // Every other triangle wound backwards: the filter reorients them internally, so explicit
  // rotations see the same smooth normals and the edit is the same.
  auto oriented = BumpyPlane(40);
  vtkNew<vtkPolyData> shuffled;
  shuffled->DeepCopy(oriented);
  vtkNew<vtkCellArray> flipped;
  auto cells = vtk::TakeSmartPointer(oriented->GetPolys()->NewIterator());
  for (cells->GoToFirstCell(); !cells->IsDoneWithTraversal(); cells->GoToNextCell())
  {
    vtkIdType size;
    const vtkIdType* ids;
    cells->GetCurrentCell(size, ids);
    const vtkIdType reversed[3] = { ids[0], ids[2], ids[1] };
    flipped->InsertNextCell(3, cells->GetCurrentCellId() % 2 ? reversed : ids);
  }
  shuffled->SetPolys(flipped);
  vtkNew<vtkTransform> bend;
  bend->Translate(0, 0, 0.2);
  bend->RotateY(-30.0);
  vtkSmartPointer<vtkPolyData> results[2];
  int k = 0;
  for (vtkPolyData* mesh : { static_cast<vtkPolyData*>(oriented), static_cast<vtkPolyData*>(shuffled) })
  {
    auto filter = PlaneEdit(mesh);
    filter->SetRotationModeToExplicit();
    filter->SetHandleTransform(bend);
    filter->Update();
    results[k++] = filter->GetOutput();
  }
  EXPECT_LT(MaxPointDistance(results[0], results[1]), 1e-12 * Diagonal(oriented));
}

TEST(Degenerate, HolesInTheRegion)
{
  // Remove the cells around a point inside the ROI: the edit goes around the hole.
  auto input = BumpyPlane(40);
  vtkNew<vtkCellArray> kept;
  auto cells = vtk::TakeSmartPointer(input->GetPolys()->NewIterator());
  for (cells->GoToFirstCell(); !cells->IsDoneWithTraversal(); cells->GoToNextCell())
  {
    vtkIdType size;
    const vtkIdType* ids;
    cells->GetCurrentCell(size, ids);
    double c[3] = { 0, 0, 0 };
    for (vtkIdType i = 0; i < size; ++i)
    {
      vtkMath::Add(c, input->GetPoint(ids[i]), c);
    }
    if (std::hypot(c[0] / 3 - 0.6, c[1] / 3 - 0.5) > 0.05)
    {
      kept->InsertNextCell(size, ids);
    }
  }
  input->SetPolys(kept);
  auto filter = Lifted(input, Lift);
  filter->SetRotationModeToExplicit();
  ExpectCleanEdit(input, filter, Lift);
}

TEST(Degenerate, OnlyTheHandlesComponentIsEdited)
{
  // Two planes side by side: the one without the handle stays bit-identical.
  auto first = BumpyPlane(30);
  vtkNew<vtkPolyData> both;
  both->DeepCopy(first);
  const vtkIdType offset = first->GetNumberOfPoints();
  for (vtkIdType i = 0; i < offset; ++i)
  {
    double p[3];
    first->GetPoint(i, p);
    p[0] += 1.5;
    both->GetPoints()->InsertNextPoint(p);
  }
  auto cells = vtk::TakeSmartPointer(first->GetPolys()->NewIterator());
  for (cells->GoToFirstCell(); !cells->IsDoneWithTraversal(); cells->GoToNextCell())
  {
    vtkIdType size;
    const vtkIdType* ids;
    cells->GetCurrentCell(size, ids);
    const vtkIdType shifted[3] = { ids[0] + offset, ids[1] + offset, ids[2] + offset };
    both->GetPolys()->InsertNextCell(3, shifted);
  }
  auto filter = Lifted(both, Lift);
  filter->SetROIRadius(1.0); // reaches across the gap in space, not along the surface
  filter->Update();
  ExpectSoundEdit(both, filter, Lift);
  for (vtkIdType i = offset; i < both->GetNumberOfPoints(); ++i)
  {
    double p[3], q[3];
    both->GetPoint(i, p);
    filter->GetOutput()->GetPoint(i, q);
    ASSERT_TRUE(p[0] == q[0] && p[1] == q[1] && p[2] == q[2]);
  }
}

TEST(Degenerate, FarAwayAndTinyCoordinatesKeepTheirPrecision)
{
  // The filter centres and scales internally: a plane offset by 1e6, and one scaled by 1e-6,
  // edit like the unit plane to 1e-9 of their size. (The radii avoid the grid's exact edge-path
  // distances, where the last bit of a coordinate would decide membership.)
  auto unit = BumpyPlane(30);
  auto reference = Lifted(unit, Lift);
  reference->SetHandleRadius(0.0613);
  reference->SetROIRadius(0.3471);
  reference->SetRotationModeToExplicit();
  reference->Update();
  for (auto [scale, offset] : { std::make_pair(1.0, 1e6), std::make_pair(1e-6, 0.0) })
  {
    vtkNew<vtkPolyData> moved;
    moved->DeepCopy(unit);
    for (vtkIdType i = 0; i < moved->GetNumberOfPoints(); ++i)
    {
      double p[3];
      unit->GetPoint(i, p);
      moved->GetPoints()->SetPoint(i, scale * p[0] + offset, scale * p[1] + offset, scale * p[2] + offset);
    }
    auto filter = PlaneEdit(moved);
    filter->SetHandleCenter(0.5 * scale + offset, 0.5 * scale + offset, offset);
    filter->SetHandleRadius(0.0613 * scale);
    filter->SetROIRadius(0.3471 * scale);
    filter->SetRotationModeToExplicit();
    filter->SetHandleTransform(Translation(scale * Lift[0], scale * Lift[1], scale * Lift[2]));
    filter->Update();
    double worst = 0.0;
    for (vtkIdType i = 0; i < unit->GetNumberOfPoints(); ++i)
    {
      double a[3], b[3];
      reference->GetOutput()->GetPoint(i, a);
      filter->GetOutput()->GetPoint(i, b);
      for (int c = 0; c < 3; ++c)
      {
        worst = std::max(worst, std::abs((b[c] - offset) / scale - a[c]));
      }
    }
    EXPECT_LT(worst, 1e-9 * Diagonal(unit)) << "scale " << scale << " offset " << offset;
  }
}

TEST(Degenerate, WholeComponentWithAnchorsIsWellPosed)
{
  // An ROI over the whole plane has no fixed vertex, but its outer anchors hold it.
  auto input = BumpyPlane(30);
  auto filter = Lifted(input, Lift);
  filter->SetROIRadius(10.0);
  ErrorCatcher errors(filter);
  filter->Update();
  EXPECT_EQ(errors.Messages, "");
  EXPECT_EQ(filter->GetNumberOfROIVertices(), input->GetNumberOfPoints());
}

TEST(Limits, AbortPassesTheInputThroughAndTheNextUpdateWorks)
{
  auto input = BumpyPlane(40);
  auto filter = Lifted(input, Lift);
  vtkNew<vtkCallbackCommand> abort;
  abort->SetCallback([](vtkObject* caller, unsigned long, void*, void*) {
    static_cast<vtkAlgorithm*>(caller)->AbortExecuteOn();
  });
  const unsigned long tag = filter->AddObserver(vtkCommand::ProgressEvent, abort);
  filter->Update();
  EXPECT_EQ(MaxPointDistance(input, filter->GetOutput()), 0.0);
  filter->RemoveObserver(tag);
  filter->AbortExecuteOff();
  filter->Modified();
  filter->Update();
  ExpectSoundEdit(input, filter, Lift);
}

TEST(Limits, AFactorLargerThanTheMemoryLimitIsRefused)
{
  if (!Filter::IsCholmodAvailable())
  {
    GTEST_SKIP() << "only CHOLMOD predicts the factor's size";
  }
  auto input = BumpyPlane(80);
  auto filter = Lifted(input, Lift);
  filter->Update();
  EXPECT_GT(filter->GetFactorMemory(), 0.0);
  const double needed = filter->GetFactorMemory();
  filter->SetMaximumFactorMemory(0.5 * needed);
  ErrorCatcher errors(filter);
  filter->Update();
  EXPECT_NE(errors.Messages.find("MB allowed"), std::string::npos) << errors.Messages;
  EXPECT_EQ(MaxPointDistance(input, filter->GetOutput()), 0.0);
}

TEST(Limits, TwoFiltersInTwoThreadsMatchSequentialRuns)
{
  // Separate filter instances share nothing: concurrent updates give the sequential results.
  auto first = BumpyPlane(50);
  auto second = BumpyPlane(60);
  auto configure = [](vtkPolyData* mesh, int mode) {
    auto filter = Lifted(mesh, Lift);
    filter->SetRotationMode(mode);
    return filter;
  };
  auto a = configure(first, Filter::ROTATION_EXPLICIT);
  auto b = configure(second, Filter::ROTATION_IMPLICIT);
  a->Update();
  b->Update();
  vtkNew<vtkPolyData> sequentialA, sequentialB;
  sequentialA->DeepCopy(a->GetOutput());
  sequentialB->DeepCopy(b->GetOutput());

  auto c = configure(first, Filter::ROTATION_EXPLICIT);
  auto d = configure(second, Filter::ROTATION_IMPLICIT);
  std::thread one([&] { c->Update(); });
  std::thread two([&] { d->Update(); });
  one.join();
  two.join();
  EXPECT_LT(MaxPointDistance(sequentialA, c->GetOutput()), 1e-12 * Diagonal(first));
  EXPECT_LT(MaxPointDistance(sequentialB, d->GetOutput()), 1e-12 * Diagonal(second));
}
