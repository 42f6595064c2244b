#include "RestShape.h"

#include "SurfaceAdapter.h"

#include "vtkPoints.h"

namespace LaplacianEditing
{
namespace Pipeline
{

vtkPolyData* RestShape::Get(vtkPolyData* input)
{
  const vtkMTimeType inputTime = SurfaceAdapter::GetContentTime(input);
  if (input != this->LastInput || inputTime != this->CommittedInput)
  {
    this->Commits.clear();
  }
  this->LastInput = input;
  this->CommittedInput = inputTime;
  if (this->Commits.empty())
  {
    return input;
  }
  if (this->CommittedRest->GetPoints() != this->Commits.back())
  {
    this->CommittedRest->ShallowCopy(input);
    this->CommittedRest->SetPoints(this->Commits.back());
  }
  return this->CommittedRest;
}

void RestShape::Commit(vtkPoints* points)
{
  auto committed = vtkSmartPointer<vtkPoints>::New();
  committed->SetDataType(points->GetDataType()); // DeepCopy keeps float otherwise
  committed->DeepCopy(points);
  this->Commits.push_back(committed);
}

bool RestShape::Undo()
{
  if (this->Commits.empty())
  {
    return false;
  }
  this->Commits.pop_back();
  return true;
}

bool RestShape::GetPoint(vtkPolyData* input, vtkIdType id, double point[3]) const
{
  if (!input || id < 0 || id >= input->GetNumberOfPoints())
  {
    return false;
  }
  const bool committed =
    !this->Commits.empty() && this->Commits.back()->GetNumberOfPoints() == input->GetNumberOfPoints();
  (committed ? this->Commits.back().Get() : input->GetPoints())->GetPoint(id, point);
  return true;
}
}
}
