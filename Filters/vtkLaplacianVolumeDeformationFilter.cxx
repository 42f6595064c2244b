#include "vtkLaplacianVolumeDeformationFilter.h"

#include "EditPipeline.h"
#include "RestShape.h"
#include "Stopwatch.h"
#include "VolumeFollower.h"

#include "vtkCallbackCommand.h"
#include "vtkDataSetAttributes.h"
#include "vtkErrorCode.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkLaplacianDeformationFilter.h"
#include "vtkObjectFactory.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSelection.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkSmartPointer.h"
#include "vtkUnstructuredGrid.h"

#include <algorithm>

namespace lep = LaplacianEditing::Pipeline;

vtkStandardNewMacro(vtkLaplacianVolumeDeformationFilter);

struct vtkLaplacianVolumeDeformationFilter::vtkInternals
{
  vtkSmartPointer<vtkLaplacianDeformationFilter> Surface;
  lep::RestShape Rest;
  lep::VolumeFollower Follower;
  vtkNew<vtkCallbackCommand> CommitObserver;
  vtkNew<vtkCallbackCommand> ProgressObserver; // the boundary's edit, during this filter's
  vtkMTimeType ArrayTime = 0; // of the array selection last handed to the surface filter
  bool Settling = false;       // the last update's settle stopped at SettleTimeLimit
};

vtkLaplacianVolumeDeformationFilter::vtkLaplacianVolumeDeformationFilter()
  : Internals(new vtkInternals)
{
  this->SetNumberOfInputPorts(2);
  this->SetInputArrayToProcess(
    0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, vtkDataSetAttributes::SCALARS);
  this->Internals->Follower.SetFilter(this);
  // Commits through the surface filter (a widget's) commit the volume too.
  vtkCallbackCommand* observer = this->Internals->CommitObserver;
  observer->SetClientData(this);
  observer->SetCallback([](vtkObject*, unsigned long event, void* self, void*) {
    auto* filter = static_cast<vtkLaplacianVolumeDeformationFilter*>(self);
    if (event == vtkLaplacianDeformationFilter::EditCommittedEvent)
    {
      filter->SurfaceCommitted();
    }
    else
    {
      filter->SurfaceCommitUndone();
    }
  });
  // The boundary's edit reports as this filter's second step, and this filter's abort ends it.
  vtkCallbackCommand* progress = this->Internals->ProgressObserver;
  progress->SetClientData(this);
  progress->SetCallback([](vtkObject* caller, unsigned long, void* self, void* data) {
    auto* filter = static_cast<vtkLaplacianVolumeDeformationFilter*>(self);
    filter->UpdateProgress(0.1 + 0.3 * *static_cast<double*>(data));
    if (filter->GetAbortExecute())
    {
      static_cast<vtkAlgorithm*>(caller)->AbortExecuteOn();
    }
  });
  auto surface = vtkSmartPointer<vtkLaplacianDeformationFilter>::New();
  surface->SetRotationModeToAsRigidAsPossible(); // a volume's boundary keeps its details best so
  this->SetSurfaceFilter(surface);
}

vtkLaplacianVolumeDeformationFilter::~vtkLaplacianVolumeDeformationFilter()
{
  this->Internals->Surface->RemoveObserver(this->Internals->CommitObserver);
}

vtkLaplacianDeformationFilter* vtkLaplacianVolumeDeformationFilter::GetSurfaceFilter()
{
  return this->Internals->Surface;
}

void vtkLaplacianVolumeDeformationFilter::SetSurfaceFilter(vtkLaplacianDeformationFilter* surface)
{
  vtkInternals& internals = *this->Internals;
  if (!surface || surface == internals.Surface)
  {
    return;
  }
  if (internals.Surface)
  {
    internals.Surface->RemoveObserver(internals.CommitObserver);
  }
  internals.Surface = surface;
  surface->AddObserver(vtkLaplacianDeformationFilter::EditCommittedEvent, internals.CommitObserver);
  surface->AddObserver(vtkLaplacianDeformationFilter::CommitUndoneEvent, internals.CommitObserver);
  internals.ArrayTime = 0;
  this->Modified();
}

