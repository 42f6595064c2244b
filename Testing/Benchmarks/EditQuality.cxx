// The quality of large edits, measured against CGAL 5.5's Surface_mesh_deformation (ARAP) on the
// same vertex sets; prints one JSON line per edit.
//
//   EditQuality DATA_DIR [--edit cactus|twist|armadillo|bend|all] [--picture DIR] [--sre ALPHA]
//
// Edits:
//  - cactus: CGAL's cactus.off with cactus.sel (0 fixed, 1 ROI, 2 handle) and the 70-degree
//    turn of cactus.def, in array selection;
//  - twist: stanford-bunny.obj with unused vertices dropped; the handle is the highest vertex
//    (an ear tip), with an edge-path ROI of 0.15 and a handle of 0.03 of the diagonal; it turns
//    120 degrees about the ear's long axis (the principal axis of the ROI) through the handle's
//    centroid;
//  - armadillo: Armadillo.ply's hand, the handle at vertex 0 (a fingertip), ROI 0.25 and handle
//    0.04 of the diagonal, translated by 0.01 of the diagonal;
//  - bend: bumps.obj, a large region: three quarters of the sheet, whose far strip turns 60
//    degrees (ReferenceEdits.h).
//
// For each mode: the ARAP energy of the result (per ROI vertex, the best rotation of its
// one-ring and the weighted squared residual of its edges, normalized by the ROI's weighted
// squared edge lengths; clamped cotangent weights), the ROI's area ratio, the faces turned over,
// setup and update seconds. For CGAL ARAP (its default, cotangent weights), the same after 1, 5,
// 50 and 1000 iterations from the rest shape, with the seconds spent. With --picture, writes
// DIR/<edit>-modes.png: the rest shape, none, explicit (5 iterations), implicit, as rigid as
// possible, and CGAL ARAP after 1000 iterations, side by side (offscreen; run under Xvfb).
//
// --sre ALPHA adds smoothed rotations (RotationSmoothing) at CGAL's alpha: ours at the default
// iterations ("sre") and run out ("sre_converged", 20,000 iterations at most), and CGAL's
// SRE_ARAP after 1, 5, 50, 1000 and 5000 iterations, each with its RMS distance over the ROI
// from our run-out result, in fractions of the diagonal. CGAL's alpha is relative to the whole
// surface's area and ours to the region's, so ours is given alpha times their ratio.
#include "BenchmarkMeasures.h"
#include "EditingScene.h"
#include "ReferenceEdits.h"

#include "vtkLaplacianDeformationFilter.h"


#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkIntArray.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkTransform.h"

#ifdef LAPLACIAN_EDITING_HAS_CGAL
#include "CGALSurface.h"

#include <CGAL/Surface_mesh_deformation.h>
#endif

#include <chrono>
#include <cstdlib>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

namespace le = LaplacianEditing;

