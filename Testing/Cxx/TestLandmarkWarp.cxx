// vtkLaplacianLandmarkWarp: landmarks at their sources give the input back, a rigid motion of
// every landmark moves the surface rigidly, an exact fit meets every target (checked by
// locating each landmark on the input and the output independently), components without
// landmarks stay, only new targets reuse the factor, a settle split by a time limit ends where
// the uncut one does, and bad landmarks are clear errors.
#include "FilterTestHelpers.h"
#include "ImageWarp.h"
#include "KnownWarps.h"

#include "vtkLaplacianLandmarkWarp.h"

#include "vtkAppendPolyData.h"
#include "vtkCellData.h"
#include "vtkCellLocator.h"
#include "vtkDoubleArray.h"
#include "vtkErrorCode.h"
#include "vtkFieldData.h"
#include "vtkGenericCell.h"
#include "vtkIdFilter.h"
#include "vtkMath.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkSphereSource.h"
#include "vtkThinPlateSplineTransform.h"
#include "vtkTransformPolyDataFilter.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <random>

using namespace FilterTestHelpers;

namespace
{
using KnownWarps::Moved;
using KnownWarps::SurfacePoints;

// Double-precision points: the exact fit is checked to 1e-9 of the diagonal, finer than float
// points (the meshes' own) can hold.
vtkSmartPointer<vtkPolyData> Load(const std::string& name)
{
  auto mesh = KnownWarps::LoadDouble(DataDir + "/" + name);
  EXPECT_TRUE(mesh && mesh->GetNumberOfPoints() > 0) << name;
  return mesh;
}

vtkSmartPointer<vtkLaplacianLandmarkWarp> Warp(vtkPolyData* mesh, vtkPoints* sources, vtkPoints* targets)
{
  auto warp = vtkSmartPointer<vtkLaplacianLandmarkWarp>::New();
  warp->SetInputData(mesh);
  warp->SetSourceLandmarks(sources);
  warp->SetTargetLandmarks(targets);
  return warp;
}

// The points bent about the z axis through the middle of the mesh's base, by `perUnit`
// radians per unit of height (y).
vtkSmartPointer<vtkPoints> Bent(vtkPolyData* mesh, vtkPoints* points, double perUnit)
{
  double bounds[6];
  mesh->GetBounds(bounds);
  const std::array<double, 3> center = { 0.5 * (bounds[0] + bounds[1]), bounds[2], 0.0 };
  return Moved(points, [center, perUnit](const double* p, double* q) {
    const double angle = perUnit * (p[1] - center[1]);
    const double x = p[0] - center[0], y = p[1] - center[1];
    q[0] = center[0] + std::cos(angle) * x - std::sin(angle) * y;
    q[1] = center[1] + std::sin(angle) * x + std::cos(angle) * y;
    q[2] = p[2];
  });
}

// Where each landmark ended, found independently: its nearest point on the input (cell and
// weights), evaluated on the output, plus its offset from the input surface.
double LargestMiss(vtkPolyData* input, vtkPolyData* output, vtkPoints* sources, vtkPoints* targets)
{
  vtkNew<vtkCellLocator> locator;
  locator->SetDataSet(input);
  locator->BuildLocator();
  vtkNew<vtkGenericCell> cell;
  double worst = 0.0;
  for (vtkIdType i = 0; i < sources->GetNumberOfPoints(); ++i)
  {
    double source[3], closest[3], squared, weights[3], pcoords[3], sub, target[3], end[3] = { 0, 0, 0 };
    vtkIdType id;
    int subId;
    sources->GetPoint(i, source);
    locator->FindClosestPoint(source, closest, cell, id, subId, squared);
    cell->EvaluatePosition(closest, nullptr, subId, pcoords, sub, weights);
    for (int c = 0; c < 3; ++c)
    {
      double p[3];
      output->GetPoint(cell->GetPointId(c), p);
      for (int k = 0; k < 3; ++k)
      {
        end[k] += weights[c] * p[k] + (c == 0 ? source[k] - closest[k] : 0.0);
      }
    }
    targets->GetPoint(i, target);
    worst = std::max(worst, std::sqrt(vtkMath::Distance2BetweenPoints(end, target)));
  }
  return worst;
}
}

