#include "vtkLaplacianOutputWriter.h"

#include "vtkLaplacianNormalRefresher.h"
#include "vtkLaplacianSurfaceAdapter.h"

#include "vtkDataArray.h"
#include "vtkLookupTable.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSMPTools.h"
#include "vtkSmartPointer.h"
#include "vtkVariant.h"

namespace le = LaplacianEditing;

namespace
{
// The roles' colours as in the paper's Fig. 2 (fixed grey, anchors red, free green, handle
// yellow), as an indexed table, annotated with the roles' names for colour legends.
vtkSmartPointer<vtkLookupTable> NewRoleColors()
{
  auto table = vtkSmartPointer<vtkLookupTable>::New();
  const struct
  {
    const char* Name;
    double Color[3];
  } roles[] = { { "fixed", { 0.75, 0.75, 0.75 } }, { "anchor", { 0.85, 0.20, 0.15 } },
    { "free", { 0.35, 0.75, 0.35 } }, { "handle", { 0.95, 0.85, 0.10 } } };
  table->IndexedLookupOn();
  table->SetNumberOfTableValues(4);
  for (int role = 0; role < 4; ++role)
  {
    table->SetTableValue(role, roles[role].Color[0], roles[role].Color[1], roles[role].Color[2]);
    table->SetAnnotation(vtkVariant(role), roles[role].Name);
  }
  return table;
}

// A copy of `points` with the region's points moved to `solution`.
vtkSmartPointer<vtkPoints> MovePoints(
  vtkPoints* points, const vtkLaplacianSurfaceAdapter& surface, const le::Positions& solution)
{
  auto moved = vtkSmartPointer<vtkPoints>::New();
  moved->SetDataType(points->GetDataType());
  moved->DeepCopy(points);
  const auto& roiPoints = surface.GetRegionPoints();
  vtkSMPTools::For(0, static_cast<vtkIdType>(roiPoints.size()), [&](vtkIdType begin, vtkIdType end) {
    for (vtkIdType r = begin; r < end; ++r)
    {
      const le::Vector3 p = surface.Denormalize(solution.row(roiPoints[r].second).transpose());
      moved->SetPoint(roiPoints[r].first, p.data());
    }
  });
  return moved;
}
}

void vtkLaplacianOutputWriter::Write(vtkPolyData* rest, vtkPolyData* output,
  const vtkLaplacianSurfaceAdapter& surface, const vtkLaplacianNormalRefresher& normals,
  const le::Positions& solution) const
{
  output->SetPoints(MovePoints(rest->GetPoints(), surface, solution));
  normals.Refresh(output, surface.GetMesh()->GetPositions(), surface.GetRowOfVertex(), solution);
}

void vtkLaplacianOutputWriter::AddEditRoles(
  vtkPolyData* output, vtkDataArray* roles, bool generate, bool colors)
{
  if (!generate)
  {
    return;
  }
  roles->SetLookupTable(colors ? NewRoleColors() : nullptr);
  vtkPointData* pointData = output->GetPointData();
  pointData->AddArray(roles);
  if (!pointData->GetScalars())
  {
    pointData->SetActiveScalars("EditRole"); // a default mapper then shows the roles
  }
}
