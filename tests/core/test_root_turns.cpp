// The body fit's root rotation moved by turns away from a reference, which stays well
// conditioned where the axis-angle vector is singular (a person turned nearly once round).
#include <clothtrack/body/BodyFitPose.h>

#include <gtest/gtest.h>

#include <Eigen/SVD>

#include <cmath>

using namespace clothtrack;
using namespace clothtrack::bodyfit;

namespace
{
/// Smallest singular value of the rotation matrix's derivative by three parameters, the matrix
/// written as nine numbers: how far the least effective unit step turns the body.
template <typename RotationOf> double weakestStep(const RotationOf& rotationOf)
{
  const double h = 1e-6;
  Eigen::Matrix<double, 9, 3> jacobian;
  const Eigen::Matrix3d r0 = rotationOf(Vec3::Zero());
  for (int c = 0; c < 3; ++c)
  {
    const Eigen::Matrix3d d = (rotationOf(h * Vec3::Unit(c)) - r0) / h;
    jacobian.col(c) = Eigen::Map<const Eigen::Matrix<double, 9, 1>>(d.data());
  }
  return Eigen::JacobiSVD<Eigen::Matrix<double, 9, 3>>(jacobian).singularValues().minCoeff();
}
} // namespace

TEST(RootTurns, TurnToAndBackGivesTheSameRotation)
{
  const RootTurns turns{axisAngleToMatrix(Vec3(0.3, 2.9, -0.4))};
  for (const Vec3& root : {Vec3(0.1, -0.2, 0.3), Vec3(0.0, 6.1, 0.0), Vec3(2.0, -1.5, 1.0)})
  {
    const Vec3 back = turns.rootAfter(turns.turnTo(root));
    EXPECT_LE(back.norm(), M_PI + 1e-12);
    EXPECT_LT((axisAngleToMatrix(back) - axisAngleToMatrix(root)).norm(), 1e-9);
  }
  EXPECT_LT(turns.turnTo(turns.rootAfter(Vec3::Zero())).norm(), 1e-9);
}

TEST(RootTurns, StayWellConditionedWhereTheAxisAngleIsSingular)
{
  // Facing 357 degrees round the vertical: a step of the axis-angle vector across its axis
  // barely turns the body, a turn about any world axis turns it fully.
  const Vec3 root(0.0, 2.0 * M_PI - 0.05, 0.0);
  const double axisAngle =
      weakestStep([&](const Vec3& step) { return axisAngleToMatrix(root + step); });
  const RootTurns turns{axisAngleToMatrix(root)};
  const double byTurns =
      weakestStep([&](const Vec3& step) { return axisAngleToMatrix(turns.rootAfter(step)); });
  EXPECT_LT(axisAngle, 0.02);
  EXPECT_NEAR(byTurns, std::sqrt(2.0), 1e-4);
}
