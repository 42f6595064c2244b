// Offscreen image regression tests of real edits, compared with committed baselines. Every
// panel is drawn by a vtkPolyDataMapper with default settings: the EditRole colours come from
// the array itself.
// Usage: TestLaplacianDeformationImages <case> <data folder> -V <baseline.png> -T <temp folder>
//
//   BumpyPlaneEdit  the demo's embedded edit: before and after
//   Fig6Rotations   the paper's Fig. 6 (top): original, bent without rotations, bent with
//                   explicit rotations
//   Fig3Orders      the paper's Fig. 3: a strip pulled up, first and second order
//   BunnyModes      the Stanford bunny's ear bent: none, explicit, implicit
//   CactusModes     CGAL's cactus edit (.sel/.def, a 70-degree turn): none, explicit (five
//                   iterations), implicit, as rigid as possible (cotangent weights)
//   TwistModes      the bunny's ear twisted 120 degrees about its axis, in the same modes
//   LandmarkWarp    the articulated known warp (KnownWarps.h) from 100 landmarks: the rest,
//                   the true shape, VTK's thin-plate spline and vtkLaplacianLandmarkWarp
//   LabelImageWarp  spot's head turned by the landmark warp (300 landmarks): the rest, the
//                   inside of the rest as a label image warped through the warp's displacement
//                   grid (its boundary, blurred by a voxel to draw), the warped surface
//   VolumeClip      tetgen's spot, its head turned 90 degrees and lifted by
//                   vtkLaplacianVolumeDeformationFilter: rest and edited, the cells on one side
//                   of the plane across the turn, coloured by ScaledJacobian (red 0, blue 1)
#include "EditingScene.h"
#include "KnownWarps.h"
#include "ReferenceEdits.h"
#include "ImageWarp.h"
#include "VolumeMeshes.h"

#include "BumpyPlane.h"
#include "vtkLaplacianDeformationFilter.h"
#include "vtkLaplacianLandmarkWarp.h"
#include "vtkLaplacianVolumeDeformationFilter.h"

#include "vtkCellData.h"
#include "vtkDataSetSurfaceFilter.h"
#include "vtkExtractGeometry.h"
#include "vtkFlyingEdges3D.h"
#include "vtkImageCast.h"
#include "vtkImageGaussianSmooth.h"
#include "vtkPlane.h"
#include "vtkPointData.h"

#include "vtkIntArray.h"
#include "vtkMath.h"
#include "vtkOBJReader.h"
#include "vtkPlaneSource.h"
#include "vtkRegressionTestImage.h"
#include "vtkThinPlateSplineTransform.h"
#include "vtkTransformPolyDataFilter.h"
#include "vtkTransform.h"

#include <functional>
#include <iostream>
#include <map>
#include <string>
#include <vector>

namespace
{
using Filter = vtkLaplacianDeformationFilter;

struct Scene
{
  std::vector<vtkSmartPointer<vtkPolyData>> Meshes;
  double ViewDirection[3] = { 0.0, 1.0, -0.6 };
  double ViewUp[3] = { 0.0, 0.0, 1.0 };
  bool FrameRegion = false; // frame the edited region instead of the whole meshes
};

vtkSmartPointer<vtkPolyData> Edited(Filter* filter)
{
  filter->Update();
  auto copy = vtkSmartPointer<vtkPolyData>::New();
  copy->DeepCopy(filter->GetOutput());
  return copy;
}

Scene BumpyPlaneEdit(const std::string&)
{
  Scene scene;
  vtkNew<Filter> filter;
  scene.Meshes = { EditingScene::SetUpBumpyPlaneEdit(filter), Edited(filter) };
  return scene;
}

Scene Fig6Rotations(const std::string&)
{
  auto plane = MakeBumpyPlane();
  vtkNew<vtkIntArray> selection;
  selection->SetName("Selection");
  for (vtkIdType i = 0; i < plane->GetNumberOfPoints(); ++i)
  {
    const double x = plane->GetPoint(i)[0];
    selection->InsertNextValue(x < 0.03 ? 0 : (x > 0.97 ? 2 : 1));
  }
  plane->GetPointData()->AddArray(selection);
  vtkNew<vtkTransform> bend;
  bend->Translate(0.97, 0.5, 0.4);
  bend->RotateY(-60.0);
  bend->Translate(-0.97, -0.5, 0.0);
  Scene scene;
  scene.Meshes.push_back(plane);
  for (int mode : { Filter::ROTATION_NONE, Filter::ROTATION_EXPLICIT })
  {
    vtkNew<Filter> filter;
    filter->SetInputData(plane);
    filter->SetSelectionModeToArray();
    filter->SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, "Selection");
    filter->SetRotationMode(mode);
    filter->SetHandleTransform(bend);
    scene.Meshes.push_back(Edited(filter));
  }
  return scene;
}

