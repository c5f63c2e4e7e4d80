// Dense correspondence (geodesic patches) against ground truth, beside the rigid + nearest
// neighbour baseline.
//   bench_correspondence synthetic PRESET FRAMES [true]   synthetic captures; landmarks from the
//                                                         fitted body (or the true body: "true")
//   bench_correspondence remesh DIR [STRIDE]              a consistent-connectivity sequence
//                                                         (e.g. samba) re-meshed by the capture
//                                                         simulator; landmarks from the fitted body
// CLOTHTRACK_EPSILON and CLOTHTRACK_MAX_SEED_OFFSET override eps and the largest landmark offset
// from the body that seeds a patch (metres); CLOTHTRACK_MIN_CONSENSUS (0: off),
// CLOTHTRACK_CONSENSUS_TOLERANCE, CLOTHTRACK_CONSENSUS_RELATIVE and CLOTHTRACK_CONSENSUS_RADIUS the
// seed consensus. CLOTHTRACK_BENCH_VERBOSE=1 prints every seed and patch of the last frame.
// The template frame is chosen automatically. Error of a template vertex t in frame k: distance
// from f(t) to the ground-truth position of t's source point (the true surface point the
// template vertex was captured from) in frame k; vertices more than 3 cm from any true surface
// (surfaces the capture invented to close hidden regions) have no truth and are not counted.
#include "BenchSequence.h"

#include <clothtrack/base/Error.h>
#include <clothtrack/base/Parallel.h>
#include <clothtrack/correspondence/PatchCorrespondence.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <string>

using namespace clothtrack;
using namespace clothtrack::bench;

