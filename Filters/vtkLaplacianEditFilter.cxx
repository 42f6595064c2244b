#include "vtkLaplacianEditFilter.h"

#include "EditPipeline.h"
#include "SparseCholesky.h"
#include "VolumeFollower.h"

#include "vtkPolyData.h"
#include "vtkUnstructuredGrid.h"

#include <initializer_list>

namespace le = LaplacianEditing;
namespace lep = LaplacianEditing::Pipeline;

// The filters' enums are the core's, value for value.
static_assert(static_cast<int>(le::LaplacianWeights::Uniform) ==
    vtkLaplacianEditFilter::WEIGHTS_UNIFORM &&
  static_cast<int>(le::LaplacianWeights::Cotangent) == vtkLaplacianEditFilter::WEIGHTS_COTANGENT);
static_assert(static_cast<int>(le::RotationMode::None) == vtkLaplacianEditFilter::ROTATION_NONE &&
  static_cast<int>(le::RotationMode::Explicit) == vtkLaplacianEditFilter::ROTATION_EXPLICIT &&
  static_cast<int>(le::RotationMode::Implicit) == vtkLaplacianEditFilter::ROTATION_IMPLICIT &&
  static_cast<int>(le::RotationMode::AsRigidAsPossible) ==
    vtkLaplacianEditFilter::ROTATION_AS_RIGID_AS_POSSIBLE);
static_assert(static_cast<int>(le::SolverBackend::Cholmod) == vtkLaplacianEditFilter::SOLVER_CHOLMOD &&
  static_cast<int>(le::SolverBackend::SimplicialLDLT) ==
    vtkLaplacianEditFilter::SOLVER_SIMPLICIAL_LDLT &&
  static_cast<int>(le::SolverBackend::Distributed) == vtkLaplacianEditFilter::SOLVER_MUMPS);
static_assert(static_cast<int>(le::FillOrdering::Automatic) ==
    vtkLaplacianEditFilter::ORDERING_AUTOMATIC &&
  static_cast<int>(le::FillOrdering::AMD) == vtkLaplacianEditFilter::ORDERING_AMD &&
  static_cast<int>(le::FillOrdering::METIS) == vtkLaplacianEditFilter::ORDERING_METIS &&
  static_cast<int>(le::FillOrdering::NestedDissection) ==
    vtkLaplacianEditFilter::ORDERING_NESTED_DISSECTION);

namespace
{
const char* EnumName(int value, std::initializer_list<const char*> names)
{
  return value >= 0 && value < static_cast<int>(names.size()) ? names.begin()[value] : "?";
}
}

vtkLaplacianEditFilter::vtkLaplacianEditFilter()
  : Pipeline(new lep::EditPipeline(this, [this](unsigned long code) { this->SetErrorCode(code); }))
  , Volume(new lep::VolumeFollower)
{
  this->Volume->SetFilter(this);
  if (!IsCholmodAvailable())
  {
    this->Solver = SOLVER_SIMPLICIAL_LDLT;
  }
}

vtkLaplacianEditFilter::~vtkLaplacianEditFilter() = default;

bool vtkLaplacianEditFilter::IsCholmodAvailable()
{
  return le::SparseCholesky::IsAvailable(le::SolverBackend::Cholmod);
}

void vtkLaplacianEditFilter::SetDragging(vtkTypeBool dragging)
{
  if (this->Dragging == dragging)
  {
    return;
  }
  this->Dragging = dragging;
  if (this->Pipeline->SetDragging(dragging != 0))
  {
    this->Modified(); // the next update settles the shape the drag left
  }
}

vtkTypeBool vtkLaplacianEditFilter::GetSettling()
{
  return this->Pipeline->IsSettling();
}

void vtkLaplacianEditFilter::ContinueSettling()
{
  if (this->Pipeline->IsSettling())
  {
    this->Modified();
  }
}

vtkPolyData* vtkLaplacianEditFilter::VolumeBoundary(vtkUnstructuredGrid* grid)
{
  const std::string error = this->Volume->Update(grid, grid->GetPoints());
  return this->Pipeline->Check(error) ? this->Volume->GetMesh().GetBoundary() : nullptr;
}

bool vtkLaplacianEditFilter::FollowBoundary(
  vtkPoints* edited, vtkUnstructuredGrid* output, double from, double to)
{
  const lep::OutputEdit edit = this->Pipeline->GetEdit();
  lep::VolumeFollower::Settings settings;
  // A boundary whose settle SettleTimeLimit cut is followed as a drag step follows it; the
  // interior settles in full once the boundary has (as in vtkLaplacianVolumeDeformationFilter).
  settings.Dragging = this->Dragging != 0 || this->Pipeline->IsSettling();
  settings.Backend = static_cast<le::SolverBackend>(this->Solver);
  if (!this->Pipeline->Check(this->Volume->FollowEdit(
        &edit, edited, settings, output, this->OutputDisplacement != 0, from, to)))
  {
    output->ShallowCopy(this->GetInputDataObject(0, 0));
    return false;
  }
  return true;
}

lep::EditPipeline& vtkLaplacianEditFilter::GetEditPipeline()
{
  return *this->Pipeline;
}

const lep::EditPipeline& vtkLaplacianEditFilter::GetEditPipeline() const
{
  return *this->Pipeline;
}

bool vtkLaplacianEditFilter::GetSolvedEdit(lep::OutputEdit& edit) const
{
  if (!this->Pipeline->HasSolved())
  {
    return false;
  }
  edit = this->Pipeline->GetEdit();
  return true;
}

