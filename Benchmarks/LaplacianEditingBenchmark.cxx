// Benchmark of setup and handle moves; prints one JSON line.
//
//   LaplacianEditingBenchmark MESH [--vertex V | --point X Y Z] [--roi F] [--handle F]
//     [--translate DX DY DZ] [--moves N] [--order 1|2] [--weights uniform|cotangent]
//     [--solver cholmod|ldlt] [--mode none|explicit|implicit] [--iterations K] [--no-rescale]
//
// Radii (--roi, default 0.25; --handle, default 0.03) and the translation (default 0 0 0.05)
// are fractions of the bounding-box diagonal. Each move sets a new handle transform and
// updates the filter; the move time is the filter's solve and output time, and the wall time
// of the whole Update() is reported too.
#include "MeshReader.h"

#include "vtkLaplacianDeformationFilter.h"

#include "vtkTransform.h"

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <iomanip>
#include <iostream>
#include <string>
#include <vector>

namespace
{
double Median(std::vector<double> values)
{
  std::sort(values.begin(), values.end());
  return values[values.size() / 2];
}
}

int main(int argc, char* argv[])
{
  if (argc < 2)
  {
    std::cerr << "usage: " << argv[0]
              << " MESH [--vertex V | --point X Y Z] [--roi F] [--handle F] [--translate DX DY DZ]"
                 " [--moves N] [--order 1|2] [--weights uniform|cotangent] [--solver cholmod|ldlt]"
                 " [--mode none|explicit|implicit] [--iterations K] [--no-rescale]\n";
    return EXIT_FAILURE;
  }
  std::string error;
  vtkSmartPointer<vtkPolyData> mesh = MeshReader::Read(argv[1], error);
  if (!mesh)
  {
    std::cerr << "error: " << error << "\n";
    return EXIT_FAILURE;
  }
  vtkIdType vertex = 0;
  double point[3];
  bool usePoint = false;
  double roi = 0.25, handle = 0.03, translate[3] = { 0.0, 0.0, 0.05 };
  int moves = 20;
  vtkNew<vtkLaplacianDeformationFilter> filter;
  for (int i = 2; i < argc; ++i)
  {
    const std::string arg = argv[i];
    auto next = [&]() { return i + 1 < argc ? std::string(argv[++i]) : std::string(); };
    if (arg == "--vertex")
      vertex = std::atol(next().c_str());
    else if (arg == "--point")
    {
      usePoint = true;
      for (double& c : point)
        c = std::atof(next().c_str());
    }
    else if (arg == "--roi")
      roi = std::atof(next().c_str());
    else if (arg == "--handle")
      handle = std::atof(next().c_str());
    else if (arg == "--translate")
      for (double& c : translate)
        c = std::atof(next().c_str());
    else if (arg == "--moves")
      moves = std::max(1, std::atoi(next().c_str()));
    else if (arg == "--order")
      filter->SetOperatorOrder(std::atoi(next().c_str()));
    else if (arg == "--weights")
      filter->SetLaplacianWeights(next() == "cotangent" ? 1 : 0);
    else if (arg == "--solver")
      filter->SetSolver(next() == "ldlt" ? 1 : 0);
    else if (arg == "--mode")
    {
      const std::string mode = next();
      filter->SetRotationMode(mode == "explicit" ? 1 : (mode == "implicit" ? 2 : 0));
    }
    else if (arg == "--iterations")
      filter->SetNumberOfIterations(std::atoi(next().c_str()));
    else if (arg == "--no-rescale")
      filter->PreserveDetailScaleOff();
    else
    {
      std::cerr << "unknown argument " << arg << "\n";
      return EXIT_FAILURE;
    }
  }
  if (!usePoint)
  {
    if (vertex < 0 || vertex >= mesh->GetNumberOfPoints())
    {
      std::cerr << "error: vertex " << vertex << " out of range\n";
      return EXIT_FAILURE;
    }
    mesh->GetPoint(vertex, point);
  }
  const double diagonal = mesh->GetLength();
  filter->SetInputData(mesh);
  filter->SetHandleCenter(point);
  filter->SetROIRadius(roi * diagonal);
  filter->SetHandleRadius(handle * diagonal);
  vtkNew<vtkTransform> transform;
  filter->SetHandleTransform(transform);
  filter->Update();
  const int factorizations = filter->GetNumberOfFactorizations();
  if (factorizations == 0)
  {
    std::cerr << "error: setup failed\n";
    return EXIT_FAILURE;
  }
  const double setup = filter->GetSetupTime();
  const double analysis = filter->GetAnalysisTime();
  const double factorization = filter->GetFactorizationTime();

  std::vector<double> solveTimes, updateTimes;
  for (int move = 1; move <= moves; ++move)
  {
    const double s = static_cast<double>(move) / moves;
    transform->Identity();
    transform->Translate(
      s * translate[0] * diagonal, s * translate[1] * diagonal, s * translate[2] * diagonal);
    const auto start = std::chrono::steady_clock::now();
    filter->Update();
    updateTimes.push_back(
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    solveTimes.push_back(filter->GetSolveTime());
  }
  const char* weights = filter->GetLaplacianWeights() == 1 ? "cotangent" : "uniform";
  const char* solver = filter->GetSolver() == 0 ? "cholmod" : "ldlt";
  const char* modes[] = { "none", "explicit", "implicit" };
  std::cout << std::setprecision(6) << "{\"mesh\": \"" << argv[1] << "\", \"vertices\": "
            << mesh->GetNumberOfPoints() << ", \"roi_vertices\": " << filter->GetNumberOfROIVertices()
            << ", \"handle_vertices\": " << filter->GetNumberOfHandleVertices()
            << ", \"order\": " << filter->GetOperatorOrder() << ", \"weights\": \"" << weights
            << "\", \"solver\": \"" << solver << "\", \"mode\": \""
            << modes[filter->GetRotationMode()] << "\", \"iterations\": "
            << filter->GetNumberOfIterations() << ", \"setup_seconds\": " << setup
            << ", \"analysis_seconds\": " << analysis
            << ", \"factorization_seconds\": " << factorization
            << ", \"move_median_seconds\": " << Median(solveTimes)
            << ", \"update_median_seconds\": " << Median(updateTimes) << ", \"moves\": " << moves
            << ", \"factorizations\": " << filter->GetNumberOfFactorizations() << "}\n";
  // Moving the handle must never refactor.
  return filter->GetNumberOfFactorizations() == factorizations ? EXIT_SUCCESS : EXIT_FAILURE;
}