namespace
{
using Clock = BenchmarkMeasures::Clock;
using BenchmarkMeasures::SecondsSince;

struct Mode
{
  const char* Name;
  int Rotation;
  int Iterations;
  int ImplicitFormulation;
  int ARAPIterations = 30;
  double Convergence = 1e-3;
  bool Accelerate = true;
  bool Linear = false; // implicit mode without its rigid step
  double RotationSmoothing = 0.0;
};

// The panels of --picture: copies of the results, in order.
using Panels = std::vector<vtkSmartPointer<vtkPolyData>>;

vtkSmartPointer<vtkPolyData> Copy(vtkPolyData* mesh)
{
  auto copy = vtkSmartPointer<vtkPolyData>::New();
  copy->DeepCopy(mesh);
  return copy;
}

std::string MeasureMode(const ReferenceEdits::Edit& edit, const ReferenceEdits::Measured& measured,
  const Mode& mode, double* energy = nullptr, Panels* panels = nullptr,
  std::vector<le::Vector3>* points = nullptr)
{
  vtkNew<vtkLaplacianDeformationFilter> filter;
  ReferenceEdits::Configure(edit, filter);
  filter->SetRotationMode(mode.Rotation);
  filter->SetNumberOfIterations(mode.Iterations);
  filter->SetImplicitFormulation(mode.ImplicitFormulation);
  filter->SetARAPIterations(mode.ARAPIterations);
  filter->SetConvergence(mode.Convergence);
  filter->SetAcceleration(mode.Accelerate);
  filter->SetPreserveDetailScale(!mode.Linear);
  filter->SetRotationSmoothing(mode.RotationSmoothing);
  if (mode.Rotation == vtkLaplacianDeformationFilter::ROTATION_AS_RIGID_AS_POSSIBLE)
  {
    filter->SetLaplacianWeightsToCotangent(); // as CGAL's ARAP and the measure
  }
  filter->Update(); // setup
  const double setup = filter->GetSetupTime();
  filter->SetHandleTransform(const_cast<vtkTransform*>(edit.Handle.Get()));
  const Clock::time_point start = Clock::now();
  filter->Update();
  const double update = SecondsSince(start);
  if (panels)
  {
    panels->push_back(Copy(filter->GetOutput()));
  }
  if (energy)
  {
    const auto deformed = ReferenceEdits::PointsOf(filter->GetOutput());
    *energy = le::MeasureEdit(measured.Mesh, measured.Region, deformed).Energy;
  }
  if (points)
  {
    *points = ReferenceEdits::PointsOf(filter->GetOutput());
  }
  std::ostringstream json;
  json << std::setprecision(5) << "\"" << mode.Name << "\": {"
       << measured.Json(ReferenceEdits::PointsOf(filter->GetOutput())) << ", \"free_motion_ratio\": "
       << measured.FreeMotionRatio(ReferenceEdits::PointsOf(filter->GetOutput()), edit.Labels)
       << ", \"arap_iterations\": " << filter->GetNumberOfARAPIterations()
       << ", \"setup_seconds\": " << setup
       << ", \"update_seconds\": " << update << "}";
  return json.str();
}

#ifdef LAPLACIAN_EDITING_HAS_CGAL
// CGAL ARAP (or, with a reference, SRE_ARAP at `alpha`) from the rest shape: the measures
// after each iteration count, with the seconds, and the distance from `reference` if given.
template <CGAL::Deformation_algorithm_tag Technique>
std::string MeasureCGAL(const ReferenceEdits::Edit& edit, const ReferenceEdits::Measured& measured,
  double target, Panels* panels, const std::vector<le::Vector3>* reference = nullptr,
  double alpha = 0.0)
{
  using namespace CGALSurface;
  using Deformation = CGAL::Surface_mesh_deformation<Mesh, CGAL::Default, CGAL::Default, Technique>;

  Mesh surface;
  const std::vector<Vertex> vertices = CGALSurface::Build(edit.Mesh, surface);
  Deformation deformation(surface);
  deformation.set_sre_arap_alpha(alpha);
  for (vtkIdType i = 0; i < edit.Labels->GetNumberOfTuples(); ++i)
  {
    if (edit.Labels->GetValue(i) > 0)
    {
      deformation.insert_roi_vertex(vertices[i]);
    }
    if (edit.Labels->GetValue(i) == 2)
    {
      deformation.insert_control_vertex(vertices[i]);
      const Kernel::Point_3& p = surface.point(vertices[i]);
      double moved[3];
      edit.Handle->TransformPoint(std::array<double, 3>{ p.x(), p.y(), p.z() }.data(), moved);
      deformation.set_target_position(vertices[i], Kernel::Point_3(moved[0], moved[1], moved[2]));
    }
  }
  Clock::time_point start = Clock::now();
  const bool ready = deformation.preprocess();
  const double preprocess = SecondsSince(start);
  std::ostringstream json;
  json << std::setprecision(5) << (reference ? "\"cgal_sre_arap\"" : "\"cgal_arap\"")
       << ": {\"preprocess_ok\": " << (ready ? "true" : "false")
       << ", \"preprocess_seconds\": " << preprocess;
  // One iteration at a time (only deform() is timed): the measures after 1, 5, 50 and 1000
  // iterations, and when CGAL first reaches `target` (our ARAP mode's energy; 0: not sought).
  double seconds = 0.0;
  bool reached = target <= 0.0;
  const int last = reference ? 5000 : 1000;
  for (int iteration = 1; iteration <= last; ++iteration)
  {
    start = Clock::now();
    deformation.deform(1, 0.0); // continues from the current result
    seconds += SecondsSince(start);
    const bool report = iteration == 1 || iteration == 5 || iteration == 50 || iteration == 1000 ||
      iteration == last;
    if (!report && (reached || iteration % 5 != 0))
    {
      continue; // the energy is checked every fifth iteration until reached
    }
    std::vector<le::Vector3> deformed;
    for (Vertex v : vertices)
    {
      const Kernel::Point_3& p = surface.point(v);
      deformed.emplace_back(p.x(), p.y(), p.z());
    }
    const double energy = le::MeasureEdit(measured.Mesh, measured.Region, deformed).Energy;
    if (!reached && energy <= target)
    {
      reached = true;
      json << ", \"reaches_arap_energy\": {\"iterations\": " << iteration
           << ", \"deform_seconds\": " << seconds << "}";
    }
    if (iteration == 1000 && !reference && panels && !panels->empty())
    {
      // The last panel (our ARAP result) with CGAL's points, so that it keeps the roles.
      vtkSmartPointer<vtkPolyData> cgal = Copy(panels->back());
      for (vtkIdType i = 0; i < static_cast<vtkIdType>(deformed.size()); ++i)
      {
        cgal->GetPoints()->SetPoint(i, deformed[i].data());
      }
      panels->push_back(cgal);
    }
    if (report)
    {
      json << ", \"" << iteration << "\": {" << measured.Json(deformed)
           << ", \"free_motion_ratio\": " << measured.FreeMotionRatio(deformed, edit.Labels);
      if (reference)
      {
        json << ", \"distance\": " << measured.Distance(deformed, *reference) / edit.Mesh->GetLength();
      }
      json << ", \"deform_seconds\": " << seconds << "}";
    }
  }
  json << "}";
  return json.str();
}
#endif
}

