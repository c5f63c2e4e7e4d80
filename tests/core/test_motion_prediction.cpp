#include <clothtrack/base/Error.h>
#include <clothtrack/fit/MotionPrediction.h>
#include <clothtrack/mesh/Primitives.h>

#include <Eigen/Geometry>
#include <gtest/gtest.h>

using namespace clothtrack;

TEST(MotionPrediction, ARigidMotionOfTheLandmarksMovesEveryPointRigidly)
{
  const TriangleMesh sphere = icosphere(2, 0.5);
  const Eigen::Matrix3d R =
      Eigen::AngleAxisd(0.7, Vec3(0.2, 1.0, 0.1).normalized()).toRotationMatrix();
  const Vec3 t(0.3, -0.1, 0.05);
  std::vector<Vec3> before, after;
  for (int v = 0; v < sphere.numVertices(); v += 7)
  {
    before.push_back(sphere.vertex(v));
    after.push_back(R * sphere.vertex(v) + t);
  }
  const Points moved = predictMotion(sphere.V, before, after, 0.3);
  for (int v = 0; v < sphere.numVertices(); ++v)
    EXPECT_LT((moved.row(v).transpose() - (R * sphere.vertex(v) + t)).norm(), 1e-9) << v;
}

TEST(MotionPrediction, EachRegionFollowsItsOwnLandmarks)
{
  // Two arms 1 m apart: the left one moves up 10 cm, the right one turns about its own centre.
  std::vector<Vec3> before, after;
  const Eigen::Matrix3d turn = Eigen::AngleAxisd(0.5, Vec3::UnitZ()).toRotationMatrix();
  const Vec3 rightCentre(1.0, 0.0, 0.0);
  for (int k = 0; k < 4; ++k)
  {
    const Vec3 offset(0.05 * (k % 2), 0.05 * (k / 2), 0.02 * k);
    before.push_back(offset);
    after.push_back(offset + Vec3(0, 0.1, 0));
    before.push_back(rightCentre + offset);
    after.push_back(rightCentre + turn * offset);
  }
  Points points(2, 3);
  points.row(0) << 0.02, 0.02, 0.03;
  points.row(1) << 1.02, 0.02, 0.03;
  const Points moved = predictMotion(points, before, after, 0.15);
  EXPECT_LT((moved.row(0) - (points.row(0) + Eigen::RowVector3d(0, 0.1, 0))).norm(), 1e-6);
  const Vec3 expected = rightCentre + turn * (points.row(1).transpose() - rightCentre);
  EXPECT_LT((moved.row(1).transpose() - expected).norm(), 1e-6);
}

TEST(MotionPrediction, FewLandmarksTranslateAndBadInputIsAnError)
{
  Points points = Points::Zero(3, 3);
  points.row(1) << 1, 0, 0;
  EXPECT_TRUE(predictMotion(points, {}, {}).isApprox(points));
  const Points shifted =
      predictMotion(points, {Vec3(0, 0, 0), Vec3(1, 0, 0)}, {Vec3(0, 0.2, 0), Vec3(1, 0.4, 0)});
  EXPECT_LT((shifted.row(1) - Eigen::RowVector3d(1, 0.3, 0)).norm(), 1e-12);
  EXPECT_THROW(predictMotion(points, {Vec3::Zero()}, {}), Error);
  EXPECT_THROW(predictMotion(points, {Vec3::Zero()}, {Vec3::Zero()}, 0.0), Error);
}
