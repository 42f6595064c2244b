// HandleMotion: the one convention of a handle's motion properties. Rotation angles are degrees
// about x, then y, then z (R = Rz Ry Rx), about a centre; the translation follows the rotation.
// The filters' HandleRotation and HandleTranslation, their handle group motions and the handle
// widget's representation all go through these functions.
#ifndef LaplacianEditing_Pipeline_HandleMotion_h
#define LaplacianEditing_Pipeline_HandleMotion_h

#include "vtkLaplacianEditingFiltersModule.h" // for export macro
#include "vtkSmartPointer.h"

class vtkTransform;

namespace LaplacianEditing
{
namespace Pipeline
{
class VTKLAPLACIANEDITINGFILTERS_EXPORT HandleMotion
{
public:
  /// x' = R (x - center) + center + translation.
  static vtkSmartPointer<vtkTransform> Transform(
    const double center[3], const double rotation[3], const double translation[3]);

  /// R for rotation angles in degrees.
  static void RotationMatrix(const double angles[3], double matrix[3][3]);

  /// The angles of a rotation matrix R, in degrees. Where the angle about y is +-90 degrees, only
  /// the difference or sum of the other two is defined, and the angle about x is 0.
  static void Angles(const double matrix[3][3], double angles[3]);
};
}
}

#endif
