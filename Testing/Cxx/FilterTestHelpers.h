// Helpers shared by the filter tests.
#ifndef FilterTestHelpers_h
#define FilterTestHelpers_h

#include "BumpyPlane.h"
#include "vtkLaplacianDeformationFilter.h"

#include "vtkCallbackCommand.h"
#include "vtkCommand.h"
#include "vtkMath.h"
#include "vtkDataArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPointSet.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"
#include "vtkTransform.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

namespace FilterTestHelpers
{
inline const std::string DataDir = LAPLACIAN_EDITING_DATA_DIR;

// Collects the filter's error (or warning) messages instead of printing them.
class ErrorCatcher
{
public:
  explicit ErrorCatcher(vtkObject* object, unsigned long event = vtkCommand::ErrorEvent)
  {
    this->Callback->SetClientData(this);
    this->Callback->SetCallback([](vtkObject*, unsigned long, void* self, void* message) {
      static_cast<ErrorCatcher*>(self)->Messages += static_cast<const char*>(message);
    });
    object->AddObserver(event, this->Callback);
  }
  std::string Messages;

private:
  vtkNew<vtkCallbackCommand> Callback;
};

// Whether `output` has a Displacement array equal to its points minus `rest`'s, exactly; the
// largest component of it.
inline double ExpectDisplacement(vtkPointSet* rest, vtkPointSet* output)
{
  vtkDataArray* displacement = output->GetPointData()->GetArray("Displacement");
  if (!displacement || displacement->GetNumberOfComponents() != 3)
  {
    ADD_FAILURE() << "no three-component Displacement array";
    return 0.0;
  }
  double largest = 0.0;
  for (vtkIdType i = 0; i < rest->GetNumberOfPoints(); ++i)
  {
    double p[3], q[3];
    rest->GetPoint(i, p);
    output->GetPoint(i, q);
    for (int k = 0; k < 3; ++k)
    {
      EXPECT_EQ(displacement->GetComponent(i, k), q[k] - p[k]) << "point " << i;
      largest = std::max(largest, std::abs(q[k] - p[k]));
    }
  }
  return largest;
}

inline vtkSmartPointer<vtkPolyData> BumpyPlane(int resolution = 60)
{
  return MakeBumpyPlane(resolution);
}

inline double Diagonal(vtkPolyData* mesh)
{
  return mesh->GetLength();
}

inline double MaxPointDistance(vtkPointSet* a, vtkPointSet* b)
{
  double worst = 0.0;
  for (vtkIdType i = 0; i < a->GetNumberOfPoints(); ++i)
  {
    double p[3], q[3];
    a->GetPoint(i, p);
    b->GetPoint(i, q);
    worst = std::max(worst, std::sqrt(vtkMath::Distance2BetweenPoints(p, q)));
  }
  return worst;
}

inline vtkSmartPointer<vtkLaplacianDeformationFilter> PlaneEdit(vtkPolyData* input)
{
  auto filter = vtkSmartPointer<vtkLaplacianDeformationFilter>::New();
  filter->SetInputData(input);
  filter->SetHandleCenter(0.5, 0.5, 0.0);
  filter->SetHandleRadius(0.06);
  filter->SetROIRadius(0.35);
  return filter;
}

inline vtkSmartPointer<vtkTransform> Translation(double x, double y, double z)
{
  auto transform = vtkSmartPointer<vtkTransform>::New();
  transform->Translate(x, y, z);
  return transform;
}
}

using namespace FilterTestHelpers;

#endif
