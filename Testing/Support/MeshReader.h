// Reads a surface mesh by file extension: OBJ, PLY, STL, OFF, VTP or legacy VTK.
#ifndef MeshReader_h
#define MeshReader_h

#include "vtkCellArray.h"
#include "vtkOBJReader.h"
#include "vtkPLYReader.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPolyDataReader.h"
#include "vtkSTLReader.h"
#include "vtkSmartPointer.h"
#include "vtkXMLPolyDataReader.h"

#include <algorithm>
#include <cctype>
#include <fstream>
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
      line >> id;
    }
    polys->InsertNextCell(static_cast<vtkIdType>(ids.size()), ids.data());
  }
  auto mesh = vtkSmartPointer<vtkPolyData>::New();
  mesh->SetPoints(points);
  mesh->SetPolys(polys);
  return mesh;
}

/// The mesh, or nullptr with `error` set.
inline vtkSmartPointer<vtkPolyData> Read(const std::string& path, std::string& error)
{
  if (!std::ifstream(path))
  {
    error = "cannot open " + path;
    return nullptr;
  }
  std::string extension = path.substr(path.find_last_of('.') + 1);
  std::transform(extension.begin(), extension.end(), extension.begin(),
    [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  vtkSmartPointer<vtkPolyData> mesh;
  if (extension == "obj")
    mesh = ReadWith<vtkOBJReader>(path);
  else if (extension == "ply")
    mesh = ReadWith<vtkPLYReader>(path);
  else if (extension == "stl")
    mesh = ReadWith<vtkSTLReader>(path);
  else if (extension == "off")
    mesh = ReadOFF(path);
  else if (extension == "vtp")
    mesh = ReadWith<vtkXMLPolyDataReader>(path);
  else if (extension == "vtk")
    mesh = ReadWith<vtkPolyDataReader>(path);
  else
  {
    error = "unknown mesh format '." + extension + "' (use OBJ, PLY, STL, OFF, VTP or VTK)";
    return nullptr;
  }
  if (!mesh || mesh->GetNumberOfPolys() == 0)
  {
    error = path + " holds no polygons";
    return nullptr;
  }
  return mesh;
}
}

#endif