TEST(LandmarkWarp, LandmarksAtTheirSourcesGiveTheInputBack)
{
  auto bunny = Load("stanford-bunny.obj");
  auto sources = SurfacePoints(bunny, 200);
  for (int mode = vtkLaplacianLandmarkWarp::ROTATION_NONE;
       mode <= vtkLaplacianLandmarkWarp::ROTATION_AS_RIGID_AS_POSSIBLE; ++mode)
  {
    SCOPED_TRACE(mode);
    auto warp = Warp(bunny, sources, sources);
    warp->SetRotationMode(mode);
    warp->Update();
    EXPECT_EQ(warp->GetErrorCode(), vtkErrorCode::NoError);
    EXPECT_LE(MaxPointDistance(warp->GetPolyDataOutput(), bunny), 1e-12 * Diagonal(bunny));
  }
}

TEST(LandmarkWarp, ARigidMotionOfEveryLandmarkMovesTheSurfaceRigidly)
{
  auto spot = Load("spot.obj");
  auto sources = SurfacePoints(spot, 60);
  vtkNew<vtkTransform> motion;
  motion->Translate(0.3, -0.1, 0.2);
  motion->RotateWXYZ(70.0, 1.0, 2.0, 0.5);
  auto map = [&](const double* p, double* q) { motion->TransformPoint(p, q); };
  auto warp = Warp(spot, sources, Moved(sources, map));
  warp->SetARAPIterations(2000);
  warp->SetConvergence(1e-12);
  warp->Update();
  double worst = 0.0;
  for (vtkIdType i = 0; i < spot->GetNumberOfPoints(); ++i)
  {
    double p[3], q[3];
    map(spot->GetPoint(i), p);
    warp->GetPolyDataOutput()->GetPoint(i, q);
    worst = std::max(worst, std::sqrt(vtkMath::Distance2BetweenPoints(p, q)));
  }
  std::cout << "rigid motion: largest distance " << worst / Diagonal(spot) << " of the diagonal after "
            << warp->GetNumberOfARAPIterations() << " iterations\n";
  EXPECT_LE(worst, 1e-6 * Diagonal(spot));
}

TEST(LandmarkWarp, AnExactFitMeetsEveryTarget)
{
  auto bunny = Load("stanford-bunny.obj");
  auto sources = SurfacePoints(bunny, 300);
  auto targets = Bent(bunny, sources, 4.0);
  for (int mode = vtkLaplacianLandmarkWarp::ROTATION_NONE;
       mode <= vtkLaplacianLandmarkWarp::ROTATION_AS_RIGID_AS_POSSIBLE; ++mode)
  {
    SCOPED_TRACE(mode);
    auto warp = Warp(bunny, sources, targets);
    warp->SetRotationMode(mode);
    warp->Update();
    const double miss = LargestMiss(bunny, warp->GetPolyDataOutput(), sources, targets);
    EXPECT_LE(miss, 1e-9 * Diagonal(bunny));
    EXPECT_LE(warp->GetMaximumLandmarkDistance(), 1e-9 * Diagonal(bunny));
    auto* distances = vtkDoubleArray::SafeDownCast(
      warp->GetPolyDataOutput()->GetFieldData()->GetArray("LandmarkDistance"));
    ASSERT_NE(distances, nullptr);
    EXPECT_EQ(distances->GetNumberOfTuples(), sources->GetNumberOfPoints());
    EXPECT_GT(MaxPointDistance(warp->GetPolyDataOutput(), bunny), 0.05 * Diagonal(bunny));
  }
}

TEST(LandmarkWarp, ASoftFitPullsAsItsWeightSays)
{
  auto bunny = Load("stanford-bunny.obj");
  auto sources = SurfacePoints(bunny, 100);
  auto targets = Bent(bunny, sources, 4.0);
  double misses[2];
  const double weights[2] = { 0.1, 10.0 };
  for (int k = 0; k < 2; ++k)
  {
    auto warp = Warp(bunny, sources, targets);
    warp->ExactFitOff();
    warp->SetLandmarkWeight(weights[k]);
    warp->Update();
    misses[k] = warp->GetRMSLandmarkDistance();
  }
  std::cout << "soft fit: RMS miss " << misses[0] / Diagonal(bunny) << " of the diagonal at weight 0.1, "
            << misses[1] / Diagonal(bunny) << " at 10\n";
  EXPECT_GT(misses[0], 3.0 * misses[1]);
  EXPECT_GT(misses[1], 0.0);
}

