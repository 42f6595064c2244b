#include "HandleMotion.h"

#include "vtkMath.h"
#include "vtkMatrix4x4.h"
#include "vtkTransform.h"

#include <algorithm>
#include <cmath>

namespace LaplacianEditing
{
namespace Pipeline
{
vtkSmartPointer<vtkTransform> HandleMotion::Transform(
  const double center[3], const double rotation[3], const double translation[3])
{
  auto transform = vtkSmartPointer<vtkTransform>::New();
  transform->PostMultiply();
  transform->Translate(-center[0], -center[1], -center[2]);
  transform->RotateX(rotation[0]);
  transform->RotateY(rotation[1]);
  transform->RotateZ(rotation[2]);
  transform->Translate(center);
  transform->Translate(translation);
  return transform;
}

void HandleMotion::RotationMatrix(const double angles[3], double matrix[3][3])
{
  const double origin[3] = { 0.0, 0.0, 0.0 };
  // Hold the transform: its matrix dies with it.
  vtkSmartPointer<vtkTransform> transform = Transform(origin, angles, origin);
  vtkMatrix4x4* m = transform->GetMatrix();
  for (int r = 0; r < 3; ++r)
  {
    for (int c = 0; c < 3; ++c)
    {
      matrix[r][c] = m->GetElement(r, c);
    }
  }
}

void HandleMotion::Angles(const double m[3][3], double angles[3])
{
  // R = Rz(c) Ry(b) Rx(a).
  const double b = std::asin(std::max(-1.0, std::min(1.0, -m[2][0])));
  double a = 0.0, c = 0.0;
  if (std::abs(m[2][0]) < 1.0 - 1e-12)
  {
    a = std::atan2(m[2][1], m[2][2]);
    c = std::atan2(m[1][0], m[0][0]);
  }
  else
  {
    c = std::atan2(-m[0][1], m[1][1]);
  }
  angles[0] = vtkMath::DegreesFromRadians(a);
  angles[1] = vtkMath::DegreesFromRadians(b);
  angles[2] = vtkMath::DegreesFromRadians(c);
}
}
}
