// vtkLaplacianLandmarkWarp against VTK's vtkThinPlateSplineTransform, in one run, on surfaces
// with a known deformation (Testing/Support/KnownWarps.h: articulated, hinge, bend); prints one
// JSON line per warp, landmark count and method.
//
//   LandmarkWarpBenchmark DATA_DIR [--warp articulated|hinge|bend|all]
//     [--landmarks 100,300,1000,10000] [--tps-max N] [--tps-basis r2logr,r]
//     [--modes arap,none,explicit,implicit] [--bending W] [--spline-prior W]
//     [--rotation-smoothing A] [--drags N] [--draws N]
//
// Landmarks are random points on the surface (inside triangles), their targets the known
// motion of them. For each method: the root-mean-square distance of every vertex from the true
// shape and the largest drift of the part that should stay, both in fractions of the diagonal,
// and the seconds the warp took (a fresh filter: binding, factorization and solve). TPS runs up
// to --tps-max landmarks (1000; its time grows with the cube of the count), with VTK's default
// kernel (r2logr) or the 3D one (r). --bending, --spline-prior and --rotation-smoothing set the
// warp's BendingWeight, SplinePriorWeight and RotationSmoothing (their defaults: 100, 1, 0). After the largest count, --drags (20) updates move one landmark with the factorization
// reused (Dragging on): the median seconds an update and the factorizations in all. --draws
// repeats each count with other random landmarks (seeds 3, 4, ...), each line saying its draw.
#include "BenchmarkMeasures.h"
#include "KnownWarps.h"

#include "vtkLaplacianLandmarkWarp.h"

#include "vtkCellArray.h"
#include "vtkThinPlateSplineTransform.h"
#include "vtkTransformPolyDataFilter.h"

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

