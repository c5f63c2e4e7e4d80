#include "Parallel.h"

#include <atomic>

namespace clothtrack
{
namespace
{
std::atomic<int> requestedThreads{0};
}

void setThreadCount(int count)
{
  requestedThreads = std::max(0, count);
}

int threadCount()
{
  const int requested = requestedThreads;
  if (requested > 0) return requested;
  return std::max(1u, std::thread::hardware_concurrency());
}
} // namespace clothtrack
