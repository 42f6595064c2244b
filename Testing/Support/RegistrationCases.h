// Template fitting's cases, for RegistrationBenchmark and TestSurfaceRegistration: the template
// is a known warp's surface (KnownWarps.h), every vertex of which has a true position, the warp's
// motion of it; the target is that warped surface remeshed (other vertices), and in the variants
// noisy, holed, a point cloud, or posed (turned 30 degrees and scaled by 1.1). A few landmark
// pairs are random template points and their true positions. Measure gives, in percent of the
// template's diagonal, the root-mean-square distance of a fit's vertices from their true
// positions (the correspondence error) and from the target, and the triangles turned over
// against the true shape.
#ifndef LaplacianEditing_Testing_RegistrationCases_h
#define LaplacianEditing_Testing_RegistrationCases_h

#include "KnownWarps.h"

#include "vtkCellArray.h"
#include "vtkCleanPolyData.h"
#include "vtkGenericCell.h"
#include "vtkIdList.h"
#include "vtkLoopSubdivisionFilter.h"
#include "vtkMath.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkPolyDataNormals.h"
#include "vtkQuadricDecimation.h"
#include "vtkStaticCellLocator.h"
#include "vtkStaticPointLocator.h"
#include "vtkTriangle.h"
#include "vtkTriangleFilter.h"

#include <cmath>
#include <random>
#include <string>

namespace RegistrationCases
{
// The pose of the posed case: 30 degrees about the axis (1, 1, 1) through the template's
// centre, then scaled by 1.1 about it.
struct Pose
{
  double Center[3] = { 0.0, 0.0, 0.0 };
  double Rotation[3][3];

  explicit Pose(vtkPolyData* mesh)
  {
    mesh->GetCenter(this->Center);
    double axis[3] = { 1.0, 1.0, 1.0 }, quaternion[4];
    vtkMath::Normalize(axis);
    const double half = 15.0 * KnownWarps::Degree;
    quaternion[0] = std::cos(half);
    for (int k = 0; k < 3; ++k)
    {
      quaternion[k + 1] = std::sin(half) * axis[k];
    }
    vtkMath::QuaternionToMatrix3x3(quaternion, this->Rotation);
  }

