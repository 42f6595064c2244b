#include "DisplacementArray.h"

#include "vtkDataArray.h"
#include "vtkPoints.h"

namespace LaplacianEditing
{
namespace Pipeline
{
vtkDataArray* DisplacementArray::Update(
  vtkPoints* rest, vtkPoints* moved, const std::vector<vtkIdType>& ids, std::uint64_t key)
{
  vtkDataArray* restPoints = rest->GetData();
  if (!this->Zeros || this->Zeros->GetDataType() != restPoints->GetDataType() ||
    this->Zeros->GetNumberOfTuples() != restPoints->GetNumberOfTuples())
  {
    this->Zeros.TakeReference(restPoints->NewInstance());
    this->Zeros->SetName("Displacement");
    this->Zeros->SetNumberOfComponents(3);
    this->Zeros->SetNumberOfTuples(restPoints->GetNumberOfTuples());
    this->Zeros->Fill(0.0);
  }
  return this->Array.Update(this->Zeros, ids, key, [&](vtkDataArray* array) {
    for (vtkIdType id : ids)
    {
      double p[3], q[3];
      rest->GetPoint(id, p);
      moved->GetPoint(id, q);
      const double displacement[3] = { q[0] - p[0], q[1] - p[1], q[2] - p[2] };
      array->SetTuple(id, displacement);
    }
  });
}
}
}
