#pragma once
// What a rig of depth cameras around a person delivers: only the surface that some camera sees,
// as points, with noise along each camera ray and stray points. Used to make point-cloud
// captures with ground truth from any mesh sequence.
#include <clothtrack/mesh/PointCloud.h>

namespace clothtrack
{
struct DepthRig
{
  int cameras = 4;               ///< evenly spaced on a horizontal circle around `centre`
  Vec3 centre = Vec3::Zero();    ///< the point every camera looks at (Y up)
  double distance = 3.0;         ///< metres from the centre, horizontally
  double elevation = 0.3;        ///< camera height above the centre, metres
  int width = 480, height = 640; ///< image size, pixels
  double focalPixels = 600;      ///< about 5 mm between pixels at 3 m
  double noise = 0.003;          ///< standard deviation of the depth error along the ray, metres
  double outliers = 0.01;        ///< stray points added, as a share of the seen points
  unsigned seed = 1;
};

/// Camera k's position.
Vec3 cameraPosition(const DepthRig& rig, int k);

/// The points of `truth` seen by the rig's cameras (one per pixel and camera), noisy, plus
/// stray points in the box around the subject. Deterministic for a given rig.
PointCloud captureDepth(const TriangleMesh& truth, const DepthRig& rig);
} // namespace clothtrack
