// HandleMaps: how each handle group moves: its transform object or its motion properties, as the core's affine maps.
//
// A handle group follows its vtkLinearTransform where one is set. Otherwise group 0 follows
// the filter's HandleTranslation and HandleRotation about HandleCenter, and groups 1, 2, ...
// their motions (a translation, then rotation angles about x, y, z) about their rest centroids,
// which this class finds once per region. Maps() turns all of them into the core's frame.
#ifndef LaplacianEditing_Pipeline_HandleMaps_h
#define LaplacianEditing_Pipeline_HandleMaps_h

#include "EditRegion.h"
#include "Types.h"
#include "vtkLaplacianEditingFiltersModule.h" // for export macro

#include "vtkIndent.h"
#include "vtkSmartPointer.h"
#include "vtkType.h"

#include <array>
#include <map>
#include <optional>
#include <vector>

class vtkLinearTransform;

namespace LaplacianEditing
{
namespace Pipeline
{
class SurfaceAdapter;

class VTKLAPLACIANEDITINGFILTERS_EXPORT HandleMaps
{
public:
  ///@{
  /// The transform objects, one slot per group; the setters return whether anything changed.
  bool SetTransform(int group, vtkLinearTransform* transform);
  vtkLinearTransform* GetTransform(int group) const;
  int GetNumberOfTransforms() const { return static_cast<int>(this->Transforms.size()); }
  bool RemoveAllTransforms();
  /// The newest MTime of the transform objects (0 without any).
  vtkMTimeType GetTransformsMTime() const;
  ///@}

  ///@{
  /// The motions of groups 1 and above, as (translation, rotation); the setters return whether
  /// anything changed.
  bool SetMotion(int group, const std::array<double, 6>& motion);
  bool GetMotion(int group, double motion[6]) const;
  int GetNumberOfMotions() const { return static_cast<int>(this->Motions.size()); }
  bool RemoveAllMotions();
  ///@}

  /// Finds each group's rest centroid in `region` (once per region: moves read them).
  void FindGroupCenters(
    const LaplacianEditing::EditRegion& region, const SurfaceAdapter& surface);
  /// Group `group`'s rest centroid in the last region; nullptr if it has no vertex there.
  const double* GetGroupCenter(int group) const;

  /// The maps of `groups` handle groups in the core's frame of `surface`; group 0 without a
  /// transform object moves by `rotation` about `center`, then `translation`.
  std::vector<LaplacianEditing::AffineMap> Maps(int groups, const SurfaceAdapter& surface,
    const double center[3], const double rotation[3], const double translation[3]) const;

  void PrintSelf(ostream& os, vtkIndent indent) const;

private:
  std::vector<vtkSmartPointer<vtkLinearTransform>> Transforms;
  std::map<int, std::array<double, 6>> Motions;
  std::vector<std::optional<std::array<double, 3>>> GroupCenters;
};

}
}

#endif
