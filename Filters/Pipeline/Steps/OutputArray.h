// OutputArray: one array of a filter's output kept between updates: the rest array with some tuples written in place.
//
// A handle move changes the points of one region, the normals around it and nothing else, so
// an update writes those tuples into a buffer it kept from an earlier update, after putting
// back the rest values of the tuples that buffer's own last update wrote. A move then costs
// what its region costs. A whole copy of the rest array is made only when the rest array
// changed (a new input, a commit) or when every buffer is held by another object.
//
// Copy on write: a buffer that anyone else holds (a user's reference or shallow copy, a
// rendering cache) is never written. A buffer is free when its only references are this
// object's (and its vtkPoints') and those of the outputs of the filters connected to the
// output, which the next pipeline update recomputes (the PipelineHolders function counts
// them: ParaView puts a pass-through filter after every source). A consumer that keeps the previous output
// elsewhere until it updates again (ParaView's representations) makes the updates alternate
// between two buffers, each written in place; at most MaximumBuffers are kept, and one held
// elsewhere beyond that is left to its holder.
#ifndef LaplacianEditing_Pipeline_OutputArray_h
#define LaplacianEditing_Pipeline_OutputArray_h

#include "TupleExtremes.h"

#include "vtkAOSDataArrayTemplate.h"
#include "vtkArrayDispatch.h"
#include "vtkDataArrayRange.h"
#include "vtkSMPThreadLocal.h"
#include "vtkSMPTools.h"
#include "vtkSmartPointer.h"
#include "vtkType.h"

#include <cstdint>
#include <functional>
#include <vector>

class vtkDataArray;
class vtkObjectBase;
class vtkPoints;

namespace LaplacianEditing
{
namespace Pipeline
{
class OutputArray
{
public:
  using Writer = std::function<void(vtkDataArray*)>;
  /// How many references to `object` the outputs of the filters downstream hold, not counting
  /// those through `ownPoints` (the buffer's vtkPoints, when `object` is its array).
  using Holders = std::function<int(vtkObjectBase* object, vtkObjectBase* ownPoints)>;

  /// The references that do not make a buffer shared; none by default.
  void SetPipelineHolders(const Holders& holders) { this->PipelineHolders = holders; }

  /// An array equal to `rest` except at the tuples `ids`, which `write` sets (all of them).
  /// `key` names what `write` writes: a buffer whose last update had the same rest, ids and key
  /// is returned untouched (not even Modified), held elsewhere or not, since it is not written.
  /// With no ids, `rest` itself.
  vtkDataArray* Update(
    vtkDataArray* rest, const std::vector<vtkIdType>& ids, std::uint64_t key, const Writer& write);
  /// The same for a point set's points.
  vtkPoints* Update(
    vtkPoints* rest, const std::vector<vtkIdType>& ids, std::uint64_t key, const Writer& write);

  /// Sets tuple `ids[i]` of `array` to the `Components` values `value(i, values)` gives, for
  /// every i, in parallel and on the array's own value type: a virtual SetTuple per tuple costs
  /// a large region's drag step more than its solve's back-substitution (performance.md,
  /// "Measured choices").
  /// With `measured`, the extremes of the values written, as the array stores them, are added
  /// to it in the same pass (an update's write passed to its own WriteExtremes() keeps the
  /// array's cached ranges without passing over its tuples again).
  template <int Components, typename Value>
  static void SetTuples(vtkDataArray* array, const std::vector<vtkIdType>& ids, const Value& value,
    TupleExtremes* measured = nullptr)
  {
    auto write = [&](auto* typed) {
      auto tuples = vtk::DataArrayTupleRange<Components>(typed);
      using Stored = typename decltype(tuples)::ComponentType;
      vtkSMPThreadLocal<TupleExtremes> extremes{ TupleExtremes{ Components } };
      const vtkIdType count = static_cast<vtkIdType>(ids.size());
#if defined(__GNUC__)
      // The ids need not be in order, and a store that misses the cache holds the next ones
      // back: the tuples 32 ahead are fetched for writing first (contiguous arrays only; the
      // points' write of a 610k-vertex region lost a third of its time, performance.md).
      constexpr vtkIdType ahead = 32;
      auto* aos = vtkAOSDataArrayTemplate<Stored>::FastDownCast(typed);
      Stored* contiguous = aos ? aos->GetPointer(0) : nullptr;
#endif
      vtkSMPTools::For(0, count, [&](vtkIdType begin, vtkIdType end) {
        double values[Components];
        Stored stored[Components];
        TupleExtremes& local = extremes.Local();
        for (vtkIdType i = begin; i < end; ++i)
        {
#if defined(__GNUC__)
          if (contiguous && i + ahead < count)
          {
            __builtin_prefetch(contiguous + Components * ids[i + ahead], 1);
          }
#endif
          value(i, values);
          auto tuple = tuples[ids[i]];
          for (int c = 0; c < Components; ++c)
          {
            stored[c] = static_cast<Stored>(values[c]);
            tuple[c] = stored[c];
          }
          if (measured)
          {
            local.Add(stored);
          }
        }
      });
      for (auto it = extremes.begin(); measured && it != extremes.end(); ++it)
      {
        measured->Merge(*it);
      }
    };
    if (!vtkArrayDispatch::Dispatch::Execute(array, write))
    {
      write(array);
    }
  }

  /// Where this array's current update lets its writer measure what it writes (SetTuples'
  /// `measured`); valid inside the update's write only.
  TupleExtremes* WriteExtremes() { return &this->Written; }

  /// How many whole copies of a rest array the updates made.
  vtkIdType GetNumberOfCopies() const { return this->Copies; }

  static constexpr int MaximumBuffers = 3;

private:
  struct Buffer
  {
    vtkSmartPointer<vtkDataArray> Array;
    vtkSmartPointer<vtkPoints> Points; // wraps Array when the rest is a vtkPoints
    // What the buffer holds: the rest array it copied (compared, never dereferenced) at its
    // modification time, the tuples its last update wrote, and that update's key.
    const vtkDataArray* Source = nullptr;
    vtkMTimeType SourceTime = 0;
    std::vector<vtkIdType> Written;
    std::vector<vtkIdType> WrittenSorted; // Written, sorted, once each: a drag's moves reuse it
    std::uint64_t Key = 0;
    // The extremes of the tuples outside a set that changes (CachedRanges in the source), and
    // that set: measured once for a region, they keep the cached ranges when its writes reach an
    // extreme.
    std::vector<std::vector<double>> Unchanged;
    std::vector<vtkIdType> UnchangedOutside;
    // The extremes of the tuples the last update wrote, while the array stays as it left it
    // (its modification time then): the next write of the same tuples need not measure them.
    std::vector<std::vector<double>> WrittenExtremes;
    vtkMTimeType WrittenTime = 0;
    vtkIdType LastUse = 0;
    bool IsFree(const Holders& pipeline) const;
  };

  Buffer* Find(vtkDataArray* rest, const std::vector<vtkIdType>& ids, std::uint64_t key);
  Buffer& Acquire(vtkDataArray* rest, bool points);
  void Refresh(Buffer& buffer, vtkDataArray* rest, const std::vector<vtkIdType>& ids,
    std::uint64_t key, const Writer& write);

  std::vector<Buffer> Buffers;
  TupleExtremes Written; // what the current update's writer measured
  Holders PipelineHolders;
  vtkIdType Copies = 0;
  vtkIdType Uses = 0;
};

}
}

#endif
