#pragma once
// Which of several alignments of one sequence, each made under a different body model, to keep,
// without a ground truth. A body model that explains the person's proportions poses the template
// close to each frame: the template fit then has less to stretch and ends closer to the frame's
// surface. A model whose shoulders or legs sit wrong leaves the fit to pull the template's
// triangles along the surface. Either figure alone can mislead: on trousers-squat the MakeHuman
// model's alignment is stretched 8 % less than the built-in model's but lies as far from the
// frames, and is 0.17 cm worse. So a model replaces another only when its alignment is better on
// both (docs/body-fit.md, "Which model").
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

/// Index of the alignment to keep: the first, replaced by a later one only when that one is both
/// less stretched and closer to the frames, each by more than `margin` (a share of the kept
/// one's figure), so that the first named model stays when two are as good. On pjump, where the
/// MakeHuman model is the better by 0.5 cm, its alignment is 7.8 % less stretched and 9.7 %
/// closer. Throws Error when there is no alignment.
int preferredAlignment(const std::vector<AlignmentFigures>& figures,
                       double margin = kModelChoiceMargin);
} // namespace clothtrack
