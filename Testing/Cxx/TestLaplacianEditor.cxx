// The editor decides what to recompute: these rules are tested here, without VTK.
#include "NumericsTestMeshes.h"

#include "LaplacianEditor.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <memory>

using namespace LaplacianEditing;
using namespace LaplacianEditing::Testing;

namespace
{
struct EditorCase : ::testing::Test
{
  std::shared_ptr<const SurfaceMesh> Mesh = std::make_shared<SurfaceMesh>(MakeGrid(24, 24));
  LaplacianEditor Editor;
  DeformationOptions System;
  RotationOptions Rotation;
  int LabelCalls = 0;

  // Labels: a central disc is the ROI, its middle the handle.
  std::vector<int> Labels()
  {
    ++this->LabelCalls;
    std::vector<int> labels(this->Mesh->GetNumberOfVertices(), 0);
    for (int v = 0; v < this->Mesh->GetNumberOfVertices(); ++v)
    {
      const double r = (this->Mesh->GetPositions()[v] - Vector3(0.5, 0.5, 0.0)).norm();
      labels[v] = r < 0.1 ? 2 : r < 0.35 ? 1 : 0;
    }
    return labels;
  }

  RegionRequest Geodesic(const Vector3& center) const
  {
    RegionRequest request;
    request.CenterVertex = this->Mesh->FindNearestVertex(center);
    request.HandleRadius = 0.1;
    request.ROIRadius = 0.35;
    return request;
  }

  unsigned Update(const RegionRequest& region)
  {
    EditStatus status = this->Editor.UpdateRegion(
      region, [this] { return this->Labels(); }, this->System);
    EXPECT_TRUE(status.Ok()) << status.Error;
    const EditStatus rotation = this->Editor.UpdateRotationModel(this->Rotation);
    EXPECT_TRUE(rotation.Ok()) << rotation.Error;
    return status.Work | rotation.Work;
  }

  void SetUp() override { this->Editor.SetMesh(this->Mesh); }
};
}

TEST_F(EditorCase, AHandleMoveNeverRefactors)
{
  EXPECT_EQ(this->Update(this->Geodesic(Vector3(0.5, 0.5, 0.0))), RebuiltRegion | RebuiltSystem);
  ASSERT_EQ(this->Editor.GetNumberOfFactorizations(), 1);
  Positions result;
  for (double t : { 0.05, 0.1, 0.2 })
  {
    EXPECT_EQ(this->Update(this->Geodesic(Vector3(0.5, 0.5, 0.0))), RebuiltNothing);
    ASSERT_TRUE(this->Editor.Solve({ Translation(Vector3(0, 0, t)) }, result).Ok());
  }
  EXPECT_EQ(this->Editor.GetNumberOfFactorizations(), 1);
}

TEST_F(EditorCase, MovingTheCenterWithinOneVertexNeverRefactors)
{
  this->Update(this->Geodesic(Vector3(0.5, 0.5, 0.0)));
  EXPECT_EQ(this->Update(this->Geodesic(Vector3(0.501, 0.499, 0.0))), RebuiltNothing);
  EXPECT_EQ(this->Update(this->Geodesic(Vector3(0.6, 0.5, 0.0))), RebuiltRegion | RebuiltSystem);
  EXPECT_EQ(this->Editor.GetNumberOfFactorizations(), 2);
}

TEST_F(EditorCase, MovingTheCenterInArrayModeNeverRefactors)
{
  RegionRequest labeled;
  labeled.Selection = RegionRequest::Kind::Labeled;
  labeled.LabelsVersion = 7;
  EXPECT_EQ(this->Update(labeled), RebuiltRegion | RebuiltSystem);
  labeled.CenterVertex = 3; // the handle centre plays no part in a labeled selection
  labeled.HandleRadius = 0.5;
  EXPECT_EQ(this->Update(labeled), RebuiltNothing);
  EXPECT_EQ(this->LabelCalls, 1);
  labeled.LabelsVersion = 8;
  EXPECT_EQ(this->Update(labeled), RebuiltRegion | RebuiltSystem);
  EXPECT_EQ(this->LabelCalls, 2);
}