Scene Fig3Orders(const std::string&)
{
  vtkNew<vtkPlaneSource> strip;
  strip->SetOrigin(-1.5, 0.0, 0.0);
  strip->SetPoint1(1.5, 0.0, 0.0);
  strip->SetPoint2(-1.5, 0.5, 0.0);
  strip->SetResolution(120, 20);
  strip->Update();
  vtkNew<vtkTransform> pull;
  pull->Translate(0.0, 0.0, 0.5);
  Scene scene;
  for (int order : { 1, 2 })
  {
    vtkNew<Filter> filter;
    filter->SetInputConnection(strip->GetOutputPort());
    filter->SetHandleCenter(0.0, 0.25, 0.0);
    filter->SetHandleRadius(0.02);
    filter->SetROIRadius(1.2);
    filter->SetOperatorOrder(order);
    filter->SetHandleTransform(pull);
    scene.Meshes.push_back(Edited(filter));
  }
  scene.ViewDirection[0] = 0.3, scene.ViewDirection[1] = 1.0, scene.ViewDirection[2] = -0.5;
  return scene;
}

Scene BunnyModes(const std::string& data)
{
  vtkNew<vtkOBJReader> reader;
  reader->SetFileName((data + "/stanford-bunny.obj").c_str());
  reader->Update();
  vtkPolyData* bunny = reader->GetOutput();
  // The handle on the top of an ear (the highest vertex).
  vtkIdType top = 0;
  for (vtkIdType i = 1; i < bunny->GetNumberOfPoints(); ++i)
  {
    top = bunny->GetPoint(i)[1] > bunny->GetPoint(top)[1] ? i : top;
  }
  const double diagonal = bunny->GetLength();
  double tip[3];
  bunny->GetPoint(top, tip);
  auto earEdit = [&](int mode) {
    vtkNew<Filter> filter;
    filter->SetInputData(bunny);
    filter->SetHandleCenter(tip);
    filter->SetHandleRadius(0.03 * diagonal);
    filter->SetROIRadius(0.22 * diagonal);
    filter->SetRotationMode(mode);
    return filter;
  };
  // Bend the ear about its cross-section at the ROI's edge (the anchors' centroid), 40 degrees
  // about the view axis.
  auto rest = earEdit(Filter::ROTATION_NONE);
  rest->Update();
  vtkDataArray* roles = rest->GetOutput()->GetPointData()->GetArray("EditRole");
  double pivot[3] = { 0.0, 0.0, 0.0 };
  int anchors = 0;
  for (vtkIdType i = 0; i < bunny->GetNumberOfPoints(); ++i)
  {
    if (roles->GetTuple1(i) == Filter::ROLE_ANCHOR)
    {
      vtkMath::Add(pivot, bunny->GetPoint(i), pivot);
      ++anchors;
    }
  }
  vtkMath::MultiplyScalar(pivot, 1.0 / anchors);
  vtkNew<vtkTransform> bend;
  bend->Translate(pivot);
  bend->RotateZ(40.0);
  bend->Translate(-pivot[0], -pivot[1], -pivot[2]);
  Scene scene;
  for (int mode : { Filter::ROTATION_NONE, Filter::ROTATION_EXPLICIT, Filter::ROTATION_IMPLICIT })
  {
    auto filter = earEdit(mode);
    filter->SetHandleTransform(bend);
    scene.Meshes.push_back(Edited(filter));
  }
  scene.ViewDirection[0] = 0.0, scene.ViewDirection[1] = 0.0, scene.ViewDirection[2] = -1.0;
  scene.ViewUp[0] = 0.0, scene.ViewUp[1] = 1.0, scene.ViewUp[2] = 0.0;
  return scene;
}
}

// One edit in every rotation mode, side by side.
Scene EveryMode(const ReferenceEdits::Edit& edit)
{
  Scene scene;
  for (int mode : { Filter::ROTATION_NONE, Filter::ROTATION_EXPLICIT, Filter::ROTATION_IMPLICIT,
         Filter::ROTATION_AS_RIGID_AS_POSSIBLE })
  {
    vtkNew<Filter> filter;
    ReferenceEdits::Configure(edit, filter);
    filter->SetRotationMode(mode);
    filter->SetNumberOfIterations(5);
    if (mode == Filter::ROTATION_AS_RIGID_AS_POSSIBLE)
    {
      filter->SetLaplacianWeightsToCotangent();
    }
    filter->SetHandleTransform(const_cast<vtkTransform*>(edit.Handle.Get()));
    scene.Meshes.push_back(Edited(filter));
  }
  return scene;
}

