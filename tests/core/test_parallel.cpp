#include <clothtrack/Parallel.h>

#include <gtest/gtest.h>

#include <atomic>
#include <stdexcept>
#include <thread>
#include <vector>

using namespace clothtrack;

namespace
{
struct ThreadCount
{
  explicit ThreadCount(int count) { setThreadCount(count); }
  ~ThreadCount() { setThreadCount(0); }
};
} // namespace

TEST(Parallel, EveryIndexOnceForAnyThreadCount)
{
  for (int threads : {1, 2, 3, 8})
  {
    const ThreadCount scope(threads);
    std::vector<int> hits(10000, 0);
    parallelFor(
        0, 10000, [&](int i) { ++hits[i]; }, 16);
    for (int i = 0; i < 10000; ++i) ASSERT_EQ(hits[i], 1) << "index " << i << ", " << threads;
  }
}

TEST(Parallel, NestedAndConcurrentLoopsFinish)
{
  const ThreadCount scope(4);
  std::atomic<int> total{0};
  auto nested = [&]
  {
    parallelFor(
        0, 8,
        [&](int)
        {
          parallelFor(
              0, 1000, [&](int) { ++total; }, 10);
        },
        1);
  };
  std::thread other(nested);
  nested();
  other.join();
  EXPECT_EQ(total.load(), 2 * 8 * 1000);
}

TEST(Parallel, AnExceptionReachesTheCaller)
{
  const ThreadCount scope(4);
  for (int thrower : {0, 3})
    EXPECT_THROW(parallelFor(
                     0, 4,
                     [&](int i)
                     {
                       if (i == thrower) throw std::runtime_error("chunk failed");
                     },
                     1),
                 std::runtime_error);
  // The pool is usable afterwards.
  std::atomic<int> count{0};
  parallelFor(
      0, 100, [&](int) { ++count; }, 1);
  EXPECT_EQ(count.load(), 100);
}