TEST_F(EditorCase, OnlyTheChangedPartIsRebuilt)
{
  const RegionRequest region = this->Geodesic(Vector3(0.5, 0.5, 0.0));
  this->Update(region);
  this->System.Weights = LaplacianWeights::Cotangent;
  EXPECT_EQ(this->Update(region), RebuiltSystem);
  this->Rotation.Mode = RotationMode::Explicit;
  EXPECT_EQ(this->Update(region), RebuiltRotationModel);
  this->Rotation.Iterations = 3; // a solve option, not a model
  EXPECT_EQ(this->Update(region), RebuiltNothing);
  this->Rotation.Mode = RotationMode::Implicit;
  EXPECT_EQ(this->Update(region), RebuiltRotationModel);
  EXPECT_EQ(this->Editor.GetNumberOfFactorizations(), 4); // the coupled system, the rigid step's
  this->Rotation.PreserveDetailScale = false;
  EXPECT_EQ(this->Update(region), RebuiltNothing);
  this->Rotation.PreserveDetailScale = true;
  EXPECT_EQ(this->Update(region), RebuiltNothing);
  this->Rotation.Mode = RotationMode::Explicit;
  EXPECT_EQ(this->Update(region), RebuiltNothing);
  this->System.MaximumFactorBytes = 1e12; // a new limit is tried anew, with the models on it
  EXPECT_EQ(this->Update(region), RebuiltSystem | RebuiltRotationModel);
}

TEST_F(EditorCase, AFailedRequestIsRememberedUntilItChanges)
{
  RegionRequest labeled;
  labeled.Selection = RegionRequest::Kind::Labeled;
  labeled.LabelsVersion = 1;
  auto noHandle = [this] {
    ++this->LabelCalls;
    std::vector<int> labels = this->Labels();
    std::replace(labels.begin(), labels.end(), 2, 1);
    return labels;
  };
  EXPECT_FALSE(this->Editor.UpdateRegion(labeled, noHandle, this->System).Ok());
  const EditStatus again = this->Editor.UpdateRegion(labeled, noHandle, this->System);
  EXPECT_FALSE(again.Ok());
  EXPECT_NE(again.Error.find("handle"), std::string::npos) << again.Error;
  EXPECT_EQ(this->LabelCalls, 2); // one selection, not two
  Positions result;
  EXPECT_FALSE(this->Editor.Solve({}, result).Ok());
  labeled.LabelsVersion = 2;
  EXPECT_EQ(this->Update(labeled), RebuiltRegion | RebuiltSystem);
}

TEST_F(EditorCase, AffineRowsReproduceTheSolveWhereItIsAffine)
{
  // A process that holds some of the region's points places them from their affine rows and
  // the maps' entries alone. Two handle groups with general maps: the rows must agree with the
  // solve to 1e-12 relative in the None mode and the linear implicit one; no other mode is
  // affine.
  RegionRequest labeled;
  labeled.Selection = RegionRequest::Kind::Labeled;
  labeled.LabelsVersion = 1;
  auto twoGroups = [this] {
    std::vector<int> labels = this->Labels();
    for (int v = 0; v < this->Mesh->GetNumberOfVertices(); ++v)
    {
      labels[v] = (this->Mesh->GetPositions()[v] - Vector3(0.7, 0.5, 0.0)).norm() < 0.06 ? 3 : labels[v];
    }
    return labels;
  };
  ASSERT_TRUE(this->Editor.UpdateRegion(labeled, twoGroups, this->System).Ok());
  ASSERT_EQ(this->Editor.GetRegion().NumberOfHandleGroups, 2);
  AffineMap first, second;
  first << 0.9, -0.3, 0.1, 0.2, 0.35, 0.95, 0.05, -0.1, -0.1, 0.02, 1.1, 0.3;
  second << 1.0, 0.2, 0.0, -0.05, -0.2, 1.0, 0.1, 0.0, 0.0, -0.1, 0.9, 0.15;
  const std::vector<AffineMap> maps = { first, second };
  std::vector<int> rows; // every third row, backwards
  for (int k = this->Editor.GetRegion().GetNumberOfVertices() - 1; k >= 0; k -= 3)
  {
    rows.push_back(k);
  }
  auto check = [&](RotationMode mode, bool preserveDetailScale, bool affine) {
    this->Rotation.Mode = mode;
    this->Rotation.PreserveDetailScale = preserveDetailScale;
    ASSERT_TRUE(this->Editor.UpdateRotationModel(this->Rotation).Ok());
    ASSERT_EQ(this->Editor.IsAffineInHandleMaps(), affine);
    if (!affine)
    {
      return;
    }
    Positions solved;
    ASSERT_TRUE(this->Editor.Solve(maps, solved).Ok());
    const Positions placed =
      this->Editor.GetAffineRows(rows).Evaluate(HandleMapParameters(maps, 2));
    ASSERT_EQ(placed.rows(), static_cast<Eigen::Index>(rows.size()));
    double error = 0.0;
    for (std::size_t i = 0; i < rows.size(); ++i)
    {
      error = std::max(error, (placed.row(i) - solved.row(rows[i])).cwiseAbs().maxCoeff());
    }
    EXPECT_LT(error, 1e-12 * solved.cwiseAbs().maxCoeff());
  };
  check(RotationMode::None, true, true);
  check(RotationMode::Implicit, false, true);
  check(RotationMode::Implicit, true, false);
  check(RotationMode::Explicit, true, false);
}
