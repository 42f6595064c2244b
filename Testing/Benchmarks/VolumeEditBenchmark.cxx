// vtkLaplacianVolumeDeformationFilter on tetgen's meshes of the closed surfaces in DATA_DIR,
// against what else carries a boundary edit into a volume: the interior left where it was, and
// the harmonic extension (the P1 displacement Laplacian with uniform diffusivity, the CFD mesh
// motion solvers' default). Prints one JSON line per mesh and method.
//
//   VolumeEditBenchmark DATA_DIR [--meshes spot:90,homer:60] [--switches pq1.4a0.0005]
//     [--cache DIR] [--roi 0.3] [--handle 0.03] [--lift 0.1] [--drags 10]
//     [--drag-iterations K] [--no-drag-graph] [--settle-limit S] [--write DIR] [--meshes-only]
//
// The edit (one per mesh, NAME:DEGREES): the handle on the boundary point farthest from the
// centroid, radius --handle and region --roi of the diagonal, as-rigid-as-possible; it turns by
// DEGREES about the axis across the line from the centroid, about the handle, and moves --lift of
// the diagonal the way it turns. Every method gets the same boundary motion, the surface filter's.
// Inverted cells and the smallest scaled Jacobian are vtkMeshQuality's (Verdict). The filter's
// settled update reports its zone, iterations and seconds; then --drags steps of a drag to the same
// pose (Dragging on, factors reused): the median seconds a step of the volume filter (its first,
// which prepares the zone and its graph, and its longest after the first), and of the surface
// filter alone on the boundary surface; the steps the deformation graph took and the cells it
// repaired; the largest distance of a boundary point from its edited position in any
// step, and the drag's lag: the largest distance of a point at the drag's end from the settled
// volume of its release, and the release's boundary from the settled update's (as shares of the
// diagonal; --drag-iterations sets the filter's DragVolumeIterations, --no-drag-graph turns its
// DragGraph off (drag steps by the injective iteration alone); --settle-limit gives the
// release a SettleTimeLimit of S seconds and continues it update by update, as the ParaView
// panel does, reporting the updates and the longest), and the process's peak memory (of the whole
// run, every method's). --write saves the rest, settled and released meshes as .vtu for a look in
// ParaView (the released one with its EditFailed cells); --meshes-only makes the meshes and stops.
#include "BenchmarkMeasures.h"
#include "VolumeMeshes.h"

#include "SparseCholesky.h"
#include "Stopwatch.h"

#include "vtkLaplacianDeformationFilter.h"
#include "vtkLaplacianVolumeDeformationFilter.h"

#include "vtkGeometryFilter.h"
#include "vtkMath.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkXMLUnstructuredGridWriter.h"

#include <Eigen/Geometry>
#include <Eigen/LU>
#include <Eigen/SparseCore>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

