#pragma once
// The frames of an 'align' run: listed, read and checked once at the start (a bad frame stops
// the run before the long stages, or is left out with --skip-bad-frames), then handed to the
// stages from a cache of bounded size. When a sequence's frames do not fit in it, each cleaned
// frame is kept in OUT/work/frames as its binary arrays and read from there when needed again:
// memory stays the same for any length.
#include "AlignOptions.h"

#include <clothtrack/eval/MarkerError.h>
#include <clothtrack/mesh/FrameConsistency.h>
#include <clothtrack/mesh/FrameSource.h>

#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace clothtrack::app
{
/// The frames of a run and what came with them.
struct Input
{
  std::vector<std::string> files, truthFiles;
  std::vector<int> frameNumber; ///< index in the full input list
  std::shared_ptr<CachedFrames> frames;
  std::shared_ptr<CachedFrames> truth; ///< null without a ground truth
  std::optional<MarkerTrajectories> markers;
  std::vector<FrameJump> jumps; ///< frames whose size or place breaks with the others (warned)
  /// Whether the frames were kept in the work folder (they did not fit in memory).
  bool spilled = false;
  int count() const { return static_cast<int>(files.size()); }
  FramePtr frame(int k) const { return frames->frame(k); }
};

/// "A:B" (either end may be empty) -> [begin, end) of `count` frames. Throws UsageError.
std::pair<int, int> frameRange(const std::string& spec, int count);

/// Whether the frames of the run are point clouds: reconstructed into OUT/reconstructed by the
/// first process to read them, which the others then wait for.
bool inputHasPointClouds(const AlignSettings& s);

/// Lists, reads and checks the frames (and ground truth and markers) of a run; `work` receives
/// the cleaned frames that do not fit in memory. Prints progress and warnings; throws UsageError
/// or Error naming the file.
Input readInput(const AlignSettings& settings, const std::filesystem::path& work);
} // namespace clothtrack::app
