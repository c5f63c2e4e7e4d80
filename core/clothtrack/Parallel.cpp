#include "Parallel.h"

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

namespace clothtrack
{
namespace
{
std::atomic<int> requestedThreads{0};

int hardwareThreads()
{
  return static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
}

/// Spins on `ready` for up to a few tens of microseconds: a loop's chunks start (and end)
/// within that time of each other far more often than not, and waking a sleeping thread
/// takes about as long.
template <class Ready> bool spinUntil(const Ready& ready)
{
  const auto until = std::chrono::steady_clock::now() + std::chrono::microseconds(50);
  for (int spin = 1;; ++spin)
  {
    if (ready()) return true;
    if (spin % 64 == 0 && std::chrono::steady_clock::now() > until) return false;
    std::this_thread::yield();
  }
}

/// Worker threads that run the chunks of one loop at a time, with the thread that started it.
class WorkerPool
{
public:
  static WorkerPool& instance()
  {
    static WorkerPool pool;
    return pool;
  }

  ~WorkerPool()
  {
    {
      const std::lock_guard<std::mutex> lock(mutex_);
      stopping_ = true;
    }
    wake_.notify_all();
    for (auto& w : workers_) w.join();
  }

  /// False when the pool is running another loop.
  bool tryRun(int chunks, const std::function<void(int)>& chunk)
  {
    if (busy_.exchange(true)) return false;
    {
      std::unique_lock<std::mutex> lock(mutex_);
      // Workers start on first use; one fewer than the hardware threads (the caller works too).
      while (static_cast<int>(workers_.size()) < std::min(chunks, hardwareThreads()) - 1)
        workers_.emplace_back([this] { work(); });
      job_ = &chunk;
      chunks_ = chunks;
      next_ = 0;
      pending_ = chunks;
      failure_ = nullptr;
      generation_.fetch_add(1);
    }
    wake_.notify_all();
    std::unique_lock<std::mutex> lock(mutex_);
    runClaimed(lock);
    if (pending_ > 0)
    {
      lock.unlock();
      if (!spinUntil([this] { return pending_.load() == 0; }))
      {
        lock.lock();
        finished_.wait(lock, [this] { return pending_ == 0; });
        lock.unlock();
      }
      lock.lock();
    }
    job_ = nullptr;
    const std::exception_ptr failure = failure_;
    lock.unlock();
    busy_ = false;
    if (failure) std::rethrow_exception(failure);
    return true;
  }

private:
  WorkerPool() = default;

  /// Runs unclaimed chunks of the current loop; called with the lock held.
  void runClaimed(std::unique_lock<std::mutex>& lock)
  {
    while (job_ && next_ < chunks_)
    {
      const int t = next_++;
      const std::function<void(int)>* job = job_;
      lock.unlock();
      std::exception_ptr failure;
      try
      {
        (*job)(t);
      }
      catch (...)
      {
        failure = std::current_exception();
      }
      lock.lock();
      if (failure && !failure_) failure_ = failure;
      if (--pending_ == 0) finished_.notify_one();
    }
  }

  void work()
  {
    unsigned long long seen = generation_;
    std::unique_lock<std::mutex> lock(mutex_);
    while (true)
    {
      if (generation_ == seen && !stopping_)
      {
        lock.unlock();
        spinUntil([&] { return generation_.load() != seen; });
        lock.lock();
        wake_.wait(lock, [&] { return generation_ != seen || stopping_; });
      }
      if (stopping_) return;
      seen = generation_;
      runClaimed(lock);
    }
  }

  std::mutex mutex_;
  std::condition_variable wake_, finished_;
  std::vector<std::thread> workers_;
  std::atomic<bool> busy_{false};
  std::atomic<unsigned long long> generation_{0};
  // The current loop; guarded by mutex_ (pending_ is also read without it while spinning).
  const std::function<void(int)>* job_ = nullptr;
  int chunks_ = 0, next_ = 0;
  std::atomic<int> pending_{0};
  std::exception_ptr failure_;
  bool stopping_ = false;
};
} // namespace

void setThreadCount(int count)
{
  requestedThreads = std::max(0, count);
}

int threadCount()
{
  const int requested = requestedThreads;
  return requested > 0 ? requested : hardwareThreads();
}

namespace detail
{
void runChunks(int chunks, const std::function<void(int)>& chunk)
{
  if (WorkerPool::instance().tryRun(chunks, chunk)) return;
  for (int t = 0; t < chunks; ++t) chunk(t);
}
} // namespace detail
} // namespace clothtrack
