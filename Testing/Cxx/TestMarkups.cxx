// 3D Slicer's landmark files: vtkLaplacianMarkupsReader and vtkLaplacianMarkupsWriter, and the
// landmark warp's landmarks paired by label. The files in Testing/Data are in Slicer's
// documented formats: the same three points as markups JSON in LPS and in RAS, as FCSV 4.11
// (LPS) and as a legacy FCSV (coordinate system 0, RAS).
#include "FilterTestHelpers.h"

#include "vtkLaplacianLandmarkWarp.h"
#include "vtkLaplacianMarkupsReader.h"
#include "vtkLaplacianMarkupsWriter.h"

#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkSphereSource.h"
#include "vtkStringArray.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <string>

namespace
{
using FilterTestHelpers::ErrorCatcher;

const std::string FilesDir = LAPLACIAN_EDITING_TEST_DATA_DIR;
const std::string TemporaryDir = LAPLACIAN_EDITING_TEMPORARY_DIR;

// The points of the files, in RAS.
const double Expected[3][3] = { { 12.5, -30.25, 4.0 }, { -20.0, 5.5, 18.75 }, { 45.0, 5.5, 18.75 } };

vtkSmartPointer<vtkPolyData> Read(const std::string& path)
{
  vtkNew<vtkLaplacianMarkupsReader> reader;
  reader->SetFileName(path.c_str());
  ErrorCatcher warnings(reader, vtkCommand::WarningEvent); // the LPS file's unplaced point
  reader->Update();
  auto points = vtkSmartPointer<vtkPolyData>::New();
  points->ShallowCopy(reader->GetOutput());
  return points;
}

std::string Label(vtkPolyData* points, vtkIdType i)
{
  return vtkStringArray::SafeDownCast(points->GetPointData()->GetAbstractArray("Label"))->GetValue(i);
}
}

class MarkupsFiles : public ::testing::TestWithParam<std::string>
{
};

TEST_P(MarkupsFiles, GiveTheSamePointsInRAS)
{
  vtkSmartPointer<vtkPolyData> points = Read(FilesDir + "/" + GetParam());
  ASSERT_EQ(points->GetNumberOfPoints(), 3);
  EXPECT_EQ(points->GetNumberOfVerts(), 3);
  for (vtkIdType i = 0; i < 3; ++i)
  {
    for (int k = 0; k < 3; ++k)
    {
      EXPECT_EQ(points->GetPoint(i)[k], Expected[i][k]) << "point " << i;
    }
  }
  EXPECT_EQ(Label(points, 0), "nose");
  EXPECT_EQ(Label(points, 1), "left ear");
}

INSTANTIATE_TEST_SUITE_P(Slicer, MarkupsFiles,
  ::testing::Values("landmarks-lps.mrk.json", "landmarks-ras.mrk.json", "landmarks.fcsv",
    "landmarks-legacy.fcsv"),
  [](const ::testing::TestParamInfo<std::string>& info) {
    std::string name = info.param.substr(0, info.param.find('.'));
    name += info.param.find("fcsv") != std::string::npos ? "_fcsv" : "_json";
    for (char& c : name)
    {
      c = c == '-' ? '_' : c;
    }
    return name;
  });

TEST(Markups, QuotedLabelsAndUnplacedPoints)
{
  EXPECT_EQ(Label(Read(FilesDir + "/landmarks-legacy.fcsv"), 2), "right ear, lower");
  // The LPS file's fourth control point has no position yet: left out, with a warning.
  vtkNew<vtkLaplacianMarkupsReader> reader;
  reader->SetFileName((FilesDir + "/landmarks-lps.mrk.json").c_str());
  ErrorCatcher warnings(reader, vtkCommand::WarningEvent);
  reader->Update();
  EXPECT_EQ(reader->GetOutput()->GetNumberOfPoints(), 3);
  EXPECT_NE(warnings.Messages.find("1 control points have no position"), std::string::npos)
    << warnings.Messages;
}

TEST(Markups, WriterRoundTripsInEitherFrame)
{
  vtkSmartPointer<vtkPolyData> points = Read(FilesDir + "/landmarks-lps.mrk.json");
  for (int system : { vtkLaplacianMarkupsWriter::LPS, vtkLaplacianMarkupsWriter::RAS })
  {
    const std::string path = TemporaryDir + "/round-trip-" + std::to_string(system) + ".mrk.json";
    vtkNew<vtkLaplacianMarkupsWriter> writer;
    writer->SetInputData(points);
    writer->SetFileName(path.c_str());
    writer->SetCoordinateSystem(system);
    ASSERT_EQ(writer->Write(), 1);
    vtkSmartPointer<vtkPolyData> back = Read(path);
    ASSERT_EQ(back->GetNumberOfPoints(), 3);
    for (vtkIdType i = 0; i < 3; ++i)
    {
      for (int k = 0; k < 3; ++k)
      {
        EXPECT_EQ(back->GetPoint(i)[k], Expected[i][k]) << "point " << i << ", system " << system;
      }
      EXPECT_EQ(Label(back, i), Label(points, i));
    }
    std::ifstream text(path);
    const std::string content((std::istreambuf_iterator<char>(text)), std::istreambuf_iterator<char>());
    EXPECT_NE(content.find(system == vtkLaplacianMarkupsWriter::LPS ? "\"LPS\"" : "\"RAS\""),
      std::string::npos);
  }
}

