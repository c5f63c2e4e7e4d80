// Rigid motion between point sets with PCL: generalized ICP recovers a known motion of an
// asymmetric shape, RANSAC keeps the pairs that follow one motion and drops the rest, and the
// start prediction leaves a stray landmark out with it.
#include <clothtrack/base/Error.h>
#include <clothtrack/cloud/RigidConsensus.h>
#include <clothtrack/cloud/RigidRegistration.h>
#include <clothtrack/mesh/Primitives.h>
#include <clothtrack/mesh/SurfacePoint.h>
#include <clothtrack/pipeline/LandmarkConsensus.h>

#include <gtest/gtest.h>

#include <cmath>
#include <random>

using namespace clothtrack;

namespace
{
/// A ring with a ball beside it: no rotation maps it onto itself.
Points asymmetricShape()
{
  return concatenate(torus(0.3, 0.08, 48, 16), icosphere(3, 0.12, Vec3(0.45, 0.2, 0.0))).V;
}

Eigen::Isometry3d knownMotion(double degrees, const Vec3& axis, const Vec3& shift)
{
  Eigen::Isometry3d m = Eigen::Isometry3d::Identity();
  m.linear() = Eigen::AngleAxisd(degrees * M_PI / 180.0, axis.normalized()).toRotationMatrix();
  m.translation() = shift;
  return m;
}

Points moved(const Points& points, const Eigen::Isometry3d& motion)
{
  Points out(points.rows(), 3);
  for (long i = 0; i < points.rows(); ++i)
    out.row(i) = (motion * Vec3(points.row(i).transpose())).transpose();
  return out;
}

double angleBetween(const Eigen::Isometry3d& a, const Eigen::Isometry3d& b)
{
  return Eigen::AngleAxisd(a.linear().transpose() * b.linear()).angle() * 180.0 / M_PI;
}
} // namespace

TEST(RigidRegistration, RecoversAKnownTurnAndShift)
{
  const Points source = asymmetricShape();
  const Eigen::Isometry3d truth = knownMotion(20.0, Vec3(0.1, 1, 0), Vec3(0.04, -0.02, 0.05));
  Points target = moved(source, truth);
  std::mt19937 rng(5);
  std::normal_distribution<double> noise(0.0, 0.002);
  for (long i = 0; i < target.rows(); ++i)
    for (int c = 0; c < 3; ++c) target(i, c) += noise(rng);
  const RigidRegistration r = registerRigidly(source, target);
  EXPECT_TRUE(r.converged);
  EXPECT_LT(angleBetween(r.motion, truth), 1.0);
  EXPECT_LT((r.motion.translation() - truth.translation()).norm(), 0.01);
  EXPECT_GT(r.overlap, 0.9);
}

TEST(RigidRegistration, OverlapTellsAPartialMatch)
{
  // The ball is missing on the target: a rigid motion explains only the ring's points.
  const Points ring = torus(0.3, 0.08, 48, 16).V;
  const RigidRegistration r = registerRigidly(asymmetricShape(), ring);
  EXPECT_LT(r.overlap, 0.9);
  EXPECT_GT(r.overlap, 0.3);
}

TEST(RigidRegistration, RefusesTooFewPoints)
{
  Points few(4, 3);
  few << 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1;
  try
  {
    registerRigidly(few, asymmetricShape());
    FAIL() << "no error";
  }
  catch (const Error& e)
  {
    EXPECT_NE(std::string(e.what()).find("source has 4 points"), std::string::npos) << e.what();
  }
}

TEST(RigidConsensus, DropsPairsThatFollowAnotherMotion)
{
  std::mt19937 rng(9);
  std::uniform_real_distribution<double> u(-0.5, 0.5);
  const Eigen::Isometry3d truth = knownMotion(15.0, Vec3(0, 1, 0.2), Vec3(0.1, 0.0, -0.03));
  std::vector<Vec3> before, after;
  for (int i = 0; i < 30; ++i)
  {
    before.emplace_back(u(rng), 2.0 * u(rng), u(rng));
    after.push_back(truth * before.back());
  }
  // A third of as many again moved 30 cm further: landmarks carried onto the wrong limb.
  for (int i = 0; i < 10; ++i)
  {
    before.emplace_back(u(rng), 2.0 * u(rng), u(rng));
    after.push_back(truth * before.back() + Vec3(0.3, 0.0, 0.0));
  }
  const RigidConsensus c = rigidConsensus(before, after, 0.02);
  ASSERT_TRUE(c.found);
  EXPECT_EQ(c.inliers, 30);
  for (int i = 0; i < 40; ++i) EXPECT_EQ(c.inlier[i], i < 30) << i;
  EXPECT_LT(angleBetween(c.motion, truth), 0.1);
  EXPECT_LT((c.motion.translation() - truth.translation()).norm(), 1e-3);
}

TEST(RigidConsensus, NeedsThreePairsOfEqualLists)
{
  const std::vector<Vec3> two = {Vec3(0, 0, 0), Vec3(1, 0, 0)};
  const RigidConsensus c = rigidConsensus(two, two, 0.01);
  EXPECT_FALSE(c.found);
  EXPECT_EQ(c.inlier, std::vector<bool>(2, false));
  EXPECT_THROW(rigidConsensus(two, {Vec3::Zero()}, 0.01), Error);
}

TEST(LandmarkConsensus, KeepsALandmarkOnTheWrongSideOutOfThePrediction)
{
  // Frame b is frame a moved 10 cm; one landmark of b was carried to the far side of the
  // sphere. Unfiltered, it bends the predicted motion around it; with consensus, every point
  // moves by exactly the 10 cm.
  TriangleMesh a = icosphere(2, 0.5);
  TriangleMesh b = a;
  const Vec3 shift(0.0, 0.1, 0.0);
  b.V.rowwise() += shift.transpose();
  std::vector<OrientedSurfacePoint> onA, onB;
  for (int f = 0, id = 0; f < a.numFaces(); f += 2, ++id)
  {
    OrientedSurfacePoint p;
    p.id = id;
    p.face = f;
    p.bary = Vec3(1, 0, 0);
    onA.push_back(p);
    onB.push_back(p);
  }
  const Vec3 strayAt = a.vertex(a.F(onA[5].face, 0));
  int farthest = 0;
  for (int f = 0; f < a.numFaces(); ++f)
    if ((a.vertex(a.F(f, 0)) - strayAt).norm() > (a.vertex(a.F(farthest, 0)) - strayAt).norm())
      farthest = f;
  onB[5].face = farthest;

  StartPredictionOptions options;
  auto frames = [&](int k) { return borrowedFrame(k == 0 ? a : b); };
  auto landmarks = [&](int k) -> const std::vector<OrientedSurfacePoint>&
  { return k == 0 ? onA : onB; };
  auto largestError = [&](const Points& moved)
  { return (moved.rowwise() - shift.transpose() - a.V).rowwise().norm().maxCoeff(); };

  const Points plain = landmarkStartPrediction(frames, landmarks, options)(1, 0, a.V);
  options.landmarkConsensus = 0.02;
  const Points filtered = landmarkStartPrediction(frames, landmarks, options)(1, 0, a.V);
  EXPECT_GT(largestError(plain), 0.02);
  EXPECT_LT(largestError(filtered), 1e-6);
}
