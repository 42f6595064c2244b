// Template fitting against today's baselines, on Testing/Support/RegistrationCases.h's cases
// (the known warps articulated, bend and turned head; not the hinge, whose narrow band folds
// 3,904 of the bunny's triangles, so that its true shape is no fit's goal). Prints one JSON line
// per warp, case and method.
//
//   RegistrationBenchmark DATA_DIR [--warp articulated|bend|turned-head|all]
//     [--cases remeshed,noisy,hole,cloud,posed] [--landmarks N] [--seed S] [--subdivide L]
//     [--fit Setting=value,...] [--write DIR] [--landmark-error F]
//
// --landmark-error F moves each landmark's target F times the diagonal in a random direction: a
// hand's placement error, which every method meets (the figures otherwise are for exact pairs).
//
// --write DIR saves each case's fit as DIR/WARP-CASE.vtp, with its point arrays
// CorrespondenceError (each vertex's distance from its true position, as a share of the
// diagonal) and TrueDisplacement (its true position minus the fit's), to see where a fit misses.
//
// --fit sets the fit's settings for a measurement of them (RotationMode, OperatorOrder,
// BendingWeight, RotationSmoothing, InitialMatchWeight, FinalMatchWeight, LandmarkWeight,
// NumberOfStages, WarpRounds,
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

#include "vtkDoubleArray.h"
#include "vtkPointData.h"
#include "vtkThinPlateSplineTransform.h"
#include "vtkXMLPolyDataWriter.h"

#include <algorithm>
#include <chrono>
#include <random>
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
    { "LandmarkWeight", [](R* r, double v) { r->SetLandmarkWeight(v); } },
    { "NumberOfStages", [](R* r, double v) { r->SetNumberOfStages(static_cast<int>(v)); } },
    { "WarpRounds", [](R* r, double v) { r->SetWarpRounds(static_cast<int>(v)); } },
    { "RoundsPerStage", [](R* r, double v) { r->SetRoundsPerStage(static_cast<int>(v)); } },
    { "ARAPIterations", [](R* r, double v) { r->SetARAPIterations(static_cast<int>(v)); } },
    { "LandOnTarget", [](R* r, double v) { r->SetLandOnTarget(v != 0.0); } },
  };
  return setters;
}

// Each landmark target moved `length` in a random direction.
void Misplace(vtkPoints* targets, double length, unsigned seed)
{
  std::mt19937 random(seed);
  std::normal_distribution<double> normal(0.0, 1.0);
  for (vtkIdType i = 0; i < targets->GetNumberOfPoints(); ++i)
  {
    double p[3], d[3] = { normal(random), normal(random), normal(random) };
    targets->GetPoint(i, p);
    const double norm = vtkMath::Norm(d);
    for (int k = 0; k < 3; ++k)
    {
      p[k] += length * d[k] / norm;
    }
    targets->SetPoint(i, p);
  }
}

// The fit with how far each vertex is from its true position, written to `path`.
void WriteMisses(vtkPolyData* fitted, const Case& fit, double diagonal, const std::string& path)
{
  vtkNew<vtkPolyData> misses;
  misses->ShallowCopy(fitted);
  vtkNew<vtkDoubleArray> error, toTruth;
  error->SetName("CorrespondenceError");
  toTruth->SetName("TrueDisplacement");
  toTruth->SetNumberOfComponents(3);
  for (vtkIdType i = 0; i < fitted->GetNumberOfPoints(); ++i)
  {
    double p[3], truth[3], d[3];
    fitted->GetPoint(i, p);
    fit.Truth->GetPoint(i, truth);
    vtkMath::Subtract(truth, p, d);
    error->InsertNextValue(vtkMath::Norm(d) / diagonal);
    toTruth->InsertNextTuple(d);
  }
  misses->GetPointData()->AddArray(error);
  misses->GetPointData()->AddArray(toTruth);
  vtkNew<vtkXMLPolyDataWriter> writer;
  writer->SetInputData(misses);
  writer->SetFileName(path.c_str());
  writer->Write();
}

void RunCase(const KnownWarps::Warp& warp, const Case& fit,
  const std::vector<std::pair<std::string, double>>& settings, const std::string& write)
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
    auto* fitted = vtkPolyData::SafeDownCast(registration->GetOutput());
    Print(warp.Name, fit, "surface_registration", Measure(fitted, fit, diagonal), seconds);
    if (!write.empty())
    {
      WriteMisses(fitted, fit, diagonal, write + "/" + warp.Name + "-" + fit.Name + ".vtp");
    }
  }
}
}

int main(int argc, char* argv[])
{
  if (argc < 2 || std::string(argv[1]) == "--help")
  {
    std::cout << "usage: RegistrationBenchmark DATA_DIR [--warp articulated|bend|turned-head|all]\n"
                 "  [--cases remeshed,noisy,hole,cloud,posed] [--landmarks N] [--seed S] [--subdivide L]\n"
                 "  [--fit Setting=value,...] [--write DIR] [--landmark-error F]\n";
    return argc < 2 ? 1 : 0;
  }
  const std::string data = argv[1];
  std::string which = "all", cases = "remeshed,noisy,hole,cloud,posed", write;
  int landmarks = 8, subdivide = 0;
  double landmarkError = 0.0;
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
    else if (option == "--landmark-error")
    {
      landmarkError = std::stod(value);
    }
    else if (option == "--write")
    {
      write = value;
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
      RegistrationCases::Case fit = RegistrationCases::MakeCase(name, warp, landmarks, seed);
      Misplace(fit.Targets, landmarkError * warp.Mesh->GetLength(), seed);
      RunCase(warp, fit, settings, write);
    }
  }
  return 0;
}
