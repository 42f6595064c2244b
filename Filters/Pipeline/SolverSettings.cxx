#include "SolverSettings.h"

#include <vtksys/SystemInformation.hxx>

#include <algorithm>

namespace LaplacianEditing
{
namespace Pipeline
{
// The filters' enums are the core's, value for value (static_asserts in the filters).
DeformationOptions SolverSettings::System(double availableMemory) const
{
  DeformationOptions system;
  system.Weights = static_cast<LaplacianEditing::LaplacianWeights>(this->LaplacianWeights);
  system.Order = this->OperatorOrder;
  system.HandleWeight = this->HandleWeight;
  system.AnchorWeight = this->AnchorWeight;
  system.Backend = static_cast<SolverBackend>(this->Solver);
  system.Ordering = static_cast<FillOrdering>(this->Ordering);
  system.LeastSquares = this->RotationMode != static_cast<int>(LaplacianEditing::RotationMode::AsRigidAsPossible);
  system.MaximumFactorBytes =
    1048576.0 * (this->MaximumFactorMemory > 0.0 ? this->MaximumFactorMemory : availableMemory);
  system.Distributed = this->Distributed;
  system.Bending = this->Bending;
  system.SplinePrior = this->SplinePrior;
  // Other modes' rigid step fits rotations too, but plainly: the property does not refactor them.
  system.RotationSmoothing = system.LeastSquares ? 0.0 : this->RotationSmoothing;
  return system;
}

RotationOptions SolverSettings::Rotation(double regionRadius, double scale) const
{
  RotationOptions rotation;
  rotation.Mode = static_cast<LaplacianEditing::RotationMode>(this->RotationMode);
  rotation.NormalSmoothingRadius =
    this->NormalSmoothingRadius > 0.0 ? this->NormalSmoothingRadius * scale : 0.2 * regionRadius;
  rotation.Iterations = this->NumberOfIterations;
  rotation.PreserveDetailScale = this->PreserveDetailScale;
  const bool paper = this->ImplicitFormulation == 1;
  rotation.Formulation.PerEdge = !paper;
  rotation.Formulation.AllowScaling = paper;
  // A drag caps each update's iterations; the update after it settles the shape in full.
  rotation.Arap.MaximumIterations = this->Dragging
    ? std::min(this->DragARAPIterations, this->ARAPIterations)
    : this->ARAPIterations;
  rotation.Arap.Tolerance = this->Settle ? 0.0 : this->Convergence;
  rotation.Arap.Accelerate = this->Acceleration;
  rotation.Arap.Extrapolate = this->Extrapolation;
  rotation.Arap.Dragging = this->Dragging;
  rotation.Arap.Continue = this->Continue;
  rotation.LargeRegionVertices = this->LargeRegionVertices;
  rotation.ProxyNodes = this->ProxyNodes;
  return rotation;
}

double SolverSettings::AutomaticFactorLimit()
{
  // SystemInformation reads the memory figures only when asked to (RunMemoryCheck).
  vtksys::SystemInformation system;
  system.RunMemoryCheck();
  return 0.8 * static_cast<double>(system.GetAvailablePhysicalMemory());
}
}
}