TEST(LandmarkWarp, ComponentsWithoutLandmarksStay)
{
  vtkNew<vtkSphereSource> left, right;
  left->SetCenter(-1.0, 0.0, 0.0);
  right->SetCenter(1.0, 0.0, 0.0);
  for (auto* sphere : { left.Get(), right.Get() })
  {
    sphere->SetThetaResolution(40);
    sphere->SetPhiResolution(20);
  }
  vtkNew<vtkAppendPolyData> both;
  both->AddInputConnection(left->GetOutputPort());
  both->AddInputConnection(right->GetOutputPort());
  both->Update();
  vtkPolyData* spheres = both->GetOutput();
  vtkNew<vtkPoints> sources, targets;
  sources->InsertNextPoint(-1.0, 0.0, 0.5);
  sources->InsertNextPoint(-1.0, 0.0, -0.5);
  targets->InsertNextPoint(-1.0, 0.0, 0.7);
  targets->InsertNextPoint(-1.0, 0.0, -0.5);
  auto warp = Warp(spheres, sources, targets);
  warp->Update();
  EXPECT_EQ(warp->GetNumberOfWarpedVertices(), left->GetOutput()->GetNumberOfPoints());
  const vtkIdType firstRight = left->GetOutput()->GetNumberOfPoints();
  int moved = 0;
  for (vtkIdType i = 0; i < spheres->GetNumberOfPoints(); ++i)
  {
    double p[3], q[3];
    spheres->GetPoint(i, p);
    warp->GetPolyDataOutput()->GetPoint(i, q);
    const bool same = p[0] == q[0] && p[1] == q[1] && p[2] == q[2];
    EXPECT_TRUE(i < firstRight || same) << "point " << i << " of the other sphere moved";
    moved += same ? 0 : 1;
  }
  EXPECT_GT(moved, 100);
}

TEST(LandmarkWarp, NewTargetsReuseTheFactorization)
{
  auto bunny = Load("stanford-bunny.obj");
  auto sources = SurfacePoints(bunny, 500);
  vtkNew<vtkPoints> targets;
  targets->DeepCopy(sources);
  auto warp = Warp(bunny, sources, targets);
  warp->Update();
  const int factorizations = warp->GetNumberOfFactorizations();
  warp->DraggingOn();
  for (int step = 1; step <= 5; ++step)
  {
    double p[3];
    sources->GetPoint(0, p);
    p[1] += 0.01 * step * Diagonal(bunny);
    targets->SetPoint(0, p);
    targets->Modified();
    warp->Update();
    EXPECT_LE(warp->GetNumberOfARAPIterations(), warp->GetDragARAPIterations());
    EXPECT_LE(warp->GetMaximumLandmarkDistance(), 1e-9 * Diagonal(bunny));
  }
  warp->DraggingOff();
  warp->Update();
  EXPECT_EQ(warp->GetNumberOfFactorizations(), factorizations);
  EXPECT_LE(LargestMiss(bunny, warp->GetPolyDataOutput(), sources, targets), 1e-9 * Diagonal(bunny));
}

