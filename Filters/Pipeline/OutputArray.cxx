#include "OutputArray.h"

#include "vtkDataArray.h"
#include "vtkPoints.h"

#include <algorithm>

namespace LaplacianEditing
{
namespace Pipeline
{

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
    best->Points = points ? vtkSmartPointer<vtkPoints>::New() : nullptr;
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
    ++this->Copies;
  }
  else if (buffer.Written != ids)
  {
    for (const vtkIdType id : buffer.Written)
    {
      buffer.Array->SetTuple(id, id, rest);
    }
  }
  write(buffer.Array);
  buffer.Written = ids;
  buffer.Key = key;
  buffer.Array->Modified();
  if (buffer.Points)
  {
    buffer.Points->Modified();
  }
}
}
}
