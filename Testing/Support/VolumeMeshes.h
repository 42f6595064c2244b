// Volume meshes for the tests, examples and benchmarks: tetgen's tetrahedralizations of the
// closed surfaces in ../shared/data (cached beside the build), hexahedral beams, and the
// measures a volume edit is judged by (inverted cells and the smallest scaled Jacobian, by VTK's
// own vtkMeshQuality, independently of the filter's).
#ifndef VolumeMeshes_h
#define VolumeMeshes_h

#include "MeshReader.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkCleanPolyData.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkMeshQuality.h"
#include "vtkPoints.h"
#include "vtkTransform.h"
#include "vtkTriangleFilter.h"
#include "vtkUnstructuredGrid.h"
#include "vtkUnstructuredGridReader.h"

#include <Eigen/Geometry>

#include <cmath>
#include <cstdio> // rename
#include <cstdlib>
#include <stdlib.h> // mkdtemp
#include <fstream>
#include <limits>
#include <string>

namespace VolumeMeshes
{
/// tetgen's tetrahedralization of the closed surface `surfacePath` with `switches` (quality
/// bound and volume limit, e.g. "pq1.4a0.0005": the meshes), cached in `directory` as
/// NAME-SWITCHES.vtk. Null, with `error` set, when the surface cannot be read or tetgen fails. tetgen
/// runs in a directory of its own and the result is renamed into place, so that processes making
/// the same mesh at once do not read each other's half-written files.
inline vtkSmartPointer<vtkUnstructuredGrid> Tetrahedralize(const std::string& surfacePath,
  const std::string& directory, const std::string& name, const std::string& switches,
  std::string& error)
{
  const std::string result = directory + "/" + name + "-" + switches + ".vtk"; // one file a mesh
  if (!std::ifstream(result))
  {
    vtkSmartPointer<vtkPolyData> surface = MeshReader::Read(surfacePath, error);
    if (!surface)
    {
      return nullptr;
    }
    std::string work = directory + "/" + name + ".XXXXXX";
    if (!mkdtemp(&work[0]))
    {
      error = "cannot make a directory in " + directory;
      return nullptr;
    }
    vtkNew<vtkCleanPolyData> clean;
    clean->SetInputData(surface);
    vtkNew<vtkTriangleFilter> triangles;
    triangles->SetInputConnection(clean->GetOutputPort());
    triangles->Update();
    vtkPolyData* mesh = triangles->GetOutput();
    const std::string stem = work + "/" + name;
    std::ofstream off(stem + ".off");
    off.precision(17);
    off << "OFF\n" << mesh->GetNumberOfPoints() << " " << mesh->GetNumberOfPolys() << " 0\n";
    for (vtkIdType i = 0; i < mesh->GetNumberOfPoints(); ++i)
    {
      const double* p = mesh->GetPoint(i);
      off << p[0] << " " << p[1] << " " << p[2] << "\n";
    }
    vtkIdType count = 0;
    const vtkIdType* ids = nullptr;
    for (mesh->GetPolys()->InitTraversal(); mesh->GetPolys()->GetNextCell(count, ids);)
    {
      off << "3 " << ids[0] << " " << ids[1] << " " << ids[2] << "\n";
    }
    off.close();
    const std::string command = "tetgen -" + switches + "kQ '" + stem + ".off' > /dev/null";
    const bool made = std::system(command.c_str()) == 0 &&
      std::rename((stem + ".1.vtk").c_str(), result.c_str()) == 0;
    if (std::system(("rm -rf '" + work + "'").c_str()) != 0)
    {
      // What remains is tetgen's scratch in the build's temporary folder.
    }
    if (!made)
    {
      error = "tetgen failed: " + command;
      return nullptr;
    }
  }
  vtkNew<vtkUnstructuredGridReader> reader;
  reader->SetFileName(result.c_str());
  reader->Update();
  auto grid = vtkSmartPointer<vtkUnstructuredGrid>::New();
  grid->ShallowCopy(reader->GetOutput());
  if (grid->GetNumberOfCells() == 0)
  {
    error = "no tetrahedra in " + result;
    return nullptr;
  }
  return grid;
}

/// A beam of nx x ny x nz hexahedra over [0, length] x [0, 1] x [0, 1].
inline vtkSmartPointer<vtkUnstructuredGrid> HexBeam(int nx, int ny, int nz, double length)
{
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  auto id = [=](int i, int j, int k) { return static_cast<vtkIdType>((k * (ny + 1) + j) * (nx + 1) + i); };
  for (int k = 0; k <= nz; ++k)
  {
    for (int j = 0; j <= ny; ++j)
    {
      for (int i = 0; i <= nx; ++i)
      {
        points->InsertNextPoint(length * i / nx, static_cast<double>(j) / ny, static_cast<double>(k) / nz);
      }
    }
  }
  auto grid = vtkSmartPointer<vtkUnstructuredGrid>::New();
  grid->SetPoints(points);
  grid->Allocate(static_cast<vtkIdType>(nx) * ny * nz);
  for (int k = 0; k < nz; ++k)
  {
    for (int j = 0; j < ny; ++j)
    {
      for (int i = 0; i < nx; ++i)
      {
        const vtkIdType hex[8] = { id(i, j, k), id(i + 1, j, k), id(i + 1, j + 1, k),
          id(i, j + 1, k), id(i, j, k + 1), id(i + 1, j, k + 1), id(i + 1, j + 1, k + 1),
          id(i, j + 1, k + 1) };
        grid->InsertNextCell(VTK_HEXAHEDRON, 8, hex);
      }
    }
  }
  return grid;
}

/// The edits of the measurements: the handle on the boundary point farthest from the
/// centroid; it turns by `Degrees` about the axis across the line from the centroid (about the
/// handle), and moves `Lift` (mesh units) the way it turns. At(f): the transform a fraction `f`
/// of the way.
struct Edit
{
  double Center[3];
  double Axis[3];
  double Swing[3];
  double Degrees;
  double Lift;
  vtkSmartPointer<vtkTransform> At(double fraction) const
  {
    auto transform = vtkSmartPointer<vtkTransform>::New();
    transform->PostMultiply();
    transform->Translate(-this->Center[0], -this->Center[1], -this->Center[2]);
    transform->RotateWXYZ(fraction * this->Degrees, this->Axis);
    transform->Translate(this->Center);
    const double lift = fraction * this->Lift;
    transform->Translate(lift * this->Swing[0], lift * this->Swing[1], lift * this->Swing[2]);
    return transform;
  }
};

/// The edit of `grid` turning by `degrees` and lifted by `lift` of its diagonal.
inline Edit FarEdit(vtkUnstructuredGrid* grid, double degrees, double lift)
{
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
  for (vtkIdType i = 0; i < grid->GetNumberOfPoints(); ++i)
  {
    centroid += Eigen::Vector3d(grid->GetPoint(i)) / grid->GetNumberOfPoints();
  }
  // The point farthest from the centroid is a vertex of the hull, so on the boundary.
  Eigen::Vector3d far = centroid;
  for (vtkIdType i = 0; i < grid->GetNumberOfPoints(); ++i)
  {
    const Eigen::Vector3d p(grid->GetPoint(i));
    far = (p - centroid).norm() > (far - centroid).norm() ? p : far;
  }
  const Eigen::Vector3d out = (far - centroid).normalized();
  Eigen::Vector3d axis = out.cross(Eigen::Vector3d::UnitZ());
  axis = axis.norm() > 0.3 ? axis.normalized() : out.cross(Eigen::Vector3d::UnitY()).normalized();
  const Eigen::Vector3d swing = axis.cross(out).normalized();
  Edit edit;
  for (int k = 0; k < 3; ++k)
  {
    edit.Center[k] = far[k];
    edit.Axis[k] = axis[k];
    edit.Swing[k] = swing[k];
  }
  edit.Degrees = degrees;
  edit.Lift = lift * grid->GetLength();
  return edit;
}

/// What a volume edit is judged by, from VTK's vtkMeshQuality (Verdict's scaled Jacobian of
/// tetrahedra and hexahedra): cells whose scaled Jacobian is not positive, and the smallest;
/// and how far the grid's own ScaledJacobian cell array (the filter's) is from Verdict's.
struct Validity
{
  vtkIdType Inverted = 0;
  double SmallestScaledJacobian = std::numeric_limits<double>::infinity();
  double LargestReportedQualityError = 0.0;
};

inline Validity Measure(vtkUnstructuredGrid* grid)
{
  vtkNew<vtkMeshQuality> quality;
  quality->SetInputData(grid);
  quality->SetTetQualityMeasureToScaledJacobian();
  quality->SetHexQualityMeasureToScaledJacobian();
  quality->Update();
  vtkDataArray* values = quality->GetOutput()->GetCellData()->GetArray("Quality");
  vtkDataArray* reported = grid->GetCellData()->GetArray("ScaledJacobian");
  Validity validity;
  for (vtkIdType cell = 0; cell < grid->GetNumberOfCells(); ++cell)
  {
    const double q = values->GetTuple1(cell);
    validity.Inverted += !(q > 0.0);
    validity.SmallestScaledJacobian = std::min(validity.SmallestScaledJacobian, q);
    if (reported)
    {
      validity.LargestReportedQualityError =
        std::max(validity.LargestReportedQualityError, std::abs(reported->GetTuple1(cell) - q));
    }
  }
  return validity;
}
}

#endif
