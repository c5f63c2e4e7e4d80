#include "FrameSource.h"

#include <clothtrack/base/Error.h>

#include <string>

namespace clothtrack
{
FramePtr borrowedFrame(const TriangleMesh& mesh)
{
  return FramePtr(std::shared_ptr<const void>(), &mesh); // aliasing: owns nothing
}

std::size_t meshBytes(const TriangleMesh& mesh)
{
  return sizeof(TriangleMesh) + mesh.V.size() * sizeof(double) + mesh.F.size() * sizeof(int);
}

FramePtr FramesInMemory::frame(int k) const
{
  if (k < 0 || k >= count())
    throw Error("frame " + std::to_string(k) + " of a sequence of " + std::to_string(count()));
  return frames_[k] ? borrowedFrame(*frames_[k]) : nullptr;
}

CachedFrames::CachedFrames(int count, std::function<TriangleMesh(int)> load,
                           std::size_t budgetBytes)
    : count_(count), load_(std::move(load)), budget_(budgetBytes)
{
}

FramePtr CachedFrames::frame(int k) const
{
  if (k < 0 || k >= count_)
    throw Error("frame " + std::to_string(k) + " of a sequence of " + std::to_string(count_));
  {
    const std::lock_guard<std::mutex> lock(mutex_);
    if (auto found = kept_.find(k); found != kept_.end())
    {
      recent_.splice(recent_.begin(), recent_, found->second.place);
      return found->second.mesh;
    }
    ++loads_;
  }
  FramePtr mesh = std::make_shared<const TriangleMesh>(load_(k));
  const std::lock_guard<std::mutex> lock(mutex_);
  if (auto found = kept_.find(k); found != kept_.end()) return found->second.mesh; // raced
  keep(k, mesh);
  return mesh;
}

void CachedFrames::offer(int k, TriangleMesh mesh)
{
  if (k < 0 || k >= count_) return;
  auto shared = std::make_shared<const TriangleMesh>(std::move(mesh));
  const std::lock_guard<std::mutex> lock(mutex_);
  if (kept_.count(k) == 0) keep(k, shared);
}

void CachedFrames::keep(int k, const FramePtr& mesh) const
{
  const std::size_t bytes = meshBytes(*mesh);
  if (bytes > budget_) return;
  while (bytes_ + bytes > budget_ && !recent_.empty())
  {
    const int dropped = recent_.back();
    recent_.pop_back();
    bytes_ -= kept_[dropped].bytes;
    kept_.erase(dropped);
  }
  recent_.push_front(k);
  kept_[k] = Kept{mesh, bytes, recent_.begin()};
  bytes_ += bytes;
  peakBytes_ = std::max(peakBytes_, bytes_);
}

long CachedFrames::loads() const
{
  const std::lock_guard<std::mutex> lock(mutex_);
  return loads_;
}

std::size_t CachedFrames::peakBytes() const
{
  const std::lock_guard<std::mutex> lock(mutex_);
  return peakBytes_;
}
} // namespace clothtrack
