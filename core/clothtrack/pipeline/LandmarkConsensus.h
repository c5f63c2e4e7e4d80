#pragma once
// The start prediction's landmark pairs checked by random sample consensus: a landmark carried
// onto the wrong limb of one frame moves unlike its neighbours and would bend the locally rigid
// motion that moves the neighbour's fit (fit/MotionPrediction.h).
#include <clothtrack/fit/MotionPrediction.h>

namespace clothtrack
{
/// The pairs that the rigid motion of the pairs within `radius` carries within `tolerance`
/// (cloud/RigidConsensus.h, locallyRigidPairs; metres). Empty for a tolerance of 0.
LandmarkPairFilter locallyRigidLandmarkFilter(double tolerance, double radius);

/// landmarkStartPrediction over options.predictRadius, its pairs filtered by
/// locallyRigidLandmarkFilter(options.landmarkConsensus, options.predictRadius).
StartPrediction landmarkStartPrediction(
    const std::function<FramePtr(int)>& frames,
    const std::function<const std::vector<OrientedSurfacePoint>&(int)>& landmarks,
    const StartPredictionOptions& options);
} // namespace clothtrack
