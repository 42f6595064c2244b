/**
 * @class   vtkLaplacianOutputWriter
 * @brief   writes a solved edit into a filter's output: moved points, refreshed normals and the
 *          EditRole array (not wrapped)
 *
 * The output is the rest surface with all its point and cell data; the writer replaces the
 * points, the point and cell normals near the edit, and adds EditRole. Every point outside the
 * region keeps its rest coordinates exactly.
 */
#ifndef vtkLaplacianOutputWriter_h
#define vtkLaplacianOutputWriter_h

#include "Types.h"

class vtkDataArray;
class vtkLaplacianNormalRefresher;
class vtkLaplacianSurfaceAdapter;
class vtkPolyData;

class vtkLaplacianOutputWriter
{
public:
  /// Writes `solution` (rows follow the surface's region, in the core's frame) into `output`, a
  /// shallow copy of `rest`.
  void Write(vtkPolyData* rest, vtkPolyData* output, const vtkLaplacianSurfaceAdapter& surface,
    const vtkLaplacianNormalRefresher& normals, const LaplacianEditing::Positions& solution) const;

  /// Adds `roles` as the EditRole array when `generate` is on: the active scalars where the
  /// output has none, with an indexed lookup table of the paper's Fig. 2 colours when `colors`
  /// is on.
  static void AddEditRoles(vtkPolyData* output, vtkDataArray* roles, bool generate, bool colors);
};

#endif
