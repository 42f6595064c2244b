// One surface being edited: the editor owns the region, its pre-factored Laplacian system and,
// built on first use, what the rotation mode needs. It alone decides what to recompute: each
// Update compares typed requests with what it holds and rebuilds exactly what changed, and it
// says what it rebuilt. A handle move is a Solve, which never refactors.
//
//  - None: reconstruct from the rest differential coordinates (Section 3).
//  - Explicit: take that reconstruction as the reference, estimate smooth normals on it
//    (Section 7), rotate each delta by its local frame's rotation (Section 4), solve again with
//    the same factor; each further iteration uses the previous result as the reference.
//  - Implicit: solve the coupled system of linearized transforms (Section 5; see
//    ImplicitSimilaritySystem.h), then, by default, one local-global step of the
//    as-rigid-as-possible energy from that result: the linearized rotations lengthen details
//    under large turns, and the step's true rotations take the growth out.
//  - AsRigidAsPossible: the local-global iteration of Sorkine and Alexa (2007) on its own square
//    system; it needs no least-squares system (DeformationOptions::LeastSquares off). Each solve
//    starts from the previous result of the same region, so a drag keeps converging.
#ifndef LaplacianEditing_LaplacianEditor_h
#define LaplacianEditing_LaplacianEditor_h

#include "AsRigidAsPossibleSolver.h"
#include "DeformationSystem.h"
#include "ImplicitSimilaritySystem.h"
#include "LocalFrames.h"
#include "ParallelFor.h"
#include "ProxyArapSolver.h"
#include "SmoothNormals.h"

#include <cstdint>
#include <functional>
#include <memory>

namespace LaplacianEditing
{
/// How the handle and the ROI are chosen. Two requests are equal when they select the same
/// region: only the fields of their kind count.
struct RegionRequest
{
  enum class Kind
  {
    Geodesic,  // discs around CenterVertex
    Labeled,   // per-vertex labels (0 fixed, 1 ROI, 2 + g handle group g)
    Components // the connected components holding Seeds, all free (a landmark warp's)
  };
  Kind Selection = Kind::Geodesic;
  int CenterVertex = -1;
  double HandleRadius = 0.0;
  double ROIRadius = 0.0;
  double AnchorPadding = 0.1;
  /// Labeled: changes whenever the labels may have changed.
  std::uint64_t LabelsVersion = 0;
  /// Labeled: vertices within it of the handles join the ROI (0: the labels alone).
  double GrowRadius = 0.0;
  /// Components: vertices whose components make the region.
  std::vector<int> Seeds;
  /// How distances are measured (region, anchors, normal smoothing).
  DistanceMethod Distances = DistanceMethod::FastMarching;

  bool operator==(const RegionRequest& other) const;
  bool operator!=(const RegionRequest& other) const { return !(*this == other); }
};

enum class RotationMode
{
  None,
  Explicit,
  Implicit,
  AsRigidAsPossible
};

struct RotationOptions
{
  RotationMode Mode = RotationMode::None;
  /// Support radius of the smooth normals (explicit mode), in mesh units.
  double NormalSmoothingRadius = 0.1;
  /// Explicit mode: reference-rotate-solve passes (1 is the paper's method).
  int Iterations = 1;
  /// Implicit mode: the rigid correction (one as-rigid-as-possible step after the solve).
  bool PreserveDetailScale = true;
  /// Implicit mode: which energy (see ImplicitSimilaritySystem.h).
  ImplicitFormulation Formulation;
  /// As-rigid-as-possible mode: the work per solve.
  ArapOptions Arap;
  /// As-rigid-as-possible mode: a region of more vertices than this (0: none) drags on a proxy
  /// of about ProxyNodes nodes and settles by multigrid (ProxyArapSolver), where a smaller one
  /// factors its system; regions held by points are always factored.
  int LargeRegionVertices = 0;
  int ProxyNodes = 10000;
};

/// What an Update rebuilt (bit flags).
enum Rebuilt : unsigned
{
  RebuiltNothing = 0,
  RebuiltRegion = 1,
  RebuiltSystem = 2,
  RebuiltRotationModel = 4
};

/// The outcome of an Update or a Solve. Ignoring it does not compile.
struct [[nodiscard]] EditStatus
{
  /// Empty on success.
  std::string Error;
  /// Rebuilt flags.
  unsigned Work = RebuiltNothing;

  bool Ok() const { return this->Error.empty(); }
};

class LaplacianEditor
{
public:
  /// The surface to edit; forgets everything built for the previous one.
  void SetMesh(std::shared_ptr<const SurfaceMesh> mesh);

  /// Brings the region and its factored system up to date with the requests. `labels` gives
  /// the per-vertex labels of a labeled selection; it is called only when the region must be
  /// reselected. A request that failed is remembered: the same request again fails at once,
  /// without refactoring.
  EditStatus UpdateRegion(const RegionRequest& region,
    const std::function<std::vector<int>()>& labels, const DeformationOptions& system);

  /// Builds what the rotation mode needs for the current region, unless it is there already
  /// (the implicit mode factors its coupled system). A failure is remembered as above.
  EditStatus UpdateRotationModel(const RotationOptions& rotation);

