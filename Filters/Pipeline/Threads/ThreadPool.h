// ThreadPool: worker threads started once and kept, for the loops SMPFor runs where VTK's own
// backend would start threads at every loop.
//
// VTK before 9.3 runs vtkSMPTools::For on its STDThread backend (ParaView 5.11's only threaded
// one) by starting and joining a thread per core at each call, and a drag step makes about six
// such calls (what that costs a ParaView drag frame: Documentation/performance.md, "Frames per
// second during a drag"). The calling thread works
// too; a call made while the pool is busy (from inside a loop body, or from another thread) runs
// on its caller alone, as VTK runs a nested loop. Bodies must not throw (on a worker, as on
// VTK's STDThread threads, an exception ends the process).
//
// Between loops, workers and caller spin for 50 us before they sleep on the condition
// variables: a drag step runs its loops back to back, and a wake-up through the kernel cost
// about 100 us a loop on this machine's virtual cores (an empty loop: 100 us sleeping, 1 us
// spinning; a 185 us loop over 90k values on 2 threads: 145 us, 95 us). After a step, the spin
// ends before the render needs the cores.
#ifndef LaplacianEditing_Pipeline_ThreadPool_h
#define LaplacianEditing_Pipeline_ThreadPool_h

#include "vtkLaplacianEditingFiltersModule.h" // for export macro

#include <atomic>
#include <condition_variable>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

namespace LaplacianEditing
{
namespace Pipeline
{
class VTKLAPLACIANEDITINGFILTERS_EXPORT ThreadPool
{
public:
  /// `threads` threads work on each loop, the caller among them.
  explicit ThreadPool(int threads);
  ~ThreadPool();
  ThreadPool(const ThreadPool&) = delete;
  ThreadPool& operator=(const ThreadPool&) = delete;

  /// The process's pool: as many threads as cores, at most VTK_SMP_MAX_THREADS when set.
  static ThreadPool& Shared();

  /// Calls body(first, last) on disjoint ranges that cover [begin, end), about four per thread.
  void For(int begin, int end, const std::function<void(int first, int last)>& body);

  int GetNumberOfThreads() const { return static_cast<int>(this->Workers.size()) + 1; }

private:
  void Work();
  void Serve();

  std::atomic<bool> InUse{ false }; // a loop has the workers
  std::mutex Lock;                   // guards what follows, to the atomic counter
  std::condition_variable Wake;
  std::condition_variable Finished;
  const std::function<void(int, int)>* Body = nullptr;
  std::atomic<long long> Next{ 0 }; // wide: it runs a chunk per thread past End
  int End = 0;
  int Chunk = 1;
  std::atomic<int> Busy{ 0 }; // workers still on the current loop
  std::atomic<unsigned long> Loop{ 0 };
  bool Stopping = false;
  std::vector<std::thread> Workers;
};
}
}

#endif
