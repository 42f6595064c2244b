// Points that are one point: the copies of a seam (texture charts, the pieces of a parallel
// source, a triangle soup) are often computed separately and differ by rounding, so equality
// is taken up to a small tolerance.
#ifndef LaplacianEditing_CoincidentPoints_h
#define LaplacianEditing_CoincidentPoints_h

#include "Types.h"

#include <array>
#include <cstdint>
#include <unordered_map>
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

  /// Well above the rounding of coordinates computed separately (1e-16 of their magnitude) and
  /// far below any edge of a mesh one would edit, as a fraction of the mesh's size.
  static constexpr double RelativeTolerance = 1e-10;

private:
  using Bin = std::array<std::int64_t, 3>;
  struct BinHash
  {
    std::size_t operator()(const Bin& bin) const;
  };
  Bin BinOf(const Vector3& p) const;

  double Tolerance;
  double BinSize;
  Vector3 Origin;
  // Per bin its last added point; each point links to the one added before it in its bin.
  std::unordered_map<Bin, int, BinHash> LastInBin;
  std::vector<Vector3> Positions;
  std::vector<int> Ids;
  std::vector<int> PreviousInBin;
};
}

#endif
