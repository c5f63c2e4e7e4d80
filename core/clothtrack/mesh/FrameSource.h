#pragma once
// A sequence's frames handed out one at a time, so that a stage holds only the frames it works
// on: a long capture does not fit in memory, and a frame read again costs little next to its fit
// (io/ reads 0.6 MB frames in a few milliseconds).
#include <clothtrack/mesh/TriangleMesh.h>

#include <cstddef>
#include <functional>
#include <list>
#include <memory>
#include <mutex>
#include <unordered_map>
#include <vector>

namespace clothtrack
{
/// A frame while somebody holds it: a cache may drop its own reference at any time.
using FramePtr = std::shared_ptr<const TriangleMesh>;

/// A mesh owned elsewhere (which must outlive every use), handed out as a FramePtr.
FramePtr borrowedFrame(const TriangleMesh& mesh);

/// Bytes a mesh's arrays take in memory.
std::size_t meshBytes(const TriangleMesh& mesh);

class FrameSource
{
public:
  virtual ~FrameSource() = default;
  virtual int count() const = 0;
  /// Frame k, null where the sequence has none (a frame that could not be read). Safe to call
  /// from several threads at once.
  virtual FramePtr frame(int k) const = 0;
};

/// Frames already in memory, owned by the caller (null entries stand for missing frames).
class FramesInMemory final : public FrameSource
{
public:
  explicit FramesInMemory(std::vector<const TriangleMesh*> frames) : frames_(std::move(frames)) {}
  int count() const override { return static_cast<int>(frames_.size()); }
  FramePtr frame(int k) const override;

private:
  std::vector<const TriangleMesh*> frames_;
};

/// Frames loaded when first asked for and kept while their bytes fit in a budget; past it the
/// least recently used are dropped (a frame still held elsewhere lives on with its holder).
class CachedFrames final : public FrameSource
{
public:
  /// `load(k)` reads frame k (it may throw; it runs outside the cache's lock, so several frames
  /// load at once). `budgetBytes` of 0 keeps no frame beyond its use.
  CachedFrames(int count, std::function<TriangleMesh(int k)> load, std::size_t budgetBytes);
  int count() const override { return count_; }
  FramePtr frame(int k) const override;
  /// Keeps `mesh` as frame k where the budget allows: a frame read for another purpose first.
  void offer(int k, TriangleMesh mesh);

  /// Frames read so far, counting each reading again of a dropped frame.
  long loads() const;
  /// The most bytes the kept frames took at once.
  std::size_t peakBytes() const;

private:
  void keep(int k, const FramePtr& mesh) const; ///< under the lock

  int count_;
  std::function<TriangleMesh(int)> load_;
  std::size_t budget_;
  mutable std::mutex mutex_;
  mutable std::list<int> recent_; ///< most recently used first
  struct Kept
  {
    FramePtr mesh;
    std::size_t bytes = 0;
    std::list<int>::iterator place;
  };
  mutable std::unordered_map<int, Kept> kept_;
  mutable std::size_t bytes_ = 0, peakBytes_ = 0;
  mutable long loads_ = 0;
};
} // namespace clothtrack