int vtkLaplacianVolumeDeformationFilter::FillInputPortInformation(int port, vtkInformation* info)
{
  if (port == 1)
  {
    info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkSelection");
    info->Set(vtkAlgorithm::INPUT_IS_OPTIONAL(), 1);
    return 1;
  }
  return this->Superclass::FillInputPortInformation(port, info);
}

vtkMTimeType vtkLaplacianVolumeDeformationFilter::GetMTime()
{
  return std::max(this->Superclass::GetMTime(), this->Internals->Surface->GetMTime());
}

int vtkLaplacianVolumeDeformationFilter::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkUnstructuredGrid* input = vtkUnstructuredGrid::GetData(inputVector[0]);
  vtkUnstructuredGrid* output = vtkUnstructuredGrid::GetData(outputVector);
  this->SetErrorCode(vtkErrorCode::NoError);
  output->ShallowCopy(input);
  // One piece of a distributed mesh would take the faces between pieces for its boundary.
  const int pieces = outputVector->GetInformationObject(0)->Get(
    vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_PIECES());
  if (pieces > 1)
  {
    vtkErrorMacro(<< "The volume edit needs the whole mesh and was asked for one of " << pieces
                  << " pieces; run it in a serial session (the built-in server, or one process).");
    this->SetErrorCode(vtkErrorCode::UserError);
    return 1;
  }
  if (!this->Edit(input, output))
  {
    this->SetErrorCode(vtkErrorCode::UserError);
    output->ShallowCopy(input);
  }
  return 1;
}

bool vtkLaplacianVolumeDeformationFilter::Edit(vtkUnstructuredGrid* input, vtkUnstructuredGrid* output)
{
  const LaplacianEditing::Stopwatch watch;
  vtkInternals& internals = *this->Internals;
  internals.Settling = false;
  vtkPoints* rest = internals.Rest.Get(input)->GetPoints();
  std::string error = internals.Follower.Update(input, rest);
  if (!error.empty())
  {
    vtkErrorMacro(<< error);
    return false;
  }
  this->UpdateProgress(0.1);

  // The boundary's edit, by the surface filter, on the grid's point ids.
  vtkLaplacianDeformationFilter* surface = internals.Surface;
  vtkPolyData* boundary = internals.Follower.GetMesh().GetBoundary();
  if (surface->GetInputDataObject(0, 0) != boundary)
  {
    surface->SetInputData(boundary);
  }
  vtkDataObject* selection = this->GetInputDataObject(1, 0);
  if (surface->GetNumberOfInputConnections(1) != (selection ? 1 : 0) ||
    (selection && surface->GetInputDataObject(1, 0) != selection))
  {
    surface->SetInputData(1, selection);
  }
  vtkInformation* array = this->GetInputArrayInformation(0);
  if (array->GetMTime() != internals.ArrayTime)
  {
    surface->SetInputArrayToProcess(0, array);
    internals.ArrayTime = array->GetMTime();
  }
  if (surface->GetSelectionMode() == vtkLaplacianDeformationFilter::SELECTION_ARRAY)
  {
    internals.Follower.GetMesh().SetBoundaryLabels(this->GetInputArrayToProcess(0, input));
  }
  const unsigned long forward = surface->AddObserver(vtkCommand::ProgressEvent, internals.ProgressObserver);
  surface->Update();
  surface->RemoveObserver(forward);
  surface->AbortExecuteOff();
  if (surface->GetErrorCode() != vtkErrorCode::NoError)
  {
    vtkErrorMacro(<< "The edit of the boundary surface failed (the surface filter's error above "
                     "says why); the input passes through.");
    return false;
  }
  this->UpdateProgress(0.4);

  // The interior follows the points the boundary's edit moved.
  lep::OutputEdit edit;
  const bool solved = surface->GetSolvedEdit(edit);
  lep::VolumeFollower::Settings settings;
  settings.Iterations = this->VolumeIterations;
  settings.DragIterations = this->DragVolumeIterations;
  settings.Graph = this->DragGraph != 0;
  // A boundary whose settle the time limit cut is followed as a drag step follows it; the
  // interior settles once the boundary has, within what is left of the limit.
  const bool boundarySettling = surface->GetSettling() != 0;
  settings.Dragging = surface->GetDragging() != 0 || boundarySettling;
  const double limit = this->SettleTimeLimit;
  settings.TimeLimit = limit > 0.0 ? std::max(1e-9, limit - watch.Seconds()) : 0.0;
  // The volume is solved on one process: a surface solved by MUMPS has its volume by CHOLMOD.
  settings.Backend = surface->GetSolver() == vtkLaplacianDeformationFilter::SOLVER_SIMPLICIAL_LDLT
    ? LaplacianEditing::SolverBackend::SimplicialLDLT
    : LaplacianEditing::SolverBackend::Cholmod;
  // An abort (a new grab, say) ends the settle at a valid iterate; the next release settles.
  error = internals.Follower.FollowEdit(solved ? &edit : nullptr,
    surface->GetOutput()->GetPoints(), settings, output, this->OutputDisplacement != 0, 0.4, 0.9);
  if (!error.empty())
  {
    vtkErrorMacro(<< error);
    return false;
  }
  internals.Settling = boundarySettling || internals.Follower.GetFacts().OutOfTime;
  return true;
}

