#include "CoincidentPoints.h"

#include <algorithm>
#include <cmath>

namespace LaplacianEditing
{
namespace
{
// Bins much larger than the tolerance, so that a point near enough a bin's border to have a
// twin across it is rare, and most lookups read one bin.
constexpr double BinsPerTolerance = 1024.0;
}

CoincidentPoints::CoincidentPoints(double tolerance, const Vector3& origin)
  : Tolerance(tolerance)
  , BinSize(BinsPerTolerance * tolerance > 0.0 ? BinsPerTolerance * tolerance : 1.0)
  , Origin(origin)
{
}

std::size_t CoincidentPoints::Slot(const Bin& bin) const
{
  std::uint64_t hash = 0;
  for (std::int64_t index : bin)
  {
    hash = (hash ^ static_cast<std::uint64_t>(index)) * 0x9E3779B97F4A7C15ull;
  }
  const std::size_t mask = this->SlotLast.size() - 1;
  std::size_t slot = static_cast<std::size_t>(hash >> 20) & mask;
  while (this->SlotLast[slot] >= 0 && this->Bins[this->SlotLast[slot]] != bin)
  {
    slot = (slot + 1) & mask;
  }
  return slot;
}

void CoincidentPoints::Rehash(std::size_t slots)
{
  std::vector<int> last = std::move(this->SlotLast);
  this->SlotLast.assign(slots, -1);
  for (int point : last)
  {
    if (point >= 0)
    {
      this->SlotLast[this->Slot(this->Bins[point])] = point;
    }
  }
}

void CoincidentPoints::Reserve(std::size_t count)
{
  std::size_t slots = 16;
  while (slots < 2 * count)
  {
    slots *= 2;
  }
  if (slots > this->SlotLast.size())
  {
    this->Rehash(slots);
  }
  this->Bins.reserve(count);
  this->Positions.reserve(count);
  this->Ids.reserve(count);
  this->PreviousInBin.reserve(count);
}

CoincidentPoints::Bin CoincidentPoints::BinOf(const Vector3& p) const
{
  Bin bin;
  for (int a = 0; a < 3; ++a)
  {
    // Clamped so that a point far from the origin cannot overflow the index.
    const double index = std::floor((p[a] - this->Origin[a]) / this->BinSize);
    bin[a] = static_cast<std::int64_t>(std::max(-4e18, std::min(4e18, index)));
  }
  return bin;
}

int CoincidentPoints::Find(const Vector3& p) const
{
  const Bin bin = this->BinOf(p);
  // Per axis, the bins a twin can lie in: this one, and a neighbour whose border is within
  // the tolerance.
  std::array<std::array<int, 3>, 3> steps;
  std::array<int, 3> counts;
  for (int a = 0; a < 3; ++a)
  {
    const double low = this->Origin[a] + static_cast<double>(bin[a]) * this->BinSize;
    counts[a] = 0;
    steps[a][counts[a]++] = 0;
    if (p[a] - low <= this->Tolerance)
    {
      steps[a][counts[a]++] = -1;
    }
    if (low + this->BinSize - p[a] <= this->Tolerance)
    {
      steps[a][counts[a]++] = 1;
    }
  }
  int found = -1;
  if (this->SlotLast.empty())
  {
    return found;
  }
  for (int i = 0; i < counts[0]; ++i)
  {
    for (int j = 0; j < counts[1]; ++j)
    {
      for (int k = 0; k < counts[2]; ++k)
      {
        const std::size_t slot =
          this->Slot({ bin[0] + steps[0][i], bin[1] + steps[1][j], bin[2] + steps[2][k] });
        for (int point = this->SlotLast[slot]; point >= 0; point = this->PreviousInBin[point])
        {
          if ((this->Positions[point] - p).cwiseAbs().maxCoeff() <= this->Tolerance &&
            (found < 0 || this->Ids[point] < found))
          {
            found = this->Ids[point];
          }
        }
      }
    }
  }
  return found;
}

void CoincidentPoints::Add(const Vector3& p, int id)
{
  if (2 * (this->UsedSlots + 1) > this->SlotLast.size())
  {
    this->Rehash(std::max<std::size_t>(16, 2 * this->SlotLast.size()));
  }
  const int point = static_cast<int>(this->Positions.size());
  const Bin bin = this->BinOf(p);
  const std::size_t slot = this->Slot(bin);
  this->UsedSlots += this->SlotLast[slot] < 0 ? 1 : 0;
  this->Bins.push_back(bin);
  this->Positions.push_back(p);
  this->Ids.push_back(id);
  this->PreviousInBin.push_back(this->SlotLast[slot]);
  this->SlotLast[slot] = point;
}
}
