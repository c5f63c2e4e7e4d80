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
  if (frames.size() != aligned.size())
    throw Error("Sequence quality: " + std::to_string(aligned.size()) + " aligned frames for " +
                std::to_string(frames.size()) + " frames.");
  return sequenceQuality([&](int k) { return *aligned[k]; }, templateFaces, FramesInMemory(frames),
                         knownSurfaceDistance, templateFrame, options, posedByBody);
}

SequenceQuality sequenceQuality(const AlignedAccess& aligned, const Triangles& templateFaces,
                                const FrameSource& frames,
                                const std::vector<double>& knownSurfaceDistance, int templateFrame,
                                const FrameConfidenceOptions& options,
                                const TemplatePosedByBody& posedByBody)
{
  const int n = frames.count();
  SequenceQuality q;
  q.surfaceDistance.assign(n, 0.0);
  q.coverageDistance.assign(n, 0.0);
  if (templateFrame >= n)
    throw Error("Sequence quality: template frame " + std::to_string(templateFrame) + " of " +
                std::to_string(n) + " frames.");
  const bool judge = templateFrame >= 0;
  if (judge) q.confidence.resize(n);
  std::optional<ConfidenceMeter> meter;
  if (judge) meter.emplace(TriangleMesh{aligned(templateFrame), templateFaces}, options);
  auto measure = [&](int k, const Points& positions)
  {
    const FramePtr frame = frames.frame(k);
    if (!frame) throw Error("Sequence quality: frame " + std::to_string(k) + " is missing.");
    const bool known =
        k < static_cast<int>(knownSurfaceDistance.size()) && knownSurfaceDistance[k] >= 0;
    q.surfaceDistance[k] =
        known ? knownSurfaceDistance[k] : meanClosestDistance(positions, SurfaceLocator(*frame));
    const TriangleMesh alignedMesh{positions, templateFaces};
    q.coverageDistance[k] = meanClosestDistance(frame->V, SurfaceLocator(alignedMesh));
    if (!judge) return;
    FrameConfidence& c = q.confidence[k];
    meter->measureDistortion(positions, c);
    if (posedByBody)
      if (const std::optional<Points> posed = posedByBody(k))
        meter->measureBodyDistance(positions, *posed, c);
    c.surfaceDistance = q.surfaceDistance[k];
    c.coverageDistance = q.coverageDistance[k];
    judgeConfidence(c, options);
  };
  // Blocks of frames, each with the aligned frames on either side for the jitter.
  const int block = std::max(8, 4 * threadCount());
  for (int begin = 0; begin < n; begin += block)
  {
    const int end = std::min(n, begin + block);
    const int first = std::max(0, begin - 1), last = std::min(n - 1, end);
    std::vector<Points> window(last - first + 1);
    parallelFor(
        first, last + 1, [&](int k) { window[k - first] = aligned(k); }, 1);
    parallelFor(
        begin, end, [&](int k) { measure(k, window[k - first]); }, 1);
    for (int k = std::max(1, begin); k < end && k + 1 < n; ++k)
    {
      const Points& before = window[k - 1 - first];
      const Points& now = window[k - first];
      const Points& after = window[k + 1 - first];
      q.jitter.push_back((after - 2 * now + before).rowwise().norm().mean());
    }
  }
  for (int k = 0; k < static_cast<int>(q.confidence.size()); ++k)
    if (q.confidence[k].doubtful()) q.doubtfulFrames.push_back(k);
  q.meanSurfaceDistance = mean(q.surfaceDistance);
  q.meanCoverageDistance = mean(q.coverageDistance);
  q.meanJitter = mean(q.jitter);
  return q;
}
} // namespace clothtrack