void vtkLaplacianVolumeDeformationFilter::SetSettleTimeLimit(double seconds)
{
  // The surface filter's too; one set on the surface filter alone (by an application that
  // continues the surface's settle) leaves the interior's uncut, so that it still ends settled.
  seconds = std::min(std::max(seconds, 0.0), 3600.0);
  this->Internals->Surface->SetSettleTimeLimit(seconds);
  if (this->SettleTimeLimit != seconds)
  {
    this->SettleTimeLimit = seconds;
    this->Modified();
  }
}

vtkTypeBool vtkLaplacianVolumeDeformationFilter::GetSettling()
{
  return this->Internals->Settling;
}

void vtkLaplacianVolumeDeformationFilter::ContinueSettling()
{
  if (this->Internals->Settling)
  {
    this->Internals->Surface->ContinueSettling(); // if its own settle was the one cut
    this->Modified();
  }
}

void vtkLaplacianVolumeDeformationFilter::SurfaceCommitted()
{
  // The surface committed its edit and put its handle at rest. The volume commits the interior
  // that followed that edit: the last update's, or, if the volume has not followed it, the
  // next update's (which solves the committed boundary at rest).
  vtkPoints* edited = this->Internals->Surface->GetOutput()->GetPoints();
  if (!edited || !this->Internals->Follower.Follows(edited))
  {
    this->Update();
  }
  vtkUnstructuredGrid* output = this->GetOutput();
  if (this->GetErrorCode() == vtkErrorCode::NoError && output->GetPoints())
  {
    this->Internals->Rest.Commit(output->GetPoints());
    this->Modified();
  }
}

void vtkLaplacianVolumeDeformationFilter::SurfaceCommitUndone()
{
  if (this->Internals->Rest.Undo())
  {
    this->Modified();
  }
}

void vtkLaplacianVolumeDeformationFilter::CommitEdit()
{
  this->Internals->Surface->CommitEdit();
}

bool vtkLaplacianVolumeDeformationFilter::UndoCommit()
{
  return this->Internals->Surface->UndoCommit();
}

int vtkLaplacianVolumeDeformationFilter::GetNumberOfCommits()
{
  return this->Internals->Rest.GetNumberOfCommits();
}

void vtkLaplacianVolumeDeformationFilter::SetSelectionData(vtkSelection* selection)
{
  this->SetInputData(1, selection);
}

void vtkLaplacianVolumeDeformationFilter::SetDragging(vtkTypeBool dragging)
{
  if (this->GetDragging() != dragging)
  {
    this->Internals->Surface->SetDragging(dragging);
    if (!dragging)
    {
      this->Modified(); // the update after a drag settles the interior
    }
  }
}

vtkTypeBool vtkLaplacianVolumeDeformationFilter::GetDragging()
{
  return this->Internals->Surface->GetDragging();
}

