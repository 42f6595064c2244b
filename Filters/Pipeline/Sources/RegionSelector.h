// RegionSelector: where the handle and the region of interest come from, and how far an edit reaches.
//
// The handle is a geodesic disc around the vertex nearest a centre point, the labels of an
// integer point array (0 fixed, 1 ROI, 2 + g handle group g), or a vtkSelection, labelled as
// such an array (2 on the selected points and the points of selected cells) with the ROI grown
// around it. The selector checks the choice, finds the part of the rest surface the edit can
// reach (one pass over the points, repeated only when what it reads changes), makes the core's
// request for the region, and warns about a region that is likely a mistake.
#ifndef LaplacianEditing_Pipeline_RegionSelector_h
#define LaplacianEditing_Pipeline_RegionSelector_h

#include "EditRegion.h"
#include "LaplacianEditor.h" // for RegionRequest
#include "SurfaceAdapter.h"
#include "vtkLaplacianEditingFiltersModule.h" // for export macro

#include "vtkSmartPointer.h"

#include <functional>
#include <memory>
#include <string>

class vtkDataArray;
class vtkIntArray;
class vtkObject;
class vtkPolyData;
class vtkSelection;

namespace LaplacianEditing
{
namespace Pipeline
{
/// The properties that choose an edit's region, radii in mesh units.
struct RegionParameters
{
  bool FromArray = false; // the filter's SelectionMode Array
  double HandleCenter[3] = { 0.0, 0.0, 0.0 };
  double HandleRadius = 0.0;
  double ROIRadius = 0.0;
  double AnchorPadding = 0.1;
  int DistanceMethod = 0;
  /// The explicit mode's normal smoothing support (0: automatic), which the reach includes.
  double NormalSmoothingRadius = 0.0;
};

class VTKLAPLACIANEDITINGFILTERS_EXPORT RegionSelector
{
public:
  using Parameters = RegionParameters;

  /// Labels the handle of a selection on `input` (see LabelSelection).
  using Labeler = std::function<vtkSmartPointer<vtkIntArray>(vtkPolyData*, vtkSelection*)>;

  /// Chooses the labels for an edit of `input`: `selection` labelled by `label` (made again
  /// only when the selection or the input changes) where there is one, else, `fromArray`, the
  /// integer `array`, else none (geodesic discs). Returns an error message, empty on success.
  std::string SelectLabels(vtkPolyData* input, vtkSelection* selection, bool fromArray,
    vtkDataArray* array, const Labeler& label);
  /// The labels chosen (nullptr: geodesic discs).
  vtkDataArray* GetLabels() const { return this->Labels; }

  /// The handle labels of `input` for `selection`: 2 on the selected points and on the points
  /// of selected cells, 0 elsewhere. Nodes whose PROCESS_ID names another piece than `piece`
  /// are skipped, as ParaView's selections of ids address each piece.
  static vtkSmartPointer<vtkIntArray> LabelSelection(
    vtkPolyData* input, vtkSelection* selection, int piece);

  /// How far the ROI grows around a selection's handle (0 for labels from an array).
  double SelectionGrowth(const Parameters& parameters) const;

  /// The part of `rest` the edit can reach, for the surface graph.
  const Reach& ComputeReach(vtkPolyData* rest, const Parameters& parameters);

  /// Sets how far `reach` extends around its seeds (the handle centre, or the labelled
  /// points), widened by `widening`: `extent` is the distance from the handle centre to the
  /// nearest polygon corner or, for labels, half the labelled points' extent; `growth` how far a
  /// selection's ROI grows. Without seeds or polygons (`extent` < 0) it reaches everything, so
  /// that the core says what is wrong on the whole input. The parallel filter bounds its global
  /// reach with it too.
  static void SetMargin(Reach& reach, const Parameters& parameters, bool labelled, double extent,
    double growth, double widening = 0.0);

  /// The core's request for the region on `surface`, built from `rest`.
  LaplacianEditing::RegionRequest Request(vtkPolyData* rest,
    const SurfaceAdapter& surface, const Parameters& parameters) const;

  /// Warns, through `reporter`, about a region that is likely not what the user meant: a
  /// handle centre away from the surface, an ROI that swallows its component, a handle or ROI
  /// of one vertex. `region` is the one selected for `request`; `diagonal` is the surface's.
  void Warn(vtkObject* reporter, const LaplacianEditing::RegionRequest& request,
    const LaplacianEditing::EditRegion& region, const SurfaceAdapter& surface,
    const Parameters& parameters, double diagonal) const;

private:
  // The vertex of `surface` nearest `center` (mesh units), found again only for another
  // centre or graph: each update asks, and a scan of a 2M-vertex graph is a millisecond of a
  // drag step.
  int NearestVertex(const SurfaceAdapter& surface, const double center[3]) const;

  vtkDataArray* Labels = nullptr;
  // A selection's labels and what they were made from (selection time, input content time).
  vtkSmartPointer<vtkIntArray> SelectedLabels;
  vtkMTimeType SelectedKey[2] = { 0, 0 };
  // The reach and what it was computed from (rest time, labels time, handle centre), with the
  // labelled points' half extent or the handle centre's distance to the surface.
  Reach LastReach;
  double ReachKey[5] = { -1.0, -1.0, 0.0, 0.0, 0.0 };
  double ReachExtent = 0.0;
  // NearestVertex's last answer and its question.
  mutable std::weak_ptr<const LaplacianEditing::SurfaceMesh> NearestMesh;
  mutable LaplacianEditing::Vector3 NearestPoint = LaplacianEditing::Vector3::Zero();
  mutable int NearestId = -1;
};

}
}

#endif
