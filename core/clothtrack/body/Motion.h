#pragma once
// Procedural motions as joint-angle curves over time, for the synthetic captures. Rotations
// follow BodyPose: axis-angle in world axes at rest (A-pose, facing +Z, left on +X). Feet are
// not pinned here: groundedPose() in BodyModel users lifts or lowers the body onto the floor.
#include "BodyModel.h"

#include <string>
#include <vector>

namespace clothtrack
{
enum class MotionType
{
  Walk,       ///< walking forward along +Z, arms swinging
  Turn,       ///< turning on the spot, one full turn every 4 s, small steps
  Squat,      ///< squats every 3 s, arms forward
  ArmRaise,   ///< arms from hanging against the body to overhead and back, every 3 s
  Wave,       ///< right arm raised and waving
  Dance,      ///< a samba-like dance: hip sway, alternating steps, arms in and out
  WalkLoop,   ///< walking a circle of 1 m radius (one full turn every 5 s), knees raised high
  HalfTurns,  ///< quick half-turns (180 degrees in 0.4 s, every 1.2 s), arms swinging out
  CrossedArms ///< standing still, forearms folded across the chest, breathing and a slight sway
};

/// "walk", "turn", "squat", "armraise", "wave", "dance", "walkloop", "halfturns",
/// "crossedarms"; throws Error on anything else.
MotionType motionFromName(const std::string& name);
const std::vector<std::string>& motionNames();

/// Pose at `time` seconds.
BodyPose motionPose(MotionType motion, double time);
} // namespace clothtrack