// The surface filter's handle and region properties.
void vtkLaplacianVolumeDeformationFilter::SetHandleCenter(double x, double y, double z)
{
  this->Internals->Surface->SetHandleCenter(x, y, z);
}
void vtkLaplacianVolumeDeformationFilter::SetHandleCenter(const double center[3])
{
  this->SetHandleCenter(center[0], center[1], center[2]);
}
double* vtkLaplacianVolumeDeformationFilter::GetHandleCenter()
{
  return this->Internals->Surface->GetHandleCenter();
}
void vtkLaplacianVolumeDeformationFilter::SetHandleTranslation(double x, double y, double z)
{
  this->Internals->Surface->SetHandleTranslation(x, y, z);
}
void vtkLaplacianVolumeDeformationFilter::SetHandleTranslation(const double translation[3])
{
  this->SetHandleTranslation(translation[0], translation[1], translation[2]);
}
double* vtkLaplacianVolumeDeformationFilter::GetHandleTranslation()
{
  return this->Internals->Surface->GetHandleTranslation();
}
void vtkLaplacianVolumeDeformationFilter::SetHandleRotation(double x, double y, double z)
{
  this->Internals->Surface->SetHandleRotation(x, y, z);
}
void vtkLaplacianVolumeDeformationFilter::SetHandleRotation(const double rotation[3])
{
  this->SetHandleRotation(rotation[0], rotation[1], rotation[2]);
}
double* vtkLaplacianVolumeDeformationFilter::GetHandleRotation()
{
  return this->Internals->Surface->GetHandleRotation();
}
void vtkLaplacianVolumeDeformationFilter::SetHandleTransform(int group, vtkLinearTransform* transform)
{
  this->Internals->Surface->SetHandleTransform(group, transform);
}
vtkLinearTransform* vtkLaplacianVolumeDeformationFilter::GetHandleTransform(int group)
{
  return this->Internals->Surface->GetHandleTransform(group);
}
void vtkLaplacianVolumeDeformationFilter::SetHandleGroupMotion(vtkIdType group,
  double translationX, double translationY, double translationZ, double rotationX,
  double rotationY, double rotationZ)
{
  this->Internals->Surface->SetHandleGroupMotion(
    group, translationX, translationY, translationZ, rotationX, rotationY, rotationZ);
}
void vtkLaplacianVolumeDeformationFilter::RemoveAllHandleGroupMotions()
{
  this->Internals->Surface->RemoveAllHandleGroupMotions();
}
int vtkLaplacianVolumeDeformationFilter::GetNumberOfHandleGroups()
{
  return this->Internals->Surface->GetNumberOfHandleGroups();
}
void vtkLaplacianVolumeDeformationFilter::SetHandleRadius(double radius)
{
  this->Internals->Surface->SetHandleRadius(radius);
}
double vtkLaplacianVolumeDeformationFilter::GetHandleRadius()
{
  return this->Internals->Surface->GetHandleRadius();
}
void vtkLaplacianVolumeDeformationFilter::SetROIRadius(double radius)
{
  this->Internals->Surface->SetROIRadius(radius);
}
double vtkLaplacianVolumeDeformationFilter::GetROIRadius()
{
  return this->Internals->Surface->GetROIRadius();
}
void vtkLaplacianVolumeDeformationFilter::SetRadiusUnits(int units)
{
  this->Internals->Surface->SetRadiusUnits(units);
}
int vtkLaplacianVolumeDeformationFilter::GetRadiusUnits()
{
  return this->Internals->Surface->GetRadiusUnits();
}
void vtkLaplacianVolumeDeformationFilter::SetRadiusUnitsToAbsolute()
{
  this->SetRadiusUnits(vtkLaplacianDeformationFilter::RADIUS_ABSOLUTE);
}
void vtkLaplacianVolumeDeformationFilter::SetRadiusUnitsToDiagonalFraction()
{
  this->SetRadiusUnits(vtkLaplacianDeformationFilter::RADIUS_DIAGONAL_FRACTION);
}
void vtkLaplacianVolumeDeformationFilter::SetSelectionMode(int mode)
{
  this->Internals->Surface->SetSelectionMode(mode);
}
int vtkLaplacianVolumeDeformationFilter::GetSelectionMode()
{
  return this->Internals->Surface->GetSelectionMode();
}
void vtkLaplacianVolumeDeformationFilter::SetSelectionModeToGeodesic()
{
  this->SetSelectionMode(vtkLaplacianDeformationFilter::SELECTION_GEODESIC);
}
void vtkLaplacianVolumeDeformationFilter::SetSelectionModeToArray()
{
  this->SetSelectionMode(vtkLaplacianDeformationFilter::SELECTION_ARRAY);
}
void vtkLaplacianVolumeDeformationFilter::SetRotationMode(int mode)
{
  this->Internals->Surface->SetRotationMode(mode);
}
int vtkLaplacianVolumeDeformationFilter::GetRotationMode()
{
  return this->Internals->Surface->GetRotationMode();
}
void vtkLaplacianVolumeDeformationFilter::SetRotationModeToNone()
{
  this->SetRotationMode(vtkLaplacianDeformationFilter::ROTATION_NONE);
}
void vtkLaplacianVolumeDeformationFilter::SetRotationModeToAsRigidAsPossible()
{
  this->SetRotationMode(vtkLaplacianDeformationFilter::ROTATION_AS_RIGID_AS_POSSIBLE);
}

