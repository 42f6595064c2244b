// libFuzzer harness: builds a mesh and the filter's parameters from the fuzzer's bytes and runs
// the filter. Random triangles (degenerate, duplicated, non-manifold), NaN and infinite
// coordinates, random selections, radii, modes, weights, orders and transforms. Errors are
// allowed (and silenced); crashes, sanitizer reports and non-finite output from finite input
// are failures.
//
// Built with clang's -fsanitize=fuzzer by scripts/test; built without it (RunFuzzRegressions.cxx
// supplies main) it replays the committed regression inputs as a CTest test.
#include "vtkLaplacianDeformationFilter.h"

#include "vtkCallbackCommand.h"
#include "vtkCellArray.h"
#include "vtkCommand.h"
#include "vtkIntArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkTransform.h"

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <limits>

namespace
{
// Reads the input front to back; past its end it yields zeros.
class ByteReader
{
public:
  ByteReader(const uint8_t* data, size_t size)
    : Data(data)
    , Size(size)
  {
  }
  uint8_t Byte() { return this->Position < this->Size ? this->Data[this->Position++] : 0; }
  int Below(int limit) { return limit > 0 ? this->Byte() % limit : 0; }
  double Unit() { return (this->Byte() * 256 + this->Byte()) / 65535.0; } // [0, 1]
  double Coordinate()
  {
    switch (this->Byte())
    {
      case 255:
        return std::numeric_limits<double>::quiet_NaN();
      case 254:
        return std::numeric_limits<double>::infinity();
      case 253:
        return 1e6 + this->Unit();
      default:
        return 2.0 * this->Unit() - 1.0;
    }
  }

private:
  const uint8_t* Data;
  size_t Size;
  size_t Position = 0;
};
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
  ByteReader in(data, size);
  const int numberOfPoints = 3 + in.Below(61);
  const int numberOfCells = 1 + in.Below(120);
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  bool finite = true;
  for (int i = 0; i < numberOfPoints; ++i)
  {
    const double p[3] = { in.Coordinate(), in.Coordinate(), in.Coordinate() };
    finite = finite && std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2]);
    points->InsertNextPoint(p);
  }
  vtkNew<vtkCellArray> polys;
  for (int c = 0; c < numberOfCells; ++c)
  {
    const int corners = 3 + in.Below(3) / 2; // mostly triangles, some quads
    polys->InsertNextCell(corners);
    for (int k = 0; k < corners; ++k)
    {
      polys->InsertCellPoint(in.Below(numberOfPoints));
    }
  }
  vtkNew<vtkPolyData> mesh;
  mesh->SetPoints(points);
  mesh->SetPolys(polys);

  vtkNew<vtkLaplacianDeformationFilter> filter;
  filter->SetInputData(mesh);
  filter->SetRotationMode(in.Below(3));
  filter->SetLaplacianWeights(in.Below(2));
  filter->SetOperatorOrder(1 + in.Below(2));
  filter->SetSolver(in.Below(2));
  filter->SetMergeCoincidentPoints(in.Below(2));
  filter->SetNumberOfIterations(1 + in.Below(3));
  filter->SetPreserveDetailScale(in.Below(2));
  filter->SetAnchorPadding(in.Unit() * 0.5);
  filter->SetHandleCenter(in.Coordinate(), in.Coordinate(), in.Coordinate());
  filter->SetHandleRadius(in.Unit() * 1.5 - 0.1);
  filter->SetROIRadius(in.Unit() * 3.0 - 0.1);
  if (in.Below(2))
  {
    vtkNew<vtkIntArray> selection;
    selection->SetName("Selection");
    for (int i = 0; i < numberOfPoints; ++i)
    {
      selection->InsertNextValue(in.Below(5) - (in.Below(16) == 0 ? 1 : 0));
    }
    mesh->GetPointData()->AddArray(selection);
    filter->SetSelectionModeToArray();
    filter->SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, "Selection");
  }
  vtkNew<vtkTransform> transform;
  transform->Translate(in.Coordinate(), in.Coordinate(), in.Coordinate());
  transform->RotateWXYZ(360.0 * in.Unit(), in.Unit(), in.Unit(), in.Unit() + 1e-3);
  transform->Scale(0.5 + in.Unit(), 0.5 + in.Unit(), 0.5 + in.Unit());
  filter->SetHandleTransform(in.Below(3), transform);

  bool failed = false;
  vtkNew<vtkCallbackCommand> onError;
  onError->SetClientData(&failed);
  onError->SetCallback(
    [](vtkObject*, unsigned long, void* flag, void*) { *static_cast<bool*>(flag) = true; });
  filter->AddObserver(vtkCommand::ErrorEvent, onError);
  filter->Update();

  vtkPolyData* output = filter->GetOutput();
  if (output->GetNumberOfPoints() != numberOfPoints)
  {
    std::abort(); // the output must always hold every input point
  }
  if (finite && !failed)
  {
    for (vtkIdType i = 0; i < output->GetNumberOfPoints(); ++i)
    {
      const double* p = output->GetPoint(i);
      if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2]))
      {
        std::abort(); // finite input, no error, yet a non-finite result
      }
    }
  }
  return 0;
}
