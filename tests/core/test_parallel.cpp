#include <clothtrack/base/Parallel.h>

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
  // Loops run as before afterwards.
  std::atomic<int> count{0};
  parallelFor(
      0, 100, [&](int) { ++count; }, 1);
  EXPECT_EQ(count.load(), 100);
}

TEST(Parallel, ThreadBudgetIsTheCallingThreadsOwn)
{
  const ThreadCount scope(4);
  {
    const ThreadBudget budget(1);
    EXPECT_EQ(threadCount(), 1);
    int otherThreads = 0;
    std::thread other([&] { otherThreads = threadCount(); });
    other.join();
    EXPECT_EQ(otherThreads, 4); // another thread keeps the process's count
    {
      const ThreadBudget inner(3);
      EXPECT_EQ(threadCount(), 3);
    }
    EXPECT_EQ(threadCount(), 1);
  }
  EXPECT_EQ(threadCount(), 4);
}

TEST(Parallel, LoopsFromTwoThreadsBothRunInParallel)
{
  // The two fitting chains each start loops: each gets a team of its own, and every index is
  // visited once in both.
  const ThreadCount scope(2);
  std::vector<int> a(5000, 0), b(5000, 0);
  std::atomic<int> teamsOfTwo{0};
  auto loop = [&](std::vector<int>& hits)
  {
    std::vector<std::thread::id> ids(hits.size());
    parallelFor(
        0, static_cast<int>(hits.size()),
        [&](int i)
        {
          ++hits[i];
          ids[i] = std::this_thread::get_id();
        },
        1);
    if (ids.front() != ids.back()) ++teamsOfTwo;
  };
  std::thread other([&] { loop(b); });
  loop(a);
  other.join();
  for (size_t i = 0; i < a.size(); ++i) ASSERT_TRUE(a[i] == 1 && b[i] == 1) << i;
  EXPECT_EQ(teamsOfTwo.load(), 2);
}
