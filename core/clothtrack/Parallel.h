#pragma once
// A minimal parallel loop over an index range for the VTK-free core (the VTK layer uses
// vtkSMPTools). Iterations must be independent; they are split into one contiguous chunk per
// thread, so results that depend only on the index are the same for any thread count.
// The chunks run on a pool of threads started once: the solvers run loops of a millisecond or
// less, for which starting threads would cost as much as the loop. A loop started while the
// pool is busy (inside another loop, or from a second thread) runs in its caller alone.
#include <algorithm>
#include <functional>

namespace clothtrack
{
/// Threads used by parallelFor: 0 means one per hardware thread.
void setThreadCount(int count);
int threadCount();

namespace detail
{
/// chunk(0) .. chunk(chunks - 1), on the pool when it is free, else one after the other.
void runChunks(int chunks, const std::function<void(int)>& chunk);
} // namespace detail

template <class Body> void parallelFor(int begin, int end, const Body& body, int minChunk = 64)
{
  const int n = end - begin;
  const int threads = std::min(threadCount(), std::max(1, n / std::max(1, minChunk)));
  if (threads <= 1)
  {
    for (int i = begin; i < end; ++i) body(i);
    return;
  }
  detail::runChunks(threads,
                    [&](int t)
                    {
                      const int from =
                          begin + static_cast<int>(static_cast<long long>(n) * t / threads);
                      const int to =
                          begin + static_cast<int>(static_cast<long long>(n) * (t + 1) / threads);
                      for (int i = from; i < to; ++i) body(i);
                    });
}

/// Parts of the fixed split of forSpans and parallelSum.
constexpr int kFixedSpans = 16;

/// body(from, to, span) over a fixed split of [0, size) into kFixedSpans spans, in parallel.
/// The split does not depend on the thread count, so per-span results summed in span order
/// (parallelSum) are the same for any number of threads.
template <class Body> void forSpans(long size, const Body& body)
{
  parallelFor(
      0, kFixedSpans, [&](int k) { body(size * k / kFixedSpans, size * (k + 1) / kFixedSpans, k); },
      1);
}

/// Sum of body(from, to) (a double) over the spans of forSpans, added in span order.
template <class Body> double parallelSum(long size, const Body& body)
{
  double partial[kFixedSpans];
  forSpans(size, [&](long from, long to, int k) { partial[k] = body(from, to); });
  double sum = 0;
  for (double p : partial) sum += p;
  return sum;
}
} // namespace clothtrack
