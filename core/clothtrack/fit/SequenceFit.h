#pragma once
// Stage 3 over a sequence, in the paper's order (Shehu et al. 2016, section 4.3): the template
// frame j keeps the template; frames j-1 .. 0 and j+1 .. N-1 are fitted one after the other,
// each started from its neighbour's fit. The chains are independent (more than two: see
// sequenceChains) and run side by side when threadCount() > 1, each with its own TemplateFitter
// (a fitter keeps its factorisations).
#include "TemplateFit.h"

#include <clothtrack/base/Progress.h>
#include <clothtrack/mesh/FrameSource.h>

#include <functional>
#include <optional>
#include <vector>

namespace clothtrack
{
/// Turns the fit of frame `from` into the start of frame k (e.g. landmarkStartPrediction).
using StartPrediction = std::function<Points(int k, int from, const Points& fitOfFrom)>;

/// One chain of frames fitted one after the other: first, first + direction, ... up to `end`
/// (excluded); the first starts from the template, each next one from its neighbour's fit.
struct FitChain
{
  int first = 0, end = 0, direction = 1;
  int frames() const { return (end - first) * direction; }
  /// Whether frame k is one of the chain's.
  bool contains(int k) const { return (k - first) * direction >= 0 && (end - k) * direction > 0; }
};

/// The chains of a sequence fit. Up to two: the paper's, backward and forward from the template
/// frame. More: each side split into consecutive chains in proportion to its frames; a chain away
/// from the template starts at its key frame (the end nearer the template) from the template
/// itself, template to frame (the start prediction moves it there), so that chains are
/// independent and can run on different processes. Backward chains come first, nearest the
/// template first.
std::vector<FitChain> sequenceChains(int numFrames, int templateFrame, int count);

/// What the chains read and where their results go. Every callback is called one at a time
/// (never by both chains at once), and what it returns is copied at once.
struct SequenceFitHooks
{
  /// Frame k (held while it is fitted). Required.
  std::function<FramePtr(int k)> frame;
  /// Correspondences of frame k; null (or no function) for none.
  std::function<const VertexTargets*(int k)> targets;
  /// The start of frame k; by default the neighbour's fit as it is.
  StartPrediction start;
  /// Frame k's fit from an earlier run (positions at least), which is kept instead of fitting
  /// the frame (resuming an interrupted run); nullopt to fit it.
  std::function<std::optional<FrameFit>(int k)> resumed;
  /// The solver state the earlier run had after fitting frame k (see `fitterState`), asked for
  /// the last resumed frame before a frame to fit. With it, the frames fitted after the resumed
  /// ones come out exactly as in a run that was never interrupted; without it (nullopt) they
  /// start from a fresh solver and differ within the solver's tolerance.
  std::function<std::optional<TemplateFitterState>(int k)> resumedState;
  /// Called with the solver state after each fitted frame (the template frame and resumed
  /// frames excepted), before `fitted`: kept, it lets an interrupted run resume exactly.
  std::function<void(int k, const TemplateFitterState& state)> fitterState;
  /// Called with each frame as soon as it is fitted, the template frame included (not for
  /// resumed frames): writing, evaluation.
  std::function<void(int k, const FrameFit& fit)> fitted;
  /// Fraction of the frames done; returning false cancels (Error thrown).
  StageProgress progress;
  /// Judges the fit of frame k (e.g. judgeFits, pipeline/FitJudge.h): at most 1 is trusted.
  /// A frame judged past retryAbove is fitted again from other starts (the neighbour's fit
  /// without the start prediction; nearest points alone, without the correspondences, which
  /// may be wrong) and the best judged fit is kept. Unlike the other hooks, the judge may run
  /// in both chains at once.
  std::function<double(int k, const TriangleMesh& frame, const FrameFit& fit)> judge;
  /// A judged frame is fitted again when its doubt exceeds this (at least 1).
  double retryAbove = 1.0;
  /// False for a long sequence: each frame's positions, correspondence flags and surface
  /// distances are dropped from the result once `fitted` has had them and the next frame of its
  /// chain has started from them (its mean surface distance is kept), so that memory does not
  /// grow with the sequence. Resumed frames are dropped too.
  bool keepFits = true;
  /// How many chains the sequence is fitted in (sequenceChains).
  int chainCount = 2;
  /// The chains this call fits (indices into sequenceChains); empty for all. The others' frames
  /// are left unfitted (empty, `fitted` not called). The call that fits chain 0 reports the
  /// template frame.
  std::vector<int> fitChains;
};

/// Fits the template through all `numFrames` frames. Throws Error (naming the frame) when a fit
/// fails, or when cancelled.
std::vector<FrameFit> fitTemplateSequence(const TriangleMesh& templateMesh, int templateFrame,
                                          int numFrames, const SequenceFitHooks& hooks,
                                          const TemplateFitOptions& options = {});
} // namespace clothtrack
