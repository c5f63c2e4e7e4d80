#pragma once
// Stage 3 does not pass a doubtful frame on unjudged: each fit is judged by its ground-truth-free
// confidence (eval/FrameConfidence.h), and the sequence fit tries a clearly doubtful frame again
// from other starts (fit/SequenceFit.h).
#include <clothtrack/eval/FrameConfidence.h>
#include <clothtrack/eval/SequenceQuality.h>
#include <clothtrack/fit/SequenceFit.h>

namespace clothtrack
{
struct FitJudgeOptions
{
  FrameConfidenceOptions limits;
  /// Frames whose severity (the largest measure over its limit) is above this are fitted again.
  /// Retrying the barely doubtful frames of pjump (severity 1.0-1.15, tangential sliding) cost
  /// 75 % more fit time for 0.08 cm less mean error (docs/confidence.md); a collapsed frame is
  /// far past its limits.
  double retrySeverity = 1.5;
};

/// Sets hooks.judge (each fit's severity) and hooks.retryAbove. With `posedByBody`
/// (pipeline/BodyStartPrediction.h), a fit far from where the frame's body carries the template
/// is judged too.
void judgeFits(SequenceFitHooks& hooks, const TriangleMesh& templateMesh,
               const FitJudgeOptions& options = {}, TemplatePosedByBody posedByBody = {});

/// The mean surface distance a frame's fit measured (kept when its vertices were dropped, else
/// from its per-vertex distances); -1 when it has none (a resumed frame).
double fittedSurfaceDistance(const FrameFit& fit);

/// The quality of a fitted sequence and each frame's confidence (eval/SequenceQuality.h), reusing
/// the surface distances the fit measured (resumed frames have none and are measured).
SequenceQuality fittedSequenceQuality(const std::vector<FrameFit>& fits,
                                      const Triangles& templateFaces,
                                      const std::vector<const TriangleMesh*>& frames,
                                      int templateFrame, const FitJudgeOptions& options = {},
                                      const TemplatePosedByBody& posedByBody = {});

/// The same over frames read when needed, each frame's fitted vertices from `aligned` (fits
/// whose vertices were dropped, SequenceFitHooks::keepFits, keep their mean surface distance).
SequenceQuality fittedSequenceQuality(const std::vector<FrameFit>& fits,
                                      const Triangles& templateFaces, const FrameSource& frames,
                                      const AlignedAccess& aligned, int templateFrame,
                                      const FitJudgeOptions& options = {},
                                      const TemplatePosedByBody& posedByBody = {});
} // namespace clothtrack
