// Template fitting against today's baselines, on Testing/Support/RegistrationCases.h's cases
// (the known warps articulated, bend and turned head; not the hinge, whose narrow band folds
// 3,904 of the bunny's triangles, so that its true shape is no fit's goal). Prints one JSON line
// per warp, case and method.
//
//   RegistrationBenchmark DATA_DIR [--warp articulated|bend|turned-head|all]
//     [--cases remeshed,noisy,hole,cloud,posed] [--landmarks N] [--seed S] [--subdivide L]
//     [--fit Setting=value,...]
//
// --fit sets the fit's settings for a measurement of them (RotationMode, OperatorOrder,
// BendingWeight, RotationSmoothing, InitialMatchWeight, FinalMatchWeight, NumberOfStages, WarpRounds,
// RoundsPerStage, ARAPIterations, LandOnTarget); the defaults otherwise.
//
// --subdivide L fits a template Loop-subdivided L times (4^L times the vertices; the
// articulated Armadillo's 37k become 149k at L = 1), its true shape the same warp's.
//
// Methods: vtkLaplacianSurfaceRegistration (its defaults) on the whole target with the landmarks;
// VTK's vtkThinPlateSplineTransform (its default kernel) and vtkLaplacianLandmarkWarp (its
// defaults), each on the landmarks alone; and "truth", the true shape itself, whose distance to
// the target is what remeshing and noise leave. Measures (RegistrationCases::Measure): the
// correspondence error and the distance to the target in percent of the template's diagonal, the
// triangles turned over against the true shape, and the seconds.
#include "BenchmarkMeasures.h"
#include "RegistrationCases.h"

#include "vtkLaplacianLandmarkWarp.h"
#include "vtkLaplacianSurfaceRegistration.h"

#include "vtkPointData.h"
#include "vtkThinPlateSplineTransform.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iomanip>
#include <functional>
#include <iostream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace
{
using Clock = BenchmarkMeasures::Clock;
using BenchmarkMeasures::SecondsSince;
using BenchmarkMeasures::Split;
using RegistrationCases::Case;
using RegistrationCases::Measure;
using RegistrationCases::Measures;

void Print(const std::string& warp, const Case& fit, const std::string& method,
  const Measures& m, double seconds)
{
  std::cout << std::setprecision(4) << "{\"warp\": \"" << warp << "\", \"case\": \"" << fit.Name
            << "\", \"method\": \"" << method << "\", \"landmarks\": "
            << fit.Sources->GetNumberOfPoints()
            << ", \"target_points\": " << fit.Target->GetNumberOfPoints()
            << ", \"correspondence_percent\": " << m.Correspondence
            << ", \"to_target_percent\": " << m.ToTarget << ", \"turned_over\": " << m.TurnedOver
            << ", \"seconds\": " << seconds << "}" << std::endl;
}

using Setter = std::function<void(vtkLaplacianSurfaceRegistration*, double)>;

// The settings --fit may set, by name.
const std::map<std::string, Setter>& FitSetters()
{
  using R = vtkLaplacianSurfaceRegistration;
  static const std::map<std::string, Setter> setters = {
    { "RotationMode", [](R* r, double v) { r->SetRotationMode(static_cast<int>(v)); } },
    { "OperatorOrder", [](R* r, double v) { r->SetOperatorOrder(static_cast<int>(v)); } },
    { "BendingWeight", [](R* r, double v) { r->SetBendingWeight(v); } },
    { "RotationSmoothing", [](R* r, double v) { r->SetRotationSmoothing(v); } },
    { "InitialMatchWeight", [](R* r, double v) { r->SetInitialMatchWeight(v); } },
    { "FinalMatchWeight", [](R* r, double v) { r->SetFinalMatchWeight(v); } },
    { "NumberOfStages", [](R* r, double v) { r->SetNumberOfStages(static_cast<int>(v)); } },
    { "WarpRounds", [](R* r, double v) { r->SetWarpRounds(static_cast<int>(v)); } },
    { "RoundsPerStage", [](R* r, double v) { r->SetRoundsPerStage(static_cast<int>(v)); } },
    { "ARAPIterations", [](R* r, double v) { r->SetARAPIterations(static_cast<int>(v)); } },
    { "LandOnTarget", [](R* r, double v) { r->SetLandOnTarget(v != 0.0); } },
  };
  return setters;
}

void RunCase(const KnownWarps::Warp& warp, const Case& fit,
  const std::vector<std::pair<std::string, double>>& settings)
{
  const double diagonal = warp.Mesh->GetLength();
  {
    // The true shape itself: its distance to the target is the floor of any fit's.
    auto truth = vtkSmartPointer<vtkPolyData>::New();
    truth->ShallowCopy(warp.Mesh);
    truth->SetPoints(fit.Truth);
    Print(warp.Name, fit, "truth", Measure(truth, fit, diagonal), 0.0);
  }
  {
    const auto start = Clock::now();
    vtkNew<vtkThinPlateSplineTransform> spline;
    spline->SetSourceLandmarks(fit.Sources);
    spline->SetTargetLandmarks(fit.Targets);
    auto splined = vtkSmartPointer<vtkPolyData>::New();
    splined->ShallowCopy(warp.Mesh);
    vtkNew<vtkPoints> moved;
    moved->SetDataTypeToDouble();
    spline->TransformPoints(warp.Mesh->GetPoints(), moved);
    splined->SetPoints(moved);
    const double seconds = SecondsSince(start);
    Print(warp.Name, fit, "thin_plate_spline", Measure(splined, fit, diagonal), seconds);
  }
  {
    const auto start = Clock::now();
    vtkNew<vtkLaplacianLandmarkWarp> landmarkWarp;
    landmarkWarp->SetInputData(warp.Mesh);
    landmarkWarp->SetSourceLandmarks(fit.Sources);
    landmarkWarp->SetTargetLandmarks(fit.Targets);
    landmarkWarp->Update();
    const double seconds = SecondsSince(start);
    Print(warp.Name, fit, "landmark_warp",
      Measure(vtkPolyData::SafeDownCast(landmarkWarp->GetOutput()), fit, diagonal), seconds);
  }
  {
    // The fit onto the whole target, with the same landmarks.
    const auto start = Clock::now();
    vtkNew<vtkPolyData> landmarks;
    landmarks->SetPoints(fit.Sources);
    vtkSmartPointer<vtkDataArray> places;
    places.TakeReference(fit.Targets->GetData()->NewInstance());
    places->DeepCopy(fit.Targets->GetData());
    places->SetName("Target");
    landmarks->GetPointData()->AddArray(places);
    vtkNew<vtkLaplacianSurfaceRegistration> registration;
    registration->SetInputData(warp.Mesh);
    registration->SetTargetData(fit.Target);
    registration->SetLandmarksData(landmarks);
    for (const auto& setting : settings)
    {
      FitSetters().at(setting.first)(registration, setting.second);
    }
    registration->Update();
    const double seconds = SecondsSince(start);
    Print(warp.Name, fit, "surface_registration",
      Measure(vtkPolyData::SafeDownCast(registration->GetOutput()), fit, diagonal), seconds);
  }
}
}

