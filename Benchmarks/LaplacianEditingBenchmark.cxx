// Benchmark of setup and handle moves; prints one JSON line.
//
//   LaplacianEditingBenchmark MESH|--sphere N [--vertex V|largest | --point X Y Z] [--roi F] [--handle F]
//     [--translate DX DY DZ] [--moves N] [--order 1|2] [--weights uniform|cotangent]
//     [--solver cholmod|ldlt] [--ordering auto|amd|metis|nesdis]
//     [--mode none|explicit|implicit] [--iterations K] [--no-rescale]
//
// --sphere N generates a UV sphere of about N vertices instead of reading a mesh (for the
// scaling curve). --vertex largest picks the first vertex of the largest connected component.
// Radii (--roi, default 0.25; --handle, default 0.03) and the translation (default 0 0 0.05)
// are fractions of the bounding-box diagonal. The JSON line also gives the peak resident memory
// of the process and the BLAS library that CHOLMOD runs on. Each move sets a new handle transform and
// updates the filter; the move time is the filter's solve and output time, and the wall time
// of the whole Update() is reported too.
#include "MeshReader.h"

#include "vtkLaplacianDeformationFilter.h"

#include "vtkIdTypeArray.h"
#include "vtkPointData.h"
#include "vtkPolyDataConnectivityFilter.h"
#include "vtkSphereSource.h"
#include "vtkTransform.h"

#include <sys/resource.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <fstream>
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

double PeakMemoryMegabytes()
{
  rusage usage;
  getrusage(RUSAGE_SELF, &usage);
  return usage.ru_maxrss / 1024.0;
}

// The BLAS library mapped into this process: CHOLMOD's supernodes run on it.
std::string LoadedBlas()
{
  std::ifstream maps("/proc/self/maps");
  std::string line;
  while (std::getline(maps, line))
  {
    for (const char* name : { "openblas", "libblas", "mkl", "blis", "atlas" })
    {
      if (line.find(name) != std::string::npos)
      {
        return line.substr(line.find('/'));
      }
    }
  }
  return "none";
}

vtkSmartPointer<vtkPolyData> Sphere(double vertices)
{
  vtkNew<vtkSphereSource> sphere;
  const int phi = std::max(8, static_cast<int>(std::sqrt(vertices / 2.0)));
  sphere->SetPhiResolution(phi);
  sphere->SetThetaResolution(2 * phi);
  sphere->Update();
  return sphere->GetOutput();
}

vtkIdType FirstVertexOfLargestComponent(vtkPolyData* mesh)
{
  vtkNew<vtkPolyDataConnectivityFilter> connectivity;
  connectivity->SetInputData(mesh);
  connectivity->SetExtractionModeToAllRegions();
  connectivity->ColorRegionsOn();
  connectivity->Update();
  vtkIdTypeArray* sizes = connectivity->GetRegionSizes();
  vtkIdType largest = 0;
  for (vtkIdType r = 1; r < sizes->GetNumberOfTuples(); ++r)
  {
    largest = sizes->GetValue(r) > sizes->GetValue(largest) ? r : largest;
  }
  vtkDataArray* regions = connectivity->GetOutput()->GetPointData()->GetArray("RegionId");
  for (vtkIdType i = 0; i < regions->GetNumberOfTuples(); ++i)
  {
    if (regions->GetTuple1(i) == largest)
    {
      return mesh->FindPoint(connectivity->GetOutput()->GetPoint(i));
    }
  }
  return 0;
}
}

int main(int argc, char* argv[])
{
  if (argc < 2)
  {
    std::cerr << "usage: " << argv[0]
              << " MESH [--vertex V | --point X Y Z] [--roi F] [--handle F] [--translate DX DY DZ]"
                 " [--moves N] [--order 1|2] [--weights uniform|cotangent] [--solver cholmod|ldlt]"
                 " [--ordering auto|amd|metis|nesdis] [--mode none|explicit|implicit] [--iterations K]"
                 " [--no-rescale]\n";
    return EXIT_FAILURE;
  }
  std::string error;
  const std::string meshName =
    std::string(argv[1]) == "--sphere" && argc > 2 ? "sphere-" + std::string(argv[2]) : argv[1];
  vtkSmartPointer<vtkPolyData> mesh = meshName.rfind("sphere-", 0) == 0
    ? Sphere(std::atof(argv[2]))
    : MeshReader::Read(argv[1], error);
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
  bool largest = false;
  for (int i = meshName == argv[1] ? 2 : 3; i < argc; ++i)
  {
    const std::string arg = argv[i];
    auto next = [&]() { return i + 1 < argc ? std::string(argv[++i]) : std::string(); };
    if (arg == "--vertex")
    {
      const std::string value = next();
      largest = value == "largest";
      vertex = largest ? 0 : std::atol(value.c_str());
    }
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
    else if (arg == "--ordering")
    {
      const std::string ordering = next();
      filter->SetOrdering(ordering == "amd" ? 1 : ordering == "metis" ? 2 : ordering == "nesdis" ? 3 : 0);
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
  if (largest)
  {
    vertex = FirstVertexOfLargestComponent(mesh);
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
  const char* orderings[] = { "auto", "amd", "metis", "nesdis" };
  std::cout << std::setprecision(6) << "{\"mesh\": \"" << meshName << "\", \"vertices\": "
            << mesh->GetNumberOfPoints() << ", \"roi_vertices\": " << filter->GetNumberOfROIVertices()
            << ", \"handle_vertices\": " << filter->GetNumberOfHandleVertices()
            << ", \"order\": " << filter->GetOperatorOrder() << ", \"weights\": \"" << weights
            << "\", \"solver\": \"" << solver << "\", \"ordering\": \""
            << orderings[filter->GetOrdering()] << "\", \"mode\": \""
            << modes[filter->GetRotationMode()] << "\", \"iterations\": "
            << filter->GetNumberOfIterations() << ", \"setup_seconds\": " << setup
            << ", \"analysis_seconds\": " << analysis
            << ", \"factorization_seconds\": " << factorization
            << ", \"move_median_seconds\": " << Median(solveTimes)
            << ", \"update_median_seconds\": " << Median(updateTimes) << ", \"moves\": " << moves
            << ", \"factorizations\": " << filter->GetNumberOfFactorizations()
            << ", \"peak_memory_mb\": " << PeakMemoryMegabytes() << ", \"blas\": \"" << LoadedBlas()
            << "\"}\n";
  // Moving the handle must never refactor.
  return filter->GetNumberOfFactorizations() == factorizations ? EXIT_SUCCESS : EXIT_FAILURE;
}
