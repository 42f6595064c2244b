// Offscreen image regression tests of real edits, compared with committed baselines.
// Usage: TestLaplacianDeformationImages <case> <data folder> -V <baseline.png> -T <temp folder>
#include "EditingScene.h"

#include "vtkLaplacianDeformationFilter.h"

#include "vtkOBJReader.h"
#include "vtkRegressionTestImage.h"
#include "vtkTransform.h"

#include <iostream>
#include <string>

namespace
{
vtkSmartPointer<vtkPolyData> BunnyEdit(vtkLaplacianDeformationFilter* filter, const std::string& data)
{
  vtkNew<vtkOBJReader> reader;
  reader->SetFileName((data + "/stanford-bunny.obj").c_str());
  reader->Update();
  vtkPolyData* bunny = reader->GetOutput();
  // The handle on the top of an ear (the highest vertex), pulled up and back.
  vtkIdType top = 0;
  for (vtkIdType i = 1; i < bunny->GetNumberOfPoints(); ++i)
  {
    top = bunny->GetPoint(i)[1] > bunny->GetPoint(top)[1] ? i : top;
  }
  const double diagonal = bunny->GetLength();
  filter->SetInputData(bunny);
  filter->SetHandleCenter(bunny->GetPoint(top));
  filter->SetHandleRadius(0.03 * diagonal);
  filter->SetROIRadius(0.3 * diagonal);
  vtkNew<vtkTransform> pull;
  pull->Translate(0.0, 0.08 * diagonal, -0.08 * diagonal);
  filter->SetHandleTransform(pull);
  return bunny;
}
}

int main(int argc, char* argv[])
{
  if (argc < 3)
  {
    std::cerr << "usage: " << argv[0] << " <case> <data folder> -V <baseline> -T <temp>\n";
    return EXIT_FAILURE;
  }
  const std::string name = argv[1];
  vtkNew<vtkLaplacianDeformationFilter> filter;
  vtkSmartPointer<vtkPolyData> before;
  double direction[3] = { 0.0, 1.0, -0.6 };
  double up[3] = { 0.0, 0.0, 1.0 };
  if (name == "BumpyPlaneEdit")
  {
    before = EditingScene::SetUpBumpyPlaneEdit(filter);
  }
  else if (name == "BunnyEdit")
  {
    before = BunnyEdit(filter, argv[2]);
    direction[0] = 0.0, direction[1] = 0.0, direction[2] = -1.0;
    up[0] = 0.0, up[1] = 1.0, up[2] = 0.0;
  }
  else
  {
    std::cerr << "unknown case " << name << "\n";
    return EXIT_FAILURE;
  }
  filter->Update();
  vtkSmartPointer<vtkRenderWindow> window =
    EditingScene::MakeBeforeAfterWindow(before, filter->GetOutput(), direction, up);
  window->Render();
  const int result = vtkRegressionTestImageThreshold(window, 0.05);
  return result == vtkRegressionTester::PASSED ? EXIT_SUCCESS : EXIT_FAILURE;
}
