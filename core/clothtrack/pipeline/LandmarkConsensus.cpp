#include "LandmarkConsensus.h"

#include <clothtrack/cloud/RigidConsensus.h>

namespace clothtrack
{
LandmarkPairFilter locallyRigidLandmarkFilter(double tolerance, double radius)
{
  if (!(tolerance > 0)) return {};
  return [tolerance, radius](const std::vector<Vec3>& before, const std::vector<Vec3>& after)
  { return locallyRigidPairs(before, after, radius, tolerance); };
}

StartPrediction landmarkStartPrediction(
    const std::function<FramePtr(int)>& frames,
    const std::function<const std::vector<OrientedSurfacePoint>&(int)>& landmarks,
    const StartPredictionOptions& options)
{
  return landmarkStartPrediction(
      frames, landmarks, options.predictRadius,
      locallyRigidLandmarkFilter(options.landmarkConsensus, options.predictRadius));
}
} // namespace clothtrack
