#include "ThreadPool.h"

#include <algorithm>
#include <chrono>
#include <cstdlib>

namespace LaplacianEditing
{
namespace Pipeline
{
namespace
{
template <class Condition>
bool SpinUntil(Condition condition)
{
  const auto until = std::chrono::steady_clock::now() + std::chrono::microseconds(50);
  while (!condition())
  {
    if (std::chrono::steady_clock::now() > until)
    {
      return false;
    }
  }
  return true;
}
}
ThreadPool::ThreadPool(int threads)
{
  for (int t = 1; t < threads; ++t)
  {
    this->Workers.emplace_back([this] { this->Serve(); });
  }
}

ThreadPool::~ThreadPool()
{
  {
    std::lock_guard<std::mutex> lock(this->Lock);
    this->Stopping = true;
  }
  this->Wake.notify_all();
  for (std::thread& worker : this->Workers)
  {
    worker.join();
  }
}

ThreadPool& ThreadPool::Shared()
{
  static ThreadPool pool([] {
    int threads = std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
    if (const char* most = std::getenv("VTK_SMP_MAX_THREADS"))
    {
      threads = std::atoi(most) > 0 ? std::min(threads, std::atoi(most)) : threads;
    }
    return threads;
  }());
  return pool;
}

void ThreadPool::For(int begin, int end, const std::function<void(int, int)>& body)
{
  if (begin >= end)
  {
    return;
  }
  bool idle = false;
  if (this->Workers.empty() || end - begin == 1 || !this->InUse.compare_exchange_strong(idle, true))
  {
    body(begin, end);
    return;
  }
  {
    std::lock_guard<std::mutex> lock(this->Lock);
    const int pieces = 4 * this->GetNumberOfThreads();
    this->Body = &body;
    this->Next = begin;
    this->End = end;
    this->Chunk = std::max(1, (end - begin + pieces - 1) / pieces);
    this->Busy = static_cast<int>(this->Workers.size());
    ++this->Loop;
  }
  this->Wake.notify_all();
  this->Work();
  if (!SpinUntil([this] { return this->Busy.load() == 0; }))
  {
    std::unique_lock<std::mutex> lock(this->Lock);
    this->Finished.wait(lock, [this] { return this->Busy == 0; });
  }
  this->Body = nullptr;
  this->InUse = false;
}

void ThreadPool::Work()
{
  for (long long first = this->Next.fetch_add(this->Chunk); first < this->End;
       first = this->Next.fetch_add(this->Chunk))
  {
    const int from = static_cast<int>(first);
    (*this->Body)(from, from + std::min(this->Chunk, this->End - from));
  }
}

void ThreadPool::Serve()
{
  unsigned long served = 0;
  for (;;)
  {
    if (!SpinUntil([&] { return this->Loop.load() != served; }))
    {
      std::unique_lock<std::mutex> lock(this->Lock);
      this->Wake.wait(lock, [&] { return this->Stopping || this->Loop != served; });
    }
    {
      std::lock_guard<std::mutex> lock(this->Lock);
      if (this->Stopping)
      {
        return;
      }
      served = this->Loop;
    }
    this->Work();
    if (--this->Busy == 0)
    {
      std::lock_guard<std::mutex> lock(this->Lock);
      this->Finished.notify_one();
    }
  }
}
}
}