TEST(LandmarkWarp, LandmarksFromAPointSetOnPortOne)
{
  auto bunny = Load("stanford-bunny.obj");
  auto sources = SurfacePoints(bunny, 150);
  auto targets = Bent(bunny, sources, 3.0);
  auto byPoints = Warp(bunny, sources, targets);
  byPoints->Update();

  vtkNew<vtkPolyData> landmarks;
  landmarks->SetPoints(sources);
  vtkNew<vtkDoubleArray> target;
  target->SetName("Target");
  target->DeepCopy(targets->GetData());
  target->SetName("Target");
  landmarks->GetPointData()->AddArray(target);
  vtkNew<vtkLaplacianLandmarkWarp> byPort;
  byPort->SetInputData(bunny);
  byPort->SetLandmarksData(landmarks);
  byPort->Update();
  EXPECT_EQ(byPort->GetErrorCode(), vtkErrorCode::NoError);
  EXPECT_EQ(MaxPointDistance(byPort->GetPolyDataOutput(), byPoints->GetPolyDataOutput()), 0.0);

  landmarks->GetPointData()->RemoveArray("Target");
  ErrorCatcher errors(byPort);
  byPort->Modified();
  byPort->Update();
  EXPECT_NE(errors.Messages.find("three components holding the targets"), std::string::npos);
  EXPECT_EQ(MaxPointDistance(byPort->GetPolyDataOutput(), bunny), 0.0);
}

TEST(LandmarkWarp, PointAndCellDataPassThrough)
{
  auto bunny = Load("stanford-bunny.obj");
  vtkNew<vtkIdFilter> ids;
  ids->SetInputData(bunny);
  ids->SetPointIdsArrayName("PointIds");
  ids->SetCellIdsArrayName("CellIds");
  ids->Update();
  auto* input = vtkPolyData::SafeDownCast(ids->GetOutput());
  auto sources = SurfacePoints(input, 50);
  auto warp = Warp(input, sources, Bent(input, sources, 2.0));
  warp->Update();
  vtkPolyData* output = warp->GetPolyDataOutput();
  ASSERT_NE(output->GetPointData()->GetArray("PointIds"), nullptr);
  ASSERT_NE(output->GetCellData()->GetArray("CellIds"), nullptr);
  EXPECT_EQ(output->GetNumberOfCells(), input->GetNumberOfCells());
  EXPECT_EQ(output->GetPointData()->GetArray("PointIds")->GetTuple1(123), 123.0);
}

TEST(LandmarkWarp, FarLandmarksWarnOrFail)
{
  // A sphere of radius 0.5: a landmark at radius r lies r - 0.5 from the surface.
  vtkNew<vtkSphereSource> source;
  source->SetThetaResolution(60);
  source->SetPhiResolution(30);
  source->Update();
  vtkPolyData* sphere = source->GetOutput();
  const double diagonal = Diagonal(sphere);
  auto landmarksAt = [](double radius) {
    auto points = vtkSmartPointer<vtkPoints>::New();
    points->InsertNextPoint(0.0, 0.0, radius);
    points->InsertNextPoint(0.0, 0.0, -0.5);
    points->InsertNextPoint(0.5, 0.0, 0.0);
    return points;
  };
  {
    auto sources = landmarksAt(0.5 + 0.03 * diagonal); // bound, with a warning
    auto warp = Warp(sphere, sources, sources);
    ErrorCatcher warnings(warp, vtkCommand::WarningEvent);
    warp->Update();
    EXPECT_NE(warnings.Messages.find("farther from the surface than BindingTolerance"), std::string::npos);
    EXPECT_EQ(warp->GetErrorCode(), vtkErrorCode::NoError);
    EXPECT_LE(MaxPointDistance(warp->GetPolyDataOutput(), sphere), 1e-12 * diagonal);
    // The same landmarks, a stricter limit: now on no component.
    ErrorCatcher errors(warp);
    warp->SetMaximumBindingDistance(0.02);
    warp->Update();
    EXPECT_NE(errors.Messages.find("Source landmark 0 lies on no component"), std::string::npos);
  }
  auto sources = landmarksAt(0.5 + 0.2 * diagonal); // on no component
  auto warp = Warp(sphere, sources, sources);
  ErrorCatcher errors(warp);
  warp->Update();
  EXPECT_NE(errors.Messages.find("Source landmark 0 lies on no component"), std::string::npos);
  EXPECT_EQ(warp->GetErrorCode(), vtkErrorCode::UserError);
  EXPECT_EQ(MaxPointDistance(warp->GetPolyDataOutput(), sphere), 0.0);
}

