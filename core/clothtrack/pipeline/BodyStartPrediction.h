#pragma once
// The start of each frame's template fit from the body fitted to it (body/SkinnedTemplate.h):
// the template posed by the frame's body. Frames whose body fit is not trusted start as the
// fallback says (the landmark prediction, or the neighbour's fit).
#include <clothtrack/body/BodyFit.h>
#include <clothtrack/body/SkinnedTemplate.h>
#include <clothtrack/fit/SequenceFit.h>

#include <vector>

namespace clothtrack
{
/// What a fitted sequence of bodies gives the start: one skeleton and one trusted flag per frame,
/// and the posed vertices and skinning weights of the template frame's body.
struct FittedBodies
{
  std::vector<PosedSkeleton> skeletons;
  std::vector<bool> trusted;
  Points templateBody;
  Eigen::MatrixXd weights;
};

/// The start of frame k: the template bound to the template frame's body and posed by frame k's.
/// Untrusted frames start from `fallback` (which may be empty: the neighbour's fit as it is);
/// when the template frame's body is not trusted, `fallback` itself is returned.
StartPrediction bodyStartPrediction(const TriangleMesh& templateMesh, int templateFrame,
                                    FittedBodies bodies, StartPrediction fallback);

/// The same from a body fit result and its model (the command line): frames whose fit is not
/// ok are not trusted.
StartPrediction bodyStartPrediction(const BodyModel& model, const BodyFitResult& body,
                                    const TriangleMesh& templateMesh, int templateFrame,
                                    StartPrediction fallback);
} // namespace clothtrack
