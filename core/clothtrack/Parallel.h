#pragma once
// A minimal parallel loop over an index range for the VTK-free core (the VTK layer uses
// vtkSMPTools). Iterations must be independent; they are split into one contiguous chunk per
// thread, so results that depend only on the index are the same for any thread count.
#include <algorithm>
#include <thread>
#include <vector>

namespace clothtrack
{
/// Threads used by parallelFor: 0 means one per hardware thread.
void setThreadCount(int count);
int threadCount();

template <class Body> void parallelFor(int begin, int end, const Body& body, int minChunk = 64)
{
  const int n = end - begin;
  const int threads = std::min(threadCount(), std::max(1, n / std::max(1, minChunk)));
  if (threads <= 1)
  {
    for (int i = begin; i < end; ++i) body(i);
    return;
  }
  std::vector<std::thread> workers;
  workers.reserve(threads - 1);
  auto chunk = [&](int t)
  {
    const int from = begin + static_cast<int>(static_cast<long long>(n) * t / threads);
    const int to = begin + static_cast<int>(static_cast<long long>(n) * (t + 1) / threads);
    for (int i = from; i < to; ++i) body(i);
  };
  for (int t = 1; t < threads; ++t) workers.emplace_back(chunk, t);
  chunk(0);
  for (auto& w : workers) w.join();
}
} // namespace clothtrack
