#pragma once
// Each frame's landmarks, held while a stage uses them and read again from the body stage's
// file (OUT/work/landmarks.jsonl, a line per frame) when needed: a long sequence's landmarks,
// 6 kB a frame, do not stay in memory.
#include <clothtrack/pipeline/BodyStage.h>

#include <nlohmann/json.hpp>

#include <cstdint>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

namespace clothtrack::app
{
/// A frame's landmarks as the body stage file holds them: [id, face, bary (3), direction (3),
/// offset] each.
nlohmann::json landmarksJson(const FrameLandmarks& landmarks);
/// The inverse; std::exception on anything else.
FrameLandmarks landmarksFromJson(const nlohmann::json& list);

class StoredLandmarks
{
public:
  /// `frames` frames without landmarks (the body fit was skipped).
  explicit StoredLandmarks(int frames = 0);
  /// Landmarks held in memory (a body fit whose file this process did not write).
  explicit StoredLandmarks(std::vector<FrameLandmarks> landmarks);
  /// Frame k's landmarks on the line of `path` that starts at byte lineOffsets[k], in the field
  /// "landmarks"; counts[k] of them.
  StoredLandmarks(std::string path, std::vector<std::int64_t> lineOffsets, std::vector<int> counts);

  int frames() const { return static_cast<int>(counts_.size()); }
  int count(int k) const { return counts_.at(k); }
  /// Frame k's landmarks, read when not held. Valid until release(k). Safe from several threads.
  const FrameLandmarks& operator[](int k);
  /// The caller is done with frame k's landmarks (a frame kept() stays).
  void release(int k);
  /// Frame k's landmarks are never released (the template frame's, used by every frame).
  void keep(int k);

private:
  FrameLandmarks read(int k) const;

  std::string path_;
  std::vector<std::int64_t> offsets_;
  std::vector<int> counts_;
  std::vector<std::shared_ptr<const FrameLandmarks>> held_;
  std::vector<bool> kept_;
  std::unique_ptr<std::mutex> mutex_ = std::make_unique<std::mutex>(); // movable
};
} // namespace clothtrack::app
