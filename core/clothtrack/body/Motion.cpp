#include "Motion.h"

#include <clothtrack/base/Error.h>

#include <cmath>

namespace clothtrack
{
const std::vector<std::string>& motionNames()
{
  static const std::vector<std::string> names = {
      "walk", "turn", "squat", "armraise", "wave", "dance", "walkloop", "halfturns", "crossedarms"};
  return names;
}

MotionType motionFromName(const std::string& name)
{
  const auto& names = motionNames();
  for (size_t k = 0; k < names.size(); ++k)
    if (names[k] == name) return static_cast<MotionType>(k);
  std::string all;
  for (const auto& n : names) all += (all.empty() ? "" : ", ") + n;
  throw Error("unknown motion '" + name + "' (one of: " + all + ")");
}

namespace
{
void set(BodyPose& p, int joint, double x, double y, double z)
{
  p.rotations.row(joint) << x, y, z;
}

// Arms lowered from the A-pose by `down` radians (about the body's front axis).
void armsDown(BodyPose& p, double down)
{
  set(p, LeftShoulder, 0, 0, -down);
  set(p, RightShoulder, 0, 0, down);
}
} // namespace

BodyPose motionPose(MotionType motion, double t)
{
  BodyPose p;
  const double twoPi = 2 * M_PI;
  switch (motion)
  {
  case MotionType::Walk:
  {
    // Hip flexion is a negative rotation about X (the foot goes forward), knee flexion positive.
    const double phase = twoPi * t / 1.1;
    const double s = std::sin(phase);
    set(p, LeftHip, -0.42 * s, 0, 0);
    set(p, RightHip, 0.42 * s, 0, 0);
    set(p, LeftKnee, 0.05 + 0.6 * std::max(0.0, std::sin(phase + 2.2)), 0, 0);
    set(p, RightKnee, 0.05 + 0.6 * std::max(0.0, std::sin(phase + 2.2 + M_PI)), 0, 0);
    set(p, LeftAnkle, -0.15 * s, 0, 0);
    set(p, RightAnkle, 0.15 * s, 0, 0);
    set(p, LeftShoulder, 0.35 * s, 0, -0.55);
    set(p, RightShoulder, -0.35 * s, 0, 0.55);
    set(p, LeftElbow, -0.25 - 0.15 * std::max(0.0, -s), 0, 0);
    set(p, RightElbow, -0.25 - 0.15 * std::max(0.0, s), 0, 0);
    set(p, Pelvis, 0, 0.12 * s, 0);
    set(p, Spine2, 0, -0.1 * s, 0);
    p.translation = Vec3(0, 0.015 * std::cos(2 * phase), 1.2 * t);
    break;
  }
  case MotionType::Turn:
  {
    const double step = std::sin(twoPi * t / 0.8);
    set(p, Pelvis, 0, twoPi * t / 4.0, 0);
    set(p, LeftHip, -0.2 * std::max(0.0, step), 0, 0);
    set(p, RightHip, -0.2 * std::max(0.0, -step), 0, 0);
    set(p, LeftKnee, 0.4 * std::max(0.0, step), 0, 0);
    set(p, RightKnee, 0.4 * std::max(0.0, -step), 0, 0);
    armsDown(p, 0.45);
    set(p, LeftElbow, -0.4, 0, 0);
    set(p, RightElbow, -0.4, 0, 0);
    break;
  }
  case MotionType::Squat:
  {
    const double s = 0.5 * (1 - std::cos(twoPi * t / 3.0));
    set(p, LeftHip, -1.5 * s, 0, -0.08 * s);
    set(p, RightHip, -1.5 * s, 0, 0.08 * s);
    set(p, LeftKnee, 2.0 * s, 0, 0);
    set(p, RightKnee, 2.0 * s, 0, 0);
    set(p, LeftAnkle, -0.45 * s, 0, 0);
    set(p, RightAnkle, -0.45 * s, 0, 0);
    set(p, Spine1, 0.35 * s, 0, 0);
    set(p, LeftShoulder, -1.2 * s, 0, -0.3 * s);
    set(p, RightShoulder, -1.2 * s, 0, 0.3 * s);
    break;
  }
  case MotionType::ArmRaise:
  {
    // From hanging against the sides (0.75 rad below the A-pose) to overhead (1.3 rad above).
    const double s = 0.5 * (1 - std::cos(twoPi * t / 3.0));
    armsDown(p, 0.75 - 2.05 * s);
    set(p, LeftElbow, -0.15 * (1 - s), 0, 0);
    set(p, RightElbow, -0.15 * (1 - s), 0, 0);
    break;
  }
  case MotionType::Wave:
  {
    set(p, LeftShoulder, 0, 0, -0.7);
    set(p, RightShoulder, 0, 0, -1.25);
    set(p, RightElbow, 0, 0, -0.6 - 0.45 * std::sin(twoPi * t / 0.7));
    set(p, Head, 0, -0.2, 0);
    break;
  }
  case MotionType::Dance:
  {
    const double beat = twoPi * t / 0.9;
    const double s = std::sin(beat), c = std::cos(beat);
    set(p, Pelvis, 0, 0.35 * std::sin(beat / 2), 0.12 * s);
    set(p, Spine2, 0, -0.15 * std::sin(beat / 2), -0.1 * s);
    set(p, LeftHip, -0.35 * std::max(0.0, s), 0, -0.1 * s);
    set(p, RightHip, -0.35 * std::max(0.0, -s), 0, -0.1 * s);
    set(p, LeftKnee, 0.15 + 0.5 * std::max(0.0, s), 0, 0);
    set(p, RightKnee, 0.15 + 0.5 * std::max(0.0, -s), 0, 0);
    // Arms sweep in against the body and out above the shoulders.
    set(p, LeftShoulder, -0.3 * c, 0, -0.6 + 0.9 * std::sin(beat / 2));
    set(p, RightShoulder, 0.3 * c, 0, 0.6 + 0.9 * std::sin(beat / 2));
    set(p, LeftElbow, -0.5 - 0.3 * s, 0, 0);
    set(p, RightElbow, -0.5 + 0.3 * s, 0, 0);
    p.translation = Vec3(0.12 * std::sin(beat / 2), 0, 0.1 * std::sin(beat / 4));
    break;
  }
  case MotionType::WalkLoop:
  {
    // Heading turns with the path: facing +Z at the start, along (sin h, 0, cos h) after.
    const double radius = 1.0, heading = twoPi * t / 5.0;
    const double phase = twoPi * t / 1.0;
    const double s = std::sin(phase);
    set(p, Pelvis, 0, heading, 0);
    // High knee raises: the swinging leg's hip flexes far, its knee folds.
    set(p, LeftHip, -0.95 * std::max(0.0, s) + 0.25 * std::max(0.0, -s), 0, 0);
    set(p, RightHip, -0.95 * std::max(0.0, -s) + 0.25 * std::max(0.0, s), 0, 0);
    set(p, LeftKnee, 0.1 + 1.3 * std::max(0.0, s), 0, 0);
    set(p, RightKnee, 0.1 + 1.3 * std::max(0.0, -s), 0, 0);
    set(p, LeftShoulder, -0.45 * s, 0, -0.55);
    set(p, RightShoulder, 0.45 * s, 0, 0.55);
    set(p, LeftElbow, -0.6, 0, 0);
    set(p, RightElbow, -0.6, 0, 0);
    p.translation = Vec3(radius * (1 - std::cos(heading)), 0.02 * std::cos(2 * phase),
                         radius * std::sin(heading));
    break;
  }
  case MotionType::HalfTurns:
  {
    // Each 1.2 s: 0.4 s of turning by half a turn (smoothstep), then 0.8 s facing still.
    const double period = 1.2, turn = 0.4;
    const double u = std::min(1.0, std::fmod(t, period) / turn);
    const double heading = M_PI * (std::floor(t / period) + u * u * (3 - 2 * u));
    const double spin = std::sin(M_PI * u); // arms fly out while turning
    set(p, Pelvis, 0, heading, 0);
    set(p, LeftHip, -0.25 * spin, 0, -0.05);
    set(p, RightHip, 0, 0, 0.05);
    set(p, LeftKnee, 0.1 + 0.5 * spin, 0, 0);
    set(p, RightKnee, 0.1, 0, 0);
    armsDown(p, 0.6 - 0.9 * spin);
    set(p, LeftElbow, -0.8 * (1 - spin), 0, 0);
    set(p, RightElbow, -0.8 * (1 - spin), 0, 0);
    break;
  }
  case MotionType::CrossedArms:
  {
    // Upper arms hang against the sides, forearms folded forward and turned in across the chest.
    const double breath = std::sin(twoPi * t / 3.5);
    set(p, LeftShoulder, -0.1, -1.5, -0.7);
    set(p, RightShoulder, -0.1, 1.5, 0.7);
    set(p, LeftElbow, -2.1 - 0.05 * breath, 0, 0);
    set(p, RightElbow, -2.1 - 0.05 * breath, 0, 0);
    set(p, Spine2, 0.03 * breath, 0, 0);
    set(p, Pelvis, 0, 0.08 * std::sin(twoPi * t / 6.0), 0.02 * breath);
    break;
  }
  }
  return p;
}
} // namespace clothtrack
