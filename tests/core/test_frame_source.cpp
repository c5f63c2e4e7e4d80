// Frames handed out one at a time: the cache keeps what its budget allows and reads the rest
// again, a frame in use outlives its eviction, binary copies round-trip exactly, and the quality
// of a sequence measured over streamed frames equals the one measured over frames in memory.
#include "TestUtil.h"

#include <clothtrack/base/Error.h>
#include <clothtrack/base/Parallel.h>
#include <clothtrack/eval/SequenceQuality.h>
#include <clothtrack/io/MeshBinary.h>
#include <clothtrack/mesh/FrameSource.h>
#include <clothtrack/mesh/Primitives.h>

#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <filesystem>
#include <fstream>

using namespace clothtrack;

namespace
{
/// A sphere shifted by k centimetres along x: each frame is told apart by its first vertex.
TriangleMesh shiftedSphere(int k)
{
  TriangleMesh mesh = icosphere(2, 0.2);
  mesh.V.col(0).array() += 0.01 * k;
  return mesh;
}

bool isFrame(const TriangleMesh& mesh, int k)
{
  const TriangleMesh expected = shiftedSphere(k);
  return mesh.V == expected.V && mesh.F == expected.F;
}
} // namespace

TEST(FrameSource, ACacheWithinItsBudgetReadsEachFrameOnce)
{
  const std::size_t bytes = meshBytes(shiftedSphere(0));
  CachedFrames frames(5, shiftedSphere, 5 * bytes);
  for (int round = 0; round < 3; ++round)
    for (int k = 0; k < 5; ++k) EXPECT_TRUE(isFrame(*frames.frame(k), k));
  EXPECT_EQ(frames.loads(), 5);
  EXPECT_EQ(frames.peakBytes(), 5 * bytes);
  EXPECT_THROW(frames.frame(5), Error);
  EXPECT_THROW(frames.frame(-1), Error);
}

TEST(FrameSource, PastItsBudgetTheLeastRecentlyUsedFrameIsReadAgain)
{
  const std::size_t bytes = meshBytes(shiftedSphere(0));
  CachedFrames frames(4, shiftedSphere, 2 * bytes);
  frames.frame(0);
  frames.frame(1);
  frames.frame(0); // 1 is now the least recently used
  frames.frame(2); // drops 1
  EXPECT_EQ(frames.loads(), 3);
  frames.frame(0);
  EXPECT_EQ(frames.loads(), 3);
  EXPECT_TRUE(isFrame(*frames.frame(1), 1));
  EXPECT_EQ(frames.loads(), 4);
  EXPECT_LE(frames.peakBytes(), 2 * bytes);
}

TEST(FrameSource, AFrameInUseOutlivesItsEviction)
{
  const std::size_t bytes = meshBytes(shiftedSphere(0));
  CachedFrames frames(3, shiftedSphere, bytes);
  const FramePtr held = frames.frame(0);
  frames.frame(1);
  frames.frame(2); // frame 0 left the cache long ago
  EXPECT_TRUE(isFrame(*held, 0));
  CachedFrames none(3, shiftedSphere, 0); // keeps nothing beyond its use
  none.frame(1);
  none.frame(1);
  EXPECT_EQ(none.loads(), 2);
  EXPECT_EQ(none.peakBytes(), 0u);
}

TEST(FrameSource, AnOfferedFrameIsNotReadAgain)
{
  const std::size_t bytes = meshBytes(shiftedSphere(0));
  CachedFrames frames(3, shiftedSphere, 3 * bytes);
  frames.offer(1, shiftedSphere(1));
  EXPECT_TRUE(isFrame(*frames.frame(1), 1));
  EXPECT_EQ(frames.loads(), 0);
}

TEST(FrameSource, ThreadsGetTheirOwnFrames)
{
  const std::size_t bytes = meshBytes(shiftedSphere(0));
  CachedFrames frames(40, shiftedSphere, 3 * bytes); // far fewer than the threads ask for
  std::atomic<int> wrong{0};
  setThreadCount(4);
  parallelFor(
      0, 400, [&](int i) { wrong += !isFrame(*frames.frame((i * 7) % 40), (i * 7) % 40); }, 1);
  setThreadCount(0);
  EXPECT_EQ(wrong.load(), 0);
  EXPECT_LE(frames.peakBytes(), 3 * bytes);
}

TEST(FrameSource, AFailedReadIsTheCallersError)
{
  CachedFrames frames(
      2, [](int k) -> TriangleMesh { throw Error("frame_" + std::to_string(k) + ".obj: gone"); },
      1 << 20);
  try
  {
    frames.frame(1);
    FAIL() << "no error";
  }
  catch (const Error& e)
  {
    EXPECT_EQ(std::string(e.what()), "frame_1.obj: gone");
  }
}

TEST(MeshBinary, RoundTripsBitForBit)
{
  const std::string dir = test::scratchDir("mesh_binary");
  TriangleMesh mesh = shiftedSphere(3);
  mesh.V(0, 1) = std::nextafter(mesh.V(0, 1), 1.0);
  writeMeshBinary(dir + "/a.bin", mesh);
  const TriangleMesh back = readMeshBinary(dir + "/a.bin");
  EXPECT_TRUE(back.V == mesh.V);
  EXPECT_TRUE(back.F == mesh.F);
  EXPECT_FALSE(std::filesystem::exists(dir + "/a.bin.part"));
}