TEST(LandmarkWarp, BadLandmarksAreClearErrors)
{
  auto bunny = Load("stanford-bunny.obj");
  auto sources = SurfacePoints(bunny, 10);
  vtkNew<vtkPoints> fewer, nan;
  fewer->DeepCopy(sources);
  fewer->SetNumberOfPoints(9);
  nan->DeepCopy(sources);
  nan->SetPoint(4, std::nan(""), 0.0, 0.0);
  const struct
  {
    vtkPoints* Sources;
    vtkPoints* Targets;
    const char* Message;
  } cases[] = { { sources, fewer, "There are 10 source landmarks and 9 targets" },
    { nan, sources, "Source landmark 4 has a NaN or infinite coordinate." },
    { sources, nan, "Target landmark 4 has a NaN or infinite coordinate." },
    { nullptr, nullptr, "No landmarks" } };
  for (const auto& bad : cases)
  {
    SCOPED_TRACE(bad.Message);
    auto warp = Warp(bunny, bad.Sources, bad.Targets);
    ErrorCatcher errors(warp);
    warp->Update();
    EXPECT_NE(errors.Messages.find(bad.Message), std::string::npos) << errors.Messages;
    EXPECT_EQ(warp->GetErrorCode(), vtkErrorCode::UserError);
    EXPECT_EQ(MaxPointDistance(warp->GetPolyDataOutput(), bunny), 0.0); // the input, passed through
  }
  // A surface without polygons.
  vtkNew<vtkPolyData> empty;
  auto warp = Warp(empty, sources, sources);
  ErrorCatcher errors(warp);
  warp->Update();
  EXPECT_NE(errors.Messages.find("The input mesh is empty."), std::string::npos);
}

TEST(LandmarkWarp, APieceOfADistributedSurfaceIsRefused)
{
  auto bunny = Load("stanford-bunny.obj");
  auto sources = SurfacePoints(bunny, 10);
  auto warp = Warp(bunny, sources, Moved(sources, [](const double* p, double* q) {
    q[0] = p[0] + 0.01;
    q[1] = p[1];
    q[2] = p[2];
  }));
  ErrorCatcher errors(warp);
  warp->UpdatePiece(0, 2, 0);
  EXPECT_NE(errors.Messages.find("needs the whole surface and was asked for one of 2 pieces"),
    std::string::npos);
  EXPECT_EQ(warp->GetErrorCode(), vtkErrorCode::UserError);
  EXPECT_EQ(MaxPointDistance(warp->GetPolyDataOutput(), bunny), 0.0);
}

TEST(LandmarkWarp, LandmarksATriangleCannotAllMeetWarnAndFitInLeastSquares)
{
  // Four landmarks in one triangle: three fix its affine motion, the fourth asks another.
  auto bunny = Load("stanford-bunny.obj");
  vtkNew<vtkIdList> corners;
  bunny->GetCellPoints(1000, corners);
  double p[3][3];
  for (int c = 0; c < 3; ++c)
  {
    bunny->GetPoint(corners->GetId(c), p[c]);
  }
  const double weights[4][3] = { { 0.6, 0.2, 0.2 }, { 0.2, 0.6, 0.2 }, { 0.2, 0.2, 0.6 },
    { 1.0 / 3, 1.0 / 3, 1.0 / 3 } };
  vtkNew<vtkPoints> sources, targets;
  sources->SetDataTypeToDouble();
  for (const auto& w : weights)
  {
    double x[3];
    for (int k = 0; k < 3; ++k)
    {
      x[k] = w[0] * p[0][k] + w[1] * p[1][k] + w[2] * p[2][k];
    }
    sources->InsertNextPoint(x);
  }
  targets->DeepCopy(sources);
  double lifted[3];
  sources->GetPoint(3, lifted);
  lifted[1] += 0.01 * Diagonal(bunny);
  targets->SetPoint(3, lifted);
  auto warp = Warp(bunny, sources, targets);
  ErrorCatcher warnings(warp, vtkCommand::WarningEvent);
  warp->Update();
  EXPECT_NE(warnings.Messages.find("The landmarks cannot all be met"), std::string::npos);
  EXPECT_EQ(warp->GetErrorCode(), vtkErrorCode::NoError);
  // Least squares: the lift is shared, each landmark short of its target, none of it lost.
  const double miss = warp->GetMaximumLandmarkDistance();
  EXPECT_GT(miss, 1e-3 * Diagonal(bunny));
  EXPECT_LT(miss, 0.01 * Diagonal(bunny));
}