Scene CactusModes(const std::string& data)
{
  ReferenceEdits::Edit edit;
  if (!ReferenceEdits::LoadCactus(data, edit))
  {
    return Scene();
  }
  Scene scene = EveryMode(edit);
  scene.ViewDirection[0] = 1.0, scene.ViewDirection[1] = 0.0, scene.ViewDirection[2] = 0.0;
  return scene;
}

Scene TwistModes(const std::string& data)
{
  ReferenceEdits::Edit edit;
  if (!ReferenceEdits::LoadTwist(data, edit))
  {
    return Scene();
  }
  Scene scene = EveryMode(edit);
  scene.ViewDirection[0] = 0.0, scene.ViewDirection[1] = 0.0, scene.ViewDirection[2] = -1.0;
  scene.ViewUp[0] = 0.0, scene.ViewUp[1] = 1.0, scene.ViewUp[2] = 0.0;
  scene.FrameRegion = true;
  return scene;
}

Scene LandmarkWarp(const std::string& data)
{
  const KnownWarps::Warp warp = KnownWarps::Articulated(data);
  if (!warp.Mesh || warp.Mesh->GetNumberOfPoints() == 0)
  {
    return Scene();
  }
  auto sources = KnownWarps::SurfacePoints(warp.Mesh, 100);
  auto targets = KnownWarps::Moved(sources, warp.Map);
  auto truth = vtkSmartPointer<vtkPolyData>::New();
  truth->DeepCopy(warp.Mesh);
  truth->SetPoints(KnownWarps::Moved(warp.Mesh->GetPoints(), warp.Map));
  vtkNew<vtkThinPlateSplineTransform> spline;
  spline->SetSourceLandmarks(sources);
  spline->SetTargetLandmarks(targets);
  vtkNew<vtkTransformPolyDataFilter> splined;
  splined->SetInputData(warp.Mesh);
  splined->SetTransform(spline);
  splined->Update();
  vtkNew<vtkLaplacianLandmarkWarp> warped;
  warped->SetInputData(warp.Mesh);
  warped->SetSourceLandmarks(sources);
  warped->SetTargetLandmarks(targets);
  warped->Update();
  Scene scene;
  scene.Meshes = { warp.Mesh, truth, splined->GetOutput(), warped->GetPolyDataOutput() };
  scene.ViewDirection[0] = 0.0, scene.ViewDirection[1] = -1.0, scene.ViewDirection[2] = 0.0;
  scene.ViewUp[0] = 0.0, scene.ViewUp[1] = 0.0, scene.ViewUp[2] = 1.0;
  return scene;
}

// The cells of `grid` behind the plane through `origin` with `normal`, as a surface coloured
// by the cell array ScaledJacobian.
vtkSmartPointer<vtkPolyData> ClippedByQuality(vtkUnstructuredGrid* grid, const double origin[3],
  const double normal[3])
{
  vtkNew<vtkPlane> plane;
  plane->SetOrigin(origin);
  plane->SetNormal(normal);
  vtkNew<vtkExtractGeometry> clip;
  clip->SetInputData(grid);
  clip->SetImplicitFunction(plane);
  clip->ExtractInsideOn();
  clip->ExtractBoundaryCellsOn();
  vtkNew<vtkDataSetSurfaceFilter> surface;
  surface->SetInputConnection(clip->GetOutputPort());
  surface->Update();
  auto clipped = vtkSmartPointer<vtkPolyData>::New();
  clipped->DeepCopy(surface->GetOutput());
  clipped->GetPointData()->SetScalars(nullptr);
  clipped->GetCellData()->SetActiveScalars("ScaledJacobian");
  return clipped;
}