  void Apply(const double* p, double* q) const
  {
    double d[3] = { p[0] - this->Center[0], p[1] - this->Center[1], p[2] - this->Center[2] };
    vtkMath::Multiply3x3(this->Rotation, d, q);
    for (int k = 0; k < 3; ++k)
    {
      q[k] = this->Center[k] + 1.1 * q[k];
    }
  }
};

struct Case
{
  std::string Name;
  vtkSmartPointer<vtkPolyData> Target;
  vtkSmartPointer<vtkPoints> Truth; // each template vertex's true position
  vtkSmartPointer<vtkPoints> Sources, Targets; // the landmark pairs
};

// The warped surface with other vertices: Loop-subdivided once (every vertex moves or is new),
// then decimated to 40% of that, about 1.6 times the template's triangles, within a small
// fraction of the true surface (the "truth" line's distance to the target).
// `mesh` Loop-subdivided `levels` times, with double-precision points (a finer template of the
// same shape: 4 times the vertices a level).
inline vtkSmartPointer<vtkPolyData> Subdivided(vtkPolyData* mesh, int levels)
{
  vtkNew<vtkTriangleFilter> triangles;
  triangles->SetInputData(mesh);
  vtkNew<vtkCleanPolyData> clean; // one vertex per position: seams do not open
  clean->SetInputConnection(triangles->GetOutputPort());
  vtkNew<vtkLoopSubdivisionFilter> split;
  split->SetInputConnection(clean->GetOutputPort());
  split->SetNumberOfSubdivisions(levels);
  split->Update();
  auto fine = vtkSmartPointer<vtkPolyData>::New();
  fine->DeepCopy(split->GetOutput());
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->DeepCopy(fine->GetPoints());
  fine->SetPoints(points);
  return fine;
}

inline vtkSmartPointer<vtkPolyData> Remeshed(vtkPolyData* mesh, const KnownWarps::Motion& map)
{
  vtkNew<vtkQuadricDecimation> decimate;
  decimate->SetInputData(Subdivided(mesh, 1));
  decimate->SetTargetReduction(0.6);
  decimate->Update();
  auto remeshed = vtkSmartPointer<vtkPolyData>::New();
  remeshed->DeepCopy(decimate->GetOutput());
  remeshed->SetPoints(KnownWarps::Moved(remeshed->GetPoints(), map));
  return remeshed;
}

// Every point moved along its normal by Gaussian noise of `sigma`.
inline void AddNoise(vtkPolyData* mesh, double sigma, unsigned seed)
{
  vtkNew<vtkPolyDataNormals> normals;
  normals->SetInputData(mesh);
  normals->SplittingOff();
  normals->ComputePointNormalsOn();
  normals->Update();
  vtkDataArray* n = normals->GetOutput()->GetPointData()->GetNormals();
  std::mt19937 random(seed);
  std::normal_distribution<double> noise(0.0, sigma);
  for (vtkIdType i = 0; i < mesh->GetNumberOfPoints(); ++i)
  {
    double p[3], d[3];
    mesh->GetPoint(i, p);
    n->GetTuple(i, d);
    const double shift = noise(random);
    for (int k = 0; k < 3; ++k)
    {
      p[k] += shift * d[k];
    }
    mesh->GetPoints()->SetPoint(i, p);
  }
}

// The triangles whose centroid lies within `radius` of the target's point farthest up (y)
// removed: a scan's hole.
inline void CutHole(vtkPolyData* mesh, double radius)
{
  vtkIdType top = 0;
  for (vtkIdType i = 1; i < mesh->GetNumberOfPoints(); ++i)
  {
    if (mesh->GetPoint(i)[1] > mesh->GetPoint(top)[1])
    {
      top = i;
    }
  }
  double center[3];
  mesh->GetPoint(top, center);
  vtkNew<vtkCellArray> kept;
  vtkNew<vtkIdList> corners;
  for (vtkIdType c = 0; c < mesh->GetNumberOfCells(); ++c)
  {
    mesh->GetCellPoints(c, corners);
    double centroid[3] = { 0.0, 0.0, 0.0 };
    for (vtkIdType j = 0; j < corners->GetNumberOfIds(); ++j)
    {
      const double* p = mesh->GetPoint(corners->GetId(j));
      for (int k = 0; k < 3; ++k)
      {
        centroid[k] += p[k] / corners->GetNumberOfIds();
      }
    }
    if (std::sqrt(vtkMath::Distance2BetweenPoints(centroid, center)) > radius)
    {
      kept->InsertNextCell(corners);
    }
  }
  mesh->SetPolys(kept);
}

inline Case MakeCase(const std::string& name, const KnownWarps::Warp& warp, int landmarks, unsigned seed)
{
  const double diagonal = warp.Mesh->GetLength();
  const Pose pose(warp.Mesh);
  KnownWarps::Motion map = warp.Map;
  if (name == "posed")
  {
    map = [&warp, pose](const double* p, double* q) {
      double moved[3];
      warp.Map(p, moved);
      pose.Apply(moved, q);
    };
  }
  Case made{ name, Remeshed(warp.Mesh, map), KnownWarps::Moved(warp.Mesh->GetPoints(), map),
    KnownWarps::SurfacePoints(warp.Mesh, landmarks, seed), nullptr };
  made.Targets = KnownWarps::Moved(made.Sources, map);
  if (name == "noisy" || name == "cloud")
  {
    AddNoise(made.Target, 0.002 * diagonal, seed);
  }
  if (name == "hole")
  {
    CutHole(made.Target, 0.08 * diagonal);
  }
  if (name == "cloud")
  {
    auto cloud = vtkSmartPointer<vtkPolyData>::New();
    cloud->SetPoints(made.Target->GetPoints());
    made.Target = cloud;
  }
  return made;
}

// The measures of one fit, in percent of the template's diagonal.
struct Measures
{
  double Correspondence = 0.0;
  double ToTarget = 0.0;
  int TurnedOver = 0;
};

inline Measures Measure(vtkPolyData* fitted, const Case& fit, double diagonal)
{
  Measures measures;
  const vtkIdType n = fitted->GetNumberOfPoints();
  double squares = 0.0, toTarget = 0.0;
  vtkNew<vtkStaticCellLocator> cells;
  vtkNew<vtkStaticPointLocator> points;
  const bool surface = fit.Target->GetNumberOfPolys() > 0;
  if (surface)
  {
    cells->SetDataSet(fit.Target);
    cells->BuildLocator();
  }
  else
  {
    points->SetDataSet(fit.Target);
    points->BuildLocator();
  }
  vtkNew<vtkGenericCell> cell;
  for (vtkIdType i = 0; i < n; ++i)
  {
    double p[3], truth[3], closest[3], d2 = 0.0;
    fitted->GetPoint(i, p);
    fit.Truth->GetPoint(i, truth);
    squares += vtkMath::Distance2BetweenPoints(p, truth);
    if (surface)
    {
      vtkIdType id;
      int sub;
      cells->FindClosestPoint(p, closest, cell, id, sub, d2);
    }
    else
    {
      fit.Target->GetPoint(points->FindClosestPoint(p), closest);
      d2 = vtkMath::Distance2BetweenPoints(p, closest);
    }
    toTarget += d2;
  }
  measures.Correspondence = 100.0 * std::sqrt(squares / n) / diagonal;
  measures.ToTarget = 100.0 * std::sqrt(toTarget / n) / diagonal;
  vtkNew<vtkIdList> corners;
  for (vtkIdType c = 0; c < fitted->GetNumberOfCells(); ++c)
  {
    fitted->GetCellPoints(c, corners);
    if (corners->GetNumberOfIds() != 3)
    {
      continue;
    }
    double a[3][3], b[3][3], na[3], nb[3];
    for (int j = 0; j < 3; ++j)
    {
      fitted->GetPoint(corners->GetId(j), a[j]);
      fit.Truth->GetPoint(corners->GetId(j), b[j]);
    }
    vtkTriangle::ComputeNormalDirection(a[0], a[1], a[2], na);
    vtkTriangle::ComputeNormalDirection(b[0], b[1], b[2], nb);
    measures.TurnedOver += vtkMath::Dot(na, nb) < 0.0 ? 1 : 0;
  }
  return measures;
}
} // namespace RegistrationCases

#endif