TEST(LandmarkWarp, PointsNoPolygonUsesFollowTheSurface)
{
  // The bunny's 1,113 unused points move as the surface point nearest them does: a translation
  // of every landmark moves them by it too.
  auto bunny = Load("stanford-bunny.obj");
  std::vector<char> used(bunny->GetNumberOfPoints(), 0);
  vtkIdType count;
  const vtkIdType* ids;
  for (bunny->GetPolys()->InitTraversal(); bunny->GetPolys()->GetNextCell(count, ids);)
  {
    std::for_each(ids, ids + count, [&](vtkIdType id) { used[id] = 1; });
  }
  const auto unused = std::count(used.begin(), used.end(), 0);
  ASSERT_GT(unused, 1000);
  const double shift[3] = { 0.01, 0.02, -0.015 };
  auto sources = SurfacePoints(bunny, 100);
  auto map = [&](const double* p, double* q) {
    for (int k = 0; k < 3; ++k)
    {
      q[k] = p[k] + shift[k];
    }
  };
  auto warp = Warp(bunny, sources, Moved(sources, map));
  warp->Update();
  double worst = 0.0;
  for (vtkIdType i = 0; i < bunny->GetNumberOfPoints(); ++i)
  {
    if (!used[i])
    {
      double p[3], q[3];
      map(bunny->GetPoint(i), p);
      warp->GetPolyDataOutput()->GetPoint(i, q);
      worst = std::max(worst, std::sqrt(vtkMath::Distance2BetweenPoints(p, q)));
    }
  }
  std::cout << unused << " unused points, the farthest " << worst / Diagonal(bunny)
            << " of the diagonal from the translated position\n";
  EXPECT_LE(worst, 1e-6 * Diagonal(bunny));
}

TEST(LandmarkWarp, ALabelImageWarpsAsItsSurface)
{
  // The inside of spot as a label image, warped through the warp's displacement grid, against
  // the warped surface voxelized the same way.
  const KnownWarps::Warp warp = KnownWarps::TurnedHead(DataDir);
  auto sources = SurfacePoints(warp.Mesh, 300);
  auto landmarks = Warp(warp.Mesh, sources, Moved(sources, warp.Map));
  landmarks->OutputDisplacementOn();
  landmarks->Update();
  vtkPolyData* warped = landmarks->GetPolyDataOutput();
  double bounds[6], edited[6];
  warp.Mesh->GetBounds(bounds);
  warped->GetBounds(edited);
  for (int a = 0; a < 3; ++a)
  {
    const double margin = 0.05 * warp.Mesh->GetLength();
    bounds[2 * a] = std::min(bounds[2 * a], edited[2 * a]) - margin;
    bounds[2 * a + 1] = std::max(bounds[2 * a + 1], edited[2 * a + 1]) + margin;
  }
  vtkSmartPointer<vtkImageData> rest = ImageWarp::Voxelize(warp.Mesh, bounds, 80);
  vtkSmartPointer<vtkImageData> image = ImageWarp::WarpLabels(rest, warped);
  vtkSmartPointer<vtkImageData> surface = ImageWarp::Voxelize(warped, bounds, 80);
  const double dice = ImageWarp::Dice(image, surface), before = ImageWarp::Dice(rest, surface);
  std::cout << "label image warped with the surface: Dice " << dice << " (unwarped " << before
            << ")\n";
  EXPECT_GE(dice, 0.95);
  EXPECT_LT(before, dice);
}

