#pragma once
// Which of several alignments of one sequence, each made under a different body model, to keep,
// without a ground truth. A body model that explains the person's proportions poses the template
// close to each frame: the template fit then has less to stretch and ends closer to the frame's
// surface. A model whose shoulders or legs sit wrong leaves the fit to pull the template's
// triangles along the surface. Either figure alone can mislead: on trousers-squat the MakeHuman
// model's alignment is stretched 8 % less than the built-in model's but lies as far from the
// frames, and is 0.17 cm worse. So a model replaces the first only when its alignment is better on
// both (docs/body-fit.md, "Which model").
#include <string>
#include <vector>

namespace clothtrack
{
/// Share by which another alignment's figures must both be lower to replace the kept one.
inline constexpr double kModelChoiceMargin = 0.02;

/// Ground-truth-free figures of one alignment, each a mean over its frames.
struct AlignmentFigures
{
  double stretch = 0.0;         ///< FrameConfidence::stretch
  double surfaceDistance = 0.0; ///< FrameConfidence::surfaceDistance, metres
};

/// Mean of the finite values (a frame without one, NaN, is left out). Throws Error when no frame
/// has one.
double meanOverFrames(const std::vector<double>& perFrame);

/// Index of the alignment to keep. The first is the reference, kept unless another alignment is
/// both less stretched and closer to the frames than it, each by more than `margin` (a share of
/// the first's figure), so that the first named model stays when two are as good. Of several
/// such, the one whose smaller relative gain of the two is the largest: no other then beats it on
/// both figures, and the order of the later models does not matter. (Each replacing the one
/// kept so far would keep the wider model on pjump before the MakeHuman one named after it:
/// MakeHuman is 5.9 % closer to the frames but only 0.9 % less stretched than the wider model,
/// and 0.3 cm more accurate.) On pjump, where the MakeHuman model is the better by 0.5 cm, its
/// alignment is 7.8 % less stretched than the built-in model's and 9.7 % closer. Throws Error
/// when there is no alignment.
int preferredAlignment(const std::vector<AlignmentFigures>& figures,
                       double margin = kModelChoiceMargin);

/// preferredAlignment's rule in words, as metrics.json and the report give it.
std::string modelChoiceCriterion(double margin = kModelChoiceMargin);

/// The same rule in words for alignments under several template frames, the first the one
/// chosen by pose (metrics.json's template_choice).
std::string templateChoiceCriterion(double margin = kModelChoiceMargin);
} // namespace clothtrack
