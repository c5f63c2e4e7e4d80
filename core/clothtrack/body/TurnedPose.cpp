#include "TurnedPose.h"

#include "BodyFitPose.h"

#include <cmath>

namespace clothtrack
{
int oppositeJoint(int joint)
{
  // The left arm (clavicle to wrist) and the right arm, then the left leg and the right leg, are
  // runs of equal length in the joint order.
  constexpr int armRun = RightClavicle - LeftClavicle, legRun = RightHip - LeftHip;
  if (joint >= LeftClavicle && joint < RightClavicle) return joint + armRun;
  if (joint >= RightClavicle && joint <= RightWrist) return joint - armRun;
  if (joint >= LeftHip && joint < RightHip) return joint + legRun;
  if (joint >= RightHip && joint <= RightToe) return joint - legRun;
  return joint;
}

BodyPose turnedInPlace(const BodyPose& pose, const Points& restJoints)
{
  const Vec3 up = (restJoints.row(Neck) - restJoints.row(Pelvis)).transpose().normalized();
  const Eigen::Matrix3d halfTurn = Eigen::AngleAxisd(M_PI, up).toRotationMatrix();
  BodyPose turned = pose;
  // Rotations are given in the rest pose's world axes: a joint rotation seen from the turned
  // body is the half turn's conjugate, whose axis-angle vector is the half turn of the vector.
  for (int j = 1; j < NumJoints; ++j)
    turned.rotations.row(j) =
        (halfTurn * pose.rotations.row(oppositeJoint(j)).transpose()).transpose();
  const Eigen::Matrix3d root = axisAngleToMatrix(pose.rotations.row(Pelvis).transpose());
  turned.rotations.row(Pelvis) = bodyfit::matrixToAxisAngle(root * halfTurn).transpose();
  return turned;
}
} // namespace clothtrack
