// PreviewParts: a drag's preview: the surface cut into the part an edit moves and the still rest.
//
// A view that redraws a whole surface whenever any point moves (ParaView's representations:
// about a second a frame at 2M points) can draw a drag as two parts instead: the still part,
// uploaded once per region, and the moving part, the polygons with a corner in the region,
// small and rewritten each move. The moving part holds its own compact copy of the points,
// normals and every point and cell array of those polygons; the still part shares the rest
// surface's points and arrays (with EditRole all fixed) and holds only its own polygons.
#ifndef LaplacianEditing_Pipeline_PreviewParts_h
#define LaplacianEditing_Pipeline_PreviewParts_h

#include "EditTypes.h"

#include "vtkNew.h"
#include "vtkPolyData.h" // for vtkNew<vtkPolyData>

#include <array>
#include <cstdint>
#include <vector>

namespace LaplacianEditing
{
namespace Pipeline
{
class PreviewParts
{
public:
  /// Cuts the surface for the region `edit` describes: `rest` the rest surface, `output` the
  /// last update's (its arrays, EditRole among them). Costs in proportion to the surface once
  /// per region (the still part's polygons).
  void Build(vtkPolyData* rest, vtkPolyData* output, const OutputEdit& edit);
  /// Whether the parts were built for this region version.
  bool IsBuiltFor(std::uint64_t regionVersion) const
  {
    return this->Built && this->RegionVersion == regionVersion;
  }

  /// Writes the solution of `edit` (the same region) into the moving part, in place.
  void Write(const OutputEdit& edit);

  vtkPolyData* GetStillPart() { return this->Still; }
  vtkPolyData* GetMovingPart() { return this->Moving; }

  /// Forgets both parts.
  void Release();

private:
  void BuildStill(vtkPolyData* rest, vtkPolyData* output, const std::vector<vtkIdType>& movingCells);
  void BuildMoving(vtkPolyData* output, const OutputEdit& edit);

  vtkNew<vtkPolyData> Still;
  vtkNew<vtkPolyData> Moving;
  // Per point of the moving part: its solution row (-1: at rest); its first points are the
  // normal refresher's, in order, so that it writes their normals as tuples 0, 1, ...
  std::vector<int> RowOfPoint;
  // The (min, max) per coordinate of the moving part's points at rest, for its ranges.
  std::array<double, 6> StillPointsExtremes = {};
  std::uint64_t RegionVersion = 0;
  bool Built = false;
};

}
}

#endif
