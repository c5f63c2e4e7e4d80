#pragma once
// The rigid motion that best carries one point set onto another, by generalized ICP
// (Segal et al. 2009, PCL's GeneralizedIterativeClosestPoint): point-to-plane on both sides,
// which tolerates the points of two captures not being the same surface points.
#include <clothtrack/mesh/TriangleMesh.h>

#include <Eigen/Geometry>

namespace clothtrack
{
struct RigidRegistrationOptions
{
  double voxelSize = 0.02;       ///< both sets thinned to one point per cube of this edge, metres
  double maximumDistance = 0.15; ///< pairs further apart than this are not used, metres
  int maximumIterations = 30;
  double inlierDistance = 0.02; ///< for RigidRegistration::overlap, metres
};

struct RigidRegistration
{
  Eigen::Isometry3d motion = Eigen::Isometry3d::Identity(); ///< source to target
  bool converged = false;
  /// Share of the (thinned) moved source points within inlierDistance of the target: how much
  /// of the motion is explained rigidly.
  double overlap = 0.0;
};

/// Throws Error when either set has fewer than 10 points after thinning.
RigidRegistration registerRigidly(const Points& source, const Points& target,
                                  const RigidRegistrationOptions& options = {});
} // namespace clothtrack
