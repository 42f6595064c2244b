// One region being edited: the pre-factored Laplacian system and, built on first use, what each
// way of keeping details oriented needs. Everything here depends only on the rest mesh and the
// region; a handle move calls Solve, which never refactors.
//
//  - None: reconstruct from the rest differential coordinates (Section 3).
//  - Explicit: take that reconstruction as the reference, estimate smooth normals on it
//    (Section 7), rotate each delta by its local frame's rotation (Section 4), solve again with
//    the same factor; each further iteration uses the previous result as the reference.
//  - Implicit: solve the coupled system of linearized similarities (Section 5). Optionally,
//    rescale each transformed delta to its rest length and solve the Laplacian system once more
//    (as Sorkine et al. 2004), which removes the linearization's growth of details under large
//    rotations.
#ifndef LaplacianEditing_LaplacianEditor_h
#define LaplacianEditing_LaplacianEditor_h

#include "DeformationSystem.h"
#include "ImplicitSimilaritySystem.h"
#include "LocalFrames.h"
#include "SmoothNormals.h"

#include <memory>

namespace LaplacianEditing
{
enum class RotationMode
{
  None,
  Explicit,
  Implicit
};

struct RotationOptions
{
  RotationMode Mode = RotationMode::None;
  /// Support radius of the smooth normals (explicit mode), in mesh units.
  double NormalSmoothingRadius = 0.1;
  /// Explicit mode: reference-rotate-solve passes (1 is the paper's method).
  int Iterations = 1;
  /// Implicit mode: the rescaling pass.
  bool PreserveDetailScale = false;
};

class LaplacianEditor
{
public:
  /// Assembles and factors the Laplacian system of a region; forgets any rotation data.
  std::string Build(std::shared_ptr<const SurfaceMesh> mesh, const EditRegion& region,
    const DeformationOptions& options);

  /// Builds (and, in implicit mode, factors) what the rotation mode needs, unless it is there
  /// already; `built` tells whether there was work. Returns an error message, empty on success.
  std::string Prepare(const RotationOptions& rotation, bool& built);

  /// The ROI positions for the handle maps (rows follow the region's vertices). Prepares the
  /// rotation mode first if needed. Returns an error message, empty on success.
  std::string Solve(const RotationOptions& rotation, const std::vector<AffineMap>& handleMaps,
    Positions& roiPositions);

  /// Numeric factorizations since construction.
  int GetNumberOfFactorizations() const { return this->NumberOfFactorizations; }
  /// Seconds of symbolic analysis and numeric factorization in the last Build or first
  /// implicit solve.
  double GetAnalysisSeconds() const { return this->AnalysisSeconds; }
  double GetFactorizationSeconds() const { return this->FactorizationSeconds; }
  /// Bytes of the factors held (as predicted by CHOLMOD's analysis; 0 if unknown).
  double GetFactorBytes() const;

  /// How per-move loops over the ROI run (serial by default).
  void SetParallelFor(ParallelFor loop) { this->Loop = std::move(loop); }

private:
  void Record(const SparseCholesky& factor);

  std::shared_ptr<const SurfaceMesh> Mesh;
  EditRegion Region;
  DeformationOptions Options;
  DeformationSystem System;
  // Explicit mode, keyed on the smoothing radius.
  std::unique_ptr<SmoothNormals> Normals;
  std::unique_ptr<LocalFrames> Frames;
  // Implicit mode.
  std::unique_ptr<ImplicitSimilaritySystem> Implicit;
  ParallelFor Loop = SerialFor;
  int NumberOfFactorizations = 0;
  double AnalysisSeconds = 0.0;
  double FactorizationSeconds = 0.0;
};
}

#endif
