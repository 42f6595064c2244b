#include "PreviewPartMapper.h"

#include "CachedRangePoints.h"

#include "vtkActor.h"
#include "vtkCellArray.h"
#include "vtkMath.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLIndexBufferObject.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkProperty.h"
#include "vtkRenderer.h"

#include <vector>

namespace LaplacianEditing
{
namespace Widgets
{
vtkStandardNewMacro(PreviewPartMapper);

namespace
{
// Whether every polygon has three points: the offsets run 0, 3, 6, ... (one pass over a raw
// array, where vtkCellArray::GetMaxCellSize visits each cell).
struct AllTriangles
{
  template <typename CellState>
  bool operator()(CellState& state) const
  {
    const auto* offsets = state.GetOffsets()->GetPointer(0);
    const vtkIdType cells = state.GetNumberOfCells();
    bool triangles = true;
    for (vtkIdType cell = 0; cell <= cells; ++cell)
    {
      triangles &= offsets[cell] == 3 * cell;
    }
    return triangles;
  }
};

// The triangles' index buffer is their connectivity: uploaded as it is stored (32-bit ids have
// the bits of GL's unsigned ones), instead of VTK's cell-by-cell append.
struct UploadTriangles
{
  template <typename CellState>
  void operator()(CellState& state, vtkOpenGLIndexBufferObject* buffer) const
  {
    using Id = typename CellState::ValueType;
    const Id* ids = state.GetConnectivity()->GetPointer(0);
    const std::size_t count = static_cast<std::size_t>(state.GetConnectivity()->GetNumberOfValues());
    buffer->IndexCount = count;
    if (count == 0)
    {
      return;
    }
    if constexpr (sizeof(Id) == sizeof(unsigned int))
    {
      buffer->Upload(ids, count, vtkOpenGLBufferObject::ElementArrayBuffer);
    }
    else
    {
      const std::vector<unsigned int> narrowed(ids, ids + count);
      buffer->Upload(narrowed, vtkOpenGLBufferObject::ElementArrayBuffer);
    }
  }
};
}

void PreviewPartMapper::BuildIBO(vtkRenderer* renderer, vtkActor* actor, vtkPolyData* input)
{
  if (renderer->GetSelector())
  {
    this->IndexKey = {}; // rebuilt after the selection too
    this->Superclass::BuildIBO(renderer, actor, input);
    return;
  }
  vtkCellArray* polygons = input->GetPolys();
  if (polygons->GetMTime() != this->PolygonsChecked)
  {
    this->OnlyTriangles = polygons->Visit(AllTriangles{});
    this->PolygonsChecked = polygons->GetMTime();
  }
  vtkProperty* property = actor->GetProperty();
  vtkDataArray* edgeFlags = input->GetPointData()->GetAttribute(vtkDataSetAttributes::EDGEFLAG);
  const std::array<vtkMTimeType, 9> key = { input->GetVerts()->GetMTime(),
    input->GetLines()->GetMTime(), polygons->GetMTime(), input->GetStrips()->GetMTime(),
    static_cast<vtkMTimeType>(property->GetRepresentation()),
    edgeFlags ? edgeFlags->GetMTime() : 0,
    static_cast<vtkMTimeType>(property->GetEdgeVisibility()),
    static_cast<vtkMTimeType>(property->GetVertexVisibility()),
    this->OnlyTriangles || !input->GetPoints() ? 0 : input->GetPoints()->GetMTime() };
  if (key == this->IndexKey)
  {
    return;
  }
  this->IndexKey = key;
  ++this->IndexBuilds;
  // VTK's key would match buffers this mapper has since replaced.
  this->IBOBuildState.Clear();
  if (!this->OnlyTriangles || property->GetRepresentation() != VTK_SURFACE ||
    property->GetEdgeVisibility() || property->GetVertexVisibility())
  {
    this->Superclass::BuildIBO(renderer, actor, input);
    return;
  }
  // What VTK builds for a surface without edges or vertices shown, the triangles uploaded whole.
  this->Primitives[PrimitivePoints].IBO->CreatePointIndexBuffer(input->GetVerts());
  this->Primitives[PrimitiveLines].IBO->CreateLineIndexBuffer(input->GetLines());
  polygons->Visit(UploadTriangles{}, this->Primitives[PrimitiveTris].IBO);
  this->Primitives[PrimitiveTriStrips].IBO->CreateStripIndexBuffer(input->GetStrips(), false);
}

void PreviewPartMapper::ComputeBounds()
{
  vtkPolyData* input = this->GetInput();
  if (!input || !input->GetPoints() || input->GetNumberOfPoints() == 0)
  {
    vtkMath::UninitializeBounds(this->Bounds);
    return;
  }
  // The ranges vtkDataArray caches, which the vertex buffer's shift and scale read next (the
  // still part's points are the input's, not always CachedRangePoints).
  LaplacianEditing::Pipeline::CachedRangePoints::RangeBounds(
    input->GetPoints()->GetData(), this->Bounds);
}
}
}