namespace
{
namespace le = LaplacianEditing;

struct Options
{
  std::string Data;
  std::string Meshes = "spot:90,homer:60";
  std::string Switches = "pq1.4a0.0005";
  std::string Cache = ".";
  std::string Write;
  double ROI = 0.3;
  double Handle = 0.03;
  double Lift = 0.1;
  int Drags = 10;
  int DragIterations = 0; // 0: the filter's default
  bool DragGraph = true;
  double SettleLimit = 0.0; // 0: the release settles in one update
  bool MeshesOnly = false;
};

void Configure(
  vtkLaplacianDeformationFilter* filter, const VolumeMeshes::Edit& edit, const Options& options)
{
  filter->SetRadiusUnitsToDiagonalFraction();
  filter->SetHandleCenter(edit.Center);
  filter->SetHandleRadius(options.Handle);
  filter->SetROIRadius(options.ROI);
  filter->SetRotationModeToAsRigidAsPossible();
}

// The largest distance between the same point in `a` and in `b`.
double LargestDistance(vtkPoints* a, vtkPoints* b)
{
  double largest = 0.0;
  for (vtkIdType i = 0; i < a->GetNumberOfPoints(); ++i)
  {
    double p[3], q[3];
    a->GetPoint(i, p);
    b->GetPoint(i, q);
    largest = std::max(largest, std::sqrt(vtkMath::Distance2BetweenPoints(p, q)));
  }
  return largest;
}

// The rest grid with its points replaced.
vtkSmartPointer<vtkUnstructuredGrid> WithPoints(vtkUnstructuredGrid* rest, vtkPoints* points)
{
  auto grid = vtkSmartPointer<vtkUnstructuredGrid>::New();
  grid->ShallowCopy(rest);
  grid->SetPoints(points);
  return grid;
}

// The harmonic extension of the boundary's displacement into the tetrahedra: K_ii u_i = -K_ib u_b
// with K the P1 stiffness matrix.
vtkSmartPointer<vtkPoints> HarmonicExtension(
  vtkUnstructuredGrid* rest, vtkPoints* boundary, const std::vector<char>& onBoundary)
{
  const vtkIdType n = rest->GetNumberOfPoints();
  std::vector<int> unknown(n, -1);
  int unknowns = 0;
  for (vtkIdType i = 0; i < n; ++i)
  {
    unknown[i] = onBoundary[i] ? -1 : unknowns++;
  }
  std::vector<Eigen::Triplet<double>> triplets;
  Eigen::MatrixXd rhs = Eigen::MatrixXd::Zero(unknowns, 3);
  for (vtkIdType cell = 0; cell < rest->GetNumberOfCells(); ++cell)
  {
    vtkIdType count;
    const vtkIdType* ids;
    rest->GetCellPoints(cell, count, ids);
    if (rest->GetCellType(cell) != VTK_TETRA)
    {
      continue;
    }
    Eigen::Matrix3d edges;
    const Eigen::Vector3d origin(rest->GetPoint(ids[0]));
    for (int k = 0; k < 3; ++k)
    {
      edges.col(k) = Eigen::Vector3d(rest->GetPoint(ids[k + 1])) - origin;
    }
    const double volume = std::abs(edges.determinant()) / 6.0;
    const Eigen::Matrix3d inverse = edges.inverse();
    Eigen::Matrix<double, 4, 3> gradients;
    gradients.row(0) = -inverse.colwise().sum();
    gradients.bottomRows<3>() = inverse;
    const Eigen::Matrix4d block = volume * gradients * gradients.transpose();
    for (int a = 0; a < 4; ++a)
    {
      if (unknown[ids[a]] < 0)
      {
        continue;
      }
      for (int b = 0; b < 4; ++b)
      {
        if (unknown[ids[b]] >= 0)
        {
          triplets.emplace_back(unknown[ids[a]], unknown[ids[b]], block(a, b));
        }
        else
        {
          const Eigen::Vector3d moved(boundary->GetPoint(ids[b]));
          const Eigen::Vector3d at(rest->GetPoint(ids[b]));
          rhs.row(unknown[ids[a]]) -= block(a, b) * (moved - at).transpose();
        }
      }
    }
  }
  Eigen::SparseMatrix<double> stiffness(unknowns, unknowns);
  stiffness.setFromTriplets(triplets.begin(), triplets.end());
  le::SparseCholesky factor;
  const std::string error = factor.Factorize(stiffness, le::SolverBackend::Cholmod);
  auto points = vtkSmartPointer<vtkPoints>::New();
  points->DeepCopy(boundary);
  if (!error.empty())
  {
    std::cerr << error << "\n";
    return points;
  }
  const Eigen::MatrixXd displacement = factor.Solve(rhs);
  for (vtkIdType i = 0; i < n; ++i)
  {
    if (unknown[i] >= 0)
    {
      const Eigen::Vector3d p = Eigen::Vector3d(rest->GetPoint(i)) +
        displacement.row(unknown[i]).transpose();
      points->SetPoint(i, p.data());
    }
  }
  return points;
}

void Report(const std::string& mesh, const std::string& method, vtkUnstructuredGrid* grid,
  const std::string& extra = "")
{
  const VolumeMeshes::Validity validity = VolumeMeshes::Measure(grid);
  std::printf("{\"mesh\": \"%s\", \"method\": \"%s\", \"tetrahedra\": %lld, \"inverted\": %lld, "
              "\"smallest_scaled_jacobian\": %.4g%s}\n",
    mesh.c_str(), method.c_str(), static_cast<long long>(grid->GetNumberOfCells()),
    static_cast<long long>(validity.Inverted), validity.SmallestScaledJacobian, extra.c_str());
  std::fflush(stdout);
}

using BenchmarkMeasures::Median;

void Run(const std::string& name, double degrees, const Options& options)
{
  std::string error;
  vtkSmartPointer<vtkUnstructuredGrid> rest = VolumeMeshes::Tetrahedralize(
    options.Data + "/" + name + ".obj", options.Cache, name, options.Switches, error);
  if (!rest)
  {
    std::cerr << name << ": " << error << "\n";
    return;
  }
  if (options.MeshesOnly)
  {
    std::printf("{\"mesh\": \"%s\", \"points\": %lld, \"tetrahedra\": %lld}\n", name.c_str(),
      static_cast<long long>(rest->GetNumberOfPoints()),
      static_cast<long long>(rest->GetNumberOfCells()));
    return;
  }
  const VolumeMeshes::Edit edit = VolumeMeshes::FarEdit(rest, degrees, options.Lift);
  std::ostringstream what;
  what << name << " " << degrees << " deg";

  // The filter, settled.
  vtkNew<vtkLaplacianVolumeDeformationFilter> volume;
  volume->SetInputData(rest);
  Configure(volume->GetSurfaceFilter(), edit, options);
  volume->SetHandleTransform(edit.At(1.0));
  const le::Stopwatch watch;
  volume->Update();
  const double seconds = watch.Seconds();
  vtkUnstructuredGrid* edited = volume->GetOutput();
  std::ostringstream facts;
  facts << ", \"zone_points\": " << volume->GetNumberOfZonePoints()
        << ", \"zone_tetrahedra\": " << volume->GetNumberOfZoneTetrahedra()
        << ", \"iterations\": " << volume->GetNumberOfVolumeIterations()
        << ", \"growths\": " << volume->GetNumberOfZoneGrowths()
        << ", \"failed_cells\": " << volume->GetNumberOfFailedCells()
        << ", \"largest_miss\": " << volume->GetLargestTargetMiss() / rest->GetLength()
        << ", \"seconds\": " << seconds << ", \"volume_setup\": " << volume->GetVolumeSetupTime()
        << ", \"volume_solve\": " << volume->GetVolumeSolveTime();
  Report(what.str(), "filter", edited, facts.str());

  // The same boundary, the interior at rest or harmonically extended.
  vtkPoints* surface = volume->GetSurfaceFilter()->GetOutput()->GetPoints();
  vtkNew<vtkGeometryFilter> boundaryFilter;
  boundaryFilter->SetInputData(rest);
  boundaryFilter->PassThroughPointIdsOn();
  boundaryFilter->Update();
  std::vector<char> onBoundary(rest->GetNumberOfPoints(), 0);
  {
    vtkPolyData* boundary = boundaryFilter->GetOutput();
    vtkDataArray* original = boundary->GetPointData()->GetArray("vtkOriginalPointIds");
    for (vtkIdType i = 0; i < boundary->GetNumberOfPoints(); ++i)
    {
      onBoundary[original ? static_cast<vtkIdType>(original->GetTuple1(i)) : i] = 1;
    }
  }
  vtkNew<vtkPoints> still;
  still->DeepCopy(rest->GetPoints());
  for (vtkIdType i = 0; i < rest->GetNumberOfPoints(); ++i)
  {
    if (onBoundary[i])
    {
      still->SetPoint(i, surface->GetPoint(i));
    }
  }
  Report(what.str(), "interior_at_rest", WithPoints(rest, still));
  const le::Stopwatch harmonicWatch;
  vtkSmartPointer<vtkPoints> harmonic = HarmonicExtension(rest, surface, onBoundary);
  std::ostringstream harmonicFacts;
  harmonicFacts << ", \"seconds\": " << harmonicWatch.Seconds();
  Report(what.str(), "harmonic_extension", WithPoints(rest, harmonic), harmonicFacts.str());

  auto write = [&](const char* suffix, vtkUnstructuredGrid* grid) {
    if (!options.Write.empty())
    {
      vtkNew<vtkXMLUnstructuredGridWriter> writer;
      writer->SetInputData(grid);
      writer->SetFileName((options.Write + "/" + name + "-" + suffix + ".vtu").c_str());
      writer->Write();
    }
  };
  write("rest", rest);
  write("edited", edited);

  // A drag to the same pose, from rest, as a widget makes it: the volume filter's steps, and the
  // surface filter's alone.
  if (options.Drags > 0)
  {
    vtkNew<vtkLaplacianVolumeDeformationFilter> dragged;
    dragged->SetInputData(rest);
    Configure(dragged->GetSurfaceFilter(), edit, options);
    if (options.DragIterations > 0)
    {
      dragged->SetDragVolumeIterations(options.DragIterations);
    }
    dragged->SetDragGraph(options.DragGraph);
    vtkNew<vtkLaplacianDeformationFilter> alone;
    vtkNew<vtkPolyData> boundary;
    boundary->DeepCopy(boundaryFilter->GetOutput());
    alone->SetInputData(boundary);
    Configure(alone, edit, options);
    std::vector<double> volumeSteps, surfaceSteps;
    int iterations = 0, graphSteps = 0, repairedCells = 0;
    double dragMiss = 0.0;
    double dragLag = 0.0; // the drag's end from the release's settled volume, largest
    double release = 0.0;  // the volume's release update, boundary and interior
    int releaseIterations = 0, releaseFactorizations = 0, releaseGrowths = 0, releaseUpdates = 1;
    double releaseLongestUpdate = 0.0;
    double boundaryApart = 0.0; // the release's boundary from the settle's from rest, largest
    for (vtkLaplacianDeformationFilter* surfaceFilter : { dragged->GetSurfaceFilter(), alone.Get() })
    {
      const bool isVolume = surfaceFilter != alone.Get();
      vtkAlgorithm* filter = isVolume ? static_cast<vtkAlgorithm*>(dragged) : alone.Get();
      filter->Update();
      surfaceFilter->DraggingOn();
      for (int step = 1; step <= options.Drags; ++step)
      {
        surfaceFilter->SetHandleTransform(edit.At(static_cast<double>(step) / options.Drags));
        const le::Stopwatch stepWatch;
        filter->Update();
        (isVolume ? volumeSteps : surfaceSteps).push_back(stepWatch.Seconds());
        iterations += isVolume ? dragged->GetNumberOfVolumeIterations() : 0;
        graphSteps += isVolume && dragged->GetNumberOfGraphNodes() > 0;
        repairedCells += isVolume ? dragged->GetNumberOfRepairedCells() : 0;
        dragMiss = std::max(dragMiss, isVolume ? dragged->GetLargestTargetMiss() : 0.0);
      }
      vtkNew<vtkPoints> dragEnd; // the volume's points at the drag's end
      if (isVolume)
      {
        dragEnd->DeepCopy(dragged->GetOutput()->GetPoints());
      }
      surfaceFilter->DraggingOff();
      if (isVolume)
      {
        dragged->SetSettleTimeLimit(options.SettleLimit);
      }
      const le::Stopwatch releaseWatch;
      filter->Update();
      if (isVolume)
      {
        releaseLongestUpdate = releaseWatch.Seconds();
        for (;;)
        {
          releaseIterations += dragged->GetNumberOfVolumeIterations();
          releaseFactorizations += dragged->GetNumberOfVolumeFactorizations();
          releaseGrowths += dragged->GetNumberOfZoneGrowths();
          if (!dragged->GetSettling())
          {
            break;
          }
          ++releaseUpdates;
          const le::Stopwatch updateWatch;
          dragged->ContinueSettling();
          dragged->Update();
          releaseLongestUpdate = std::max(releaseLongestUpdate, updateWatch.Seconds());
        }
        release = releaseWatch.Seconds();
        dragLag = LargestDistance(dragEnd, dragged->GetOutput()->GetPoints());
        boundaryApart = LargestDistance(dragged->GetSurfaceFilter()->GetOutput()->GetPoints(), surface);
      }
    }
    std::ostringstream dragFacts;
    dragFacts << ", \"volume_step\": " << Median(volumeSteps)
              << ", \"volume_first_step\": " << volumeSteps.front()
              << ", \"volume_steps_after_first_max\": "
              << *std::max_element(volumeSteps.begin() + (volumeSteps.size() > 1), volumeSteps.end())
              << ", \"surface_step\": " << Median(surfaceSteps)
              // The fastest steps: on a shared machine, the figures least disturbed by others.
              << ", \"volume_step_fastest\": "
              << *std::min_element(volumeSteps.begin(), volumeSteps.end())
              << ", \"surface_step_fastest\": "
              << *std::min_element(surfaceSteps.begin(), surfaceSteps.end())
              << ", \"volume_iterations_per_step\": "
              << static_cast<double>(iterations) / options.Drags
              << ", \"volume_graph_steps\": " << graphSteps
              << ", \"volume_repaired_cells\": " << repairedCells
              << ", \"largest_drag_miss\": " << dragMiss / rest->GetLength()
              << ", \"drag_lag\": " << dragLag / rest->GetLength()
              << ", \"release_boundary_from_rest\": " << boundaryApart / rest->GetLength()
              << ", \"release\": " << release << ", \"release_iterations\": " << releaseIterations
              << ", \"release_factorizations\": " << releaseFactorizations
              << ", \"release_growths\": " << releaseGrowths
              << ", \"release_updates\": " << releaseUpdates
              << ", \"release_longest_update\": " << releaseLongestUpdate
              << ", \"surface_points\": " << boundary->GetNumberOfPoints()
              << ", \"peak_memory_mb\": " << BenchmarkMeasures::PeakMemoryMegabytes();
    Report(what.str(), "filter_dragged", dragged->GetOutput(), dragFacts.str());
    write("released", dragged->GetOutput());
  }
}
}