namespace
{
struct Stats
{
  std::vector<double> errors;
  long long vertices = 0;
  double time = 0.0;
  void print(const char* name) const
  {
    std::vector<double> e = errors;
    double mean = 0.0;
    int far = 0;
    for (double x : e) mean += x, far += x > 0.10;
    mean /= std::max<size_t>(1, e.size());
    double p90 = 0.0;
    if (!e.empty())
    {
      std::nth_element(e.begin(), e.begin() + e.size() * 9 / 10, e.end());
      p90 = e[e.size() * 9 / 10];
    }
    std::printf("| %s | %.2f cm | %.2f cm | %.1f %% | %.1f %% | %.2f s |\n", name, 100 * mean,
                100 * p90, 100.0 * e.size() / std::max(1LL, vertices),
                100.0 * far / std::max<size_t>(1, e.size()), time);
  }
};

int evaluate(Sequence& s)
{
  const int j = chooseTemplate(s);
  const TriangleMesh& templ = s.captures[j];
  std::printf("template frame %d: %d vertices, %zu landmarks; %d threads\n", j, templ.numVertices(),
              s.landmarks[j].size(), threadCount());
  auto start = std::chrono::steady_clock::now();
  PatchCorrespondenceOptions options;
  if (const char* eps = std::getenv("CLOTHTRACK_EPSILON")) options.epsilon = std::atof(eps);
  if (const char* offset = std::getenv("CLOTHTRACK_MAX_SEED_OFFSET"))
    options.maximumSeedOffset = std::atof(offset);
  if (const char* consensus = std::getenv("CLOTHTRACK_MIN_CONSENSUS"))
    options.minimumSeedConsensus = std::atof(consensus);
  if (const char* v = std::getenv("CLOTHTRACK_CONSENSUS_RELATIVE"))
    options.seedConsensusRelativeTolerance = std::atof(v);
  if (const char* v = std::getenv("CLOTHTRACK_CONSENSUS_TOLERANCE"))
    options.seedConsensusTolerance = std::atof(v);
  if (const char* v = std::getenv("CLOTHTRACK_CONSENSUS_RADIUS"))
    options.seedConsensusRadius = std::atof(v);
  const TemplatePatches patches(templ, s.landmarks[j], options);
  std::printf("eps %.3f m, tau_s %.2f m, tau_d %.2f m, seeds within %.2f m of the body\n",
              options.epsilon, options.minimumRadius, options.maximumRadius,
              options.maximumSeedOffset);
  std::printf("template preparation %.2f s\n", seconds(start));
  Stats geodesic, baseline, baselineSame;
  double kept = 0, tried = 0, landmarkError = 0;
  int landmarkPairs = 0;
  for (size_t k = 0; k < s.captures.size(); ++k)
  {
    if (static_cast<int>(k) == j) continue;
    start = std::chrono::steady_clock::now();
    const FrameCorrespondence c = patches.correspond(s.captures[k], s.landmarks[k]);
    geodesic.time += seconds(start);
    start = std::chrono::steady_clock::now();
    const FrameCorrespondence b =
        rigidNearestCorrespondence(templ, s.landmarks[j], s.captures[k], s.landmarks[k]);
    baseline.time += seconds(start);
    for (const auto& p : c.patches) kept += p.kept, tried += 1;
    // Landmark pairs against the truth: the template landmark's nearest vertex, followed.
    for (const auto& t : s.landmarks[j])
      for (const auto& f : s.landmarks[k])
        if (f.id == t.id)
        {
          Vec3 truth;
          if (!s.truthOf(j, templ.F(t.face, 0), static_cast<int>(k), truth)) continue;
          const double e = (surfacePosition(s.captures[k], f.face, f.bary) - truth).norm();
          landmarkError += e;
          if (std::getenv("CLOTHTRACK_BENCH_VERBOSE") && k + 1 == s.captures.size())
            std::printf("frame %zu landmark %2d: seed off the truth by %.2f cm\n", k, t.id,
                        100 * e);
          ++landmarkPairs;
        }
    if (std::getenv("CLOTHTRACK_BENCH_VERBOSE") && k + 1 == s.captures.size())
    {
      std::map<int, std::pair<double, int>> byPatch;
      for (int v = 0; v < templ.numVertices(); ++v)
        if (Vec3 truth; c.vertices[v].matched() && s.truthOf(j, v, static_cast<int>(k), truth))
        {
          auto& e = byPatch[c.vertices[v].patchId];
          e.first += (c.vertices[v].position - truth).norm();
          ++e.second;
        }
      for (const auto& p : c.patches)
        std::printf("frame %zu landmark %2d: consensus %.2f, radius %.2f, %d vertices, %d "
                    "inconsistent, mean error of its nearest vertices %.2f cm\n",
                    k, p.landmarkId, p.consensus, p.radius, p.vertices, p.inconsistent,
                    byPatch.count(p.landmarkId)
                        ? 100 * byPatch[p.landmarkId].first / byPatch[p.landmarkId].second
                        : 0.0);
    }
    for (int v = 0; v < templ.numVertices(); ++v)
    {
      Vec3 truth;
      if (!s.truthOf(j, v, static_cast<int>(k), truth)) continue;
      ++geodesic.vertices;
      ++baseline.vertices;
      ++baselineSame.vertices;
      if (c.vertices[v].matched())
      {
        geodesic.errors.push_back((c.vertices[v].position - truth).norm());
        baselineSame.errors.push_back((b.vertices[v].position - truth).norm());
      }
      if (b.vertices[v].matched())
        baseline.errors.push_back((b.vertices[v].position - truth).norm());
    }
  }
  const double frames = static_cast<double>(s.captures.size() - 1);
  geodesic.time /= frames;
  baseline.time /= frames;
  std::printf("patches kept %.1f %% of the landmark pairs; landmark pairs off the truth by %.2f cm "
              "on average\n",
              100 * kept / std::max(1.0, tried), 100 * landmarkError / std::max(1, landmarkPairs));
  std::printf("| method | mean error | p90 error | matched | off > 10 cm | time/frame |\n");
  geodesic.print("geodesic patches");
  baseline.print("rigid + nearest");
  baselineSame.time = baseline.time;
  baselineSame.print("rigid + nearest, on the vertices the patches match");
  return 0;
}

int synthetic(const std::string& preset, int numFrames, bool trueLandmarks)
{
  Sequence s = syntheticSequence(preset, numFrames, trueLandmarks);
  return evaluate(s);
}

int remesh(const std::string& path, int stride)
{
  Sequence s = directorySequence(path, stride, 0, true);
  return evaluate(s);
}
} // namespace

int main(int argc, char** argv)
{
  try
  {
    const std::string mode = argc > 1 ? argv[1] : "";
    if (mode == "synthetic" && argc >= 4)
      return synthetic(argv[2], std::stoi(argv[3]), argc > 4 && std::string(argv[4]) == "true");
    if (mode == "remesh" && argc >= 3) return remesh(argv[2], argc > 3 ? std::stoi(argv[3]) : 1);
    std::fprintf(stderr, "usage: bench_correspondence synthetic PRESET FRAMES [true] | remesh DIR "
                         "[STRIDE]\n");
    return 1;
  }
  catch (const std::exception& e)
  {
    std::fprintf(stderr, "bench_correspondence: %s\n", e.what());
    return 1;
  }
}
