#include "LaplacianEditor.h"

#include <algorithm>

namespace LaplacianEditing
{
double LaplacianEditor::GetFactorBytes() const
{
  return this->System.GetFactor().GetFactorBytes() +
    (this->Implicit ? this->Implicit->GetFactor().GetFactorBytes() : 0.0);
}

void LaplacianEditor::Record(const SparseCholesky& factor)
{
  ++this->NumberOfFactorizations;
  this->AnalysisSeconds = factor.GetAnalysisSeconds();
  this->FactorizationSeconds = factor.GetFactorizationSeconds();
}

std::string LaplacianEditor::Build(std::shared_ptr<const SurfaceMesh> mesh,
  const EditRegion& region, const DeformationOptions& options)
{
  this->Mesh = std::move(mesh);
  this->Region = region;
  this->Options = options;
  this->Normals.reset();
  this->Frames.reset();
  this->Implicit.reset();
  std::string error = this->System.Build(*this->Mesh, this->Region, options);
  if (error.empty())
  {
    this->Record(this->System.GetFactor());
  }
  return error;
}

std::string LaplacianEditor::Prepare(const RotationOptions& rotation, bool& built)
{
  built = false;
  if (rotation.Mode == RotationMode::Explicit &&
    (!this->Normals || this->Normals->GetRadius() != rotation.NormalSmoothingRadius))
  {
    this->Normals = std::make_unique<SmoothNormals>();
    this->Normals->Build(*this->Mesh, this->Region.Vertices, rotation.NormalSmoothingRadius);
    this->Frames = std::make_unique<LocalFrames>();
    this->Frames->Build(*this->Mesh, this->Region.Vertices,
      this->Normals->Compute(this->System.GetRestPositions()),
      this->System.GetRestDifferentialCoordinates());
    built = true;
  }
  else if (rotation.Mode == RotationMode::Implicit && !this->Implicit)
  {
    auto implicit = std::make_unique<ImplicitSimilaritySystem>();
    const std::string error =
      implicit->Build(*this->Mesh, this->Region, this->System, this->Options);
    if (!error.empty())
    {
      return error;
    }
    this->Record(implicit->GetFactor());
    this->Implicit = std::move(implicit);
    built = true;
  }
  return {};
}

std::string LaplacianEditor::Solve(
  const RotationOptions& rotation, const std::vector<AffineMap>& handleMaps, Positions& roiPositions)
{
  bool built;
  const std::string error = this->Prepare(rotation, built);
  if (!error.empty())
  {
    return error;
  }
  if (rotation.Mode == RotationMode::Implicit)
  {
    roiPositions = this->Implicit->Solve(handleMaps);
    if (rotation.PreserveDetailScale)
    {
      roiPositions = this->System.SolveWithDifferentialCoordinates(
        this->Implicit->RotatedDifferentialCoordinates(roiPositions), handleMaps);
    }
    return {};
  }
  roiPositions = this->System.Solve(handleMaps);
  if (rotation.Mode == RotationMode::Explicit)
  {
    for (int pass = 0; pass < std::max(rotation.Iterations, 1); ++pass)
    {
      const Positions rotated = this->Frames->Rotate(
        roiPositions, this->Normals->Compute(roiPositions, this->Loop), this->Loop);
      roiPositions = this->System.SolveWithDifferentialCoordinates(rotated, handleMaps);
    }
  }
  return {};
}
}
