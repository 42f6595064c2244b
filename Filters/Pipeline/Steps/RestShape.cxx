#include "RestShape.h"

#include "ContentTime.h"

#include "vtkPoints.h"

#include <cstring>

namespace LaplacianEditing
{
namespace Pipeline
{

vtkPointSet* RestShape::Get(vtkPointSet* input)
{
  const vtkMTimeType inputTime = ContentTime(input);
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
  if (!this->CommittedRest || std::strcmp(this->CommittedRest->GetClassName(), input->GetClassName()) != 0)
  {
    this->CommittedRest.TakeReference(input->NewInstance());
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

bool RestShape::GetPoint(vtkPointSet* input, vtkIdType id, double point[3]) const
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