TEST(MeshBinary, ADamagedFileIsAnErrorNamingIt)
{
  const std::string dir = test::scratchDir("mesh_binary_bad");
  writeMeshBinary(dir + "/a.bin", shiftedSphere(0));
  std::filesystem::resize_file(dir + "/a.bin", std::filesystem::file_size(dir + "/a.bin") - 4);
  auto message = [](const std::string& path)
  {
    try
    {
      readMeshBinary(path);
    }
    catch (const Error& e)
    {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_EQ(message(dir + "/a.bin"), dir + "/a.bin: truncated or damaged binary mesh");
  test::writeText(dir + "/b.bin", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  EXPECT_EQ(message(dir + "/b.bin"), dir + "/b.bin: not a ClothTrack binary mesh");
  EXPECT_EQ(message(dir + "/none.bin"), dir + "/none.bin: cannot be opened");
  TriangleMesh bad = shiftedSphere(0);
  bad.F(3, 2) = bad.numVertices();
  writeMeshBinary(dir + "/c.bin", bad);
  EXPECT_EQ(message(dir + "/c.bin"), dir + "/c.bin: a face index is out of range");
}

TEST(FrameSource, StreamedQualityEqualsQualityInMemory)
{
  // More frames than a block of the streamed measure, so that the jitter crosses blocks.
  const int n = 37;
  const TriangleMesh sphere = icosphere(2, 0.2);
  std::vector<TriangleMesh> frames;
  std::vector<Points> aligned;
  for (int k = 0; k < n; ++k)
  {
    frames.push_back(shiftedSphere(k));
    aligned.push_back(frames.back().V * (1.0 + 0.01 * std::sin(k)));
  }
  std::vector<const TriangleMesh*> framePointers;
  std::vector<const Points*> alignedPointers;
  for (int k = 0; k < n; ++k)
  {
    framePointers.push_back(&frames[k]);
    alignedPointers.push_back(&aligned[k]);
  }
  const SequenceQuality inMemory = sequenceQuality(alignedPointers, sphere.F, framePointers, {}, 4);
  const CachedFrames streamed(n, shiftedSphere, meshBytes(sphere)); // one frame at a time
  const SequenceQuality q =
      sequenceQuality([&](int k) { return aligned[k]; }, sphere.F, streamed, {}, 4);
  EXPECT_EQ(q.surfaceDistance, inMemory.surfaceDistance);
  EXPECT_EQ(q.coverageDistance, inMemory.coverageDistance);
  ASSERT_EQ(q.jitter.size(), static_cast<size_t>(n - 2));
  EXPECT_EQ(q.jitter, inMemory.jitter);
  EXPECT_EQ(q.doubtfulFrames, inMemory.doubtfulFrames);
  EXPECT_GT(q.meanJitter, 0.0);
}

TEST(FrameSource, QualityMeasuredInPartsEqualsTheWhole)
{
  // Three processes measure a part each; one joins them. Frame 20 is pulled off its frame, so
  // that a doubt travels too.
  const int n = 37, parts = 3;
  const TriangleMesh sphere = icosphere(2, 0.2);
  std::vector<Points> aligned;
  for (int k = 0; k < n; ++k)
    aligned.push_back(shiftedSphere(k).V * (k == 20 ? 1.6 : 1.0 + 0.01 * std::sin(k)));
  const CachedFrames frames(n, shiftedSphere, meshBytes(sphere));
  const AlignedAccess access = [&](int k) { return aligned[k]; };
  const SequenceQuality whole = sequenceQuality(access, sphere.F, frames, {}, 4);
  std::vector<std::string> bytes;
  for (int part = 0; part < parts; ++part)
  {
    const auto [from, to] = rangePart(n, part, parts);
    const SequenceQuality q =
        sequenceQualityOfFrames(access, sphere.F, frames, {}, 4, {}, {}, from, to);
    bytes.push_back(encodeSequenceQuality(q, from, to));
  }
  const SequenceQuality joined = joinSequenceQuality(bytes, n);
  EXPECT_EQ(joined.surfaceDistance, whole.surfaceDistance);
  EXPECT_EQ(joined.coverageDistance, whole.coverageDistance);
  EXPECT_EQ(joined.jitter, whole.jitter);
  EXPECT_EQ(joined.meanSurfaceDistance, whole.meanSurfaceDistance);
  EXPECT_EQ(joined.meanCoverageDistance, whole.meanCoverageDistance);
  EXPECT_EQ(joined.meanJitter, whole.meanJitter);
  ASSERT_EQ(whole.doubtfulFrames, std::vector<int>{20});
  EXPECT_EQ(joined.doubtfulFrames, whole.doubtfulFrames);
  ASSERT_EQ(joined.confidence.size(), whole.confidence.size());
  for (int k = 0; k < n; ++k)
  {
    EXPECT_EQ(joined.confidence[k].severity, whole.confidence[k].severity) << k;
    EXPECT_EQ(joined.confidence[k].stretch, whole.confidence[k].stretch) << k;
    EXPECT_EQ(joined.confidence[k].doubt, whole.confidence[k].doubt) << k;
  }
  // Parts out of order, or a part missing, are an error rather than a wrong sequence.
  EXPECT_THROW(joinSequenceQuality({bytes[1], bytes[0], bytes[2]}, n), Error);
  EXPECT_THROW(joinSequenceQuality({bytes[0], bytes[1]}, n), Error);
  EXPECT_THROW(joinSequenceQuality({bytes[0].substr(0, 20), bytes[1], bytes[2]}, n), Error);
}
