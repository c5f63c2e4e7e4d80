// Frames of one sequence at one scale in one place: a frame in another unit is refused, one of
// another size or place is flagged, and a ground truth of another scale is refused.
#include <clothtrack/mesh/FrameConsistency.h>
#include <clothtrack/mesh/Primitives.h>

#include <gtest/gtest.h>

using namespace clothtrack;

namespace
{
/// A standing person's bounding box (0.5 x 1.75 x 0.3 m), its feet on the floor at `x`.
TriangleMesh person(double x = 0.0, double scale = 1.0)
{
  TriangleMesh mesh = icosphere(2);
  mesh.V.col(0) = mesh.V.col(0) * 0.25 * scale + Eigen::VectorXd::Constant(mesh.numVertices(), x);
  mesh.V.col(1) = (mesh.V.col(1).array() + 1.0) * 0.875 * scale;
  mesh.V.col(2) *= 0.15 * scale;
  return mesh;
}

std::vector<const TriangleMesh*> pointers(const std::vector<TriangleMesh>& frames)
{
  std::vector<const TriangleMesh*> out;
  for (const TriangleMesh& f : frames) out.push_back(&f);
  return out;
}
} // namespace

TEST(FrameConsistency, AWalkingPersonHasNoJump)
{
  std::vector<TriangleMesh> frames;
  for (int k = 0; k < 8; ++k) frames.push_back(person(0.05 * k)); // 5 cm per frame
  EXPECT_TRUE(frameJumps(pointers(frames)).empty());
}

TEST(FrameConsistency, AFrameInMillimetresIsRefusedWithItsUnit)
{
  std::vector<TriangleMesh> frames;
  for (int k = 0; k < 6; ++k) frames.push_back(person(0.05 * k, k == 3 ? 1000.0 : 1.0));
  const std::vector<FrameJump> jumps = frameJumps(pointers(frames));
  ASSERT_EQ(jumps.size(), 1u); // frame 3 alone: its neighbours do not repeat it as a shift
  EXPECT_EQ(jumps[0].frame, 3);
  EXPECT_TRUE(jumps[0].refused);
  EXPECT_NEAR(jumps[0].sizeRatio, 1000.0, 1.0);
  EXPECT_NE(jumps[0].problem.find("a unit 1000 times smaller"), std::string::npos)
      << jumps[0].problem;
}

TEST(FrameConsistency, AFrameOfAnotherSizeOrPlaceIsFlagged)
{
  std::vector<TriangleMesh> frames;
  for (int k = 0; k < 6; ++k) frames.push_back(person(0.05 * k, k == 1 ? 1.8 : 1.0));
  frames[4] = person(3.0); // three metres away from frame 3
  const std::vector<FrameJump> jumps = frameJumps(pointers(frames));
  ASSERT_EQ(jumps.size(), 3u);
  EXPECT_EQ(jumps[0].frame, 1);
  EXPECT_FALSE(jumps[0].refused);
  EXPECT_NEAR(jumps[0].sizeRatio, 1.8, 0.01);
  EXPECT_EQ(jumps[0].problem.find("unit"), std::string::npos); // 1.8 is no unit
  // Frame 4 jumps away and frame 5 back.
  EXPECT_EQ(jumps[1].frame, 4);
  EXPECT_NEAR(jumps[1].shift, 3.0 - 0.15, 1e-9);
  EXPECT_EQ(jumps[2].frame, 5);
  EXPECT_FALSE(jumps[1].refused);
  EXPECT_NE(jumps[1].problem.find("coordinate origin"), std::string::npos);
}

TEST(FrameConsistency, AGroundTruthOfAnotherScaleIsRefused)
{
  bool refused = true;
  EXPECT_EQ(groundTruthMismatch(person(), person(0.01), refused), "");
  EXPECT_FALSE(refused);
  const std::string inCentimetres = groundTruthMismatch(person(), person(0.0, 100.0), refused);
  EXPECT_TRUE(refused);
  EXPECT_NE(inCentimetres.find("a unit 100 times smaller"), std::string::npos) << inCentimetres;
  const std::string larger = groundTruthMismatch(person(), person(0.0, 2.0), refused);
  EXPECT_FALSE(refused);
  EXPECT_NE(larger.find("same subject"), std::string::npos) << larger;
  const std::string elsewhere = groundTruthMismatch(person(), person(2.0), refused);
  EXPECT_FALSE(refused);
  EXPECT_NE(elsewhere.find("lies 2 m from the input frame"), std::string::npos) << elsewhere;
}