// The last update's facts.
int vtkLaplacianVolumeDeformationFilter::GetNumberOfZonePoints()
{
  return this->Internals->Follower.GetFacts().ZonePoints;
}
int vtkLaplacianVolumeDeformationFilter::GetNumberOfZoneTetrahedra()
{
  return this->Internals->Follower.GetFacts().ZoneTetrahedra;
}
int vtkLaplacianVolumeDeformationFilter::GetNumberOfVolumeIterations()
{
  return this->Internals->Follower.GetFacts().Iterations;
}
int vtkLaplacianVolumeDeformationFilter::GetNumberOfVolumeFactorizations()
{
  return this->Internals->Follower.GetFacts().Factorizations;
}
int vtkLaplacianVolumeDeformationFilter::GetNumberOfZoneGrowths()
{
  return this->Internals->Follower.GetFacts().Growths;
}
int vtkLaplacianVolumeDeformationFilter::GetNumberOfFailedCells()
{
  return this->Internals->Follower.GetFacts().FailedCells;
}
int vtkLaplacianVolumeDeformationFilter::GetNumberOfGraphNodes()
{
  const auto& facts = this->Internals->Follower.GetFacts();
  return facts.ByGraph ? facts.GraphNodes : 0;
}
int vtkLaplacianVolumeDeformationFilter::GetNumberOfRepairedCells()
{
  return this->Internals->Follower.GetFacts().RepairedCells;
}
double vtkLaplacianVolumeDeformationFilter::GetLargestTargetMiss()
{
  return this->Internals->Follower.GetFacts().LargestMiss;
}
double vtkLaplacianVolumeDeformationFilter::GetVolumeSetupTime()
{
  return this->Internals->Follower.GetFacts().SetupTime;
}
double vtkLaplacianVolumeDeformationFilter::GetVolumeSolveTime()
{
  return this->Internals->Follower.GetFacts().SolveTime;
}

void vtkLaplacianVolumeDeformationFilter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "VolumeIterations: " << this->VolumeIterations << "\n";
  os << indent << "DragVolumeIterations: " << this->DragVolumeIterations << "\n";
  os << indent << "DragGraph: " << (this->DragGraph ? "On" : "Off") << "\n";
  os << indent << "NumberOfCommits: " << this->GetNumberOfCommits() << "\n";
  os << indent << "OutputDisplacement: " << (this->OutputDisplacement ? "On" : "Off") << "\n";
  os << indent << "SettleTimeLimit: " << this->SettleTimeLimit << " s\n";
  os << indent << "Settling: " << (this->Internals->Settling ? "Yes" : "No") << "\n";
  const lep::VolumeFollower::Facts& facts = this->Internals->Follower.GetFacts();
  os << indent << "Last update: " << facts.ZonePoints << " zone points, " << facts.ZoneTetrahedra
     << " corner tetrahedra, " << facts.Iterations << " iterations, " << facts.Growths
     << " growths, " << facts.FailedCells << " failed cells, largest miss " << facts.LargestMiss
     << ", setup " << facts.SetupTime << " s, solve " << facts.SolveTime << " s\n";
  os << indent << "SurfaceFilter:\n";
  this->Internals->Surface->PrintSelf(os, indent.GetNextIndent());
}
