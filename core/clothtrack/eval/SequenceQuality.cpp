#include "SequenceQuality.h"

#include <clothtrack/base/Bytes.h>
#include <clothtrack/base/Error.h>
#include <clothtrack/base/Parallel.h>
#include <clothtrack/mesh/SurfaceLocator.h>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <optional>
#include <string>

namespace clothtrack
{
namespace
{
/// Bumped with any change of the layout of encodeSequenceQuality.
constexpr std::uint32_t kQualityLayout = 0x43545132; // "CTQ2"

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
  SequenceQuality q =
      sequenceQualityOfFrames(aligned, templateFaces, frames, knownSurfaceDistance, templateFrame,
                              options, posedByBody, 0, frames.count());
  summarise(q);
  return q;
}

SequenceQuality sequenceQualityOfFrames(const AlignedAccess& aligned,
                                        const Triangles& templateFaces, const FrameSource& frames,
                                        const std::vector<double>& knownSurfaceDistance,
                                        int templateFrame, const FrameConfidenceOptions& options,
                                        const TemplatePosedByBody& posedByBody, int from, int to)
{
  const int n = frames.count();
  SequenceQuality q;
  q.surfaceDistance.assign(n, 0.0);
  q.coverageDistance.assign(n, 0.0);
  if (templateFrame >= n)
    throw Error("Sequence quality: template frame " + std::to_string(templateFrame) + " of " +
                std::to_string(n) + " frames.");
  if (from < 0 || to > n || from > to)
    throw Error("Sequence quality: frames " + std::to_string(from) + " to " + std::to_string(to) +
                " of " + std::to_string(n) + ".");
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
  for (int begin = from; begin < to; begin += block)
  {
    const int end = std::min(to, begin + block);
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
  return q;
}

namespace
{
/// Raises a frame's severity to at least `severity` and adds `why` to its doubts.
void raiseDoubt(FrameConfidence& c, double severity, const std::string& why)
{
  c.severity = std::max(c.severity, severity);
  c.confidence = std::clamp(2.0 - c.severity, 0.0, 1.0);
  c.doubt += (c.doubt.empty() ? "" : ", ") + why;
}
} // namespace

void summarise(SequenceQuality& q)
{
  q.doubtfulFrames.clear();
  for (int k = 0; k < static_cast<int>(q.confidence.size()); ++k)
    if (q.confidence[k].doubtful()) q.doubtfulFrames.push_back(k);
  q.meanSurfaceDistance = mean(q.surfaceDistance);
  q.meanCoverageDistance = mean(q.coverageDistance);
  q.meanJitter = mean(q.jitter);
}

void doubtUnplacedFrames(SequenceQuality& q, const std::vector<bool>& unplaced)
{
  if (unplaced.size() != q.confidence.size())
    throw Error("Sequence quality: " + std::to_string(unplaced.size()) + " placement flags for " +
                std::to_string(q.confidence.size()) + " frames.");
  for (size_t k = 0; k < unplaced.size(); ++k)
    if (unplaced[k])
      raiseDoubt(q.confidence[k], kUnplacedSeverity,
                 "no trusted body, and unlike the frame before it");
  summarise(q);
}

void doubtAmbiguousBodies(SequenceQuality& q, const std::vector<double>& rivalRatios)
{
  if (rivalRatios.size() != q.confidence.size())
    throw Error("Sequence quality: " + std::to_string(rivalRatios.size()) +
                " body rival ratios for " + std::to_string(q.confidence.size()) + " frames.");
  for (size_t k = 0; k < rivalRatios.size(); ++k)
  {
    if (!(rivalRatios[k] < kAmbiguousBodyRatio)) continue;
    char doubt[160];
    std::snprintf(doubt, sizeof doubt,
                  "another pose of the body, a limb elsewhere, explains it almost as well "
                  "(score ratio %.3f < %.2f)",
                  rivalRatios[k], kAmbiguousBodyRatio);
    raiseDoubt(q.confidence[k], kAmbiguousBodySeverity, doubt);
  }
  summarise(q);
}

std::string encodeSequenceQuality(const SequenceQuality& q, int from, int to)
{
  ByteWriter w;
  w.put(kQualityLayout);
  w.put(static_cast<std::int32_t>(from));
  w.put(static_cast<std::int32_t>(to));
  w.put(static_cast<std::uint8_t>(!q.confidence.empty()));
  for (int k = from; k < to; ++k)
  {
    w.put(q.surfaceDistance.at(k));
    w.put(q.coverageDistance.at(k));
    if (q.confidence.empty()) continue;
    const FrameConfidence& c = q.confidence[k];
    for (double v : {c.surfaceDistance, c.coverageDistance, c.stretch, c.folded, c.bodyDistance,
                     c.extentGap, c.severity, c.confidence})
      w.put(v);
    w.putText(c.doubt);
  }
  w.put(static_cast<std::uint32_t>(q.jitter.size()));
  for (double v : q.jitter) w.put(v);
  return w.take();
}

SequenceQuality joinSequenceQuality(const std::vector<std::string>& parts, int frames)
{
  SequenceQuality q;
  q.surfaceDistance.assign(frames, 0.0);
  q.coverageDistance.assign(frames, 0.0);
  int next = 0; // the parts follow one another
  for (const std::string& bytes : parts)
  {
    ByteReader r(bytes, "sequence quality");
    if (r.get<std::uint32_t>() != kQualityLayout)
      throw Error("sequence quality: message of another layout");
    const int from = r.get<std::int32_t>(), to = r.get<std::int32_t>();
    if (from != next || to < from || to > frames)
      throw Error("sequence quality: parts do not follow one another");
    next = to;
    const bool judged = r.get<std::uint8_t>() != 0;
    if (judged) q.confidence.resize(frames);
    for (int k = from; k < to; ++k)
    {
      q.surfaceDistance[k] = r.get<double>();
      q.coverageDistance[k] = r.get<double>();
      if (!judged) continue;
      FrameConfidence& c = q.confidence[k];
      for (double* v : {&c.surfaceDistance, &c.coverageDistance, &c.stretch, &c.folded,
                        &c.bodyDistance, &c.extentGap, &c.severity, &c.confidence})
        *v = r.get<double>();
      c.doubt = r.getText();
    }
    const auto jitter = r.get<std::uint32_t>();
    for (std::uint32_t i = 0; i < jitter; ++i) q.jitter.push_back(r.get<double>());
    r.expectEnd();
  }
  if (next != frames) throw Error("sequence quality: parts do not cover the sequence");
  summarise(q);
  return q;
}
} // namespace clothtrack
