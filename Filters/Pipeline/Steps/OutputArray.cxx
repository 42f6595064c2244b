#include "OutputArray.h"

#include "CachedRangePoints.h"
#include "TupleExtremes.h"

#include "vtkArrayDispatch.h"
#include "vtkDataArray.h"
#include "vtkDataArrayRange.h"
#include "vtkInformation.h"
#include "vtkInformationDoubleVectorKey.h"
#include "vtkInformationInformationVectorKey.h"
#include "vtkInformationVector.h"
#include "vtkPoints.h"
#include "vtkSMPTools.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace LaplacianEditing
{
namespace Pipeline
{
namespace
{
// The ranges vtkDataArray caches in its information (per component and of the tuples' norms,
// plain and finite), carried across a write of a few tuples. Modified() drops the cache, and
// whoever asks next (ParaView's data information, the points' bounds) would pass over the
// whole array. Where a cached extreme lies outside the tuples written, the new extreme is that
// one or a written value: known from the written tuples alone. Where it lies among them (a
// handle on the surface's extreme), it is the extreme of the tuples left alone or a written
// value: those tuples' extremes are measured once for the set of tuples that change, one pass
// kept for every later write of the same region (performance.md, "Measured choices").
class CachedRanges
{
public:
  using Extremes = std::vector<double>;
  static constexpr int Families = TupleExtremes::Families;

  // Before the write: the ranges cached, and the changing tuples' ranges (measured unless
  // given as `known`).
  void Capture(vtkDataArray* array, const std::vector<vtkIdType>& changing,
    const std::vector<Extremes>* known = nullptr)
  {
    this->Components = array->GetNumberOfComponents();
    vtkInformation* info = array->HasInformation() ? array->GetInformation() : nullptr;
    for (int f = 0; f < Families; ++f)
    {
      this->Cached[f] = info && this->Components <= TupleExtremes::MaximumComponents &&
        Get(info, f, this->Components, this->Ranges[f]);
    }
    if (known && known->size() == Families)
    {
      std::copy(known->begin(), known->end(), this->Old.begin());
    }
    else
    {
      this->Old = Measure(array, changing);
    }
  }

  // Whether a cached extreme may lie among the changing tuples.
  bool NeedsUnchanged() const
  {
    for (int f = 0; f < Families; ++f)
    {
      if (this->Cached[f] && !this->OutsideOld(f))
      {
        return true;
      }
    }
    return false;
  }

  // The extremes of the tuples outside `changing` (sorted).
  static std::vector<Extremes> MeasureUnchanged(vtkDataArray* array, const std::vector<vtkIdType>& changing)
  {
    std::vector<vtkIdType> ids;
    ids.reserve(array->GetNumberOfTuples() - changing.size());
    auto next = changing.begin();
    for (vtkIdType id = 0; id < array->GetNumberOfTuples(); ++id)
    {
      if (next != changing.end() && *next == id)
      {
        ++next;
        continue;
      }
      ids.push_back(id);
    }
    const std::array<Extremes, Families> unchanged = Measure(array, ids);
    return { unchanged.begin(), unchanged.end() };
  }

  // After the write and Modified(): the ranges that are still known, with the extremes of the
  // tuples left alone if given. Returns the changed tuples' extremes, measured unless given.
  std::vector<Extremes> Restore(vtkDataArray* array, const std::vector<vtkIdType>& changed,
    const std::vector<Extremes>* unchanged, const TupleExtremes* measured)
  {
    const std::array<Extremes, Families> written = measured ? measured->Get() : Measure(array, changed);
    for (int f = 0; f < Families; ++f)
    {
      if (!this->Cached[f])
      {
        continue;
      }
      std::vector<double>& range = this->Ranges[f];
      const bool outside = this->OutsideOld(f);
      if (!outside && !unchanged)
      {
        continue;
      }
      for (std::size_t i = 0; i + 1 < range.size(); i += 2)
      {
        const double low = outside ? range[i] : (*unchanged)[f][i];
        const double high = outside ? range[i + 1] : (*unchanged)[f][i + 1];
        range[i] = std::min(low, written[f][i]);
        range[i + 1] = std::max(high, written[f][i + 1]);
      }
      Set(array, f, range);
    }
    return { written.begin(), written.end() };
  }

private:
  static bool Finite(int family) { return family == 1 || family == 3; }
  static bool Norm(int family) { return family >= 2; }

  // Whether family f's cached extremes lie strictly outside the changing tuples' old values:
  // attained by a tuple not written.
  bool OutsideOld(int f) const
  {
    const std::vector<double>& range = this->Ranges[f];
    for (std::size_t i = 0; i + 1 < range.size(); i += 2)
    {
      if (!(range[i] < this->Old[f][i] && range[i + 1] > this->Old[f][i + 1]))
      {
        return false;
      }
    }
    return true;
  }

  static bool Get(vtkInformation* info, int family, int components, std::vector<double>& range)
  {
    if (Norm(family))
    {
      vtkInformationDoubleVectorKey* key =
        Finite(family) ? vtkDataArray::L2_NORM_FINITE_RANGE() : vtkDataArray::L2_NORM_RANGE();
      range.assign(2, 0.0);
      return components > 1 && info->Has(key) && (info->Get(key, range.data()), true);
    }
    vtkInformationInformationVectorKey* key = Finite(family)
      ? vtkAbstractArray::PER_FINITE_COMPONENT()
      : vtkAbstractArray::PER_COMPONENT();
    vtkInformationVector* perComponent = info->Has(key) ? info->Get(key) : nullptr;
    if (!perComponent || perComponent->GetNumberOfInformationObjects() != components)
    {
      return false;
    }
    range.assign(2 * components, 0.0);
    for (int c = 0; c < components; ++c)
    {
      vtkInformation* component = perComponent->GetInformationObject(c);
      if (!component->Has(vtkDataArray::COMPONENT_RANGE()))
      {
        return false;
      }
      component->Get(vtkDataArray::COMPONENT_RANGE(), range.data() + 2 * c);
    }
    return true;
  }

  static void Set(vtkDataArray* array, int family, const std::vector<double>& range)
  {
    if (Norm(family))
    {
      array->GetInformation()->Set(
        Finite(family) ? vtkDataArray::L2_NORM_FINITE_RANGE() : vtkDataArray::L2_NORM_RANGE(),
        range.data(), 2);
      return;
    }
    CachedRangePoints::StoreRanges(array, range.data(), Finite(family));
  }

  // The extremes in each family, (min, max) pairs, of the tuples `ids`; none give
  // (+inf, -inf). A drag writes the same hundreds of thousands of tuples at every step, so the
  // pass runs in parallel on the array's own value type, not through virtual GetTuple.
  static std::array<Extremes, Families> Measure(vtkDataArray* array, const std::vector<vtkIdType>& ids)
  {
    const int components = array->GetNumberOfComponents();
    if (components > TupleExtremes::MaximumComponents)
    {
      return TupleExtremes().Get(); // not measured; Capture caches nothing for such arrays
    }
    // Chunks of tuples, each with its own extremes, merged at the end.
    constexpr vtkIdType Chunk = 16384;
    const vtkIdType count = static_cast<vtkIdType>(ids.size());
    std::vector<TupleExtremes> chunks((count + Chunk - 1) / Chunk, TupleExtremes(components));
    auto measure = [&](auto* typed) {
      const auto tuples = vtk::DataArrayTupleRange(typed);
      using Value = typename decltype(tuples)::ComponentType;
      vtkSMPTools::For(0, static_cast<vtkIdType>(chunks.size()), 1, [&](vtkIdType begin, vtkIdType end) {
        Value values[TupleExtremes::MaximumComponents];
        for (vtkIdType c = begin; c < end; ++c)
        {
          for (vtkIdType k = c * Chunk; k < std::min(count, (c + 1) * Chunk); ++k)
          {
            const auto tuple = tuples[ids[k]];
            std::copy(tuple.begin(), tuple.end(), values);
            chunks[c].Add(values);
          }
        }
      });
    };
    if (!vtkArrayDispatch::Dispatch::Execute(array, measure))
    {
      measure(array);
    }
    TupleExtremes all(components);
    for (const TupleExtremes& chunk : chunks)
    {
      all.Merge(chunk);
    }
    return all.Get();
  }

  int Components = 0;
  std::array<bool, Families> Cached = {};
  std::array<std::vector<double>, Families> Ranges;
  std::array<Extremes, Families> Old;
};

// Sorts `ids` and drops repeats.
void SortOnce(std::vector<vtkIdType>& ids)
{
  if (!std::is_sorted(ids.begin(), ids.end()))
  {
    std::sort(ids.begin(), ids.end());
  }
  ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
}
}

bool OutputArray::Buffer::IsFree(const Holders& pipeline) const
{
  // Ours alone: the array is held here (and by its vtkPoints), the vtkPoints only here, but
  // for the pipeline's outputs downstream.
  auto others = [&](vtkObjectBase* object, vtkObjectBase* own) {
    return pipeline ? pipeline(object, own) : 0;
  };
  if (this->Points)
  {
    return this->Points->GetReferenceCount() == 1 + others(this->Points, nullptr) &&
      this->Array->GetReferenceCount() == 2 + others(this->Array, this->Points);
  }
  return this->Array->GetReferenceCount() == 1 + others(this->Array, nullptr);
}

vtkDataArray* OutputArray::Update(
  vtkDataArray* rest, const std::vector<vtkIdType>& ids, std::uint64_t key, const Writer& write)
{
  if (ids.empty())
  {
    return rest;
  }
  if (Buffer* same = this->Find(rest, ids, key))
  {
    return same->Array;
  }
  Buffer& buffer = this->Acquire(rest, false);
  this->Refresh(buffer, rest, ids, key, write);
  return buffer.Array;
}

vtkPoints* OutputArray::Update(
  vtkPoints* rest, const std::vector<vtkIdType>& ids, std::uint64_t key, const Writer& write)
{
  if (ids.empty())
  {
    return rest;
  }
  if (Buffer* same = this->Find(rest->GetData(), ids, key))
  {
    return same->Points;
  }
  Buffer& buffer = this->Acquire(rest->GetData(), true);
  this->Refresh(buffer, rest->GetData(), ids, key, write);
  return buffer.Points;
}

OutputArray::Buffer* OutputArray::Find(
  vtkDataArray* rest, const std::vector<vtkIdType>& ids, std::uint64_t key)
{
  // Sharing a buffer is safe as long as nobody writes it: one that holds this content already
  // serves whoever holds it too.
  for (Buffer& buffer : this->Buffers)
  {
    if (buffer.Source == rest && buffer.SourceTime == rest->GetMTime() && buffer.Key == key &&
      buffer.Written == ids)
    {
      buffer.LastUse = ++this->Uses;
      return &buffer;
    }
  }
  return nullptr;
}

OutputArray::Buffer& OutputArray::Acquire(vtkDataArray* rest, bool points)
{
  // The free buffer used last (in a plain pipeline, the output's own), preferring one that
  // still derives from this rest array, so that only a few tuples need writing.
  auto holds = [rest](const Buffer& b) {
    return b.Source == rest && b.SourceTime == rest->GetMTime();
  };
  Buffer* best = nullptr;
  for (Buffer& buffer : this->Buffers)
  {
    if (buffer.IsFree(this->PipelineHolders) && bool(buffer.Points) == points &&
      (!best || holds(buffer) > holds(*best) ||
        (holds(buffer) == holds(*best) && buffer.LastUse > best->LastUse)))
    {
      best = &buffer;
    }
  }
  if (!best)
  {
    // Every buffer is held elsewhere: leave the least recently used to its holder.
    if (static_cast<int>(this->Buffers.size()) >= MaximumBuffers)
    {
      this->Buffers.erase(std::min_element(this->Buffers.begin(), this->Buffers.end(),
        [](const Buffer& a, const Buffer& b) { return a.LastUse < b.LastUse; }));
    }
    this->Buffers.emplace_back();
    best = &this->Buffers.back();
  }
  if (!best->Array || best->Array->GetDataType() != rest->GetDataType())
  {
    best->Array = vtk::TakeSmartPointer(rest->NewInstance());
    best->Source = nullptr;
    best->Points = points ? vtkSmartPointer<CachedRangePoints>::New() : nullptr;
  }
  best->LastUse = ++this->Uses;
  return *best;
}

void OutputArray::Refresh(Buffer& buffer, vtkDataArray* rest,
  const std::vector<vtkIdType>& ids, std::uint64_t key, const Writer& write)
{
  const bool derived = buffer.Source == rest && buffer.SourceTime == rest->GetMTime() &&
    buffer.Array->GetNumberOfTuples() == rest->GetNumberOfTuples() &&
    buffer.Array->GetNumberOfComponents() == rest->GetNumberOfComponents();
  if (!derived)
  {
    buffer.Array->DeepCopy(rest);
    if (buffer.Points)
    {
      buffer.Points->SetData(buffer.Array); // now that it has three components
    }
    buffer.Source = rest;
    buffer.SourceTime = rest->GetMTime();
    buffer.Written.clear();
    buffer.Unchanged.clear();
    buffer.UnchangedOutside.clear();
    ++this->Copies;
  }
  // The tuples that change, sorted: the last update's, back to rest, and this one's. A fresh
  // copy holds the rest's values, and its ranges are those the rest has cached. The moves of a
  // drag write the same tuples, sorted once rather than at every move.
  const bool sameTuples = derived && buffer.Written == ids;
  std::vector<vtkIdType> merged;
  if (!sameTuples)
  {
    merged = ids;
    if (derived)
    {
      merged.insert(merged.end(), buffer.Written.begin(), buffer.Written.end());
    }
    SortOnce(merged);
    buffer.WrittenSorted = ids;
    SortOnce(buffer.WrittenSorted);
  }
  const std::vector<vtkIdType>& changing = sameTuples ? buffer.WrittenSorted : merged;
  CachedRanges ranges;
  const bool writtenKnown = sameTuples && buffer.WrittenTime == buffer.Array->GetMTime();
  ranges.Capture(derived ? buffer.Array.Get() : rest, changing,
    writtenKnown ? &buffer.WrittenExtremes : nullptr);
  if (derived && !sameTuples)
  {
    for (const vtkIdType id : buffer.Written)
    {
      buffer.Array->SetTuple(id, id, rest);
    }
  }
  if (ranges.NeedsUnchanged() && buffer.UnchangedOutside != changing)
  {
    // Before the write, the buffer's tuples outside `changing` are the rest's, as after it.
    buffer.Unchanged = CachedRanges::MeasureUnchanged(buffer.Array, changing);
    buffer.UnchangedOutside = changing;
  }
  this->Written.Reset(buffer.Array->GetNumberOfComponents());
  write(buffer.Array);
  // Where only this write's tuples change, once each, and the writer measured them all.
  const bool measured = sameTuples && ids.size() == changing.size() &&
    this->Written.GetCount() == static_cast<long long>(ids.size());
  buffer.Written = ids;
  buffer.Key = key;
  buffer.Array->Modified();
  if (buffer.Points)
  {
    buffer.Points->Modified(); // which, from VTK 9.2, marks the array modified too
  }
  buffer.WrittenExtremes = ranges.Restore(buffer.Array, changing,
    buffer.UnchangedOutside == changing ? &buffer.Unchanged : nullptr, measured ? &this->Written : nullptr);
  // Those of `ids` alone where `changing` held no other tuple.
  buffer.WrittenTime = !derived || sameTuples ? buffer.Array->GetMTime() : 0;
}
}
}
