#pragma once
// A parallel loop over an index range for the VTK-free core (the VTK layer uses vtkSMPTools).
// Iterations must be independent; they are split into one contiguous chunk per thread, so results
// that depend only on the index are the same for any thread count. The chunks run on an OpenMP
// team (libgomp keeps its threads between loops: the solvers run loops of a millisecond or less).
// A loop started inside another loop runs in its caller alone; loops started from different
// threads (the two fitting chains) each get a team of their own.
#include <Eigen/Core>

#include <algorithm>
#include <functional>
#include <utility>

namespace clothtrack
{
/// Threads used by parallelFor, for the whole process: 0 means one per hardware thread.
void setThreadCount(int count);
/// Threads the calling thread's loops use: its ThreadBudget, else the process's count.
int threadCount();

/// The threads of the loops started from the calling thread while it lives (0: the process's
/// count); a command, a filter or one of the two fitting chains sets its own this way.
class ThreadBudget
{
public:
  explicit ThreadBudget(int count);
  ~ThreadBudget();
  ThreadBudget(const ThreadBudget&) = delete;
  ThreadBudget& operator=(const ThreadBudget&) = delete;

private:
  int previous_;
};

namespace detail
{
/// chunk(0) .. chunk(chunks - 1) on an OpenMP team, chunk(0) on the calling thread; one after
/// the other inside another loop.
void runChunks(int chunks, const std::function<void(int)>& chunk);
} // namespace detail

/// body(i) for i in [begin, end), in contiguous chunks of at least `minChunk` indices, one chunk
/// per thread; the first chunk always runs on the calling thread.
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

/// Indices [first, second) of the `part`-th of `parts` contiguous, nearly equal parts of
/// [0, count): how the processes sharing a run split a sequence's frames.
inline std::pair<int, int> rangePart(int count, int part, int parts)
{
  auto at = [&](int p) { return static_cast<int>(static_cast<long long>(count) * p / parts); };
  return {at(part), at(part + 1)};
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
/// x . y over `size` doubles, summed over the spans of forSpans (the same for any thread count).
inline double parallelDot(const double* x, const double* y, long size)
{
  return parallelSum(size,
                     [&](long from, long to)
                     {
                       return Eigen::Map<const Eigen::VectorXd>(x + from, to - from)
                           .dot(Eigen::Map<const Eigen::VectorXd>(y + from, to - from));
                     });
}
} // namespace clothtrack
