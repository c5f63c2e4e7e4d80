#include "BenchSequence.h"

#include "ctBuiltinBodyModel.h"
#include "ctMeshConversion.h"
#include "ctSyntheticSequence.h"

#include <clothtrack/body/BodyFit.h>
#include <clothtrack/body/LandmarkTransfer.h>
#include <clothtrack/body/OrientedLandmarks.h>
#include <clothtrack/io/FrameList.h>
#include <clothtrack/pipeline/BodyStage.h>
#include <clothtrack/pipeline/TemplateStage.h>

#include <cstdio>

namespace clothtrack::bench
{
double seconds(std::chrono::steady_clock::time_point since)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - since).count();
}

bool Sequence::truthOf(int j, int v, int k, Vec3& position) const
{
  if (sources.empty())
  {
    position = truth[k].vertex(v);
    return true;
  }
  const SourceMap& source = sources[j];
  if (source.distance[v] > kNoTruth) return false;
  position = surfacePosition(truth[k], source.face[v], source.barycentric[v]);
  return true;
}

void fitLandmarks(Sequence& s)
{
  std::vector<const TriangleMesh*> frames;
  for (const auto& c : s.captures) frames.push_back(&c);
  const auto start = std::chrono::steady_clock::now();
  s.landmarks = fitBodyAndLandmarks(builtinBodyModel(), frames).landmarks;
  std::printf("body fit: %.1f s\n", seconds(start));
}

Sequence syntheticSequence(const std::string& preset, int numFrames, bool trueLandmarks)
{
  const BodyModel& model = builtinBodyModel();
  SyntheticOptions options;
  options.preset = preset;
  options.frames = numFrames;
  Sequence s;
  std::vector<TriangleMesh> bodies;
  generateSyntheticSequence(model, options,
                            [&](const SyntheticFrame& frame)
                            {
                              s.truth.push_back(frame.clothed);
                              bodies.push_back(frame.body);
                              SourceMap map;
                              CaptureOptions capture;
                              capture.seed = 1 + frame.index;
                              s.captures.push_back(simulateCapture(frame.clothed, capture, &map));
                              s.sources.push_back(std::move(map));
                            });
  if (trueLandmarks)
    for (size_t k = 0; k < s.captures.size(); ++k)
    {
      const SurfaceLocator locator(s.captures[k]);
      s.landmarks.push_back(landmarkSeeds(
          transferLandmarks(orientedLandmarks(model, bodies[k]), s.captures[k], locator)));
    }
  else
    fitLandmarks(s);
  std::printf("preset %s, %d frames, landmarks from the %s body\n", preset.c_str(), numFrames,
              trueLandmarks ? "true" : "fitted");
  return s;
}

Sequence directorySequence(const std::string& path, int stride, int maxFrames, bool remesh)
{
  Sequence s;
  const auto files = listFrames(path);
  for (size_t i = 0; i < files.size(); i += stride)
  {
    if (maxFrames > 0 && static_cast<int>(s.truth.size()) >= maxFrames) break;
    s.truth.push_back(loadFrame(files[i], FrameConventions()));
    if (!remesh)
    {
      s.captures.push_back(s.truth.back());
      continue;
    }
    SourceMap map;
    CaptureOptions capture;
    capture.seed = 1 + static_cast<unsigned>(i);
    s.captures.push_back(simulateCapture(s.truth.back(), capture, &map));
    s.sources.push_back(std::move(map));
  }
  std::printf("%s%s: %zu frames (stride %d)\n", path.c_str(), remesh ? " re-meshed" : "",
              s.captures.size(), stride);
  fitLandmarks(s);
  return s;
}

int chooseTemplate(const Sequence& s)
{
  std::vector<const TriangleMesh*> frames;
  for (const auto& c : s.captures) frames.push_back(&c);
  return chooseTemplateFrame(frames).chosen;
}
} // namespace clothtrack::bench
