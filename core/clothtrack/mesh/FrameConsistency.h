#pragma once
// Whether the frames of a sequence, and its ground truth, show one subject at one scale in one
// place. A frame exported in another unit, a frame of another scene, or a ground truth in other
// coordinates runs to the end otherwise, with errors of hundreds of metres and no word why.
#include <clothtrack/mesh/TriangleMesh.h>

#include <string>
#include <vector>

namespace clothtrack
{
/// A frame's size and place. The size is the square root of the surface area: unlike the
/// bounding box it hardly changes with the pose (arms raised or spread), and it scales with the
/// unit as lengths do.
struct FrameExtent
{
  double size = 0.0;
  Vec3 centre = Vec3::Zero(); ///< of the bounding box
  double height = 0.0;        ///< bounding box extent along Y
};
FrameExtent frameExtent(const TriangleMesh& mesh);

struct ConsistencyOptions
{
  /// A frame whose size is further than this factor from the sequence's median is flagged.
  double sizeTolerance = 1.5;
  /// Beyond this factor the frame cannot be the same subject in the same unit: refused.
  double sizeRefusal = 3.0;
  /// A frame whose centre is further than this from the previous frame's, in subject heights
  /// (the median height), is flagged: a person covers less between two frames of a capture.
  double maximumShift = 0.3;
};

/// A frame whose size or place breaks with the rest of the sequence.
struct FrameJump
{
  int frame = 0;
  double sizeRatio = 1.0; ///< its size over the sequence's median size
  double shift = 0.0;     ///< metres its centre moved from the previous frame's
  bool refused = false;   ///< the size is beyond ConsistencyOptions::sizeRefusal
  std::string problem;    ///< what is wrong (and, unless refused, what to do), in one sentence
};

/// The frames whose size or place jumps, in order.
std::vector<FrameJump> frameJumps(const std::vector<const TriangleMesh*>& frames,
                                  const ConsistencyOptions& options = {});
/// The same from each frame's extent, taken when it was read.
std::vector<FrameJump> frameJumps(const std::vector<FrameExtent>& extents,
                                  const ConsistencyOptions& options = {});

/// What is wrong with a ground-truth frame against the input frame it belongs to: another unit
/// (refused, `refused` set), another size or another place (warnings); empty when they agree.
/// The input is a capture, the ground truth often body and clothes: their areas differ by up to
/// a fifth, so sizes agree within sizeTolerance.
std::string groundTruthMismatch(const TriangleMesh& input, const TriangleMesh& truth, bool& refused,
                                const ConsistencyOptions& options = {});
} // namespace clothtrack
