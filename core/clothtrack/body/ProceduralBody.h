#pragma once
// The built-in body, described procedurally: a skeleton from anthropometric proportions
// (fractions of stature, after Drillis and Contini) and a closed surface as the zero level set
// of a smooth union of anatomical primitives around it, in an A-pose (arms 45 degrees down, legs
// apart) so that no limb touches the body and the surface is one genus-0 shell.
#include "Skeleton.h"

#include <random>

namespace clothtrack
{
/// Shape parameters of a procedural body. Lengths in metres; the factors are 1 for the mean body.
struct BodyParameters
{
  double stature = 1.72;
  /// 0 = male-typical, 1 = female-typical proportions (shoulders, hips, waist, chest).
  double femininity = 0.5;
  double legLength = 1.0, armLength = 1.0, torsoLength = 1.0, neckLength = 1.0;
  double shoulderWidth = 1.0, hipWidth = 1.0;
  double chestGirth = 1.0, waistGirth = 1.0, hipGirth = 1.0;
  double upperArmGirth = 1.0, forearmGirth = 1.0, thighGirth = 1.0, calfGirth = 1.0,
         neckGirth = 1.0;
  double headSize = 1.0;
  /// Anterior protrusion of the abdomen (weight) and of the chest (female-typical bust).
  double belly = 1.0, bust = 1.0;
};

/// A random plausible body: stature and proportions drawn around sex-typical means, with
/// weight acting jointly on the girths.
BodyParameters sampleBodyParameters(std::mt19937& rng);

/// Rest-pose skeleton of the mean body (only stature is used: proportions come from the surface
/// deformation of the body model).
SkeletonGeometry proceduralSkeleton(double stature);

/// Signed distance (approximate, negative inside) of the mean body surface at `p`.
double proceduralBodyDistance(const SkeletonGeometry& skeleton, double stature, const Vec3& p);
} // namespace clothtrack
