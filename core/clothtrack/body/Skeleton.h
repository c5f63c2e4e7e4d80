#pragma once
// The body model's skeleton: 22 joints in a fixed order, Y up, the person facing +Z, their left
// on +X. Each joint's bone runs from the joint to its first child (or to its end point).
#include <clothtrack/mesh/TriangleMesh.h>

#include <array>
#include <string>
#include <vector>

namespace clothtrack
{
enum Joint : int
{
  Pelvis,
  Spine1,
  Spine2,
  Spine3,
  Neck,
  Head,
  LeftClavicle,
  LeftShoulder,
  LeftElbow,
  LeftWrist,
  RightClavicle,
  RightShoulder,
  RightElbow,
  RightWrist,
  LeftHip,
  LeftKnee,
  LeftAnkle,
  LeftToe,
  RightHip,
  RightKnee,
  RightAnkle,
  RightToe,
  NumJoints
};

/// Name of each joint ("pelvis", "left_elbow", ...).
const std::array<const char*, NumJoints>& jointNames();
/// Parent of each joint (-1 for the pelvis).
const std::array<int, NumJoints>& jointParents();

/// Joint positions (NumJoints x 3) plus the end points of the leaf bones (head top, hand tips,
/// toe tips), which give every joint a bone to skin against.
struct SkeletonGeometry
{
  Points joints = Points::Zero(NumJoints, 3);
  /// End of the bone of each joint: its child's position, or the leaf's end point.
  Points boneEnds = Points::Zero(NumJoints, 3);
};

/// Sets the end of every inner bone to the child that continues it (the pelvis's to spine1, each
/// vertebra's to the next, a clavicle's to its shoulder, a limb segment's to the next joint).
/// Leaf bones (head, wrists, toes) keep the ends they have.
void setInnerBoneEnds(SkeletonGeometry& skeleton);
} // namespace clothtrack
