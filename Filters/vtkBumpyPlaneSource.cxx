#include "vtkBumpyPlaneSource.h"

#include "vtkCellArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"

#include <cmath>

vtkStandardNewMacro(vtkBumpyPlaneSource);

vtkBumpyPlaneSource::vtkBumpyPlaneSource()
{
  this->SetNumberOfInputPorts(0);
}

void vtkBumpyPlaneSource::GetBumpCenter(int i, double center[2])
{
  const int n = std::max(this->BumpsPerSide, 1);
  center[0] = (i % n + 0.5) / n;
  center[1] = (i / n + 0.5) / n;
}

int vtkBumpyPlaneSource::RequestData(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  vtkPolyData* output = vtkPolyData::GetData(outputVector);
  const int n = this->Resolution;
  const int bumps = this->BumpsPerSide * this->BumpsPerSide;

  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints((n + 1) * (n + 1));
  for (int j = 0; j <= n; ++j)
  {
    for (int i = 0; i <= n; ++i)
    {
      const double x = static_cast<double>(i) / n;
      const double y = static_cast<double>(j) / n;
      double z = 0.0;
      for (int b = 0; b < bumps; ++b)
      {
        double c[2];
        this->GetBumpCenter(b, c);
        const double r = std::hypot(x - c[0], y - c[1]) / this->BumpRadius;
        if (r < 1.0)
        {
          z += this->BumpHeight * 0.5 * (1.0 + std::cos(vtkMath::Pi() * r));
        }
      }
      points->SetPoint(j * (n + 1) + i, x, y, z);
    }
  }

  vtkNew<vtkCellArray> triangles;
  triangles->AllocateExact(2 * n * n, 6 * n * n);
  for (int j = 0; j < n; ++j)
  {
    for (int i = 0; i < n; ++i)
    {
      const vtkIdType a = j * (n + 1) + i;
      const vtkIdType b = a + 1;
      const vtkIdType c = a + n + 2;
      const vtkIdType d = a + n + 1;
      const vtkIdType lower[3] = { a, b, c };
      const vtkIdType upper[3] = { a, c, d };
      triangles->InsertNextCell(3, lower);
      triangles->InsertNextCell(3, upper);
    }
  }
  output->SetPoints(points);
  output->SetPolys(triangles);
  return 1;
}

void vtkBumpyPlaneSource::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Resolution: " << this->Resolution << "\n";
  os << indent << "BumpsPerSide: " << this->BumpsPerSide << "\n";
  os << indent << "BumpHeight: " << this->BumpHeight << "\n";
  os << indent << "BumpRadius: " << this->BumpRadius << "\n";
}
