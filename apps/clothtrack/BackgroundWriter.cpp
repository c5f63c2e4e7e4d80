#include "BackgroundWriter.h"

#include <algorithm>

namespace clothtrack::app
{
BackgroundWriter::BackgroundWriter(int capacity)
    : capacity_(static_cast<size_t>(std::max(1, capacity))), thread_([this] { run(); })
{
}

BackgroundWriter::~BackgroundWriter()
{
  {
    std::unique_lock<std::mutex> lock(mutex_);
    stopping_ = true;
  }
  changed_.notify_all();
  thread_.join();
}

void BackgroundWriter::submit(std::function<void()> task)
{
  std::unique_lock<std::mutex> lock(mutex_);
  changed_.wait(lock, [this] { return tasks_.size() < capacity_ || failure_; });
  if (failure_) std::rethrow_exception(failure_);
  tasks_.push_back(std::move(task));
  changed_.notify_all();
}

void BackgroundWriter::finish()
{
  std::unique_lock<std::mutex> lock(mutex_);
  changed_.wait(lock, [this] { return (tasks_.empty() && !running_) || failure_; });
  if (failure_) std::rethrow_exception(failure_);
}

void BackgroundWriter::run()
{
  std::unique_lock<std::mutex> lock(mutex_);
  while (true)
  {
    changed_.wait(lock, [this] { return !tasks_.empty() || stopping_; });
    if (tasks_.empty()) return; // stopping, nothing left
    std::function<void()> task = std::move(tasks_.front());
    tasks_.pop_front();
    running_ = true;
    lock.unlock();
    std::exception_ptr failure;
    try
    {
      task();
    }
    catch (...)
    {
      failure = std::current_exception();
    }
    lock.lock();
    running_ = false;
    if (failure && !failure_) failure_ = failure;
    changed_.notify_all();
  }
}
} // namespace clothtrack::app
