// Benchmark of setup and handle moves; prints one JSON line.
//
//   LaplacianEditingBenchmark MESH|--sphere N|--grid N [--vertex V|largest | --point X Y Z] [--roi F]
//     [--handle F] [--translate DX DY DZ] [--moves N] [--order 1|2]
//     [--weights uniform|cotangent] [--solver cholmod|ldlt] [--ordering auto|amd|metis|nesdis]
//     [--mode none|explicit|implicit|arap] [--iterations K] [--arap-iterations K] [--linear]
//     [--no-extrapolation] [--absolute] [--large-region N] [--proxy-nodes N]
//     [--drag-iterations K] [--settle-time-limit S] [--write DIR]
//     [--compare-cgal]
//
// --sphere N generates a UV sphere of about N vertices instead of reading a mesh (for the
// scaling curve), --grid N a flat square grid of about N points at unit spacing, with the
// handle at its centre. --vertex largest picks the first vertex of the largest connected
// component. Radii (--roi, default 0.25; --handle, default 0.03) and the translation (default
// 0 0 0.05) are fractions of the bounding-box diagonal, or mesh units with --absolute. Each move sets a new handle transform and
// updates the filter; "move" is the filter's solve and output time, "update" the wall time of
// the whole Update(). "topology" is building the surface graph (once per input mesh), "setup"
// the region's selection, assembly, factorization and precomputation (once per region). The line also gives the peak resident memory of the process and the BLAS
// library that CHOLMOD runs on.
//
// In the as-rigid-as-possible mode, the energies (the drag's last step, the release and the
// converged shape at the same pose, 1000 more iterations, or Newton steps where a large region
// settles, which stop at a 1e-8 decrease) are measured on the output itself,
// with the core's EditMeasures (clamped cotangent weights), independently of the filter's own
// figure, which a large region's drag gives for its proxy.
//
// --compare-cgal (when built with CGAL) measures, on the same welded mesh and the same
// selection (the filter's ROI and handle vertices), our setup and moves in every mode against
// CGAL's Surface_mesh_deformation with SRE-ARAP: its surface mesh and region, preprocess(), and
// deform(1) and deform(5) per move.
#include "BenchmarkMeasures.h"
#include "EditMeasures.h"
#include "MeshReader.h"
#include "SurfaceAdapter.h"
#include "SurfaceMesh.h"

#include "vtkLaplacianDeformationFilter.h"

#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkCleanPolyData.h"
#include "vtkIdTypeArray.h"
#include "vtkPlaneSource.h"
#include "vtkPointData.h"
#include "vtkPolyDataConnectivityFilter.h"
#include "vtkSphereSource.h"
#include "vtkTransform.h"
#include "vtkTriangleFilter.h"
#include "vtkXMLPolyDataWriter.h"

#ifdef LAPLACIAN_EDITING_HAS_CGAL
#include "CGALSurface.h"

#include <CGAL/Surface_mesh_deformation.h>
#endif

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

