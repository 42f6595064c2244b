/**
 * @class   vtkLaplacianEditSolver
 * @brief   the filters' solver options as the core's requests, and the facts of each update
 *          (not wrapped)
 *
 * Holds the core's LaplacianEditor for one surface. Each update hands it the region request
 * and the options (weights, order, constraint weights, solver, rotation mode and its settings);
 * the editor rebuilds exactly what they change, and a handle move only solves. The stage keeps
 * what a filter reports: factorizations, setup and solve times, the factor's memory, the
 * as-rigid-as-possible iterations and energy, and a version that changes whenever the region,
 * the system or the rotation model is rebuilt.
 */
#ifndef vtkLaplacianEditSolver_h
#define vtkLaplacianEditSolver_h

#include "LaplacianEditor.h"

#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

class vtkObject;

/// The filters' properties that shape the system and the rotation model, with the filters'
/// enum values.
struct vtkLaplacianSolverOptions
{
  int LaplacianWeights = 0;
  int OperatorOrder = 1;
  double HandleWeight = 100.0;
  double AnchorWeight = 1.0;
  int Solver = 0;
  int Ordering = 0;
  /// Megabytes; 0: the automatic limit taken with the surface.
  double MaximumFactorMemory = 0.0;
  /// The processes a factor may be spread across; not owned.
  LaplacianEditing::DistributedSolver* Distributed = nullptr;
  int RotationMode = 0;
  /// In the core's units; 0: 0.2 of the region's radius.
  double NormalSmoothingRadius = 0.0;
  int NumberOfIterations = 1;
  bool PreserveDetailScale = true;
  int ImplicitFormulation = 0;
  /// As-rigid-as-possible: this update's iterations at most, and its convergence test.
  int ARAPIterations = 30;
  double Convergence = 1e-3;
  bool Acceleration = true;
  bool Extrapolation = true;
  /// Points pulled to targets (a landmark warp's), their version and their weight.
  std::shared_ptr<const std::vector<LaplacianEditing::SurfacePoint>> Points;
  std::uint64_t PointsVersion = 0;
  double PointWeight = 100.0;
  /// As-rigid-as-possible: the bending term's weight (0: none).
  double Bending = 0.0;
};

class vtkLaplacianEditSolver
{
public:
  using Options = vtkLaplacianSolverOptions;

  /// What the last update did.
  struct Facts
  {
    double SetupTime = 0.0;
    double AnalysisTime = 0.0;
    double FactorizationTime = 0.0;
    double SolveTime = 0.0;
    int NumberOfARAPIterations = 0;
    double ARAPEnergy = 0.0;
    /// The largest distance of a point from its target, in the core's units.
    double LargestPointMiss = 0.0;
  };

  vtkLaplacianEditSolver();

  /// The surface to edit; takes the automatic factor limit once per surface, so that it does
  /// not refactor each move.
  void SetMesh(std::shared_ptr<const LaplacianEditing::SurfaceMesh> mesh);

  /// Brings the region and its system up to date; `labels` is called only when the region
  /// must be reselected. Returns an error message, empty on success; `rebuilt` receives what
  /// was rebuilt (LaplacianEditing::Rebuilt flags).
  std::string UpdateRegion(const LaplacianEditing::RegionRequest& region,
    const std::function<std::vector<int>()>& labels, const Options& options, unsigned& rebuilt);

  /// Brings the rotation model up to date; warns through `reporter` about options it ignores.
  std::string UpdateRotationModel(const Options& options, vtkObject* reporter);

  /// Solves for the handle maps and the points' targets, if there are points (in the core's
  /// frame).
  std::string Solve(const std::vector<LaplacianEditing::AffineMap>& maps,
    const LaplacianEditing::PointTargets* points = nullptr);

  /// Starts an update's facts afresh.
  void ResetFacts() { this->LastFacts = Facts(); }
  Facts& GetFacts() { return this->LastFacts; }
  const Facts& GetFacts() const { return this->LastFacts; }

  const LaplacianEditing::LaplacianEditor& GetEditor() const { return this->Editor; }
  const LaplacianEditing::Positions& GetSolution() const { return this->Solution; }
  const std::vector<LaplacianEditing::AffineMap>& GetMaps() const { return this->Maps; }
  /// Changes whenever the region, the system or the rotation model is rebuilt.
  unsigned long GetModelVersion() const { return this->ModelVersion; }
  /// Megabytes of the factors held.
  double GetFactorMemory() const { return this->Editor.GetFactorBytes() / 1048576.0; }

private:
  LaplacianEditing::LaplacianEditor Editor;
  double AvailableMemory = 0.0; // megabytes
  std::vector<LaplacianEditing::AffineMap> Maps;
  LaplacianEditing::Positions Solution;
  unsigned long ModelVersion = 0;
  LaplacianEditing::RotationMode RotationMode = LaplacianEditing::RotationMode::None;
  Facts LastFacts;
};

#endif