Scene LabelImageWarp(const std::string& data)
{
  const KnownWarps::Warp warp = KnownWarps::TurnedHead(data);
  auto sources = KnownWarps::SurfacePoints(warp.Mesh, 300);
  vtkNew<vtkLaplacianLandmarkWarp> warped;
  warped->SetInputData(warp.Mesh);
  warped->SetSourceLandmarks(sources);
  warped->SetTargetLandmarks(KnownWarps::Moved(sources, warp.Map));
  warped->OutputDisplacementOn();
  warped->Update();
  double bounds[6];
  warp.Mesh->GetBounds(bounds);
  for (int a = 0; a < 3; ++a)
  {
    bounds[2 * a] -= 0.2 * warp.Mesh->GetLength();
    bounds[2 * a + 1] += 0.2 * warp.Mesh->GetLength();
  }
  vtkSmartPointer<vtkImageData> labels = ImageWarp::WarpLabels(
    ImageWarp::Voxelize(warp.Mesh, bounds, 80), warped->GetPolyDataOutput());
  // The labels' boundary, drawn smooth: the label image blurred by a voxel, cut at one half.
  vtkNew<vtkImageCast> real;
  real->SetInputData(labels);
  real->SetOutputScalarTypeToFloat();
  vtkNew<vtkImageGaussianSmooth> blur;
  blur->SetInputConnection(real->GetOutputPort());
  blur->SetStandardDeviations(1.0, 1.0, 1.0);
  vtkNew<vtkFlyingEdges3D> boundary;
  boundary->SetInputConnection(blur->GetOutputPort());
  boundary->SetValue(0, 0.5);
  boundary->ComputeScalarsOff();
  boundary->Update();
  Scene scene;
  scene.Meshes = { warp.Mesh, boundary->GetOutput(), warped->GetPolyDataOutput() };
  scene.ViewDirection[0] = 0.0, scene.ViewDirection[1] = 0.0, scene.ViewDirection[2] = -1.0;
  scene.ViewUp[0] = 0.0, scene.ViewUp[1] = 1.0, scene.ViewUp[2] = 0.0;
  return scene;
}

Scene VolumeClip(const std::string& data)
{
  std::string error;
  vtkSmartPointer<vtkUnstructuredGrid> spot = VolumeMeshes::Tetrahedralize(
    data + "/spot.obj", LAPLACIAN_EDITING_TEMPORARY_DIR, "spot", "pq1.4a0.0005", error);
  if (!spot)
  {
    std::cerr << error << "\n";
    return Scene();
  }
  const VolumeMeshes::Edit edit = VolumeMeshes::FarEdit(spot, 90.0, 0.1);
  vtkNew<vtkLaplacianVolumeDeformationFilter> volume;
  volume->SetInputData(spot);
  volume->SetRadiusUnitsToDiagonalFraction();
  volume->SetHandleCenter(edit.Center);
  volume->SetHandleRadius(0.03);
  volume->SetROIRadius(0.3);
  volume->SetRotationModeToAsRigidAsPossible();
  volume->SetHandleTransform(edit.At(0.0));
  volume->Update();
  auto rest = vtkSmartPointer<vtkUnstructuredGrid>::New();
  rest->DeepCopy(volume->GetOutput()); // with its ScaledJacobian at rest
  volume->SetHandleTransform(edit.At(1.0));
  volume->Update();
  const double* center = spot->GetCenter();
  Scene scene;
  scene.Meshes = { ClippedByQuality(rest, center, edit.Axis),
    ClippedByQuality(volume->GetOutput(), center, edit.Axis) };
  for (int k = 0; k < 3; ++k)
  {
    scene.ViewDirection[k] = edit.Axis[k];
    scene.ViewUp[k] = edit.Swing[k];
  }
  return scene;
}

int main(int argc, char* argv[])
{
  const std::map<std::string, std::function<Scene(const std::string&)>> cases = {
    { "BumpyPlaneEdit", BumpyPlaneEdit }, { "Fig6Rotations", Fig6Rotations },
    { "Fig3Orders", Fig3Orders }, { "BunnyModes", BunnyModes }, { "CactusModes", CactusModes },
    { "TwistModes", TwistModes }, { "LandmarkWarp", LandmarkWarp }, { "LabelImageWarp", LabelImageWarp },
    { "VolumeClip", VolumeClip }
  };
  if (argc < 3 || !cases.count(argv[1]))
  {
    std::cerr << "usage: " << argv[0] << " <case> <data folder> -V <baseline> -T <temp>\n";
    return EXIT_FAILURE;
  }
  const Scene scene = cases.at(argv[1])(argv[2]);
  if (scene.Meshes.empty())
  {
    return EXIT_FAILURE;
  }
  std::vector<vtkPolyData*> meshes;
  for (const auto& mesh : scene.Meshes)
  {
    meshes.push_back(mesh);
  }
  double region[6];
  EditingScene::GetRegionBounds(meshes, region);
  vtkSmartPointer<vtkRenderWindow> window = EditingScene::MakeComparisonWindow(
    meshes, scene.ViewDirection, scene.ViewUp, 400, 400, scene.FrameRegion ? region : nullptr);
  window->Render();
  const int result = vtkRegressionTestImageThreshold(window, 0.05);
  return result == vtkRegressionTester::PASSED ? EXIT_SUCCESS : EXIT_FAILURE;
}
