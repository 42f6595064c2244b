// HandleSource: the deformation filters' edit source. The region comes from the handle: geodesic
// discs around HandleCenter, the labels of a point array, or a vtkSelection (RegionSelector);
// the motions from each handle group's transform or motion properties (HandleMaps). The serial,
// parallel and volume deformation filters share it; each sets the update's properties before
// it runs the pipeline.
#ifndef LaplacianEditing_Pipeline_HandleSource_h
#define LaplacianEditing_Pipeline_HandleSource_h

#include "EditSource.h"
#include "HandleMaps.h"
#include "RegionSelector.h"
#include "vtkLaplacianEditingFiltersModule.h" // for export macro

class vtkObject;

namespace LaplacianEditing
{
namespace Pipeline
{
class VTKLAPLACIANEDITINGFILTERS_EXPORT HandleSource : public EditSource
{
public:
  /// `reporter` warns about regions that are likely mistakes.
  explicit HandleSource(vtkObject* reporter)
    : Reporter(reporter)
  {
  }

  /// This update's properties: the region's, radii in mesh units, and group 0's motion
  /// (rotation angles in degrees about x, y, z about the handle centre, then a translation).
  RegionParameters Parameters;
  double Rotation[3] = { 0.0, 0.0, 0.0 };
  double Translation[3] = { 0.0, 0.0, 0.0 };

  RegionSelector& GetSelector() { return this->Selector; }
  HandleMaps& GetHandles() { return this->Handles; }
  const HandleMaps& GetHandles() const { return this->Handles; }

  Reach ComputeReach(vtkPolyData* rest) override;
  std::string ChooseRegion(vtkPolyData* rest, const SurfaceAdapter& surface, RegionChoice& region) override;
  void RegionSelected(
    const RegionRequest& request, const EditRegion& region, const SurfaceAdapter& surface) override;
  std::string ChooseMotions(
    const SurfaceAdapter& surface, const EditRegion& region, EditMotions& motions) override;

private:
  vtkObject* Reporter;
  RegionSelector Selector;
  HandleMaps Handles;
  double Diagonal = 0.0; // of the rest surface, for the warnings
};
}
}

#endif
