// LandmarkPairs: a template's landmarks and a subject's, given as two point sets (Slicer markups
// through vtkLaplacianMarkupsReader), paired into sources and targets. With a Label array on
// both sides, by label: each label once on each side and on both, so that a landmark placed in
// another order, or missing, is found rather than paired with the wrong one. Without labels, in
// order, and the counts must agree.
#ifndef LaplacianEditing_Pipeline_LandmarkPairs_h
#define LaplacianEditing_Pipeline_LandmarkPairs_h

#include "vtkLaplacianEditingFiltersModule.h" // for export macro

#include <string>

class vtkPointSet;
class vtkPoints;

namespace LaplacianEditing
{
namespace Pipeline
{
/// Fills `pairedSources` and `pairedTargets` (reset first) with the pairs, in the sources'
/// order. Returns an error message, empty on success.
VTKLAPLACIANEDITINGFILTERS_EXPORT std::string PairLandmarks(
  vtkPointSet* sources, vtkPointSet* targets, vtkPoints* pairedSources, vtkPoints* pairedTargets);
}
}

#endif
