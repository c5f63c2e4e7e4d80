// A body pose turned half round in place (turnedInPlace): the start from which a fit left facing
// backwards is fitted again.
#include "ctBuiltinBodyModel.h"

#include <clothtrack/body/BodyFitPose.h>
#include <clothtrack/body/TurnedPose.h>
#include <clothtrack/mesh/PointIndex.h>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

using namespace clothtrack;

namespace
{
/// Mean distance from each point of `a` to the nearest of `b`, and back, halved.
double meanGap(const Points& a, const Points& b)
{
  const PointIndex indexA(a), indexB(b);
  double sum = 0;
  for (int i = 0; i < a.rows(); ++i) sum += indexB.nearest(a.row(i).transpose()).distance;
  for (int i = 0; i < b.rows(); ++i) sum += indexA.nearest(b.row(i).transpose()).distance;
  return sum / (a.rows() + b.rows());
}

/// Arms and legs apart and bent unequally, the spine bent and twisted, turned to a heading.
BodyPose asymmetricPose()
{
  BodyPose pose;
  pose.rotations.row(Pelvis) << 0.1, 0.8, -0.05;
  pose.rotations.row(Spine1) << 0.3, 0.2, 0.1;
  pose.rotations.row(LeftShoulder) << -0.6, 0.3, 1.0;
  pose.rotations.row(LeftElbow) << -1.2, 0, 0;
  pose.rotations.row(RightShoulder) << 0.4, -0.2, -0.5;
  pose.rotations.row(RightElbow) << -0.4, 0, 0;
  pose.rotations.row(LeftHip) << -1.1, 0.1, 0.2;
  pose.rotations.row(LeftKnee) << 1.3, 0, 0;
  pose.rotations.row(RightHip) << 0.2, -0.1, -0.3;
  pose.translation << 0.2, 0.0, -0.1;
  return pose;
}
} // namespace

TEST(TurnedPose, OppositeJointsPairLeftWithRight)
{
  EXPECT_EQ(oppositeJoint(LeftClavicle), RightClavicle);
  EXPECT_EQ(oppositeJoint(RightWrist), LeftWrist);
  EXPECT_EQ(oppositeJoint(LeftHip), RightHip);
  EXPECT_EQ(oppositeJoint(RightToe), LeftToe);
  EXPECT_EQ(oppositeJoint(Neck), Neck);
  EXPECT_EQ(oppositeJoint(Pelvis), Pelvis);
  for (int j = 0; j < NumJoints; ++j) EXPECT_EQ(oppositeJoint(oppositeJoint(j)), j);
}

TEST(TurnedPose, FacesTheOtherWayOverTheSameSurface)
{
  const BodyModel& model = builtinBodyModel();
  const Eigen::VectorXd beta = Eigen::VectorXd::Zero(model.numShapeComponents());
  const BodyPose pose = asymmetricPose();
  const BodyPose turned = turnedInPlace(pose, model.joints);
  const Points body = model.posed(beta, pose).V;
  const double inPlace = meanGap(body, model.posed(beta, turned).V);

  // The same body turned rigidly half round about the up axis through its centre, for scale.
  const Vec3 centre = body.colwise().mean().transpose();
  const Eigen::Matrix3d halfTurn = Eigen::AngleAxisd(M_PI, Vec3::UnitY()).toRotationMatrix();
  const Points rigid =
      ((body.rowwise() - centre.transpose()) * halfTurn.transpose()).rowwise() + centre.transpose();
  const double rigidly = meanGap(body, rigid);
  const double heading = bodyfit::headingChange(pose, turned, Vec3::UnitY());
  std::printf("[ measured ] turned in place: %.1f degrees, surface gap %.2f cm (turned rigidly "
              "%.2f cm)\n",
              heading * 180 / M_PI, 100 * inPlace, 100 * rigidly);
  EXPECT_GT(heading, M_PI - 0.05);
  EXPECT_LT(inPlace, 0.025);
  EXPECT_LT(inPlace, 0.2 * rigidly);

  // Turned twice, the pose itself.
  const BodyPose back = turnedInPlace(turned, model.joints);
  for (int j = 0; j < NumJoints; ++j)
    EXPECT_LT((axisAngleToMatrix(back.rotations.row(j).transpose()) -
               axisAngleToMatrix(pose.rotations.row(j).transpose()))
                  .norm(),
              1e-9)
        << "joint " << j;
  EXPECT_LT((back.translation - pose.translation).norm(), 1e-12);
}
