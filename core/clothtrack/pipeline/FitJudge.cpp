#include "FitJudge.h"

#include <clothtrack/base/Error.h>

#include <memory>
#include <string>

namespace clothtrack
{
void judgeFits(SequenceFitHooks& hooks, const TriangleMesh& templateMesh,
               const FitJudgeOptions& options, TemplatePosedByBody posedByBody)
{
  // The template's edges are measured once; the coverage of each fit is estimated from a few
  // thousand of the frame's vertices.
  auto meter = std::make_shared<const ConfidenceMeter>(templateMesh, options.limits);
  hooks.judge = [meter, posedByBody = std::move(posedByBody)](int k, const TriangleMesh& frame,
                                                              const FrameFit& fit)
  {
    const double known = fit.surfaceDistance.size() ? fit.surfaceDistance.mean() : -1.0;
    const std::optional<Points> posed = posedByBody ? posedByBody(k) : std::nullopt;
    return (*meter)(fit.positions, frame, known, 4000, posed ? &*posed : nullptr).severity;
  };
  hooks.retryAbove = options.retrySeverity;
}

double fittedSurfaceDistance(const FrameFit& fit)
{
  if (fit.meanSurfaceDistance >= 0) return fit.meanSurfaceDistance;
  return fit.surfaceDistance.size() > 0 ? fit.surfaceDistance.mean() : -1.0;
}

SequenceQuality fittedSequenceQuality(const std::vector<FrameFit>& fits,
                                      const Triangles& templateFaces,
                                      const std::vector<const TriangleMesh*>& frames,
                                      int templateFrame, const FitJudgeOptions& options,
                                      const TemplatePosedByBody& posedByBody)
{
  if (frames.size() != fits.size())
    throw Error("Sequence quality: " + std::to_string(fits.size()) + " aligned frames for " +
                std::to_string(frames.size()) + " frames.");
  return fittedSequenceQuality(
      fits, templateFaces, FramesInMemory(frames), [&](int k) { return fits[k].positions; },
      templateFrame, options, posedByBody);
}

SequenceQuality fittedSequenceQuality(const std::vector<FrameFit>& fits,
                                      const Triangles& templateFaces, const FrameSource& frames,
                                      const AlignedAccess& aligned, int templateFrame,
                                      const FitJudgeOptions& options,
                                      const TemplatePosedByBody& posedByBody)
{
  std::vector<double> known;
  for (const FrameFit& f : fits) known.push_back(fittedSurfaceDistance(f));
  return sequenceQuality(aligned, templateFaces, frames, known, templateFrame, options.limits,
                         posedByBody);
}
} // namespace clothtrack
