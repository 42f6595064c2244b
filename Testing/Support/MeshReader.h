// Reads a surface mesh by file extension: OBJ, PLY, STL, VTP or legacy VTK.
#ifndef MeshReader_h
#define MeshReader_h

#include "vtkOBJReader.h"
#include "vtkPLYReader.h"
#include "vtkPolyData.h"
#include "vtkPolyDataReader.h"
#include "vtkSTLReader.h"
#include "vtkSmartPointer.h"
#include "vtkXMLPolyDataReader.h"

#include <algorithm>
#include <cctype>
#include <fstream>
#include <string>

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
  else if (extension == "vtp")
    mesh = ReadWith<vtkXMLPolyDataReader>(path);
  else if (extension == "vtk")
    mesh = ReadWith<vtkPolyDataReader>(path);
  else
  {
    error = "unknown mesh format '." + extension + "' (use OBJ, PLY, STL, VTP or VTK)";
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
