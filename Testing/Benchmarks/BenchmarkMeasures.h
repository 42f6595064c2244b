// What the benchmark programs measure and parse alike: seconds since a start, the median of
// repeated timings, the process's peak resident memory, and comma-separated option lists.
#ifndef LaplacianEditing_BenchmarkMeasures_h
#define LaplacianEditing_BenchmarkMeasures_h

#include <sys/resource.h>

#include <algorithm>
#include <chrono>
#include <sstream>
#include <string>
#include <vector>

namespace BenchmarkMeasures
{
using Clock = std::chrono::steady_clock;

inline double SecondsSince(Clock::time_point start)
{
  return std::chrono::duration<double>(Clock::now() - start).count();
}

/// "a,b,c" as its items.
inline std::vector<std::string> Split(const std::string& list)
{
  std::vector<std::string> items;
  std::stringstream stream(list);
  for (std::string item; std::getline(stream, item, ',');)
  {
    items.push_back(item);
  }
  return items;
}

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
