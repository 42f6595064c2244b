#include "UsedPointsBounds.h"

#include "OnlySurface.h"

#include "vtkCellArray.h"
#include "vtkDataArrayRange.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"

#include <algorithm>
#include <vector>

namespace
{
// vtkPolyData caches its cells' bounds in protected members and has no setter for them; a
// subclass may name them, and C++ lets its pointers to them reach any vtkPolyData.
struct CellsBoundsCache : vtkPolyData
{
  static void Set(vtkPolyData* surface, const double bounds[6])
  {
    double(vtkPolyData::*cellsBounds)[6] = &CellsBoundsCache::CellsBounds;
    vtkTimeStamp vtkPolyData::*cellsBoundsTime = &CellsBoundsCache::CellsBoundsTime;
    std::copy(bounds, bounds + 6, surface->*cellsBounds);
    (surface->*cellsBoundsTime).Modified();
  }
};

// Marks the points a cell array's cells use; false if an id is not a point.
struct MarkUsedPoints
{
  template <typename CellState>
  bool operator()(CellState& state, std::vector<char>& used, vtkIdType& usedCount) const
  {
    const auto numberOfPoints = static_cast<vtkIdType>(used.size());
    for (const auto id : vtk::DataArrayValueRange<1>(state.GetConnectivity()))
    {
      const auto point = static_cast<vtkIdType>(id);
      if (point < 0 || point >= numberOfPoints)
      {
        return false;
      }
      usedCount += used[point] ? 0 : 1;
      used[point] = 1;
    }
    return true;
  }
};
}

namespace LaplacianEditing
{
namespace Representations
{
bool UsedPointsBounds::Fill(vtkDataObject* data)
{
  vtkPolyData* surface = OnlySurface(data);
  if (!surface || !surface->GetPoints() || !this->AllPointsUsed(surface))
  {
    return false;
  }
  double bounds[6];
  surface->GetPoints()->GetBounds(bounds);
  CellsBoundsCache::Set(surface, bounds);
  return true;
}

bool UsedPointsBounds::AllPointsUsed(vtkPolyData* surface)
{
  const std::array<vtkCellArray*, 4> cells = { surface->GetVerts(), surface->GetLines(),
    surface->GetPolys(), surface->GetStrips() };
  const vtkIdType numberOfPoints = surface->GetNumberOfPoints();
  bool checked = numberOfPoints == this->NumberOfPoints;
  for (std::size_t kind = 0; kind < cells.size() && checked; ++kind)
  {
    checked = this->Cells[kind] == cells[kind] && this->CellsTimes[kind] == cells[kind]->GetMTime();
  }
  if (checked)
  {
    return this->AllUsed;
  }

  ++this->CellPasses;
  std::vector<char> used(numberOfPoints, 0);
  vtkIdType usedCount = 0;
  bool valid = true;
  for (vtkCellArray* kind : cells)
  {
    valid = valid && kind->Visit(MarkUsedPoints{}, used, usedCount);
  }
  for (std::size_t kind = 0; kind < cells.size(); ++kind)
  {
    this->Cells[kind] = cells[kind];
    this->CellsTimes[kind] = cells[kind]->GetMTime();
  }
  this->NumberOfPoints = numberOfPoints;
  this->AllUsed = valid && numberOfPoints > 0 && usedCount == numberOfPoints;
  return this->AllUsed;
}
}
}
