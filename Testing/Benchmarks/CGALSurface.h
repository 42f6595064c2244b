// The same vertices and polygons as a CGAL::Surface_mesh, for the benchmarks' comparisons with
// CGAL's Surface_mesh_deformation.
#ifndef CGALSurface_h
#define CGALSurface_h

#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkPolyData.h"

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>

#include <vector>

namespace CGALSurface
{
using Kernel = CGAL::Simple_cartesian<double>;
using Mesh = CGAL::Surface_mesh<Kernel::Point_3>;
using Vertex = Mesh::Vertex_index;

/// Fills `surface`; returns the vertex of each point, and counts the polygons CGAL refused.
inline std::vector<Vertex> Build(vtkPolyData* mesh, Mesh& surface, int* skippedFaces = nullptr)
{
  std::vector<Vertex> vertices;
  for (vtkIdType i = 0; i < mesh->GetNumberOfPoints(); ++i)
  {
    const double* p = mesh->GetPoint(i);
    vertices.push_back(surface.add_vertex(Kernel::Point_3(p[0], p[1], p[2])));
  }
  int skipped = 0;
  auto cells = vtk::TakeSmartPointer(mesh->GetPolys()->NewIterator());
  for (cells->GoToFirstCell(); !cells->IsDoneWithTraversal(); cells->GoToNextCell())
  {
    vtkIdType size;
    const vtkIdType* ids;
    cells->GetCurrentCell(size, ids);
    std::vector<Vertex> face;
    for (vtkIdType c = 0; c < size; ++c)
    {
      face.push_back(vertices[ids[c]]);
    }
    skipped += surface.add_face(face) == Mesh::null_face() ? 1 : 0;
  }
  if (skippedFaces)
  {
    *skippedFaces = skipped;
  }
  return vertices;
}
}

#endif
