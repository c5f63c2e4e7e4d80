#pragma once
// Output written on a thread of its own, so that a frame's fit does not wait for the previous
// frame's compression and disk writes.
#include <condition_variable>
#include <deque>
#include <exception>
#include <functional>
#include <mutex>
#include <thread>

namespace clothtrack::app
{
class BackgroundWriter
{
public:
  /// At most `capacity` tasks wait; submit() blocks beyond that (memory stays bounded).
  explicit BackgroundWriter(int capacity = 4);
  /// Waits for the tasks already submitted; failures not yet reported are dropped (call
  /// finish() to see them).
  ~BackgroundWriter();
  BackgroundWriter(const BackgroundWriter&) = delete;
  BackgroundWriter& operator=(const BackgroundWriter&) = delete;

  /// Queues a task; from any thread. Rethrows the failure of an earlier task, if any.
  void submit(std::function<void()> task);
  /// Waits until every task has run; rethrows the first failure.
  void finish();

private:
  void run();

  const size_t capacity_;
  std::mutex mutex_;
  std::condition_variable changed_;
  std::deque<std::function<void()>> tasks_;
  bool running_ = false, stopping_ = false;
  std::exception_ptr failure_;
  std::thread thread_;
};
} // namespace clothtrack::app