TEST(LandmarkWarp, ManyLandmarksThatCannotAllMeetStillConverge)
{
  // 10,000 landmarks on bumps.obj's 16,641 vertices: many triangles hold more than three, and
  // the bend asks each for a motion no affine triangle makes. The exact fit's corrections
  // stalled the iteration after one step (RMS error 9.2e-4 of the diagonal, against 6.5e-5
  // for least squares): such landmarks are fit in the least-squares sense, and ARAP iterates.
  const KnownWarps::Warp bend = KnownWarps::Bend(DataDir);
  vtkSmartPointer<vtkPoints> sources = SurfacePoints(bend.Mesh, 10000);
  auto warp = Warp(bend.Mesh, sources, Moved(sources, bend.Map));
  ErrorCatcher warnings(warp, vtkCommand::WarningEvent);
  warp->Update();
  EXPECT_NE(warnings.Messages.find("The landmarks cannot all be met"), std::string::npos);
  EXPECT_GT(warp->GetNumberOfARAPIterations(), 2);
  vtkSmartPointer<vtkPoints> truth = Moved(bend.Mesh->GetPoints(), bend.Map);
  vtkPoints* result = warp->GetPolyDataOutput()->GetPoints();
  double sum = 0.0;
  for (vtkIdType i = 0; i < truth->GetNumberOfPoints(); ++i)
  {
    sum += vtkMath::Distance2BetweenPoints(truth->GetPoint(i), result->GetPoint(i));
  }
  const double rms = std::sqrt(sum / truth->GetNumberOfPoints()) / Diagonal(bend.Mesh);
  EXPECT_LT(rms, 2e-4) << "the warp stopped short of the true shape";
  EXPECT_LT(warp->GetMaximumLandmarkDistance(), 1e-4 * Diagonal(bend.Mesh));
}

TEST(LandmarkWarp, SparseLandmarksBendTheSurfaceAsTheThinPlateSplineDoes)
{
  // 100 random landmarks on bumps.obj rolled up 90 degrees (LandmarkWarpBenchmark's bend, its
  // draw 4): without the spline prior the rigid energy bent the sheet its own way, 2.25 times as
  // far from the true shape as VTK's thin-plate spline; with it, the warp is as close as the
  // spline (measured 0.9985 times its RMS distance).
  const KnownWarps::Warp bend = KnownWarps::Bend(DataDir);
  vtkSmartPointer<vtkPoints> sources = SurfacePoints(bend.Mesh, 100, 3 + 4);
  vtkSmartPointer<vtkPoints> targets = Moved(sources, bend.Map);
  vtkSmartPointer<vtkPoints> truth = Moved(bend.Mesh->GetPoints(), bend.Map);
  auto rms = [&](vtkPoints* result) {
    double sum = 0.0;
    for (vtkIdType i = 0; i < truth->GetNumberOfPoints(); ++i)
    {
      sum += vtkMath::Distance2BetweenPoints(truth->GetPoint(i), result->GetPoint(i));
    }
    return std::sqrt(sum / truth->GetNumberOfPoints());
  };
  vtkNew<vtkThinPlateSplineTransform> spline;
  spline->SetSourceLandmarks(sources);
  spline->SetTargetLandmarks(targets);
  spline->SetBasisToR2LogR();
  vtkNew<vtkTransformPolyDataFilter> splined;
  splined->SetInputData(bend.Mesh);
  splined->SetTransform(spline);
  splined->Update();
  const double splineRMS = rms(splined->GetOutput()->GetPoints());
  double warpRMS[2];
  for (const double prior : { 0.0, 1.0 })
  {
    auto warp = Warp(bend.Mesh, sources, targets);
    warp->SetSplinePriorWeight(prior);
    warp->Update();
    warpRMS[prior > 0.0] = rms(warp->GetPolyDataOutput()->GetPoints());
  }
  std::cout << "RMS distance from the true shape over the spline's: " << warpRMS[0] / splineRMS
            << " without the prior, " << warpRMS[1] / splineRMS << " with\n";
  EXPECT_LE(warpRMS[1], 1.01 * splineRMS);
  EXPECT_GT(warpRMS[0], 1.5 * splineRMS);
}

