// Synthetic clothed sequences: determinism, cloth behaviour, capture and source map.
#include "ctBuiltinBodyModel.h"
#include "ctCaptureSimulation.h"
#include "ctSyntheticSequence.h"

#include <clothtrack/base/Error.h>
#include <clothtrack/mesh/MeshTopology.h>

#include <gtest/gtest.h>

#include <cstdio>

using namespace clothtrack;

namespace
{
std::vector<SyntheticFrame> run(const SyntheticOptions& options)
{
  std::vector<SyntheticFrame> frames;
  generateSyntheticSequence(builtinBodyModel(), options,
                            [&](const SyntheticFrame& f) { frames.push_back(f); });
  return frames;
}
} // namespace

TEST(SyntheticSequence, DressWalkIsDeterministicAndTheClothIsNearIsometric)
{
  SyntheticOptions options;
  options.preset = "dress-walk";
  options.frames = 12;
  options.seed = 7;
  const auto a = run(options);
  const auto b = run(options);
  ASSERT_EQ(a.size(), 12u);
  for (size_t k = 0; k < a.size(); ++k) ASSERT_EQ(a[k].clothed.V, b[k].clothed.V) << "frame " << k;
  // Same connectivity in every frame (the ground truth).
  for (const auto& f : a) EXPECT_EQ(f.clothed.F, a[0].clothed.F);

  // The garment hardly stretches: edge lengths stay close to the first frame's.
  const MeshTopology topo = buildTopology(a[0].clothed);
  double worstMeanStrain = 0;
  for (const auto& f : a)
  {
    double strain = 0;
    int count = 0;
    for (const auto& e : topo.edges)
    {
      if (e[0] < f.garmentOffset) continue;
      const double l0 = (a[0].clothed.vertex(e[0]) - a[0].clothed.vertex(e[1])).norm();
      const double l = (f.clothed.vertex(e[0]) - f.clothed.vertex(e[1])).norm();
      strain += std::abs(l / l0 - 1);
      ++count;
    }
    worstMeanStrain = std::max(worstMeanStrain, strain / count);
  }
  std::printf("[ measured ] dress-walk garment: worst per-frame mean edge strain %.2f %%\n",
              100 * worstMeanStrain);
  EXPECT_LT(worstMeanStrain, 0.05);

  // Non-rigid: the hem moves relative to the pelvis (it swings), unlike a skinned surface.
  const int hem = a[0].clothed.numVertices() - 1;
  double relativeMotion = 0;
  for (size_t k = 1; k < a.size(); ++k)
  {
    const Vec3 r0 = a[k - 1].clothed.vertex(hem) - a[k - 1].body.vertex(0);
    const Vec3 r1 = a[k].clothed.vertex(hem) - a[k].body.vertex(0);
    relativeMotion = std::max(relativeMotion, (r1 - r0).norm());
  }
  EXPECT_GT(relativeMotion, 0.005);
  // The markers are the body landmarks.
  EXPECT_EQ(a[3].markers.rows(), 14);
  EXPECT_GT(a[3].markers(0, 1), a[3].markers(13, 1)); // forehead above heel
}

TEST(SyntheticSequence, EveryPresetRunsAndCapturesStayNearTheTruth)
{
  for (const auto& preset : syntheticPresets())
  {
    SCOPED_TRACE(preset);
    SyntheticOptions options;
    options.preset = preset;
    options.frames = 3;
    const auto frames = run(options);
    ASSERT_EQ(frames.size(), 3u);
    // Without the visual-hull fill every captured vertex lies on a re-meshed true surface.
    CaptureOptions plain;
    plain.fillEnclosed = false;
    SourceMap plainMap;
    simulateCapture(frames.back().clothed, plain, &plainMap);
    int plainWithin = 0;
    for (double d : plainMap.distance) plainWithin += d <= plain.voxelSize;
    const double plainFraction = static_cast<double>(plainWithin) / plainMap.distance.size();
    // With it (the default), surfaces that close what cameras cannot see into (the disc under a
    // hem, the gap between a touching arm and the torso) are far from any true surface.
    CaptureOptions capture;
    SourceMap map;
    const TriangleMesh captured = simulateCapture(frames.back().clothed, capture, &map);
    int within = 0;
    for (double d : map.distance) within += d <= capture.voxelSize;
    const double fraction = static_cast<double>(within) / map.distance.size();
    std::printf("[ measured ] %s: %d captured vertices, %.1f %% within one voxel of the truth "
                "(%.1f %% without the "
                "visual-hull fill)\n",
                preset.c_str(), captured.numVertices(), 100 * fraction, 100 * plainFraction);
    EXPECT_GT(plainFraction, 0.99);
    EXPECT_GT(fraction, 0.85);
  }
}

TEST(SyntheticSequence, StatureSetsTheBodysHeight)
{
  for (double stature : {1.52, 1.95})
  {
    SyntheticOptions options;
    options.frames = 1;
    options.stature = stature;
    Eigen::VectorXd beta =
        generateSyntheticSequence(builtinBodyModel(), options, [](const SyntheticFrame&) {});
    EXPECT_NEAR(restHeight(builtinBodyModel(), beta), stature, 0.001);
  }
}

TEST(SyntheticSequence, BadOptionsAreErrors)
{
  SyntheticOptions options;
  options.preset = "kilt-jog";
  EXPECT_THROW(run(options), Error);
  options.preset = "dress-walk";
  options.frames = 0;
  EXPECT_THROW(run(options), Error);
  options.frames = 1;
  options.stature = 2.6; // beyond the body model's shape space
  EXPECT_THROW(run(options), Error);
}