namespace
{
using Clock = BenchmarkMeasures::Clock;
using BenchmarkMeasures::SecondsSince;
using BenchmarkMeasures::Split;

// How far a result is from the known shape: over the vertices the triangles use.
struct Distance
{
  double RMS = 0.0;
  double StayDrift = 0.0;
};

Distance Measure(const KnownWarps::Warp& warp, vtkPoints* result)
{
  vtkPolyData* mesh = warp.Mesh;
  std::vector<char> used(mesh->GetNumberOfPoints(), 0);
  const vtkIdType* cell;
  vtkIdType size;
  auto polys = mesh->GetPolys();
  for (polys->InitTraversal(); polys->GetNextCell(size, cell);)
  {
    for (vtkIdType c = 0; c < size; ++c)
    {
      used[cell[c]] = 1;
    }
  }
  Distance distance;
  double sum = 0.0;
  vtkIdType count = 0;
  for (vtkIdType i = 0; i < mesh->GetNumberOfPoints(); ++i)
  {
    if (!used[i])
    {
      continue;
    }
    double p[3], truth[3], q[3];
    mesh->GetPoint(i, p);
    warp.Map(p, truth);
    result->GetPoint(i, q);
    sum += vtkMath::Distance2BetweenPoints(q, truth);
    ++count;
    if (warp.Stays(p))
    {
      distance.StayDrift = std::max(distance.StayDrift, std::sqrt(vtkMath::Distance2BetweenPoints(q, p)));
    }
  }
  const double diagonal = mesh->GetLength();
  distance.RMS = std::sqrt(sum / std::max<vtkIdType>(count, 1)) / diagonal;
  distance.StayDrift /= diagonal;
  return distance;
}

void Report(const KnownWarps::Warp& warp, vtkIdType landmarks, const std::string& method,
  const Distance& distance, double seconds, const std::string& extra = "")
{
  std::cout << std::setprecision(4) << "{\"warp\": \"" << warp.Name << "\", \"vertices\": "
            << warp.Mesh->GetNumberOfPoints() << ", \"landmarks\": " << landmarks
            << ", \"method\": \"" << method << "\", \"rms\": " << distance.RMS
            << ", \"stay_drift\": " << distance.StayDrift << ", \"seconds\": " << seconds << extra
            << "}" << std::endl;
}

int ModeNamed(const std::string& name)
{
  if (name == "none")
  {
    return vtkLaplacianLandmarkWarp::ROTATION_NONE;
  }
  if (name == "explicit")
  {
    return vtkLaplacianLandmarkWarp::ROTATION_EXPLICIT;
  }
  if (name == "implicit")
  {
    return vtkLaplacianLandmarkWarp::ROTATION_IMPLICIT;
  }
  return vtkLaplacianLandmarkWarp::ROTATION_AS_RIGID_AS_POSSIBLE;
}

void RunThinPlateSpline(const KnownWarps::Warp& warp, vtkPoints* sources, vtkPoints* targets,
  const std::string& basis, int draw)
{
  vtkNew<vtkThinPlateSplineTransform> spline;
  if (basis == "r")
  {
    spline->SetBasisToR(); // the 3D thin-plate spline's kernel
  }
  else
  {
    spline->SetBasisToR2LogR(); // VTK's default, the 2D kernel
  }
  spline->SetSourceLandmarks(sources);
  spline->SetTargetLandmarks(targets);
  vtkNew<vtkTransformPolyDataFilter> transform;
  transform->SetInputData(warp.Mesh);
  transform->SetTransform(spline);
  const auto start = Clock::now();
  transform->Update();
  const double seconds = SecondsSince(start);
  Report(warp, sources->GetNumberOfPoints(), "tps-" + basis, Measure(warp, transform->GetOutput()->GetPoints()),
    seconds, ", \"draw\": " + std::to_string(draw));
}

// The warp's weights the command line sets; negative: the filter's default.
struct WarpWeights
{
  double Bending = -1.0;
  double SplinePrior = -1.0;
  double RotationSmoothing = -1.0;
};

vtkSmartPointer<vtkLaplacianLandmarkWarp> RunWarp(const KnownWarps::Warp& warp, vtkPoints* sources,
  vtkPoints* targets, const std::string& mode, const WarpWeights& weights, int draw)
{
  auto filter = vtkSmartPointer<vtkLaplacianLandmarkWarp>::New();
  filter->SetInputData(warp.Mesh);
  filter->SetSourceLandmarks(sources);
  filter->SetTargetLandmarks(targets);
  filter->SetRotationMode(ModeNamed(mode));
  if (weights.Bending >= 0.0)
  {
    filter->SetBendingWeight(weights.Bending);
  }
  if (weights.SplinePrior >= 0.0)
  {
    filter->SetSplinePriorWeight(weights.SplinePrior);
  }
  if (weights.RotationSmoothing >= 0.0)
  {
    filter->SetRotationSmoothing(weights.RotationSmoothing);
  }
  const auto start = Clock::now();
  filter->Update();
  const double seconds = SecondsSince(start);
  std::ostringstream extra;
  extra << std::setprecision(3) << ", \"bind_seconds\": " << filter->GetBindingTime()
        << ", \"setup_seconds\": " << filter->GetSetupTime()
        << ", \"solve_seconds\": " << filter->GetSolveTime()
        << ", \"arap_iterations\": " << filter->GetNumberOfARAPIterations()
        << ", \"largest_miss\": " << filter->GetMaximumLandmarkDistance() / warp.Mesh->GetLength()
        << ", \"draw\": " << draw;
  Report(warp, sources->GetNumberOfPoints(), mode, Measure(warp, filter->GetPolyDataOutput()->GetPoints()),
    seconds, extra.str());
  return filter;
}

// One landmark dragged among all of them: its target moves a little each update.
void RunDrag(const KnownWarps::Warp& warp, vtkLaplacianLandmarkWarp* filter, vtkPoints* targets, int drags)
{
  const int factorizations = filter->GetNumberOfFactorizations();
  filter->DraggingOn();
  double start[3];
  targets->GetPoint(0, start);
  const double step = 0.002 * warp.Mesh->GetLength();
  std::vector<double> seconds;
  for (int d = 1; d <= drags; ++d)
  {
    targets->SetPoint(0, start[0] + d * step, start[1] + d * step, start[2]);
    targets->Modified();
    const auto begin = Clock::now();
    filter->Update();
    seconds.push_back(SecondsSince(begin));
  }
  std::sort(seconds.begin(), seconds.end());
  std::cout << std::setprecision(4) << "{\"warp\": \"" << warp.Name
            << "\", \"landmarks\": " << targets->GetNumberOfPoints()
            << ", \"method\": \"drag one landmark\", \"median_seconds\": "
            << (seconds.empty() ? 0.0 : seconds[seconds.size() / 2])
            << ", \"arap_iterations\": " << filter->GetNumberOfARAPIterations()
            << ", \"new_factorizations\": " << filter->GetNumberOfFactorizations() - factorizations
            << ", \"largest_miss\": " << filter->GetMaximumLandmarkDistance() / warp.Mesh->GetLength()
            << "}" << std::endl;
}
} // namespace