namespace
{
using Clock = BenchmarkMeasures::Clock;
using BenchmarkMeasures::SecondsSince;

using BenchmarkMeasures::Median;
using BenchmarkMeasures::PeakMemoryMegabytes;

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

// A flat square grid of about `points` points, unit spacing, triangles with point normals.
vtkSmartPointer<vtkPolyData> Grid(double points)
{
  const int side = std::max(2, static_cast<int>(std::lround(std::sqrt(points))));
  vtkNew<vtkPlaneSource> plane;
  plane->SetOrigin(0.0, 0.0, 0.0);
  plane->SetPoint1(side - 1.0, 0.0, 0.0);
  plane->SetPoint2(0.0, side - 1.0, 0.0);
  plane->SetResolution(side - 1, side - 1);
  vtkNew<vtkTriangleFilter> triangles;
  triangles->SetInputConnection(plane->GetOutputPort());
  triangles->Update();
  return triangles->GetOutput();
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

struct Options
{
  std::string Mesh;
  double SphereVertices = 0.0;
  double GridPoints = 0.0;
  bool Absolute = false;
  vtkIdType Vertex = 0;
  bool LargestComponent = false;
  bool UsePoint = false;
  double Point[3] = { 0.0, 0.0, 0.0 };
  double ROI = 0.25;
  double Handle = 0.03;
  double Translate[3] = { 0.0, 0.0, 0.05 };
  int Moves = 20;
  int Order = 1;
  int Weights = vtkLaplacianDeformationFilter::WEIGHTS_UNIFORM;
  int Solver = vtkLaplacianDeformationFilter::SOLVER_CHOLMOD;
  int Ordering = vtkLaplacianDeformationFilter::ORDERING_AUTOMATIC;
  int Mode = vtkLaplacianDeformationFilter::ROTATION_NONE;
  int Iterations = 1;
  bool Linear = false;
  bool Extrapolation = true;
  bool Dragging = false;
  bool CompareCGAL = false;
  int ARAPIterations = 30;
  int ConvergedIterations = 1000;
  int LargeRegion = -1; // the filter's default
  int ProxyNodes = -1;
  int DragIterations = -1;
  double SettleTimeLimit = 0.0;
  std::string WriteDirectory;
  bool Help = false;
};

const char* const Usage = R"(usage: LaplacianEditingBenchmark MESH|--sphere N|--grid N [options]

Times one edit of MESH (OBJ, PLY, STL, VTP, VTK, OFF), of a generated sphere of about N
vertices or of a flat grid of about N points (unit spacing, handle at its centre): setup
(selection, assembly, factorization) and handle moves. Prints one JSON line.

  --vertex V|largest      handle centre on input point V, or on the largest component (0)
  --point X Y Z           handle centre at a point
  --roi F                 ROI radius, a fraction of the bounding-box diagonal (0.25)
  --handle F              handle radius, a fraction of the diagonal (0.03)
  --translate DX DY DZ    the final handle move, a fraction of the diagonal (0 0 0.05)
  --absolute              radii and translation in mesh units, not fractions of the diagonal
  --moves N               handle moves timed (20)
  --order 1|2             operator order (1)
  --weights uniform|cotangent
  --solver cholmod|ldlt
  --ordering auto|amd|metis|nesdis
  --mode none|explicit|implicit|arap   rotation mode (none)
  --iterations K          explicit mode's iterations (1)
  --arap-iterations K     as-rigid-as-possible iterations per move (30)
  --linear                implicit mode without its rigid step (PreserveDetailScale off)
  --no-extrapolation      as-rigid-as-possible updates start from the last result itself
  --dragging              the moves are a drag (the filter's Dragging on, as the widget sets it):
                          at most DragARAPIterations (2) an update, then one update on release
  --converged-iterations K  the iterations that converge the last pose for the energy ratios
                          (1000; 0: none, no ratios)
  --large-region N        LargeRegionVertices: larger regions drag on a proxy (0: never)
  --proxy-nodes N         ProxyNodes: about how many nodes a large region's proxy has
  --drag-iterations K     DragARAPIterations: at most K iterations a drag step (2)
  --settle-time-limit S   with --dragging, the release with SettleTimeLimit S, continued update
                          by update (ContinueSettling) as the widget does; also its updates and
                          the longest of them
  --write DIR             the filter's output at rest, at the drag's end, released and converged
                          (rest.vtp, dragged.vtp, released.vtp, converged.vtp) in DIR, to
                          compare shapes where the energies differ
  --compare-cgal          the same edit in CGAL 5.5's Surface_mesh_deformation
  --help                  this text
)";

bool Parse(int argc, char* argv[], Options& options)
{
  for (int i = 1; i < argc; ++i)
  {
    const std::string arg = argv[i];
    auto next = [&]() { return i + 1 < argc ? std::string(argv[++i]) : std::string(); };
    bool known = true;
    auto pick = [&](const std::string& value, std::vector<std::string> names) {
      const auto found = std::find(names.begin(), names.end(), value);
      known = found != names.end();
      return known ? static_cast<int>(found - names.begin()) : 0;
    };
    if (arg == "--help" || arg == "-h")
    {
      options.Help = true;
      return true;
    }
    else if (arg == "--sphere")
      options.SphereVertices = std::atof(next().c_str());
    else if (arg == "--grid")
      options.GridPoints = std::atof(next().c_str());
    else if (arg == "--absolute")
      options.Absolute = true;
    else if (arg == "--vertex")
    {
      const std::string value = next();
      options.LargestComponent = value == "largest";
      options.Vertex = options.LargestComponent ? 0 : std::atol(value.c_str());
    }
    else if (arg == "--point")
    {
      options.UsePoint = true;
      for (double& c : options.Point)
        c = std::atof(next().c_str());
    }
    else if (arg == "--roi")
      options.ROI = std::atof(next().c_str());
    else if (arg == "--handle")
      options.Handle = std::atof(next().c_str());
    else if (arg == "--translate")
      for (double& c : options.Translate)
        c = std::atof(next().c_str());
    else if (arg == "--moves")
      options.Moves = std::max(1, std::atoi(next().c_str()));
    else if (arg == "--order")
      options.Order = std::atoi(next().c_str());
    else if (arg == "--weights")
      options.Weights = pick(next(), { "uniform", "cotangent" });
    else if (arg == "--solver")
      options.Solver = pick(next(), { "cholmod", "ldlt" });
    else if (arg == "--ordering")
      options.Ordering = pick(next(), { "auto", "amd", "metis", "nesdis" });
    else if (arg == "--mode")
      options.Mode = pick(next(), { "none", "explicit", "implicit", "arap" });
    else if (arg == "--iterations")
      options.Iterations = std::atoi(next().c_str());
    else if (arg == "--arap-iterations")
      options.ARAPIterations = std::atoi(next().c_str());
    else if (arg == "--linear")
      options.Linear = true;
    else if (arg == "--no-extrapolation")
      options.Extrapolation = false;
    else if (arg == "--dragging")
      options.Dragging = true;
    else if (arg == "--compare-cgal")
      options.CompareCGAL = true;
    else if (arg == "--converged-iterations")
      options.ConvergedIterations = std::atoi(next().c_str());
    else if (arg == "--large-region")
      options.LargeRegion = std::atoi(next().c_str());
    else if (arg == "--write")
      options.WriteDirectory = next();
    else if (arg == "--proxy-nodes")
      options.ProxyNodes = std::atoi(next().c_str());
    else if (arg == "--drag-iterations")
      options.DragIterations = std::atoi(next().c_str());
    else if (arg == "--settle-time-limit")
      options.SettleTimeLimit = std::atof(next().c_str());
    else if (arg[0] != '-' && options.Mesh.empty())
      options.Mesh = arg;
    else
    {
      std::cerr << "unknown argument " << arg << "\n";
      return false;
    }
    if (!known)
    {
      std::cerr << "unknown value " << argv[i] << " of " << arg << "\n";
      return false;
    }
  }
  return !options.Mesh.empty() || options.SphereVertices > 0.0 || options.GridPoints > 0.0;
}

struct Measurement
{
  int ROIVertices = 0;
  int HandleVertices = 0;
  double Topology = 0.0;
  double Setup = 0.0;
  double FirstUpdate = 0.0; // the whole first update, at rest: topology, setup and solve
  double Analysis = 0.0;
  double Factorization = 0.0;
  double Move = 0.0;
  double SlowestMove = 0.0;
  double Update = 0.0;
  bool Refactored = false;
  vtkSmartPointer<vtkPolyData> Output;
  // As-rigid-as-possible mode: iterations per move (their median, and each move's), and the
  // last move's energy, absolute and over the energy converged at the same pose.
  double ARAPIterations = 0.0;
  std::vector<double> ARAPIterationsPerMove;
  double DraggedEnergy = 0.0;
  // With --dragging: the update on release, its iterations and its energy.
  int ReleaseIterations = 0;
  int ReleaseUpdates = 0;
  double LongestReleaseUpdate = 0.0;
  double Release = 0.0;
  double ReleasedEnergy = 0.0;
  double ConvergedEnergy = 0.0;

  std::string Json() const
  {
    std::ostringstream json;
    json << std::setprecision(6) << "\"topology_seconds\": " << this->Topology
         << ", \"setup_seconds\": " << this->Setup
         << ", \"first_update_seconds\": " << this->FirstUpdate
         << ", \"analysis_seconds\": " << this->Analysis
         << ", \"factorization_seconds\": " << this->Factorization
         << ", \"move_median_seconds\": " << this->Move
         << ", \"move_slowest_seconds\": " << this->SlowestMove
         << ", \"update_median_seconds\": " << this->Update;
    if (!this->ARAPIterationsPerMove.empty())
    {
      json << ", \"arap_median_iterations\": " << this->ARAPIterations << ", \"arap_iterations\": [";
      for (std::size_t k = 0; k < this->ARAPIterationsPerMove.size(); ++k)
      {
        json << (k ? ", " : "") << this->ARAPIterationsPerMove[k];
      }
      json << "]";
      json << ", \"dragged_energy\": " << this->DraggedEnergy;
      if (this->ConvergedEnergy > 0.0)
      {
        json << ", \"arap_energy_over_converged\": " << this->DraggedEnergy / this->ConvergedEnergy;
      }
      if (this->Release > 0.0)
      {
        json << ", \"release_seconds\": " << this->Release
             << ", \"release_iterations\": " << this->ReleaseIterations
             << ", \"release_updates\": " << this->ReleaseUpdates
             << ", \"longest_release_update_seconds\": " << this->LongestReleaseUpdate;
      }
      if (this->ReleasedEnergy > 0.0)
      {
        json << ", \"released_energy\": " << this->ReleasedEnergy;
      }
      if (this->ReleasedEnergy > 0.0 && this->ConvergedEnergy > 0.0)
      {
        json << ", \"released_energy_over_converged\": " << this->ReleasedEnergy / this->ConvergedEnergy;
      }
      if (this->ConvergedEnergy > 0.0)
      {
        json << ", \"converged_energy\": " << this->ConvergedEnergy;
      }
    }
    return json.str();
  }
};

// The ARAP energy of a filter's output against its input, measured by the core on the welded
// input (EditMeasures), over the points the output's EditRole marks as edited.
class OutputEnergy
{
public:
  explicit OutputEnergy(vtkPolyData* input)
    : Input(input)
  {
  }

  double operator()(vtkPolyData* output) const
  {
    vtkDataArray* roles = output->GetPointData()->GetArray("EditRole");
    std::vector<char> edited(output->GetNumberOfPoints(), 0);
    for (vtkIdType i = 0; roles && i < output->GetNumberOfPoints(); ++i)
    {
      edited[i] = roles->GetTuple1(i) != vtkLaplacianDeformationFilter::ROLE_FIXED;
    }
    if (edited != this->Edited)
    {
      this->Edited.swap(edited);
      this->BuildAroundEdited();
    }
    std::vector<LaplacianEditing::Vector3> deformed = this->Mesh.GetPositions();
    const std::vector<int>& vertexOf = this->Mesh.GetVertexOfPoint();
    for (std::size_t k = 0; k < this->Points.size(); ++k)
    {
      output->GetPoint(this->Points[k], deformed[vertexOf[k]].data());
    }
    return LaplacianEditing::MeasureEdit(this->Mesh, this->Region, deformed).Energy;
  }

private:
  // The welded mesh of the polygons with an edited corner, which hold every ring the energy
  // sums over: a graph of the whole 2.4M-point scan was 270 MB of the benchmark's peak memory.
  void BuildAroundEdited() const
  {
    std::vector<std::int64_t> offsets, connectivity, all;
    std::vector<int> pointOf(this->Input->GetNumberOfPoints(), -1);
    this->Points.clear();
    offsets.assign(1, 0);
    LaplacianEditing::Pipeline::SurfaceAdapter::VisitPolygons(
      this->Input, [&](vtkIdType size, const vtkIdType* ids) {
        if (std::none_of(ids, ids + size, [&](vtkIdType id) { return this->Edited[id] != 0; }))
        {
          return;
        }
        for (vtkIdType c = 0; c < size; ++c)
        {
          if (pointOf[ids[c]] < 0)
          {
            pointOf[ids[c]] = static_cast<int>(this->Points.size());
            this->Points.push_back(ids[c]);
          }
          connectivity.push_back(pointOf[ids[c]]);
        }
        offsets.push_back(static_cast<std::int64_t>(connectivity.size()));
      });
    std::vector<LaplacianEditing::Vector3> points(this->Points.size());
    for (std::size_t k = 0; k < points.size(); ++k)
    {
      this->Input->GetPoint(this->Points[k], points[k].data());
    }
    this->Mesh = LaplacianEditing::SurfaceMesh::FromPolygons(points, offsets, connectivity, true);
    std::vector<char> inRegion(this->Mesh.GetNumberOfVertices(), 0);
    for (std::size_t k = 0; k < this->Points.size(); ++k)
    {
      inRegion[this->Mesh.GetVertexOfPoint()[k]] |= this->Edited[this->Points[k]];
    }
    this->Region.clear();
    for (int v = 0; v < this->Mesh.GetNumberOfVertices(); ++v)
    {
      if (inRegion[v])
      {
        this->Region.push_back(v);
      }
    }
  }

  vtkPolyData* Input;
  mutable std::vector<char> Edited;
  mutable std::vector<vtkIdType> Points; // the input id of each of the mesh's points
  mutable LaplacianEditing::SurfaceMesh Mesh;
  mutable std::vector<int> Region;
};

// Sets up the edit, then drags the handle to the translation in `options.Moves` steps.
Measurement Measure(vtkPolyData* mesh, const double center[3], const Options& options, int mode,
  int iterations, const OutputEnergy& energyOf)
{
  const double diagonal = options.Absolute ? 1.0 : mesh->GetLength();
  vtkNew<vtkLaplacianDeformationFilter> filter;
  filter->SetInputData(mesh);
  filter->SetHandleCenter(center);
  filter->SetRadiusUnits(options.Absolute ? vtkLaplacianDeformationFilter::RADIUS_ABSOLUTE
                                          : vtkLaplacianDeformationFilter::RADIUS_DIAGONAL_FRACTION);
  filter->SetROIRadius(options.ROI);
  filter->SetHandleRadius(options.Handle);
  filter->SetOperatorOrder(options.Order);
  filter->SetLaplacianWeights(options.Weights);
  filter->SetSolver(options.Solver);
  filter->SetOrdering(options.Ordering);
  filter->SetRotationMode(mode);
  filter->SetNumberOfIterations(iterations);
  filter->SetPreserveDetailScale(!options.Linear);
  filter->SetExtrapolation(options.Extrapolation);
  filter->SetARAPIterations(options.ARAPIterations);
  if (options.LargeRegion >= 0)
  {
    filter->SetLargeRegionVertices(options.LargeRegion);
  }
  if (options.ProxyNodes > 0)
  {
    filter->SetProxyNodes(options.ProxyNodes);
  }
  if (options.DragIterations > 0)
  {
    filter->SetDragARAPIterations(options.DragIterations);
  }
  vtkNew<vtkTransform> transform;
  filter->SetHandleTransform(transform);
  const Clock::time_point first = Clock::now();
  filter->Update();
  const double firstUpdate = SecondsSince(first);
  auto writeShape = [&](const char* name) {
    if (!options.WriteDirectory.empty())
    {
      vtkNew<vtkXMLPolyDataWriter> writer;
      writer->SetInputData(filter->GetOutput());
      writer->SetFileName((options.WriteDirectory + "/" + name + ".vtp").c_str());
      writer->Write();
    }
  };
  writeShape("rest");

  Measurement result;
  result.ROIVertices = filter->GetNumberOfROIVertices();
  result.HandleVertices = filter->GetNumberOfHandleVertices();
  result.Topology = filter->GetTopologyTime();
  result.Setup = filter->GetSetupTime();
  result.FirstUpdate = firstUpdate;
  result.Analysis = filter->GetAnalysisTime();
  result.Factorization = filter->GetFactorizationTime();
  const int factorizations = filter->GetNumberOfFactorizations();
  if (factorizations == 0)
  {
    return result;
  }
  std::vector<double> moves, updates, arapIterations;
  filter->SetDragging(options.Dragging);
  for (int move = 1; move <= options.Moves; ++move)
  {
    const double s = diagonal * move / options.Moves;
    transform->Identity();
    transform->Translate(s * options.Translate[0], s * options.Translate[1], s * options.Translate[2]);
    const Clock::time_point start = Clock::now();
    filter->Update();
    updates.push_back(SecondsSince(start));
    moves.push_back(filter->GetSolveTime());
    arapIterations.push_back(filter->GetNumberOfARAPIterations());
  }
  result.Move = Median(moves);
  result.SlowestMove = *std::max_element(moves.begin(), moves.end());
  result.Update = Median(updates);
  result.Refactored = filter->GetNumberOfFactorizations() != factorizations;
  if (mode == vtkLaplacianDeformationFilter::ROTATION_AS_RIGID_AS_POSSIBLE)
  {
    // The drag's last energy against the optimum at that pose (the drag's result, iterated on),
    // each measured on the output.
    const double dragged = energyOf(filter->GetOutput());
    writeShape("dragged");
    double released = 0.0;
    if (options.Dragging)
    {
      // The release: one update with ARAPIterations, or with a time limit the updates that
      // continue it.
      filter->SetSettleTimeLimit(options.SettleTimeLimit);
      filter->DraggingOff();
      const Clock::time_point start = Clock::now();
      do
      {
        const Clock::time_point update = Clock::now();
        filter->ContinueSettling();
        filter->Update();
        result.LongestReleaseUpdate = std::max(result.LongestReleaseUpdate, SecondsSince(update));
        result.ReleaseIterations += filter->GetNumberOfARAPIterations();
        ++result.ReleaseUpdates;
      } while (filter->GetSettling());
      result.Release = SecondsSince(start);
      released = energyOf(filter->GetOutput());
      writeShape("released");
      filter->SetSettleTimeLimit(0.0);
    }
    result.ARAPIterations = Median(arapIterations);
    result.ARAPIterationsPerMove = arapIterations;
    double converged = 0.0;
    if (options.ConvergedIterations > 0)
    {
      filter->SetARAPIterations(options.ConvergedIterations);
      filter->SetConvergence(1e-8);
      filter->Update();
      converged = energyOf(filter->GetOutput());
      writeShape("converged");
    }
    result.DraggedEnergy = dragged;
    result.ReleasedEnergy = released;
    result.ConvergedEnergy = converged;
  }
  result.Output = filter->GetOutput();
  return result;
}

#ifdef LAPLACIAN_EDITING_HAS_CGAL
// CGAL's SRE-ARAP on the same vertices, ROI and handle. Returns a JSON fragment.
std::string MeasureCGAL(vtkPolyData* mesh, vtkDataArray* roles, const Options& options)
{
  using namespace CGALSurface;
  using Deformation = CGAL::Surface_mesh_deformation<Mesh, CGAL::Default, CGAL::Default, CGAL::SRE_ARAP>;

  // CGAL's own surface graph and region, timed as our topology and selection are.
  Clock::time_point start = Clock::now();
  Mesh surface;
  int skippedFaces = 0;
  const std::vector<Vertex> vertices = CGALSurface::Build(mesh, surface, &skippedFaces);

  Deformation deformation(surface);
  std::vector<Vertex> handles;
  std::vector<Kernel::Point_3> rest;
  for (vtkIdType i = 0; i < mesh->GetNumberOfPoints(); ++i)
  {
    const int role = static_cast<int>(roles->GetTuple1(i));
    if (role != vtkLaplacianDeformationFilter::ROLE_FIXED)
    {
      deformation.insert_roi_vertex(vertices[i]);
    }
    if (role == vtkLaplacianDeformationFilter::ROLE_HANDLE)
    {
      deformation.insert_control_vertex(vertices[i]);
      handles.push_back(vertices[i]);
      rest.push_back(surface.point(vertices[i]));
    }
  }
  const double construction = SecondsSince(start);
  start = Clock::now();
  const bool ready = deformation.preprocess();
  const double preprocess = SecondsSince(start);

  const double diagonal = mesh->GetLength();
  auto timeMoves = [&](unsigned int iterations) {
    std::vector<double> times;
    for (int move = 1; move <= options.Moves; ++move)
    {
      const double s = diagonal * move / options.Moves;
      const Kernel::Vector_3 t(s * options.Translate[0], s * options.Translate[1], s * options.Translate[2]);
      const Clock::time_point begin = Clock::now();
      for (std::size_t h = 0; h < handles.size(); ++h)
      {
        deformation.set_target_position(handles[h], rest[h] + t);
      }
      deformation.deform(iterations, 0.0);
      times.push_back(SecondsSince(begin));
    }
    return Median(times);
  };
  const double deform1 = ready ? timeMoves(1) : 0.0;
  deformation.reset();
  const double deform5 = ready ? timeMoves(5) : 0.0;

  std::ostringstream json;
  json << std::setprecision(6) << "\"cgal\": {\"preprocess_ok\": " << (ready ? "true" : "false")
       << ", \"skipped_faces\": " << skippedFaces << ", \"mesh_and_region_seconds\": " << construction
       << ", \"preprocess_seconds\": " << preprocess
       << ", \"deform1_median_seconds\": " << deform1
       << ", \"deform5_median_seconds\": " << deform5 << "}";
  return json.str();
}
#endif

// The mesh the options name, with the handle's centre in options.Point.
vtkSmartPointer<vtkPolyData> MakeMesh(Options& options, std::string& name, std::string& error)
{
  vtkSmartPointer<vtkPolyData> mesh;
  name = options.Mesh;
  if (options.SphereVertices > 0.0)
  {
    name = "sphere-" + std::to_string(static_cast<long>(options.SphereVertices));
    mesh = Sphere(options.SphereVertices);
  }
  else if (options.GridPoints > 0.0)
  {
    name = "grid-" + std::to_string(static_cast<long>(options.GridPoints));
    mesh = Grid(options.GridPoints);
    if (!options.UsePoint)
    {
      options.UsePoint = true; // the grid point nearest the centre
      options.Point[0] = options.Point[1] = std::round(mesh->GetBounds()[1] / 2.0);
    }
  }
  else
  {
    mesh = MeshReader::Read(options.Mesh, error);
  }
  if (mesh && options.LargestComponent)
  {
    options.Vertex = FirstVertexOfLargestComponent(mesh);
  }
  if (mesh && !options.UsePoint)
  {
    if (options.Vertex < 0 || options.Vertex >= mesh->GetNumberOfPoints())
    {
      error = "vertex " + std::to_string(options.Vertex) + " out of range";
      return nullptr;
    }
    mesh->GetPoint(options.Vertex, options.Point);
  }
  return mesh;
}
}

int main(int argc, char* argv[])
{
  Options options;
  if (!Parse(argc, argv, options) || options.Help)
  {
    (options.Help ? std::cout : std::cerr) << Usage;
    return options.Help ? EXIT_SUCCESS : EXIT_FAILURE;
  }
  std::string meshName, error;
  vtkSmartPointer<vtkPolyData> mesh = MakeMesh(options, meshName, error);
  if (!mesh)
  {
    std::cerr << "error: " << error << "\n";
    return EXIT_FAILURE;
  }
  if (options.CompareCGAL)
  {
    // CGAL needs one vertex per position; the filter welds internally, CGAL cannot.
    vtkNew<vtkCleanPolyData> weld;
    weld->SetInputData(mesh);
    weld->PointMergingOn();
    weld->SetTolerance(0.0);
    weld->Update();
    mesh = weld->GetOutput();
  }
  const char* modes[] = { "none", "explicit", "implicit", "arap" };
  const char* orderings[] = { "auto", "amd", "metis", "nesdis" };
  const OutputEnergy energyOf(mesh);
  const Measurement main =
    Measure(mesh, options.Point, options, options.Mode, options.Iterations, energyOf);
  if (!main.Output)
  {
    std::cerr << "error: setup failed\n";
    return EXIT_FAILURE;
  }
  std::ostringstream json;
  json << std::setprecision(6) << "{\"mesh\": \"" << meshName
       << "\", \"vertices\": " << mesh->GetNumberOfPoints()
       << ", \"roi_vertices\": " << main.ROIVertices
       << ", \"handle_vertices\": " << main.HandleVertices << ", \"order\": " << options.Order
       << ", \"weights\": \"" << (options.Weights ? "cotangent" : "uniform") << "\", \"solver\": \""
       << (options.Solver ? "ldlt" : "cholmod") << "\", \"ordering\": \""
       << orderings[options.Ordering] << "\", \"mode\": \"" << modes[options.Mode]
       << "\", \"iterations\": " << options.Iterations << ", " << main.Json()
       << ", \"moves\": " << options.Moves;
  bool refactored = main.Refactored;
  if (options.CompareCGAL)
  {
    // Every mode on the same selection, then CGAL.
    const std::pair<const char*, std::pair<int, int>> runs[] = { { "none", { 0, 1 } },
      { "explicit1", { 1, 1 } }, { "explicit3", { 1, 3 } }, { "implicit", { 2, 1 } } };
    for (const auto& [name, run] : runs)
    {
      const Measurement m = Measure(mesh, options.Point, options, run.first, run.second, energyOf);
      refactored = refactored || m.Refactored;
      json << ", \"" << name << "\": {" << m.Json() << "}";
    }
#ifdef LAPLACIAN_EDITING_HAS_CGAL
    json << ", " << MeasureCGAL(mesh, main.Output->GetPointData()->GetArray("EditRole"), options);
#else
    json << ", \"cgal\": \"not built (CGAL not found)\"";
#endif
  }
  json << ", \"peak_memory_mb\": " << PeakMemoryMegabytes() << ", \"blas\": \"" << LoadedBlas()
       << "\"}";
  std::cout << json.str() << "\n";
  // Moving the handle must never refactor.
  return refactored ? EXIT_FAILURE : EXIT_SUCCESS;
}
