// The filters' properties that shape the system and the rotation model, in the filters' enum
// values and units, and their one translation into the core's requests. Every filter fills a
// SolverSettings from its properties; nothing else converts them, so that a property means the
// same in every filter that has it.
#ifndef LaplacianEditing_Pipeline_SolverSettings_h
#define LaplacianEditing_Pipeline_SolverSettings_h

#include "LaplacianEditor.h"
#include "vtkLaplacianEditingFiltersModule.h" // for export macro

namespace LaplacianEditing
{
class DistributedSolver;

namespace Pipeline
{
struct VTKLAPLACIANEDITINGFILTERS_EXPORT SolverSettings
{
  int LaplacianWeights = 0;
  int OperatorOrder = 1;
  double HandleWeight = 100.0;
  double AnchorWeight = 1.0;
  int Solver = 0;
  int Ordering = 0;
  /// Megabytes; 0: AutomaticFactorLimit().
  double MaximumFactorMemory = 0.0;
  /// The processes a factor may be spread across; not owned.
  DistributedSolver* Distributed = nullptr;
  int RotationMode = 0;
  /// Explicit mode: the smooth normals' support in mesh units; 0: 0.2 of the region's radius.
  double NormalSmoothingRadius = 0.0;
  int NumberOfIterations = 1;
  bool PreserveDetailScale = true;
  int ImplicitFormulation = 0;
  /// As-rigid-as-possible: iterations an update, its convergence test, and its accelerations.
  int ARAPIterations = 30;
  double Convergence = 1e-3;
  bool Acceleration = true;
  bool Extrapolation = true;
  /// As-rigid-as-possible: the bending term's weight (0: none).
  double Bending = 0.0;
  /// As-rigid-as-possible with points: the spline prior's weight (0: none).
  double SplinePrior = 0.0;
  /// As-rigid-as-possible: alpha of smoothed rotations (0: plain ARAP).
  double RotationSmoothing = 0.0;
  /// A drag is going on: each update runs at most DragARAPIterations.
  bool Dragging = false;
  int DragARAPIterations = 2;
  /// As-rigid-as-possible: regions of more vertices are dragged on a proxy of about
  /// ProxyNodes nodes and settled by multigrid (0: none).
  int LargeRegionVertices = 0;
  int ProxyNodes = 10000;
  /// The update that follows a drag: ARAPIterations in full, without the convergence test,
  /// which the slow tail a drag leaves would pass at once.
  bool Settle = false;
  /// As-rigid-as-possible: seconds at most of one update's iterations outside a drag (0: no
  /// limit); the iterations left continue in the next update (EditPipeline::IsSettling).
  double TimeLimit = 0.0;
  /// The update continues one that TimeLimit cut short (ArapOptions::Continue).
  bool Continue = false;

  /// The system's options, with a factor limit of `availableMemory` megabytes where
  /// MaximumFactorMemory is automatic.
  DeformationOptions System(double availableMemory) const;
  /// The rotation model's options for a region of radius `regionRadius`, on a surface of
  /// `scale` core units per mesh unit.
  RotationOptions Rotation(double regionRadius, double scale) const;

  /// The automatic factor limit, in megabytes: 80% of the physical memory available now.
  static double AutomaticFactorLimit();
};
}
}

#endif
