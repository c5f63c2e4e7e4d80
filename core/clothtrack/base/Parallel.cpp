#include "Parallel.h"

#include <omp.h>

#include <algorithm>
#include <atomic>
#include <exception>
#include <thread>

namespace clothtrack
{
namespace
{
std::atomic<int> requestedThreads{0};
thread_local int threadBudget = 0; // 0: the process-wide setting

int hardwareThreads()
{
  return static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
}
} // namespace

void setThreadCount(int count)
{
  requestedThreads = std::max(0, count);
}

int threadCount()
{
  if (threadBudget > 0) return threadBudget;
  const int requested = requestedThreads;
  return requested > 0 ? requested : hardwareThreads();
}

ThreadBudget::ThreadBudget(int count) : previous_(threadBudget)
{
  threadBudget = std::max(0, count);
}

ThreadBudget::~ThreadBudget()
{
  threadBudget = previous_;
}

namespace detail
{
void runChunks(int chunks, const std::function<void(int)>& chunk)
{
  // A loop inside another runs in its caller alone: the outer loop already uses the threads.
  if (omp_in_parallel())
  {
    for (int t = 0; t < chunks; ++t) chunk(t);
    return;
  }
  // libgomp keeps a team's threads between loops, so a loop of a millisecond costs a few
  // microseconds to start. An exception cannot leave an OpenMP region: the first one is kept
  // and rethrown here.
  std::exception_ptr failure;
#pragma omp parallel num_threads(chunks)
  {
    // The team may be smaller than asked for: its threads share the chunks.
    const int team = omp_get_num_threads();
    for (int t = omp_get_thread_num(); t < chunks; t += team)
    {
      try
      {
        chunk(t);
      }
      catch (...)
      {
#pragma omp critical(clothtrack_parallel_failure)
        if (!failure) failure = std::current_exception();
      }
    }
  }
  if (failure) std::rethrow_exception(failure);
}
} // namespace detail
} // namespace clothtrack
