#pragma once
// Which point pairs agree with one rigid motion: random sample consensus (PCL's
// RandomSampleConsensus over SampleConsensusModelRegistration). Three pairs fix a motion; the
// motion that the most pairs follow within a tolerance wins, and is refined on them.
#include <clothtrack/mesh/TriangleMesh.h>

#include <Eigen/Geometry>

#include <vector>

namespace clothtrack
{
struct RigidConsensus
{
  Eigen::Isometry3d motion = Eigen::Isometry3d::Identity(); ///< before to after
  std::vector<bool> inlier;                                 ///< one per pair
  int inliers = 0;
  bool found = false; ///< false with fewer than 3 pairs or when every sample was degenerate
};

/// Pairs (before[i], after[i]) that the best rigid motion carries within `tolerance` (metres).
/// Deterministic (a fixed seed). Throws Error when the two lists differ in length.
RigidConsensus rigidConsensus(const std::vector<Vec3>& before, const std::vector<Vec3>& after,
                              double tolerance, int maximumIterations = 1000);

/// Pairs that agree with the rigid motion of their surroundings, for a motion that is rigid only
/// piecewise (a body's limbs): pair i is kept when rigidConsensus over the pairs whose `before`
/// lies within `radius` of before[i] counts it an inlier. Pairs with fewer than `minimumPairs`
/// such neighbours (itself included) cannot be judged and are kept.
std::vector<bool> locallyRigidPairs(const std::vector<Vec3>& before, const std::vector<Vec3>& after,
                                    double radius, double tolerance, int minimumPairs = 5);
} // namespace clothtrack
