// Points that are one point: the copies of a seam (texture charts, the pieces of a parallel
// source, a triangle soup) are often computed separately and differ by rounding, so equality
// is taken up to a small tolerance.
#ifndef LaplacianEditing_CoincidentPoints_h
#define LaplacianEditing_CoincidentPoints_h

#include "Types.h"

#include <array>
#include <cstdint>
#include <vector>

namespace LaplacianEditing
{
class CoincidentPoints
{
public:
  /// Points that differ by at most `tolerance` in every coordinate coincide. `origin` is any
  /// point near the data: positions are binned relative to it.
  CoincidentPoints(double tolerance, const Vector3& origin);

  /// The smallest id of the added points that coincide with `p`; -1 if none does.
  int Find(const Vector3& p) const;
  void Add(const Vector3& p, int id);
  /// Room for `count` points, so that adding them does not rehash.
  void Reserve(std::size_t count);

  /// Well above the rounding of coordinates computed separately (1e-16 of their magnitude) and
  /// far below any edge of a mesh one would edit, as a fraction of the mesh's size.
  static constexpr double RelativeTolerance = 1e-10;

private:
  using Bin = std::array<std::int64_t, 3>;
  Bin BinOf(const Vector3& p) const;
  // The slot of `bin` in the table: where it is, or the empty slot where it would go.
  std::size_t Slot(const Bin& bin) const;
  void Rehash(std::size_t slots);

  double Tolerance;
  double BinSize;
  Vector3 Origin;
  // Per bin its last added point, in an open-addressing table of point indices (linear probing,
  // at most half full; a slot's bin is its point's): a welded scan adds millions of points,
  // where std::unordered_map's node per bin cost seconds. Each point links to the one added
  // before it in its bin.
  std::vector<int> SlotLast; // -1: an empty slot
  std::size_t UsedSlots = 0;
  std::vector<Bin> Bins;
  std::vector<Vector3> Positions;
  std::vector<int> Ids;
  std::vector<int> PreviousInBin;
};
}

#endif