TEST(LandmarkWarp, MovedTargetsTakeThePlaceOfTheGivenOnes)
{
  // ParaView's landmark dragger: a moved target is the given one's replacement, a drag of it
  // reuses the factorization, and the warp is the one the edited targets give.
  auto bunny = Load("stanford-bunny.obj");
  auto sources = SurfacePoints(bunny, 100);
  vtkNew<vtkPoints> targets;
  targets->DeepCopy(sources);
  auto warp = Warp(bunny, sources, targets);
  warp->Update();
  const int factorizations = warp->GetNumberOfFactorizations();
  double moved[3];
  sources->GetPoint(7, moved);
  warp->DraggingOn();
  for (int step = 1; step <= 3; ++step)
  {
    moved[1] += 0.01 * Diagonal(bunny);
    warp->SetMovedTarget(7, moved[0], moved[1], moved[2]);
    warp->Update();
  }
  warp->DraggingOff();
  warp->Update();
  EXPECT_EQ(warp->GetNumberOfMovedTargets(), 1);
  EXPECT_EQ(warp->GetNumberOfFactorizations(), factorizations);
  double reported[3];
  warp->GetWarpedTargets()->GetTuple(7, reported);
  EXPECT_EQ(std::vector<double>(reported, reported + 3), std::vector<double>(moved, moved + 3));
  vtkNew<vtkPoints> edited;
  edited->DeepCopy(targets);
  edited->SetPoint(7, moved);
  EXPECT_LE(LargestMiss(bunny, warp->GetPolyDataOutput(), sources, edited), 1e-8 * Diagonal(bunny));
  // A fresh warp of the edited targets converges from the rest, the dragged one from its drag:
  // the same shape to within ARAP's convergence (measured 2.3e-4 of the diagonal).
  auto fresh = Warp(bunny, sources, edited);
  fresh->Update();
  EXPECT_LE(MaxPointDistance(warp->GetPolyDataOutput(), fresh->GetPolyDataOutput()), 1e-3 * Diagonal(bunny));
  // Forgotten, the given targets are back; a landmark past the last warns.
  warp->RemoveAllMovedTargets();
  warp->SetMovedTarget(100, 0.0, 0.0, 0.0);
  ErrorCatcher warnings(warp, vtkCommand::WarningEvent);
  warp->Update();
  EXPECT_NE(warnings.Messages.find("names landmark 100, and there are 100"), std::string::npos);
  EXPECT_LE(MaxPointDistance(warp->GetPolyDataOutput(), bunny), 1e-6 * Diagonal(bunny));
}

TEST(LandmarkWarp, ASettleSplitByATimeLimitEndsOnTheUncutSettlesShape)
{
  // ParaView's landmark dragger limits each update's settle as its handle widget does: the
  // bunny bent by 300 landmarks, warped once in one update and once with a SettleTimeLimit
  // that every step reaches, continued update by update while GetSettling(). Required: one
  // step an update, as many as the uncut warp's; each update's output meets every landmark
  // (1e-9 of the diagonal: an exact fit is a constraint of every step); the last output the
  // uncut warp's (1e-12 of the diagonal: the same iterates).
  auto bunny = Load("stanford-bunny.obj");
  auto sources = SurfacePoints(bunny, 300);
  auto targets = Bent(bunny, sources, 4.0);
  auto uncut = Warp(bunny, sources, targets);
  uncut->Update();
  EXPECT_FALSE(uncut->GetSettling());
  const int steps = uncut->GetNumberOfARAPIterations();
  ASSERT_GT(steps, 2);

  auto cut = Warp(bunny, sources, targets);
  cut->SetSettleTimeLimit(1e-9);
  int updates = 0;
  do
  {
    cut->ContinueSettling();
    cut->Update();
    ++updates;
    ASSERT_EQ(cut->GetErrorCode(), vtkErrorCode::NoError);
    ASSERT_EQ(cut->GetNumberOfARAPIterations(), 1) << "update " << updates;
    ASSERT_LE(LargestMiss(bunny, cut->GetPolyDataOutput(), sources, targets), 1e-9 * Diagonal(bunny))
      << "update " << updates;
  } while (cut->GetSettling() && updates <= steps);
  EXPECT_EQ(updates, steps);
  EXPECT_EQ(cut->GetNumberOfFactorizations(), uncut->GetNumberOfFactorizations());
  const double apart =
    MaxPointDistance(uncut->GetPolyDataOutput(), cut->GetPolyDataOutput()) / Diagonal(bunny);
  std::printf("a warp's settle cut into %d updates: %.2e of the diagonal from the uncut one\n",
    updates, apart);
  EXPECT_LT(apart, 1e-12);
}