TEST(Markups, BadFilesAreClearErrors)
{
  const std::string broken = TemporaryDir + "/broken.mrk.json";
  std::ofstream(broken) << "{ \"markups\": [ { \"controlPoints\": [ ";
  const std::string other = TemporaryDir + "/other.json";
  std::ofstream(other) << "{ \"points\": [1, 2, 3] }";
  const std::pair<std::string, std::string> cases[] = { { TemporaryDir + "/none.mrk.json",
                                                           "Cannot open" },
    { broken, "not valid JSON" }, { other, "no \"markups\" array" } };
  for (const auto& [path, message] : cases)
  {
    vtkNew<vtkLaplacianMarkupsReader> reader;
    reader->SetFileName(path.c_str());
    ErrorCatcher errors(reader);
    reader->Update();
    EXPECT_NE(errors.Messages.find(message), std::string::npos) << errors.Messages;
    EXPECT_NE(reader->GetErrorCode(), 0);
    EXPECT_EQ(reader->GetOutput()->GetNumberOfPoints(), 0);
  }
}

namespace
{
// Landmarks on a sphere: sources at five of its points, targets moved out, labelled.
struct Pairs
{
  vtkSmartPointer<vtkPolyData> Sphere;
  vtkNew<vtkPolyData> Sources, Targets;
};

void Landmarks(Pairs& pairs, bool shuffleTargets)
{
  vtkNew<vtkSphereSource> sphere;
  sphere->SetThetaResolution(24);
  sphere->SetPhiResolution(16);
  sphere->Update();
  pairs.Sphere = sphere->GetOutput();
  vtkNew<vtkPoints> sources, targets;
  vtkNew<vtkStringArray> sourceLabels, targetLabels;
  sourceLabels->SetName("Label");
  targetLabels->SetName("Label");
  const vtkIdType ids[5] = { 0, 1, 50, 100, 200 };
  for (int k = 0; k < 5; ++k)
  {
    const int j = shuffleTargets ? 4 - k : k;
    double p[3];
    pairs.Sphere->GetPoint(ids[k], p);
    sources->InsertNextPoint(p);
    sourceLabels->InsertNextValue("L" + std::to_string(k));
    pairs.Sphere->GetPoint(ids[j], p);
    targets->InsertNextPoint(1.1 * p[0], 1.1 * p[1], 1.1 * p[2]);
    targetLabels->InsertNextValue("L" + std::to_string(j));
  }
  pairs.Sources->SetPoints(sources);
  pairs.Sources->GetPointData()->AddArray(sourceLabels);
  pairs.Targets->SetPoints(targets);
  pairs.Targets->GetPointData()->AddArray(targetLabels);
}
}

TEST(Markups, WarpPairsLandmarksByLabel)
{
  Pairs ordered, shuffled;
  Landmarks(ordered, false);
  Landmarks(shuffled, true);
  vtkNew<vtkLaplacianLandmarkWarp> byOrder, byLabel;
  byOrder->SetInputData(ordered.Sphere);
  byOrder->SetSourceLandmarks(ordered.Sources->GetPoints());
  byOrder->SetTargetLandmarks(ordered.Targets->GetPoints());
  byOrder->Update();
  byLabel->SetInputData(shuffled.Sphere);
  byLabel->SetLandmarksData(shuffled.Sources);
  byLabel->SetTargetLandmarksData(shuffled.Targets);
  byLabel->Update();
  ASSERT_EQ(byLabel->GetErrorCode(), 0);
  EXPECT_EQ(byLabel->GetNumberOfLandmarks(), 5);
  EXPECT_LT(byLabel->GetMaximumLandmarkDistance(), 1e-9);
  EXPECT_EQ(FilterTestHelpers::MaxPointDistance(
              byLabel->GetPolyDataOutput(), byOrder->GetPolyDataOutput()), 0.0);
}

TEST(Markups, MissingAndDuplicateLabelsAreErrors)
{
  for (const char* fault : { "missing", "duplicate" })
  {
    Pairs pairs;
    Landmarks(pairs, true);
    auto* labels = vtkStringArray::SafeDownCast(pairs.Targets->GetPointData()->GetAbstractArray("Label"));
    labels->SetValue(2, std::string(fault) == "missing" ? "elsewhere" : labels->GetValue(1));
    vtkNew<vtkLaplacianLandmarkWarp> warp;
    warp->SetInputData(pairs.Sphere);
    warp->SetLandmarksData(pairs.Sources);
    warp->SetTargetLandmarksData(pairs.Targets);
    ErrorCatcher errors(warp);
    warp->Update();
    const std::string expected =
      std::string(fault) == "missing" ? "2 landmark labels are on one side only" : "appears twice";
    EXPECT_NE(errors.Messages.find(expected), std::string::npos) << fault << ": " << errors.Messages;
    EXPECT_EQ(FilterTestHelpers::MaxPointDistance(warp->GetPolyDataOutput(), pairs.Sphere), 0.0);
  }
}
