#pragma once
// A start for fitting the next frame that already follows the gross motion: the landmarks seen
// on both frames give, around every point, a rigid motion (least squares, Gaussian weights of the
// landmarks' distance to the point), which moves the point. Fast turns and swings, which a fit
// started from the previous frame's shape must otherwise catch up with, are then mostly done.
#include "SequenceFit.h"

#include <clothtrack/mesh/SurfacePoint.h>
#include <clothtrack/mesh/TriangleMesh.h>

#include <limits>
#include <vector>

namespace clothtrack
{
/// Positions of the landmarks found on both frames, paired by id: `before` on `a`, `after` on
/// `b`. Landmarks further than `maxOffset` from the body (on loose cloth) on either frame are
/// left out.
void pairLandmarks(const TriangleMesh& a, const std::vector<OrientedSurfacePoint>& onA,
                   const TriangleMesh& b, const std::vector<OrientedSurfacePoint>& onB,
                   std::vector<Vec3>& before, std::vector<Vec3>& after,
                   double maxOffset = std::numeric_limits<double>::infinity());

struct StartPredictionOptions
{
  /// Gaussian width (metres) of the locally rigid landmark motion that moves the neighbour's
  /// fit to a frame's start; 0 starts from the neighbour's fit as it is.
  double predictRadius = 0.3;
  /// Landmark pairs that the locally rigid motion of their neighbours (within predictRadius)
  /// does not carry within this distance are dropped first (random sample consensus,
  /// pipeline/LandmarkConsensus.h; metres). 0 keeps every pair: on pjump it dropped 2 % of the
  /// pairs and changed the mean error by 0.02 cm (BENCHMARKS.md, "PCL in the pipeline").
  double landmarkConsensus = 0.0;
};

/// Moves `points` by the locally weighted rigid motion taking `before` to `after` (paired
/// landmark positions, same order). `radius` (metres) is the Gaussian width of the weights.
/// Fewer than three pairs: a translation by their mean motion (none without pairs).
Points predictMotion(const Points& points, const std::vector<Vec3>& before,
                     const std::vector<Vec3>& after,
                     double radius = StartPredictionOptions{}.predictRadius);

/// Which paired landmark positions (before[i], after[i]) to trust: one flag per pair.
using LandmarkPairFilter = std::function<std::vector<bool>(const std::vector<Vec3>& before,
                                                           const std::vector<Vec3>& after)>;

/// The start of each frame of a sequence fit: the neighbour's fit moved by the motion of the
/// landmarks seen on both frames (pairLandmarks, predictMotion over `radius`). `frames` and
/// `landmarks` (one per frame) must outlive the prediction. `trusted`, when given, drops the
/// pairs it does not trust first (a landmark carried onto the wrong limb of one frame).
StartPrediction landmarkStartPrediction(
    const std::function<FramePtr(int)>& frames,
    const std::function<const std::vector<OrientedSurfacePoint>&(int)>& landmarks, double radius,
    const LandmarkPairFilter& trusted = {});
} // namespace clothtrack
