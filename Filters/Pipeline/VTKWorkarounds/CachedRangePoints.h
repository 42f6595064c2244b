// CachedRangePoints: points whose bounds are their array's ranges, those vtkDataArray caches.
//
// vtkPoints::ComputeBounds passes over the whole array whenever the points changed, even where
// the array still caches its ranges (VTK 9.1, 9.2: vtkDataArray::ComputeScalarRange). OutputArray
// keeps those ranges through the writes of a region, so on the points of an edit's output the
// bounds ParaView's data information asks for after each update cost nothing, not a pass over
// every point (performance.md, "Frames per second during a drag"). Where no range is cached,
// the first GetBounds computes and caches them all, for whoever asks for the ranges next.
#ifndef LaplacianEditing_Pipeline_CachedRangePoints_h
#define LaplacianEditing_Pipeline_CachedRangePoints_h

#include "vtkLaplacianEditingFiltersModule.h" // for export macro
#include "vtkPoints.h"

namespace LaplacianEditing
{
namespace Pipeline
{
class VTKLAPLACIANEDITINGFILTERS_EXPORT CachedRangePoints : public vtkPoints
{
public:
  static CachedRangePoints* New();
  vtkTypeMacro(CachedRangePoints, vtkPoints);

  void ComputeBounds() override;

  /// The component ranges of a 3-component array as bounds, those it caches if it does
  /// (computed and cached otherwise).
  static void RangeBounds(vtkDataArray* data, double bounds[6]);
  /// Caches (min, max) pairs, one per component, as the array's component ranges (or its
  /// finite ones), where vtkDataArray keeps what it computes; call after the array's last
  /// Modified(), since a later one drops them.
  static void StoreRanges(vtkDataArray* data, const double* ranges, bool finite = false);

protected:
  CachedRangePoints() = default;
  ~CachedRangePoints() override = default;

private:
  CachedRangePoints(const CachedRangePoints&) = delete;
  void operator=(const CachedRangePoints&) = delete;
};
}
}

#endif
