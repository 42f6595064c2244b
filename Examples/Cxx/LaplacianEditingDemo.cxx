// The demo: one detail-preserving edit, written as a mesh and as a before/after picture.
//
//   LaplacianEditingDemo [--output-dir DIR] [--mode none|explicit|implicit] [MESH X Y Z ROI_RADIUS]
//
// Without a mesh it edits the embedded bumpy plane. With one (OBJ, PLY, STL, VTP or VTK) it
// puts the handle at the surface vertex nearest (X, Y, Z), with a handle radius of 15% of
// ROI_RADIUS, and pulls it outward (away from the mesh centre) by 30% of ROI_RADIUS.
// Details follow the edit's rotations with explicit local frames unless --mode says otherwise.
// It prints the ROI size, the factorization time and the median time of one handle move.
#include "EditingScene.h"
#include "MeshReader.h"

#include "vtkLaplacianDeformationFilter.h"

#include "vtkMath.h"
#include "vtkTransform.h"
#include "vtkXMLPolyDataWriter.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <optional>
#include <string>
#include <vector>

namespace
{
const char* Usage = " [--output-dir DIR] [--mode none|explicit|implicit] [MESH X Y Z ROI_RADIUS]\n";

struct Demo
{
  std::string OutputDir = "demo-output";
  int Mode = vtkLaplacianDeformationFilter::ROTATION_EXPLICIT;
  std::vector<std::string> Mesh; // empty, or MESH X Y Z ROI_RADIUS
  std::string MeshName = "embedded bumpy plane";
  vtkSmartPointer<vtkPolyData> Before;
  vtkNew<vtkTransform> Pull;
  double ViewDirection[3] = { 0.0, 1.0, -0.6 };
  double ViewUp[3] = { 0.0, 0.0, 1.0 };
};

// The command line into `demo`; an exit code when the program should stop (help, an error).
std::optional<int> ParseArguments(int argc, char* argv[], Demo& demo)
{
  for (int i = 1; i < argc; ++i)
  {
    const std::string arg = argv[i];
    if (arg == "--output-dir" && i + 1 < argc)
      demo.OutputDir = argv[++i];
    else if (arg == "--mode" && i + 1 < argc)
    {
      const std::string name = argv[++i];
      demo.Mode = name == "none" ? 0 : (name == "implicit" ? 2 : 1);
    }
    else if (arg == "-h" || arg == "--help")
    {
      std::cout << "usage: " << argv[0] << Usage;
      return EXIT_SUCCESS;
    }
    else
      demo.Mesh.push_back(arg);
  }
  if (!demo.Mesh.empty() && demo.Mesh.size() != 5)
  {
    std::cerr << "usage: " << argv[0] << Usage;
    return EXIT_FAILURE;
  }
  return std::nullopt;
}

// The mesh, the handle and region on it, the pull and the view; false, with the reason on
// stderr, for a file it cannot read.
bool SetUpEdit(Demo& demo, vtkLaplacianDeformationFilter* filter)
{
  if (demo.Mesh.empty())
  {
    demo.Before = EditingScene::SetUpBumpyPlaneEdit(filter);
    demo.Pull->DeepCopy(filter->GetHandleTransform());
    return true;
  }
  std::string error;
  demo.Before = MeshReader::Read(demo.Mesh[0], error);
  if (!demo.Before)
  {
    std::cerr << "error: " << error << "\n";
    return false;
  }
  demo.MeshName = demo.Mesh[0];
  const double center[3] = { std::atof(demo.Mesh[1].c_str()), std::atof(demo.Mesh[2].c_str()),
    std::atof(demo.Mesh[3].c_str()) };
  const double radius = std::atof(demo.Mesh[4].c_str());
  filter->SetInputData(demo.Before);
  filter->SetHandleCenter(center);
  filter->SetHandleRadius(0.15 * radius);
  filter->SetROIRadius(radius);
  double middle[3], outward[3];
  demo.Before->GetCenter(middle);
  vtkMath::Subtract(center, middle, outward);
  if (vtkMath::Normalize(outward) == 0.0)
  {
    outward[2] = 1.0;
  }
  demo.Pull->Translate(0.3 * radius * outward[0], 0.3 * radius * outward[1], 0.3 * radius * outward[2]);
  // Look at the edit from the side.
  vtkMath::Perpendiculars(outward, demo.ViewDirection, demo.ViewUp, 0.0);
  return true;
}

// Drags `handle` to the pull in ten moves, as an interactive session would, and prints the
// median move.
void Drag(const Demo& demo, vtkLaplacianDeformationFilter* filter, vtkTransform* handle)
{
  std::vector<double> solveTimes;
  const int moves = 10;
  for (int move = 1; move <= moves; ++move)
  {
    handle->Identity();
    const double* full = demo.Pull->GetPosition();
    const double s = static_cast<double>(move) / moves;
    handle->Translate(s * full[0], s * full[1], s * full[2]);
    filter->Update();
    solveTimes.push_back(filter->GetSolveTime());
  }
  std::sort(solveTimes.begin(), solveTimes.end());
  std::cout << "handle move (solve and output, 3 coordinates): median "
            << 1e3 * solveTimes[moves / 2] << " ms over " << moves << " moves; factorizations: "
            << filter->GetNumberOfFactorizations() << "\n";
}

// Writes the edited mesh and the before/after picture.
void Save(Demo& demo, vtkLaplacianDeformationFilter* filter)
{
  std::filesystem::create_directories(demo.OutputDir);
  const std::string meshPath = demo.OutputDir + "/edited.vtp";
  const std::string imagePath = demo.OutputDir + "/before-after.png";
  vtkNew<vtkXMLPolyDataWriter> writer;
  writer->SetInputConnection(filter->GetOutputPort());
  writer->SetFileName(meshPath.c_str());
  writer->Write();
  vtkSmartPointer<vtkRenderWindow> window = EditingScene::MakeComparisonWindow(
    { demo.Before, filter->GetOutput() }, demo.ViewDirection, demo.ViewUp, 600, 600);
  window->Render();
  EditingScene::SaveScreenshot(window, imagePath);
  std::cout << "wrote " << meshPath << " and " << imagePath << "\n";
}
}

int main(int argc, char* argv[])
{
  Demo demo;
  if (const std::optional<int> exitCode = ParseArguments(argc, argv, demo))
  {
    return *exitCode;
  }
  vtkNew<vtkLaplacianDeformationFilter> filter;
  if (!SetUpEdit(demo, filter))
  {
    return EXIT_FAILURE;
  }
  filter->SetRotationMode(demo.Mode);
  // Select and factor once, with the handle at rest.
  vtkNew<vtkTransform> handle;
  filter->SetHandleTransform(handle);
  filter->Update();
  if (filter->GetNumberOfFactorizations() == 0)
  {
    std::cerr << "error: the filter could not set up the edit (see the message above)\n";
    return EXIT_FAILURE;
  }
  const char* modeNames[] = { "none", "explicit", "implicit" };
  std::cout << "mesh: " << demo.MeshName << " (" << demo.Before->GetNumberOfPoints() << " points)\n"
            << "ROI vertices: " << filter->GetNumberOfROIVertices()
            << ", handle vertices: " << filter->GetNumberOfHandleVertices()
            << ", rotation mode: " << modeNames[demo.Mode] << "\n"
            << "setup: " << filter->GetSetupTime() << " s (ordering "
            << filter->GetAnalysisTime() << " s, factorization " << filter->GetFactorizationTime()
            << " s)\n";
  Drag(demo, filter, handle);
  Save(demo, filter);
  return EXIT_SUCCESS;
}
