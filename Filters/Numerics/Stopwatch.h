// Seconds since a start, for the timings that the editors report.
#ifndef LaplacianEditing_Stopwatch_h
#define LaplacianEditing_Stopwatch_h

#include <chrono>

namespace LaplacianEditing
{
class Stopwatch
{
public:
  double Seconds() const
  {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - this->Start).count();
  }

private:
  std::chrono::steady_clock::time_point Start = std::chrono::steady_clock::now();
};
}

#endif