int main(int argc, char* argv[])
{
  if (argc < 2 || std::string(argv[1]) == "--help")
  {
    (argc < 2 ? std::cerr : std::cout)
      << "usage: " << argv[0]
      << " DATA_DIR [--edit cactus|twist|armadillo|bend|all] [--picture DIR] [--sre ALPHA]\n";
    return argc < 2 ? EXIT_FAILURE : EXIT_SUCCESS;
  }
  const std::string data = argv[1];
  std::string which = "all", pictures;
  double alpha = 0.0;
  for (int i = 2; i + 1 < argc; i += 2)
  {
    const std::string option = argv[i];
    if (option == "--sre")
    {
      alpha = std::stod(argv[i + 1]);
    }
    else
    {
      (option == "--picture" ? pictures : which) = argv[i + 1];
    }
  }
  const Mode modes[] = { { "none", vtkLaplacianDeformationFilter::ROTATION_NONE, 1, vtkLaplacianDeformationFilter::IMPLICIT_PER_EDGE },
    { "explicit1", vtkLaplacianDeformationFilter::ROTATION_EXPLICIT, 1, vtkLaplacianDeformationFilter::IMPLICIT_PER_EDGE },
    { "explicit5", vtkLaplacianDeformationFilter::ROTATION_EXPLICIT, 5, vtkLaplacianDeformationFilter::IMPLICIT_PER_EDGE },
    { "implicit", vtkLaplacianDeformationFilter::ROTATION_IMPLICIT, 1, vtkLaplacianDeformationFilter::IMPLICIT_PER_EDGE },
    { "implicit_linear", vtkLaplacianDeformationFilter::ROTATION_IMPLICIT, 1, vtkLaplacianDeformationFilter::IMPLICIT_PER_EDGE, 20, 1e-3, true, true },
    { "implicit_paper", vtkLaplacianDeformationFilter::ROTATION_IMPLICIT, 1, vtkLaplacianDeformationFilter::IMPLICIT_PAPER, 20, 1e-3, true, true },
    { "arap", vtkLaplacianDeformationFilter::ROTATION_AS_RIGID_AS_POSSIBLE, 1, 0 },
    { "arap_converged", vtkLaplacianDeformationFilter::ROTATION_AS_RIGID_AS_POSSIBLE, 1, 0, 1000, 1e-7 },
    { "arap_plain_converged", vtkLaplacianDeformationFilter::ROTATION_AS_RIGID_AS_POSSIBLE, 1, 0, 1000, 1e-7, false } };
  for (const std::string name : { "cactus", "twist", "armadillo", "bend" })
  {
    if (which != "all" && which != name)
    {
      continue;
    }
    ReferenceEdits::Edit edit;
    edit.Name = name;
    const bool loaded = name == "cactus" ? ReferenceEdits::LoadCactus(data, edit)
      : name == "twist"                  ? ReferenceEdits::LoadTwist(data, edit)
      : name == "bend"                   ? ReferenceEdits::LoadBend(data, edit)
                                         : ReferenceEdits::LoadArmadilloHand(data, edit);
    if (!loaded)
    {
      return EXIT_FAILURE;
    }
    const ReferenceEdits::Measured measured(edit.Mesh, edit.Labels);
    std::cout << "{\"edit\": \"" << name << "\", \"vertices\": " << edit.Mesh->GetNumberOfPoints()
              << ", \"roi_vertices\": " << measured.Region.size();
    double arapEnergy = 0.0;
    Panels panels = { Copy(edit.Mesh) };
    for (const Mode& mode : modes)
    {
      const std::string modeName = mode.Name;
      const bool shown = modeName == "none" || modeName == "explicit5" ||
        modeName == "implicit" || modeName == "arap";
      std::cout << ", "
                << MeasureMode(edit, measured, mode, modeName == "arap" ? &arapEnergy : nullptr,
                     pictures.empty() || !shown ? nullptr : &panels);
    }
#ifdef LAPLACIAN_EDITING_HAS_CGAL
    std::cout << ", "
              << MeasureCGAL<CGAL::SPOKES_AND_RIMS>(
                   edit, measured, arapEnergy, pictures.empty() ? nullptr : &panels);
#endif
    if (alpha > 0.0)
    {
      Mode smoothed = { "sre", vtkLaplacianDeformationFilter::ROTATION_AS_RIGID_AS_POSSIBLE, 1, 0 };
      smoothed.RotationSmoothing = alpha * measured.Area(true) / measured.Area(false);
      std::cout << ", " << MeasureMode(edit, measured, smoothed);
      smoothed.Name = "sre_converged";
      smoothed.ARAPIterations = 20000;
      smoothed.Convergence = 1e-9;
      std::vector<le::Vector3> converged;
      std::cout << ", " << MeasureMode(edit, measured, smoothed, nullptr, nullptr, &converged);
#ifdef LAPLACIAN_EDITING_HAS_CGAL
      std::cout << ", "
                << MeasureCGAL<CGAL::SRE_ARAP>(edit, measured, 0.0, nullptr, &converged, alpha);
#endif
    }
    std::cout << "}" << std::endl;
    if (!pictures.empty())
    {
      // The cactus from its side, the bunny's ear and Armadillo's hand from the front, framed.
      const double side[3] = { 1.0, 0.0, 0.0 }, front[3] = { 0.0, 0.0, -1.0 };
      const double zUp[3] = { 0.0, 0.0, 1.0 }, yUp[3] = { 0.0, 1.0, 0.0 };
      std::vector<vtkPolyData*> meshes(panels.begin(), panels.end());
      double region[6];
      EditingScene::GetRegionBounds(meshes, region);
      const bool cactus = name == "cactus";
      vtkSmartPointer<vtkRenderWindow> window = EditingScene::MakeComparisonWindow(
        meshes, cactus ? side : front, cactus ? zUp : yUp, 300, 300, cactus ? nullptr : region);
      window->Render();
      EditingScene::SaveScreenshot(window, pictures + "/" + name + "-modes.png");
    }
  }
  return EXIT_SUCCESS;
}
