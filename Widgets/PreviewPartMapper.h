// PreviewPartMapper: the OpenGL mapper of a drag preview's part, whose points move every frame
// and whose cells do not. ParaView's Editable Surface draws an edited surface with it too
// (vtkLaplacianSurfaceMapper), for the same reason.
//
// VTK 9.1 and 9.2 rebuild a mapper's index buffers whenever its input's points move:
// vtkOpenGLPolyDataMapper::BuildIBO compares a state that BuildBufferObjects has already filled,
// with the input's MTime among it, as it does not clear it first: buffers the points do not change,
// rebuilt every drag frame. This mapper keys them on what they are made of: the cells, the
// representation, the edge flags, the edge and vertex visibility, and the points only where a
// polygon has more than three (those are triangulated on their positions). During a hardware
// selection it leaves the decision to VTK, whose selection passes change the buffers. A surface of
// triangles shown without edges or vertices (a preview's usual part) has its connectivity for index
// buffer: uploaded whole, where VTK appends it a cell at a time (what each saves: performance.md,
// "Frames per second during a drag").
//
// Its bounds are its points' ranges: VTK's are its cells' (so that unused points do not count), a
// pass over every cell each frame, and a part's points are all its cells'. The ranges are those
// vtkDataArray caches, which the vertex buffer's shift and scale then read instead of computing
// them again.
#ifndef LaplacianEditing_Widgets_PreviewPartMapper_h
#define LaplacianEditing_Widgets_PreviewPartMapper_h

#include "vtkOpenGLPolyDataMapper.h"

#include <array>

namespace LaplacianEditing
{
namespace Widgets
{
class PreviewPartMapper : public vtkOpenGLPolyDataMapper
{
public:
  static PreviewPartMapper* New();
  vtkTypeMacro(PreviewPartMapper, vtkOpenGLPolyDataMapper);

  /// How many times the index buffers were built.
  int GetNumberOfIndexBuilds() const { return this->IndexBuilds; }

protected:
  PreviewPartMapper() = default;
  ~PreviewPartMapper() override = default;

  void BuildIBO(vtkRenderer* renderer, vtkActor* actor, vtkPolyData* input) override;
  void ComputeBounds() override;

private:
  PreviewPartMapper(const PreviewPartMapper&) = delete;
  void operator=(const PreviewPartMapper&) = delete;

  std::array<vtkMTimeType, 9> IndexKey = {};
  int IndexBuilds = 0;
  // Whether the polygons are all triangles, as of their MTime.
  vtkMTimeType PolygonsChecked = 0;
  bool OnlyTriangles = true;
};
}
}

#endif