int main(int argc, char* argv[])
{
  if (argc < 2 || std::string(argv[1]) == "--help")
  {
    std::cout << "usage: RegistrationBenchmark DATA_DIR [--warp articulated|bend|turned-head|all]\n"
                 "  [--cases remeshed,noisy,hole,cloud,posed] [--landmarks N] [--seed S] [--subdivide L]\n"
                 "  [--fit Setting=value,...]\n";
    return argc < 2 ? 1 : 0;
  }
  const std::string data = argv[1];
  std::string which = "all", cases = "remeshed,noisy,hole,cloud,posed";
  int landmarks = 8, subdivide = 0;
  unsigned seed = 3;
  std::vector<std::pair<std::string, double>> settings;
  for (int i = 2; i + 1 < argc; i += 2)
  {
    const std::string option = argv[i], value = argv[i + 1];
    if (option == "--warp")
    {
      which = value;
    }
    else if (option == "--cases")
    {
      cases = value;
    }
    else if (option == "--landmarks")
    {
      landmarks = std::stoi(value);
    }
    else if (option == "--subdivide")
    {
      subdivide = std::stoi(value);
    }
    else if (option == "--fit")
    {
      for (const std::string& setting : Split(value))
      {
        const std::size_t equals = setting.find('=');
        const std::string name = setting.substr(0, equals);
        if (equals == std::string::npos || !FitSetters().count(name))
        {
          std::cerr << "unknown fit setting " << setting << "\n";
          return 1;
        }
        settings.emplace_back(name, std::stod(setting.substr(equals + 1)));
      }
    }
    else if (option == "--seed")
    {
      seed = static_cast<unsigned>(std::stoul(value));
    }
    else
    {
      std::cerr << "unknown option " << option << "\n";
      return 1;
    }
  }
  for (const auto& make : { KnownWarps::Articulated, KnownWarps::Bend, KnownWarps::TurnedHead })
  {
    KnownWarps::Warp warp = make(data);
    if (!warp.Mesh)
    {
      std::cerr << "cannot read the meshes of " << data << "\n";
      return 1;
    }
    std::replace(warp.Name.begin(), warp.Name.end(), ' ', '-');
    if (which != "all" && which != warp.Name)
    {
      continue;
    }
    if (subdivide > 0)
    {
      warp.Mesh = RegistrationCases::Subdivided(warp.Mesh, subdivide);
      warp.Name += "-" + std::to_string(warp.Mesh->GetNumberOfPoints());
    }
    for (const std::string& name : Split(cases))
    {
      RunCase(warp, RegistrationCases::MakeCase(name, warp, landmarks, seed), settings);
    }
  }
  return 0;
}
