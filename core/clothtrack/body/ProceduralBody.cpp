#include "ProceduralBody.h"

#include <clothtrack/base/Error.h>

#include <algorithm>
#include <cmath>

namespace clothtrack
{
namespace
{
// Polynomial smooth minimum: blends two distances over a band of width k.
double smoothMin(double a, double b, double k)
{
  const double h = std::max(k - std::abs(a - b), 0.0) / k;
  return std::min(a, b) - h * h * k * 0.25;
}

// Cone with rounded ends: radius r1 at a, r2 at b.
double roundCone(const Vec3& p, const Vec3& a, const Vec3& b, double r1, double r2)
{
  const Vec3 ba = b - a;
  const double l2 = ba.squaredNorm();
  const double t = std::clamp((p - a).dot(ba) / l2, 0.0, 1.0);
  // A linear radius along the closest point is close enough for gently tapered limbs.
  return (p - (a + t * ba)).norm() - (r1 + t * (r2 - r1));
}

// Ellipsoid with semi-axes r along the orthonormal frame (u, v, w) centred at c (the usual
// bound approximation of the distance: exact zero set, smooth gradient).
double ellipsoid(const Vec3& p, const Vec3& c, const Vec3& u, const Vec3& v, const Vec3& w,
                 const Vec3& r)
{
  const Vec3 q = p - c;
  const Vec3 local(q.dot(u), q.dot(v), q.dot(w));
  const double k0 = local.cwiseQuotient(r).norm();
  const double k1 = local.cwiseQuotient(r.cwiseProduct(r)).norm();
  return k1 > 0 ? k0 * (k0 - 1.0) / k1 : -r.minCoeff();
}

double axisEllipsoid(const Vec3& p, const Vec3& c, const Vec3& r)
{
  return ellipsoid(p, c, Vec3::UnitX(), Vec3::UnitY(), Vec3::UnitZ(), r);
}

Vec3 J(const SkeletonGeometry& s, int j)
{
  return s.joints.row(j).transpose();
}
Vec3 E(const SkeletonGeometry& s, int j)
{
  return s.boneEnds.row(j).transpose();
}
} // namespace

SkeletonGeometry proceduralSkeleton(double H)
{
  SkeletonGeometry s;
  auto set = [&](int j, double x, double y, double z) { s.joints.row(j) << x * H, y * H, z * H; };
  set(Pelvis, 0, 0.530, -0.005);
  set(Spine1, 0, 0.600, -0.012);
  set(Spine2, 0, 0.670, -0.014);
  set(Spine3, 0, 0.750, -0.012);
  set(Neck, 0, 0.840, -0.010);
  set(Head, 0, 0.885, -0.004);
  const double armAngle = 45.0 * M_PI / 180.0;
  for (int side : {+1, -1})
  {
    const bool left = side > 0;
    const int clavicle = left ? LeftClavicle : RightClavicle,
              shoulder = left ? LeftShoulder : RightShoulder;
    const int elbow = left ? LeftElbow : RightElbow, wrist = left ? LeftWrist : RightWrist;
    set(clavicle, side * 0.020, 0.815, -0.004);
    set(shoulder, side * 0.108, 0.812, -0.010);
    const Vec3 down(side * std::cos(armAngle), -std::sin(armAngle), 0.0);
    s.joints.row(elbow) = s.joints.row(shoulder) + 0.186 * H * down.transpose();
    s.joints.row(wrist) = s.joints.row(elbow) + 0.146 * H * down.transpose();
    s.boneEnds.row(wrist) = s.joints.row(wrist) + 0.100 * H * down.transpose();

    const int hip = left ? LeftHip : RightHip, knee = left ? LeftKnee : RightKnee;
    const int ankle = left ? LeftAnkle : RightAnkle, toe = left ? LeftToe : RightToe;
    set(hip, side * 0.052, 0.500, 0.000);
    set(knee, side * 0.060, 0.285, 0.006);
    set(ankle, side * 0.066, 0.045, -0.010);
    set(toe, side * 0.072, 0.014, 0.085);
    s.boneEnds.row(toe) << side * 0.074 * H, 0.012 * H, 0.112 * H;
  }
  s.boneEnds.row(Head) << 0.0, H, 0.0;
  setInnerBoneEnds(s);
  return s;
}

double proceduralBodyDistance(const SkeletonGeometry& s, double H, const Vec3& p)
{
  // Torso: chest, abdomen, pelvis and buttocks blended widely; the limbs join it with a narrower
  // blend so that they stay distinct.
  const Vec3 ey = Vec3::UnitY(), ez = Vec3::UnitZ();
  double torso = axisEllipsoid(p, J(s, Spine3) + Vec3(0, -0.012 * H, 0.008 * H),
                               Vec3(0.098, 0.092, 0.066) * H);
  torso = smoothMin(
      torso,
      axisEllipsoid(p, J(s, Spine1) + Vec3(0, 0.012 * H, 0.006 * H), Vec3(0.084, 0.082, 0.060) * H),
      0.05 * H);
  torso = smoothMin(
      torso, axisEllipsoid(p, J(s, Pelvis) + Vec3(0, -0.006 * H, 0), Vec3(0.090, 0.066, 0.062) * H),
      0.05 * H);
  for (int side : {+1, -1})
    torso = smoothMin(torso,
                      axisEllipsoid(p, Vec3(side * 0.038 * H, 0.490 * H, -0.028 * H),
                                    Vec3(0.050, 0.056, 0.050) * H),
                      0.03 * H);
  // Neck and head.
  double body = smoothMin(
      torso, roundCone(p, J(s, Neck) - Vec3(0, 0.03 * H, 0), J(s, Head), 0.036 * H, 0.032 * H),
      0.03 * H);
  const Vec3 headCenter = J(s, Head) + Vec3(0, 0.055 * H, 0.012 * H);
  double head = axisEllipsoid(p, headCenter, Vec3(0.052, 0.068, 0.062) * H);
  head = smoothMin(
      head,
      axisEllipsoid(p, headCenter + Vec3(0, -0.045 * H, 0.030 * H), Vec3(0.036, 0.030, 0.030) * H),
      0.02 * H); // jaw
  head = smoothMin(head,
                   roundCone(p, headCenter + Vec3(0, 0.0, 0.058 * H),
                             headCenter + Vec3(0, -0.018 * H, 0.068 * H), 0.006 * H, 0.009 * H),
                   0.01 * H); // nose
  body = smoothMin(body, head, 0.02 * H);

  for (int side : {+1, -1})
  {
    const bool left = side > 0;
    const int clavicle = left ? LeftClavicle : RightClavicle,
              shoulder = left ? LeftShoulder : RightShoulder;
    const int elbow = left ? LeftElbow : RightElbow, wrist = left ? LeftWrist : RightWrist;
    double arm = roundCone(p, J(s, clavicle), J(s, shoulder), 0.030 * H, 0.034 * H);
    arm = smoothMin(arm, roundCone(p, J(s, shoulder), J(s, elbow), 0.033 * H, 0.024 * H), 0.01 * H);
    arm = smoothMin(arm, roundCone(p, J(s, elbow), J(s, wrist), 0.024 * H, 0.016 * H), 0.008 * H);
    // Hand: a flattened ellipsoid (palm facing the body) with a thumb.
    const Vec3 along = (E(s, wrist) - J(s, wrist)).normalized();
    const Vec3 thick = ez.cross(along).normalized() * side; // across the palm's thickness
    const Vec3 across = along.cross(thick).normalized();
    const Vec3 palm = J(s, wrist) + 0.048 * H * along;
    double hand = ellipsoid(p, palm, along, across, thick, Vec3(0.056, 0.026, 0.012) * H);
    hand = smoothMin(hand,
                     roundCone(p, J(s, wrist) + 0.02 * H * along + 0.018 * H * across,
                               J(s, wrist) + 0.06 * H * along + 0.034 * H * across, 0.009 * H,
                               0.007 * H),
                     0.008 * H);
    arm = smoothMin(arm, hand, 0.012 * H);
    body = smoothMin(body, arm, 0.025 * H);

    const int hip = left ? LeftHip : RightHip, knee = left ? LeftKnee : RightKnee;
    const int ankle = left ? LeftAnkle : RightAnkle, toe = left ? LeftToe : RightToe;
    double leg = roundCone(p, J(s, hip) + Vec3(0, 0.01 * H, 0), J(s, knee), 0.054 * H, 0.034 * H);
    const Vec3 shin = J(s, ankle) - J(s, knee);
    leg = smoothMin(leg, roundCone(p, J(s, knee), J(s, ankle), 0.033 * H, 0.020 * H), 0.01 * H);
    leg = smoothMin(leg,
                    axisEllipsoid(p, J(s, knee) + 0.32 * shin + Vec3(0, 0, -0.010 * H),
                                  Vec3(0.031, 0.075, 0.033) * H),
                    0.02 * H); // calf
    // Foot from heel to toe tip, flat sole.
    const Vec3 heel = J(s, ankle) + Vec3(0, -0.018 * H, -0.022 * H);
    const Vec3 tip = E(s, toe);
    const Vec3 footAxis = (tip - heel).normalized();
    const Vec3 footSide = ey.cross(footAxis).normalized();
    const Vec3 footUp = footAxis.cross(footSide).normalized();
    double foot = ellipsoid(p, 0.5 * (heel + tip) + 0.004 * H * ey, footAxis, footSide, footUp,
                            Vec3(0.5 * (tip - heel).norm() + 0.004 * H, 0.029 * H, 0.024 * H));
    foot = smoothMin(foot, roundCone(p, J(s, ankle), heel + 0.02 * H * ey, 0.022 * H, 0.020 * H),
                     0.015 * H);
    foot = std::max(foot, 0.002 * H - p.y()); // the sole
    leg = smoothMin(leg, foot, 0.015 * H);
    body = smoothMin(body, leg, 0.03 * H);
  }
  return body;
}

void setBodySpread(BodySpread& spread, const std::string& name, double factor)
{
  const std::pair<const char*, double*> fields[] = {
      {"legLength", &spread.legLength},         {"armLength", &spread.armLength},
      {"torsoLength", &spread.torsoLength},     {"neckLength", &spread.neckLength},
      {"shoulderWidth", &spread.shoulderWidth}, {"headSize", &spread.headSize}};
  if (!(factor >= 0.0 && factor <= 10.0))
    throw Error("the spread factor of " + name + " must lie in [0, 10] (got " +
                std::to_string(factor) + ")");
  std::string known;
  for (const auto& [fieldName, value] : fields)
  {
    if (name == fieldName)
    {
      *value = factor;
      return;
    }
    known += (known.empty() ? "" : ", ") + std::string(fieldName);
  }
  throw Error("no body proportion named '" + name + "' (" + known + ")");
}

BodyParameters sampleBodyParameters(std::mt19937& rng, const BodySpread& spread)
{
  std::normal_distribution<double> n(0.0, 1.0);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  BodyParameters b;
  const bool female = u(rng) < 0.5;
  // Sex-typical means with some overlap (femininity is a continuous proportion mix).
  b.femininity = std::clamp((female ? 0.8 : 0.2) + 0.12 * n(rng), 0.0, 1.0);
  b.stature = (female ? 1.63 : 1.76) + 0.07 * n(rng);
  const double weight = 0.10 * n(rng); // relative: girths grow together
  const double f = b.femininity - 0.5;
  b.legLength = 1.0 + 0.03 * spread.legLength * n(rng);
  b.armLength = 1.0 + 0.03 * spread.armLength * n(rng);
  b.torsoLength = 1.0 + 0.025 * spread.torsoLength * n(rng);
  b.neckLength = 1.0 + 0.06 * spread.neckLength * n(rng);
  b.shoulderWidth = 1.0 - 0.10 * f + 0.035 * spread.shoulderWidth * n(rng);
  b.hipWidth = 1.0 + 0.08 * f + 0.035 * n(rng);
  b.chestGirth = 1.0 - 0.05 * f + 0.8 * weight + 0.03 * n(rng);
  b.waistGirth = 1.0 - 0.10 * f + 1.3 * weight + 0.04 * n(rng);
  b.hipGirth = 1.0 + 0.08 * f + 0.9 * weight + 0.03 * n(rng);
  b.upperArmGirth = 1.0 - 0.08 * f + 0.9 * weight + 0.04 * n(rng);
  b.forearmGirth = 1.0 - 0.08 * f + 0.6 * weight + 0.03 * n(rng);
  b.thighGirth = 1.0 + 0.04 * f + 0.9 * weight + 0.04 * n(rng);
  b.calfGirth = 1.0 + 0.6 * weight + 0.04 * n(rng);
  b.neckGirth = 1.0 - 0.10 * f + 0.5 * weight + 0.03 * n(rng);
  b.headSize = 1.0 - 0.03 * f + 0.025 * spread.headSize * n(rng);
  b.belly = 1.0 + 2.0 * std::max(weight, -0.05) + 0.05 * n(rng);
  b.bust = 1.0 + 0.5 * f + 0.6 * weight + 0.06 * n(rng);
  return b;
}
} // namespace clothtrack
