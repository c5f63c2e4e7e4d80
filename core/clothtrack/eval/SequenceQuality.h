#pragma once
// How well an aligned sequence follows its frames without a ground truth: the distance from the
// aligned template to each frame's surface, from each frame to the aligned template (coverage:
// a frame the template misses shows here, not in the first), and the jitter of the motion.
#include "FrameConfidence.h"

#include <clothtrack/mesh/FrameSource.h>
#include <clothtrack/mesh/TriangleMesh.h>

#include <functional>
#include <string>
#include <utility>
#include <vector>

namespace clothtrack
{
struct SequenceQuality
{
  std::vector<double> surfaceDistance;  ///< per frame: mean, aligned vertices to the frame
  std::vector<double> coverageDistance; ///< per frame: mean, frame vertices to the aligned mesh
  /// Per inner frame k (1 .. N-2): mean |x(k+1) - 2 x(k) + x(k-1)| over the template vertices.
  std::vector<double> jitter;
  double meanSurfaceDistance = 0, meanCoverageDistance = 0, meanJitter = 0;
  /// Per frame: the measures above with the distortion from the template frame, and whether
  /// the frame is doubtful (FrameConfidence.h). Empty without a template frame.
  std::vector<FrameConfidence> confidence;
  std::vector<int> doubtfulFrames; ///< frames whose confidence has a doubt, in order
};

/// `*aligned[k]`: the template's vertices (connectivity `templateFaces`) in frame k.
/// `knownSurfaceDistance[k]`, when not negative, is frame k's surface distance as the fit
/// already measured it (the list may be empty). With `templateFrame` (>= 0), each frame's
/// confidence is judged too, its distortion measured from the template frame, and its distance
/// to `posedByBody` where that gives a pose.
SequenceQuality sequenceQuality(const std::vector<const Points*>& aligned,
                                const Triangles& templateFaces,
                                const std::vector<const TriangleMesh*>& frames,
                                const std::vector<double>& knownSurfaceDistance = {},
                                int templateFrame = -1, const FrameConfidenceOptions& options = {},
                                const TemplatePosedByBody& posedByBody = {});

/// Frame k's aligned template vertices; called from several threads at once.
using AlignedAccess = std::function<Points(int k)>;

/// The same over `frames.count()` frames read when needed: a few frames and their aligned
/// vertices at a time are held, whatever the sequence's length.
SequenceQuality sequenceQuality(const AlignedAccess& aligned, const Triangles& templateFaces,
                                const FrameSource& frames,
                                const std::vector<double>& knownSurfaceDistance = {},
                                int templateFrame = -1, const FrameConfidenceOptions& options = {},
                                const TemplatePosedByBody& posedByBody = {});

/// The severity doubtUnplacedFrames gives: past every limit's 1, so the frame is doubtful
/// (confidence 0.5), whatever its measures say.
inline constexpr double kUnplacedSeverity = 1.5;

/// Marks each frame k with `unplaced[k]` doubtful and lists the doubtful frames again. An
/// unplaced frame had nothing to start it: its body fit is not trusted and it does not continue
/// its predecessor (an unrelated pose of a collection), so its fit started from an unrelated
/// frame's. Its measures can all be within their limits: the template, dragged onto the frame
/// from another pose, still covers it (a collection's frame 23 cm off, pipeline/
/// BodyStartPrediction.h, unplacedFrames). Throws Error when the list does not have one entry
/// per frame.
void doubtUnplacedFrames(SequenceQuality& quality, const std::vector<bool>& unplaced);

/// A body fit whose rival (BodyFrameFit::rivalScoreRatio: another pose, a limb elsewhere, that
/// explains the frame) scores below this multiple of the fit's is ambiguous. Set on the
/// development collections of unclothed poses: below 1.2 lay the 4 of their 80 frames aligned
/// more than 10 cm off, and one aligned within it (docs/confidence.md).
inline constexpr double kAmbiguousBodyRatio = 1.2;

/// The severity doubtAmbiguousBodies gives: past every limit's 1, so the frame is doubtful
/// (confidence 0.8), but short of the 1.5 from which the template fit retries a frame: a start
/// from a neighbour's fit would not tell the two poses apart either.
inline constexpr double kAmbiguousBodySeverity = 1.2;

/// Marks each frame k whose body fit has a rival within kAmbiguousBodyRatio (`rivalRatios[k]`,
/// infinity where none was measured) doubtful, and lists the doubtful frames again. Throws Error
/// when the list does not have one entry per frame.
void doubtAmbiguousBodies(SequenceQuality& quality, const std::vector<double>& rivalRatios);

// Processes sharing a run each measure their part of the sequence (rangePart), send it as
// bytes (encodeSequenceQuality), and one joins the parts (joinSequenceQuality): the result is
// sequenceQuality's, bit for bit.

/// Frames [from, to) measured as sequenceQuality measures them, with the jitter of the inner
/// frames among them; the other frames' measures are left at zero (and their confidence at its
/// default), and the means and doubtful frames are not set (summarise).
SequenceQuality sequenceQualityOfFrames(const AlignedAccess& aligned,
                                        const Triangles& templateFaces, const FrameSource& frames,
                                        const std::vector<double>& knownSurfaceDistance,
                                        int templateFrame, const FrameConfidenceOptions& options,
                                        const TemplatePosedByBody& posedByBody, int from, int to);
/// The means and the doubtful frames of a measured sequence.
void summarise(SequenceQuality& quality);
/// The measures of frames [from, to) as bytes.
std::string encodeSequenceQuality(const SequenceQuality& quality, int from, int to);
/// The whole sequence's quality from its parts' bytes, in frame order. Throws Error when they do
/// not follow one another over the `frames` frames.
SequenceQuality joinSequenceQuality(const std::vector<std::string>& parts, int frames);
} // namespace clothtrack
