#include "SequenceQuality.h"

#include <clothtrack/base/Error.h>
#include <clothtrack/base/Parallel.h>
#include <clothtrack/mesh/SurfaceLocator.h>

#include <optional>

namespace clothtrack
{
namespace
{
double mean(const std::vector<double>& values)
{
  double sum = 0;
  for (double v : values) sum += v / values.size();
  return sum;
}
} // namespace

SequenceQuality sequenceQuality(const std::vector<const Points*>& aligned,
                                const Triangles& templateFaces,
                                const std::vector<const TriangleMesh*>& frames,
                                const std::vector<double>& knownSurfaceDistance, int templateFrame,
                                const FrameConfidenceOptions& options,
                                const TemplatePosedByBody& posedByBody)
{
  const int n = static_cast<int>(aligned.size());
  if (static_cast<int>(frames.size()) != n)
    throw Error("Sequence quality: " + std::to_string(n) + " aligned frames for " +
                std::to_string(frames.size()) + " frames.");
  SequenceQuality q;
  q.surfaceDistance.assign(n, 0.0);
  q.coverageDistance.assign(n, 0.0);
  if (templateFrame >= n)
    throw Error("Sequence quality: template frame " + std::to_string(templateFrame) + " of " +
                std::to_string(n) + " frames.");
  const bool judge = templateFrame >= 0;
  if (judge) q.confidence.resize(n);
  std::optional<ConfidenceMeter> meter;
  if (judge) meter.emplace(TriangleMesh{*aligned[templateFrame], templateFaces}, options);
  parallelFor(
      0, n,
      [&](int k)
      {
        const bool known =
            k < static_cast<int>(knownSurfaceDistance.size()) && knownSurfaceDistance[k] >= 0;
        q.surfaceDistance[k] = known ? knownSurfaceDistance[k]
                                     : meanClosestDistance(*aligned[k], SurfaceLocator(*frames[k]));
        const TriangleMesh alignedMesh{*aligned[k], templateFaces};
        q.coverageDistance[k] = meanClosestDistance(frames[k]->V, SurfaceLocator(alignedMesh));
        if (!judge) return;
        FrameConfidence& c = q.confidence[k];
        meter->measureDistortion(*aligned[k], c);
        if (posedByBody)
          if (const std::optional<Points> posed = posedByBody(k))
            meter->measureBodyDistance(*aligned[k], *posed, c);
        c.surfaceDistance = q.surfaceDistance[k];
        c.coverageDistance = q.coverageDistance[k];
        judgeConfidence(c, options);
      },
      1);
  for (int k = 0; k < static_cast<int>(q.confidence.size()); ++k)
    if (q.confidence[k].doubtful()) q.doubtfulFrames.push_back(k);
  for (int k = 1; k + 1 < n; ++k)
    q.jitter.push_back(
        (*aligned[k + 1] - 2 * *aligned[k] + *aligned[k - 1]).rowwise().norm().mean());
  q.meanSurfaceDistance = mean(q.surfaceDistance);
  q.meanCoverageDistance = mean(q.coverageDistance);
  q.meanJitter = mean(q.jitter);
  return q;
}
} // namespace clothtrack