int main(int argc, char* argv[])
{
  Options options;
  for (int i = 1; i < argc; ++i)
  {
    const std::string arg = argv[i];
    auto next = [&]() -> std::string { return i + 1 < argc ? argv[++i] : ""; };
    if (arg == "--help" || arg == "-h")
    {
      std::cout << "VolumeEditBenchmark DATA_DIR [--meshes spot:90,homer:60] [--switches "
                   "pq1.4a0.0005] [--cache DIR] [--roi 0.3] [--handle 0.03] [--lift 0.1] "
                   "[--drags 10] [--drag-iterations K] [--no-drag-graph] [--settle-limit S] [--write DIR] [--meshes-only]\n";
      return 0;
    }
    else if (arg == "--meshes")
      options.Meshes = next();
    else if (arg == "--switches")
      options.Switches = next();
    else if (arg == "--cache")
      options.Cache = next();
    else if (arg == "--write")
      options.Write = next();
    else if (arg == "--roi")
      options.ROI = std::stod(next());
    else if (arg == "--handle")
      options.Handle = std::stod(next());
    else if (arg == "--lift")
      options.Lift = std::stod(next());
    else if (arg == "--drags")
      options.Drags = std::stoi(next());
    else if (arg == "--meshes-only")
      options.MeshesOnly = true;
    else if (arg == "--drag-iterations")
      options.DragIterations = std::stoi(next());
    else if (arg == "--no-drag-graph")
      options.DragGraph = false;
    else if (arg == "--settle-limit")
      options.SettleLimit = std::stod(next());
    else if (options.Data.empty())
      options.Data = arg;
    else
    {
      std::cerr << "unknown argument " << arg << "\n";
      return 1;
    }
  }
  if (options.Data.empty())
  {
    std::cerr << "VolumeEditBenchmark DATA_DIR [options]; --help lists them\n";
    return 1;
  }
  std::stringstream meshes(options.Meshes);
  for (std::string item; std::getline(meshes, item, ',');)
  {
    const auto colon = item.find(':');
    Run(item.substr(0, colon), colon == std::string::npos ? 90.0 : std::stod(item.substr(colon + 1)),
      options);
  }
  return 0;
}
