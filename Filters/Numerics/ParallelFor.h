// How the core runs loops over independent items. The core stays free of any threading library:
// the VTK adapter hands it vtkSMPTools::For, tests and other users may keep the serial default.
#ifndef LaplacianEditing_ParallelFor_h
#define LaplacianEditing_ParallelFor_h

#include <functional>

namespace LaplacianEditing
{
/// Calls body(first, last) on disjoint ranges that cover [begin, end), possibly concurrently.
using ParallelFor =
  std::function<void(int begin, int end, const std::function<void(int first, int last)>& body)>;

inline void SerialFor(int begin, int end, const std::function<void(int, int)>& body)
{
  if (begin < end)
  {
    body(begin, end);
  }
}
}

#endif
