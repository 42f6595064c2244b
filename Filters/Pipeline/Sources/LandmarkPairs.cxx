#include "LandmarkPairs.h"

#include "vtkAbstractArray.h"
#include "vtkPointData.h"
#include "vtkPointSet.h"
#include "vtkPoints.h"
#include "vtkVariant.h"

#include <map>
#include <vector>

namespace LaplacianEditing
{
namespace Pipeline
{
std::string PairLandmarks(
  vtkPointSet* sources, vtkPointSet* targets, vtkPoints* pairedSources, vtkPoints* pairedTargets)
{
  pairedSources->SetDataTypeToDouble();
  pairedTargets->SetDataTypeToDouble();
  pairedSources->Reset();
  pairedTargets->Reset();
  vtkAbstractArray* sourceLabels = sources->GetPointData()->GetAbstractArray("Label");
  vtkAbstractArray* targetLabels = targets->GetPointData()->GetAbstractArray("Label");
  if (!sourceLabels || !targetLabels)
  {
    if (sources->GetNumberOfPoints() != targets->GetNumberOfPoints())
    {
      return "There are " + std::to_string(sources->GetNumberOfPoints()) +
        " source landmarks and " + std::to_string(targets->GetNumberOfPoints()) +
        " targets, without Label arrays to pair them by: give each source landmark one target.";
    }
    for (vtkIdType i = 0; i < sources->GetNumberOfPoints(); ++i)
    {
      pairedSources->InsertNextPoint(sources->GetPoint(i));
      pairedTargets->InsertNextPoint(targets->GetPoint(i));
    }
    return {};
  }
  // Each label once on each side, and on both.
  auto index = [](vtkAbstractArray* labels, std::map<std::string, vtkIdType>& ids, std::string& twice) {
    for (vtkIdType i = 0; i < labels->GetNumberOfValues(); ++i)
    {
      const std::string label = labels->GetVariantValue(i).ToString();
      if (!ids.emplace(label, i).second && twice.empty())
      {
        twice = label;
      }
    }
  };
  std::map<std::string, vtkIdType> fromSource, fromTarget;
  std::string twice;
  index(sourceLabels, fromSource, twice);
  index(targetLabels, fromTarget, twice);
  if (!twice.empty())
  {
    return "The landmark label \"" + twice +
      "\" appears twice on one side: each label names one landmark of the sources and one of "
      "the targets.";
  }
  std::vector<std::string> unpaired;
  for (const auto& [label, id] : fromSource)
  {
    if (!fromTarget.count(label))
    {
      unpaired.push_back(label + " (sources only)");
    }
  }
  for (const auto& [label, id] : fromTarget)
  {
    if (!fromSource.count(label))
    {
      unpaired.push_back(label + " (targets only)");
    }
  }
  if (!unpaired.empty())
  {
    std::string list;
    for (std::size_t k = 0; k < unpaired.size() && k < 5; ++k)
    {
      list += (k ? ", " : "") + unpaired[k];
    }
    return std::to_string(unpaired.size()) + " landmark labels are on one side only: " + list +
      (unpaired.size() > 5 ? ", ..." : "") + ". Pair every source label with a target label.";
  }
  for (vtkIdType i = 0; i < sourceLabels->GetNumberOfValues(); ++i)
  {
    pairedSources->InsertNextPoint(sources->GetPoint(i));
    pairedTargets->InsertNextPoint(
      targets->GetPoint(fromTarget.at(sourceLabels->GetVariantValue(i).ToString())));
  }
  return {};
}
}
}
