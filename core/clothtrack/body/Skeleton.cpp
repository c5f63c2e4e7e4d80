#include "Skeleton.h"

namespace clothtrack
{
const std::array<const char*, NumJoints>& jointNames()
{
  static const std::array<const char*, NumJoints> names = {
      "pelvis",         "spine1",         "spine2",        "spine3",      "neck",
      "head",           "left_clavicle",  "left_shoulder", "left_elbow",  "left_wrist",
      "right_clavicle", "right_shoulder", "right_elbow",   "right_wrist", "left_hip",
      "left_knee",      "left_ankle",     "left_toe",      "right_hip",   "right_knee",
      "right_ankle",    "right_toe"};
  return names;
}

const std::array<int, NumJoints>& jointParents()
{
  static const std::array<int, NumJoints> parents = {
      -1,           Pelvis,       Spine1,    Spine2,    Spine3,        Neck,          Spine3,
      LeftClavicle, LeftShoulder, LeftElbow, Spine3,    RightClavicle, RightShoulder, RightElbow,
      Pelvis,       LeftHip,      LeftKnee,  LeftAnkle, Pelvis,        RightHip,      RightKnee,
      RightAnkle};
  return parents;
}

void setInnerBoneEnds(SkeletonGeometry& skeleton)
{
  const auto& parents = jointParents();
  std::array<bool, NumJoints> done{};
  for (int j = 1; j < NumJoints; ++j)
  {
    const int p = parents[j];
    // The chest and the pelvis have several children: their bones follow the spine.
    const bool branch = (p == Spine3 && j != Neck) || (p == Pelvis && j != Spine1);
    if (!done[p] && !branch)
    {
      skeleton.boneEnds.row(p) = skeleton.joints.row(j);
      done[p] = true;
    }
  }
}
} // namespace clothtrack
