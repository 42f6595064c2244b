// Reads a surface mesh by file extension: OBJ, PLY, STL, OFF, VTP or legacy VTK; or makes a
// sphere of given resolutions.
#ifndef MeshReader_h
#define MeshReader_h

#include "vtkCellArray.h"
#include "vtkDataArray.h"
#include "vtkLoopSubdivisionFilter.h"
#include "vtkOBJReader.h"
#include "vtkPLYReader.h"
#include "vtkPoints.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkPolyDataNormals.h"
#include "vtkPolyDataReader.h"
#include "vtkSTLReader.h"
#include "vtkSphereSource.h"
#include "vtkSmartPointer.h"
#include "vtkXMLPolyDataReader.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace MeshReader
{
template <typename Reader>
vtkSmartPointer<vtkPolyData> ReadWith(const std::string& path)
{
  vtkNew<Reader> reader;
  reader->SetFileName(path.c_str());
  reader->Update();
  return reader->GetOutput();
}

/// OFF (and COFF, NOFF...): vertex coordinates first on each vertex line, extra columns ignored.
/// VTK has no OFF reader; CGAL's data sets use the format.
inline vtkSmartPointer<vtkPolyData> ReadOFF(const std::string& path)
{
  std::ifstream file(path);
  std::vector<std::string> lines;
  for (std::string line; std::getline(file, line);)
  {
    line = line.substr(0, line.find('#'));
    if (line.find_first_not_of(" \t\r") != std::string::npos)
    {
      lines.push_back(line);
    }
  }
  std::size_t next = lines.empty() || lines[0].find("OFF") == std::string::npos ? 0 : 1;
  long vertices = 0, faces = 0;
  if (next >= lines.size() || !(std::istringstream(lines[next++]) >> vertices >> faces) ||
    next + vertices + faces > lines.size())
  {
    return nullptr;
  }
  vtkNew<vtkPoints> points;
  for (long v = 0; v < vertices; ++v)
  {
    double p[3] = { 0.0, 0.0, 0.0 };
    std::istringstream(lines[next++]) >> p[0] >> p[1] >> p[2];
    points->InsertNextPoint(p);
  }
  vtkNew<vtkCellArray> polys;
  for (long f = 0; f < faces; ++f)
  {
    std::istringstream line(lines[next++]);
    vtkIdType size = 0;
    line >> size;
    std::vector<vtkIdType> ids(std::max<vtkIdType>(size, 0));
    for (vtkIdType& id : ids)
    {
      if (!(line >> id) || id < 0 || id >= vertices)
      {
        return nullptr; // a face that is not one would crash whoever reads the mesh
      }
    }
    polys->InsertNextCell(static_cast<vtkIdType>(ids.size()), ids.data());
  }
  auto mesh = vtkSmartPointer<vtkPolyData>::New();
  mesh->SetPoints(points);
  mesh->SetPolys(polys);
  return mesh;
}

/// The mesh, or nullptr with `error` set to one line that says why. VTK's own complaints about a
/// bad file come in several lines from several objects (reader, parser, executive): they are
/// kept quiet while reading, the line says it.
/// "sphere:THETAxPHI": vtkSphereSource at those resolutions, with its point normals (the big
/// meshes of the benchmarks: sphere:2000x1002 has 2M points).
inline vtkSmartPointer<vtkPolyData> Sphere(const std::string& spec)
{
  int theta = 0, phi = 0;
  char times = 0;
  std::istringstream in(spec.substr(spec.find(':') + 1));
  if (!(in >> theta >> times >> phi) || times != 'x' || theta < 3 || phi < 3)
  {
    return nullptr;
  }
  vtkNew<vtkSphereSource> sphere;
  sphere->SetThetaResolution(theta);
  sphere->SetPhiResolution(phi);
  sphere->Update();
  return sphere->GetOutput();
}

inline vtkSmartPointer<vtkPolyData> Read(const std::string& path, std::string& error);

/// "scan:LEVELS:PATH": the mesh at PATH Loop-subdivided LEVELS times, with fine bumps along its
/// normals, a stand-in for a dense scan: scan:3:Armadillo.ply has 2,378,221 vertices. The bumps,
/// 0.05% of the diagonal high and 0.6% apart, are detail that an edit must carry; the input's
/// point data is dropped.
inline vtkSmartPointer<vtkPolyData> Scan(const std::string& spec, std::string& error)
{
  const std::size_t colon = spec.find(':', 5);
  const int levels = colon == std::string::npos ? -1 : std::atoi(spec.substr(5, colon - 5).c_str());
  if (levels < 0 || levels > 6)
  {
    error = "a scan is scan:LEVELS:PATH, LEVELS from 0 to 6";
    return nullptr;
  }
  vtkSmartPointer<vtkPolyData> mesh = Read(spec.substr(colon + 1), error);
  if (!mesh)
  {
    return nullptr;
  }
  vtkNew<vtkPolyData> surface; // points and triangles only: the subdivision interpolates the rest
  surface->SetPoints(mesh->GetPoints());
  surface->SetPolys(mesh->GetPolys());
  vtkNew<vtkLoopSubdivisionFilter> subdivide;
  subdivide->SetInputData(surface);
  subdivide->SetNumberOfSubdivisions(levels);
  vtkNew<vtkPolyDataNormals> normals;
  normals->SetInputConnection(subdivide->GetOutputPort());
  normals->SplittingOff();
  normals->ComputeCellNormalsOff();
  normals->Update();
  vtkSmartPointer<vtkPolyData> scan = normals->GetOutput();
  const double diagonal = scan->GetLength();
  const double height = 5e-4 * diagonal, k = 2.0 * 3.141592653589793 / (6e-3 * diagonal);
  vtkPoints* points = scan->GetPoints();
  vtkDataArray* n = scan->GetPointData()->GetNormals();
  for (vtkIdType i = 0; i < scan->GetNumberOfPoints(); ++i)
  {
    double p[3], normal[3];
    points->GetPoint(i, p);
    n->GetTuple(i, normal);
    const double h = height * std::sin(k * p[0]) * std::sin(k * p[1]) * std::sin(k * p[2]);
    points->SetPoint(i, p[0] + h * normal[0], p[1] + h * normal[1], p[2] + h * normal[2]);
  }
  scan->GetPointData()->Initialize();
  return scan;
}

/// A mesh file by its extension, or a generated sphere (see Sphere) or scan (see Scan).
inline vtkSmartPointer<vtkPolyData> Read(const std::string& path, std::string& error)
{
  if (path.rfind("sphere:", 0) == 0)
  {
    vtkSmartPointer<vtkPolyData> sphere = Sphere(path);
    error = sphere ? "" : "a sphere is sphere:THETAxPHI, both resolutions at least 3";
    return sphere;
  }
  if (path.rfind("scan:", 0) == 0)
  {
    return Scan(path, error);
  }
  if (!std::ifstream(path))
  {
    error = "cannot open " + path;
    return nullptr;
  }
  const std::string name = path.substr(path.find_last_of('/') + 1);
  std::string extension =
    name.find('.') == std::string::npos ? "" : name.substr(name.rfind('.') + 1);
  std::transform(extension.begin(), extension.end(), extension.begin(),
    [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  using Reader = vtkSmartPointer<vtkPolyData> (*)(const std::string&);
  const std::map<std::string, Reader> readers = { { "obj", &ReadWith<vtkOBJReader> },
    { "ply", &ReadWith<vtkPLYReader> }, { "stl", &ReadWith<vtkSTLReader> }, { "off", &ReadOFF },
    { "vtp", &ReadWith<vtkXMLPolyDataReader> }, { "vtk", &ReadWith<vtkPolyDataReader> } };
  const auto reader = readers.find(extension);
  if (reader == readers.end())
  {
    error = (extension.empty() ? "no file extension on " + path
                               : "unknown mesh format '." + extension + "'") +
      " (use OBJ, PLY, STL, OFF, VTP or VTK)";
    return nullptr;
  }
  const int warnings = vtkObject::GetGlobalWarningDisplay();
  vtkObject::GlobalWarningDisplayOff();
  vtkSmartPointer<vtkPolyData> mesh = reader->second(path);
  vtkObject::SetGlobalWarningDisplay(warnings);
  if (!mesh || mesh->GetNumberOfPoints() == 0)
    error = "cannot read " + path + " as a ." + extension + " file";
  else if (mesh->GetNumberOfPolys() == 0)
    error = path + " holds no polygons";
  else
    return mesh;
  return nullptr;
}
}

#endif
