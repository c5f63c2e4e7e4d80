#pragma once
// The built-in body, described procedurally: a skeleton from anthropometric proportions
// (fractions of stature, after Drillis and Contini) and a closed surface as the zero level set
// of a smooth union of anatomical primitives around it, in an A-pose (arms 45 degrees down, legs
// apart) so that no limb touches the body and the surface is one genus-0 shell.
#include "Skeleton.h"

#include <random>
#include <string>

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

/// Factors on the population's spread of each proportion (1: the built-in model's). A wider
/// spread reaches proportions the built-in shape space lacks (pjump's shoulders and head), at a
/// price: under the one measured a 1.95 m person is fitted 8 cm shorter (BENCHMARKS.md, "A wider
/// shape space").
struct BodySpread
{
  double legLength = 1.0, armLength = 1.0, torsoLength = 1.0, neckLength = 1.0, shoulderWidth = 1.0,
         headSize = 1.0;
};

/// Sets the factor of the proportion `name` (a BodySpread field, e.g. "neckLength"). Throws Error
/// for an unknown name or a factor outside [0, 10].
void setBodySpread(BodySpread& spread, const std::string& name, double factor);

/// A random plausible body: stature and proportions drawn around sex-typical means, with
/// weight acting jointly on the girths.
BodyParameters sampleBodyParameters(std::mt19937& rng, const BodySpread& spread = {});

/// Rest-pose skeleton of the mean body (only stature is used: proportions come from the surface
/// deformation of the body model).
SkeletonGeometry proceduralSkeleton(double stature);

/// Signed distance (approximate, negative inside) of the mean body surface at `p`.
double proceduralBodyDistance(const SkeletonGeometry& skeleton, double stature, const Vec3& p);
} // namespace clothtrack
