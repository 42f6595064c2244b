// What the benchmark programs report alike: the median of repeated timings, and the process's
// peak resident memory.
#ifndef LaplacianEditing_BenchmarkMeasures_h
#define LaplacianEditing_BenchmarkMeasures_h

#include <sys/resource.h>

#include <algorithm>
#include <vector>

namespace BenchmarkMeasures
{
/// The median (the upper one of an even count); timings of a noisy machine, not their mean.
inline double Median(std::vector<double> values)
{
  std::sort(values.begin(), values.end());
  return values.empty() ? 0.0 : values[values.size() / 2];
}

/// The largest resident memory of this process so far, in megabytes.
inline double PeakMemoryMegabytes()
{
  rusage usage;
  getrusage(RUSAGE_SELF, &usage);
  return usage.ru_maxrss / 1024.0;
}
}

#endif
