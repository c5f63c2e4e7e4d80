#pragma once
// The pose as the body fit's parameter vector, and the priors on it. Internal to the body fit
// (BodyFit.cpp).
#include "BodyFit.h"

#include <Eigen/Geometry>

#include <array>
#include <cmath>

namespace clothtrack::bodyfit
{
inline constexpr int kNumExtremities = 5;
/// The joint each extremity hangs from: it cannot be further from it than in the rest pose.
inline constexpr std::array<int, kNumExtremities> kExtremityRoots = {
    Neck, LeftShoulder, RightShoulder, LeftHip, RightHip};
inline constexpr int kPoseParameters = NumJoints * 3 + 3;
inline constexpr double kStep = 1e-5; // finite-difference step (radians, metres, beta units)

/// Prior weight of each rotation parameter (x, y, z about the rest-pose axes; y is the twist
/// of a limb pointing down). Joints get the stiffness of their anatomy: knees are hinges, hips
/// bend forward far but barely twist; spine joints, clavicles, ankles and toes move little. Without
/// that, legs inside wide trousers or a dress are free to cross, twist or splay, which fits the
/// cloth as well as straight legs but is lost a few frames later.
inline Eigen::VectorXd jointPriorWeights(const BodyFitOptions& options)
{
  Eigen::VectorXd w = Eigen::VectorXd::Constant(kPoseParameters, options.posePriorWeight);
  auto stiffen = [&](int joint, double x, double y, double z)
  {
    w[3 * joint] *= x;
    w[3 * joint + 1] *= y;
    w[3 * joint + 2] *= z;
  };
  const double hinge = options.hingeStiffness;
  for (int hip : {LeftHip, RightHip}) stiffen(hip, 1.0, 0.1 * hinge, 0.03 * hinge);
  for (int knee : {LeftKnee, RightKnee}) stiffen(knee, 1.0, hinge, hinge);
  for (int ankle : {LeftAnkle, RightAnkle}) stiffen(ankle, 1.0, 0.1 * hinge, 0.1 * hinge);
  for (int toe : {LeftToe, RightToe}) stiffen(toe, 0.1 * hinge, 0.1 * hinge, 0.1 * hinge);
  // Each spine joint bends a little; a large bend there trades against the pelvis tilting
  // (under wide trousers a forward-tilted pelvis with a back-bent spine fits a squat too).
  for (int spine : {Spine1, Spine2, Spine3}) stiffen(spine, 0.1 * hinge, 0.1 * hinge, 0.1 * hinge);
  for (int clavicle : {LeftClavicle, RightClavicle})
    stiffen(clavicle, 0.1 * hinge, 0.1 * hinge, 0.1 * hinge);
  for (int wrist : {LeftWrist, RightWrist})
    stiffen(wrist, 0.03 * hinge, 0.03 * hinge, 0.03 * hinge);
  w.head<3>().setZero(); // the root turns freely
  w.tail<3>().setZero(); // translation
  return w;
}

/// Rotation parameters of the knees' bend, which is never negative (no knee bends backwards).
inline constexpr std::array<int, 2> kHingeBends = {3 * LeftKnee, 3 * RightKnee};

/// Angle (0 to pi) between the directions two poses face, seen along `up`.
inline double headingChange(const BodyPose& a, const BodyPose& b, const Vec3& up)
{
  const Vec3 u = up.normalized();
  auto facing = [&u](const BodyPose& pose)
  {
    const Vec3 f = axisAngleToMatrix(pose.rotations.row(Pelvis).transpose()) * Vec3::UnitZ();
    return Vec3(f - f.dot(u) * u);
  };
  const Vec3 fa = facing(a), fb = facing(b);
  return std::atan2(fa.cross(fb).norm(), fa.dot(fb));
}

/// Axis-angle vector of a rotation matrix, with an angle of at most pi.
inline Vec3 matrixToAxisAngle(const Eigen::Matrix3d& rotation)
{
  const Eigen::AngleAxisd a(rotation);
  return a.angle() * a.axis();
}

/// The root's rotation as a turn about world axes away from a reference rotation. An axis-angle
/// vector is singular near an angle of 2 pi: every vector of that length is the identity, so a
/// person who has turned nearly once round is tracked by steps that barely move the body, and
/// the fit lags through the next turn. A turn away from the current rotation is well conditioned
/// wherever the body faces.
struct RootTurns
{
  Eigen::Matrix3d reference;

  /// The root's axis-angle vector after `turn`.
  Vec3 rootAfter(const Vec3& turn) const
  {
    return matrixToAxisAngle(axisAngleToMatrix(turn) * reference);
  }
  /// The turn that brings the reference to the root rotation `root`.
  Vec3 turnTo(const Vec3& root) const
  {
    return matrixToAxisAngle(axisAngleToMatrix(root) * reference.transpose());
  }
};

inline Eigen::VectorXd toVector(const BodyPose& pose)
{
  Eigen::VectorXd x(kPoseParameters);
  for (int j = 0; j < NumJoints; ++j) x.segment<3>(3 * j) = pose.rotations.row(j).transpose();
  x.tail<3>() = pose.translation;
  return x;
}

inline BodyPose toPose(const Eigen::VectorXd& x)
{
  BodyPose pose;
  for (int j = 0; j < NumJoints; ++j) pose.rotations.row(j) = x.segment<3>(3 * j).transpose();
  pose.translation = x.tail<3>();
  return pose;
}

} // namespace clothtrack::bodyfit