  /// The ROI positions for the handle maps (rows follow GetRegion().Vertices) and, where the
  /// system has points (DeformationOptions::Points), their targets, which are required then.
  /// Needs a successful Update with the same rotation options.
  EditStatus Solve(const std::vector<AffineMap>& handleMaps, Positions& roiPositions,
    const PointTargets* points = nullptr);

  /// The largest distance of a point from its target after the last solve (0 without points).
  double GetLargestPointMiss() const { return this->LargestPointMiss; }

  /// Whether Solve is affine in the handle maps (None, and Implicit without the rigid
  /// correction, without points), and then its affine form on some rows (indices into
  /// GetRegion().Vertices).
  bool IsAffineInHandleMaps() const;
  AffineRows GetAffineRows(const std::vector<int>& rows) const;

  /// As-rigid-as-possible mode: what the last solve did.
  const ArapResult& GetLastArapResult() const { return this->LastArap; }
  /// As-rigid-as-possible mode: the large region's solver, where the region is one (null
  /// otherwise).
  const ProxyArapSolver* GetProxySolver() const { return this->LargeArap.get(); }

  const EditRegion& GetRegion() const { return this->Region; }

  /// Numeric factorizations since construction.
  int GetNumberOfFactorizations() const { return this->NumberOfFactorizations; }
  /// Factorizations attempted, failed ones included.
  int GetNumberOfFactorizationAttempts() const { return this->NumberOfFactorizationAttempts; }
  /// Seconds of symbolic analysis and numeric factorization of the last factorization.
  double GetAnalysisSeconds() const { return this->AnalysisSeconds; }
  double GetFactorizationSeconds() const { return this->FactorizationSeconds; }
  /// Bytes of the factors held (as predicted by CHOLMOD's analysis; 0 if unknown).
  double GetFactorBytes() const;
  /// Whether a factor held is spread across processes (DistributedSolver).
  bool IsFactorDistributed() const;

  /// How per-move loops over the ROI run (serial by default).
  void SetParallelFor(ParallelFor loop) { this->Loop = std::move(loop); }

  /// As-rigid-as-possible mode: called after each iteration of a solve that is not a drag
  /// step (ArapOptions::Progress); returning false ends the solve at that iteration's shape.
  void SetProgress(std::function<bool(double)> progress) { this->Progress = std::move(progress); }

private:
  std::string SelectRegion(const RegionRequest& request,
    const std::function<std::vector<int>()>& labels);
  std::string BuildRotationModel(const RotationOptions& rotation, bool& built);
  std::string BuildArap();
  std::string BuildLargeArap(int proxyNodes);
  // Whether the region is edited as a large one in the as-rigid-as-possible mode.
  bool IsLarge(const RotationOptions& rotation) const;
  // The linear modes' solve (`solve` for some point targets), fitted to `points`.
  Positions FitPoints(
    const std::function<Positions(const Positions&)>& solve, const PointTargets* points);
  const PointConstraints& GetPoints() const;
  EditStatus Fail(bool rotationModel, RotationMode mode, std::string error);
  void Record(const SparseCholesky& factor);

  std::shared_ptr<const SurfaceMesh> Mesh;
  // What is built, and from which requests.
  bool Ready = false;
  bool HasRegionRequest = false;
  RegionRequest RegionBuiltFrom;
  bool HasSystemOptions = false;
  DeformationOptions SystemBuiltFrom;
  RegionRequest RegionRequested;
  DeformationOptions SystemRequested;
  RotationOptions RotationRequested;
  RotationOptions Rotation;
  EditRegion Region;
  DeformationSystem System;
  // Explicit mode, keyed on the smoothing radius.
  std::unique_ptr<SmoothNormals> Normals;
  std::unique_ptr<LocalFrames> Frames;
  // As-rigid-as-possible mode, and its last result (the next solve's start).
  std::unique_ptr<AsRigidAsPossibleSolver> Arap;
  ArapIterate ArapWarmStart;
  // As-rigid-as-possible mode on a large region, and the proxy size it was built with.
  std::unique_ptr<ProxyArapSolver> LargeArap;
  std::function<bool(double)> Progress;
  int LargeArapNodes = 0;
  ArapResult LastArap;
  // Whether the points proved impossible to meet all at once (fit in the least-squares sense).
  bool PointsUnmeetable = false;
  // Implicit mode's rigid correction: its buffers, kept between moves.
  ArapIterate Straightened;
  // The linear modes' exact fit: the point targets' correction, carried from solve to solve.
  Positions PointCorrection;
  double LargestPointMiss = 0.0;
  // Implicit mode, and the formulation it was built with.
  std::unique_ptr<ImplicitSimilaritySystem> Implicit;
  ImplicitFormulation ImplicitBuiltWith;
  // The last request that failed, and why; Mode is set when the rotation model failed.
  struct Failure
  {
    RegionRequest Region;
    DeformationOptions System;
    bool RotationModel = false;
    RotationMode Mode = RotationMode::None;
    ImplicitFormulation Formulation;
    bool PreserveDetailScale = false;
    std::string Error;
  };
  std::unique_ptr<Failure> LastFailure;
  ParallelFor Loop = SerialFor;
  int NumberOfFactorizations = 0;
  int NumberOfFactorizationAttempts = 0;
  double AnalysisSeconds = 0.0;
  double FactorizationSeconds = 0.0;
};
}

#endif