lep::SolverSettings vtkLaplacianEditFilter::SharedSettings() const
{
  lep::SolverSettings settings;
  settings.LaplacianWeights = this->LaplacianWeights;
  settings.OperatorOrder = this->OperatorOrder;
  settings.Solver = this->Solver;
  settings.Ordering = this->Ordering;
  settings.MaximumFactorMemory = this->MaximumFactorMemory;
  settings.RotationMode = this->RotationMode;
  settings.NumberOfIterations = this->NumberOfIterations;
  settings.PreserveDetailScale = this->PreserveDetailScale != 0;
  settings.ImplicitFormulation = this->ImplicitFormulation;
  settings.ARAPIterations = this->ARAPIterations;
  settings.RotationSmoothing = this->RotationSmoothing;
  settings.Convergence = this->Convergence;
  settings.Acceleration = this->Acceleration != 0;
  settings.Extrapolation = this->Extrapolation != 0;
  settings.Dragging = this->Dragging != 0;
  settings.DragARAPIterations = this->DragARAPIterations;
  settings.TimeLimit = this->SettleTimeLimit;
  return settings;
}

double vtkLaplacianEditFilter::GetTopologyTime()
{
  return this->Pipeline->GetFacts().TopologyTime;
}

double vtkLaplacianEditFilter::GetSetupTime()
{
  return this->Pipeline->GetFacts().SetupTime;
}

double vtkLaplacianEditFilter::GetAnalysisTime()
{
  return this->Pipeline->GetFacts().AnalysisTime;
}

double vtkLaplacianEditFilter::GetFactorizationTime()
{
  return this->Pipeline->GetFacts().FactorizationTime;
}

double vtkLaplacianEditFilter::GetSolveTime()
{
  return this->Pipeline->GetFacts().SolveTime;
}

int vtkLaplacianEditFilter::GetNumberOfFactorizations()
{
  return this->Pipeline->GetEditor().GetNumberOfFactorizations();
}

int vtkLaplacianEditFilter::GetNumberOfFactorizationAttempts()
{
  return this->Pipeline->GetEditor().GetNumberOfFactorizationAttempts();
}

int vtkLaplacianEditFilter::GetNumberOfARAPIterations()
{
  return this->Pipeline->GetFacts().NumberOfARAPIterations;
}

double vtkLaplacianEditFilter::GetARAPEnergy()
{
  return this->Pipeline->GetFacts().ARAPEnergy;
}

double vtkLaplacianEditFilter::GetFactorMemory()
{
  return this->Pipeline->GetFactorMemory();
}

void vtkLaplacianEditFilter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "MergeCoincidentPoints: " << (this->MergeCoincidentPoints ? "On" : "Off") << "\n";
  os << indent << "LaplacianWeights: "
     << EnumName(this->LaplacianWeights, { "Uniform", "Cotangent" }) << "\n";
  os << indent << "OperatorOrder: " << this->OperatorOrder << "\n";
  os << indent << "RotationMode: "
     << EnumName(this->RotationMode, { "None", "Explicit", "Implicit", "AsRigidAsPossible" }) << "\n";
  os << indent << "NormalSmoothingRadius: " << this->NormalSmoothingRadius << "\n";
  os << indent << "NumberOfIterations: " << this->NumberOfIterations << "\n";
  os << indent << "ImplicitFormulation: "
     << EnumName(this->ImplicitFormulation, { "PerEdge", "Paper" }) << "\n";
  os << indent << "PreserveDetailScale: " << (this->PreserveDetailScale ? "On" : "Off") << "\n";
  os << indent << "ARAPIterations: " << this->ARAPIterations << "\n";
  os << indent << "RotationSmoothing: " << this->RotationSmoothing << "\n";
  os << indent << "Convergence: " << this->Convergence << "\n";
  os << indent << "Acceleration: " << (this->Acceleration ? "On" : "Off") << "\n";
  os << indent << "Extrapolation: " << (this->Extrapolation ? "On" : "Off") << "\n";
  os << indent << "Dragging: " << (this->Dragging ? "On" : "Off") << "\n";
  os << indent << "DragARAPIterations: " << this->DragARAPIterations << "\n";
  os << indent << "SettleTimeLimit: " << this->SettleTimeLimit << " s\n";
  os << indent << "Solver: " << EnumName(this->Solver, { "CHOLMOD", "SimplicialLDLT", "MUMPS" }) << "\n";
  os << indent << "Ordering: "
     << EnumName(this->Ordering, { "Automatic", "AMD", "METIS", "NestedDissection" }) << "\n";
  os << indent << "MaximumFactorMemory: " << this->MaximumFactorMemory << " MB";
  if (this->MaximumFactorMemory <= 0.0)
  {
    os << " (automatic: " << lep::SolverSettings::AutomaticFactorLimit() << " MB now)";
  }
  os << "\n";
  os << indent << "OutputDisplacement: " << (this->OutputDisplacement ? "On" : "Off") << "\n";
  os << indent << "Last update:\n";
  const vtkIndent next = indent.GetNextIndent();
  os << next << "TopologyTime: " << this->GetTopologyTime() << " s\n";
  os << next << "SetupTime: " << this->GetSetupTime() << " s (analysis "
     << this->GetAnalysisTime() << " s, factorization " << this->GetFactorizationTime() << " s)\n";
  os << next << "SolveTime: " << this->GetSolveTime() << " s\n";
  os << next << "NumberOfFactorizations: " << this->GetNumberOfFactorizations()
     << " (attempted " << this->GetNumberOfFactorizationAttempts() << ")\n";
  os << next << "FactorMemory: " << this->GetFactorMemory() << " MB\n";
  os << next << "NumberOfARAPIterations: " << this->GetNumberOfARAPIterations() << "\n";
  os << next << "ARAPEnergy: " << this->GetARAPEnergy() << "\n";
  os << next << "Settling: " << (this->Pipeline->IsSettling() ? "Yes" : "No") << "\n";
}
