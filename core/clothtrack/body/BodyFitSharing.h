#pragma once
// A body fit shared among processes (mpirun): each fits one segment of the sequence, and the
// fits are exchanged between the passes (BodyFit.h). The exchange itself is the caller's, so
// that the body fit stays free of any message-passing library.
#include <functional>
#include <string>
#include <vector>

namespace clothtrack
{
struct BodyFrameFit;

struct BodyFitSharing
{
  int part = 0;  ///< this process's segment, 0 .. parts - 1
  int parts = 1; ///< processes sharing the fit; 1: the whole sequence here
  /// Frames next to its own that a segment tracks first and then discards, in each direction:
  /// its tracks have then settled onto the sequence's by the time they reach its own frames.
  int overlap = 8;
  /// A sequence is split only when every segment gets at least this many frames; a shorter one is
  /// fitted whole by every process, which then agree bit for bit with one process.
  int minimumSegment = 24;
  /// Called by every process at the same points with its own bytes: every process's bytes, the
  /// first process's first. Needed when parts > 1.
  std::function<std::vector<std::string>(const std::string& own)> allGather;

  /// Whether a sequence of `usableFrames` frames is split.
  bool splits(int usableFrames) const
  {
    return parts > 1 && usableFrames >= parts * minimumSegment;
  }
};

/// The fits of frames `frames`, as bytes (any machine of the same byte order reads them back).
std::string encodeFrameFits(const std::vector<BodyFrameFit>& fits, const std::vector<int>& frames);
/// Writes the fits of `bytes` back into `fits`. Throws Error on bytes of another layout.
void decodeFrameFits(const std::string& bytes, std::vector<BodyFrameFit>& fits);
} // namespace clothtrack