int main(int argc, char* argv[])
{
  if (argc < 2 || std::string(argv[1]) == "--help")
  {
    std::cout << "usage: LandmarkWarpBenchmark DATA_DIR [--warp articulated|hinge|bend|all]\n"
                 "  [--landmarks 100,300,1000,10000] [--tps-max N] "
                 "[--tps-basis r2logr,r] [--modes arap,none,explicit,implicit] [--bending W] "
                 "[--spline-prior W] [--rotation-smoothing A] [--drags N] [--draws N]\n";
    return argc < 2 ? EXIT_FAILURE : EXIT_SUCCESS;
  }
  const std::string dataDir = argv[1];
  std::string which = "all", modes = "arap", bases = "r2logr";
  std::vector<std::string> counts = { "100", "300", "1000", "10000" };
  vtkIdType tpsMax = 1000;
  int drags = 20;
  int draws = 1;
  WarpWeights weights;
  for (int a = 2; a + 1 < argc; a += 2)
  {
    const std::string option = argv[a], value = argv[a + 1];
    if (option == "--warp")
    {
      which = value;
    }
    else if (option == "--landmarks")
    {
      counts = Split(value);
    }
    else if (option == "--tps-max")
    {
      tpsMax = std::stoll(value);
    }
    else if (option == "--modes")
    {
      modes = value;
    }
    else if (option == "--tps-basis")
    {
      bases = value;
    }
    else if (option == "--bending")
    {
      weights.Bending = std::stod(value);
    }
    else if (option == "--spline-prior")
    {
      weights.SplinePrior = std::stod(value);
    }
    else if (option == "--rotation-smoothing")
    {
      weights.RotationSmoothing = std::stod(value);
    }
    else if (option == "--drags")
    {
      drags = std::stoi(value);
    }
    else if (option == "--draws")
    {
      draws = std::stoi(value);
    }
    else
    {
      std::cerr << "unknown option " << option << "\n";
      return EXIT_FAILURE;
    }
  }
  for (const auto& warp : KnownWarps::All(dataDir))
  {
    if (which != "all" && which != warp.Name)
    {
      continue;
    }
    if (!warp.Mesh || warp.Mesh->GetNumberOfPoints() == 0)
    {
      std::cerr << "cannot read the mesh of the " << warp.Name << " warp in " << dataDir << "\n";
      return EXIT_FAILURE;
    }
    vtkSmartPointer<vtkLaplacianLandmarkWarp> last;
    vtkSmartPointer<vtkPoints> lastTargets;
    for (const auto& count : counts)
    {
      for (int draw = 0; draw < draws; ++draw)
      {
        const vtkIdType landmarks = std::stoll(count);
        auto sources = KnownWarps::SurfacePoints(warp.Mesh, landmarks, 3 + draw);
        auto targets = KnownWarps::Moved(sources, warp.Map);
        if (landmarks <= tpsMax)
        {
          for (const auto& basis : Split(bases))
          {
            RunThinPlateSpline(warp, sources, targets, basis, draw);
          }
        }
        for (const auto& mode : Split(modes))
        {
          last = RunWarp(warp, sources, targets, mode, weights, draw);
          lastTargets = targets;
        }
      }
    }
    if (last && drags > 0)
    {
      RunDrag(warp, last, lastTargets, drags);
    }
  }
  return EXIT_SUCCESS;
}
