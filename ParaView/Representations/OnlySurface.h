// OnlySurface: the surface a representation draws, where it draws one.
//
// ParaView's geometry representation hands its mapper a composite even for one surface; the
// Editable Surface representation's shortcuts (UsedPointsBounds, vtkLaplacianSurfaceMapper) are
// for that one surface.
#ifndef LaplacianEditing_Representations_OnlySurface_h
#define LaplacianEditing_Representations_OnlySurface_h

class vtkDataObject;
class vtkPolyData;

namespace LaplacianEditing
{
namespace Representations
{
/// `data` if it is a surface, the only non-empty leaf of a composite if that is a surface, or
/// null.
vtkPolyData* OnlySurface(vtkDataObject* data);
}
}

#endif
