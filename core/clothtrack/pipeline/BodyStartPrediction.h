#pragma once
// The start of each frame's template fit from the body fitted to it (body/SkinnedTemplate.h):
// the template posed by the frame's body. Frames whose body fit is not trusted start as the
// fallback says (the landmark prediction, or the neighbour's fit).
#include <clothtrack/body/BodyFit.h>
#include <clothtrack/body/SkinnedTemplate.h>
#include <clothtrack/fit/SequenceFit.h>

#include <memory>
#include <vector>

namespace clothtrack
{
/// `skeletons` and `trusted` have one entry per frame; `fallback` may be empty (the
/// neighbour's fit as it is).
StartPrediction bodyStartPrediction(std::shared_ptr<const SkinnedTemplate> bound,
                                    std::vector<PosedSkeleton> skeletons, std::vector<bool> trusted,
                                    StartPrediction fallback);

/// The same from a body fit result and its model (the command line, the benchmarks): frames
/// whose fit is not ok are not trusted; when the template frame's is not, every frame starts
/// from the fallback.
StartPrediction bodyStartPrediction(const BodyModel& model, const BodyFitResult& body,
                                    const TriangleMesh& templateMesh, int templateFrame,
                                    StartPrediction fallback);
} // namespace clothtrack
