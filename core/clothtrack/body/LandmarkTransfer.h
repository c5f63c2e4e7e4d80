#pragma once
// Mapping oriented anatomical points from the fitted body onto the clothed surface
// (Shehu et al. 2016, section 4.1): the line through the body point along its normal is
// intersected with the frame's surface. The closest crossing OUTSIDE the body within
// outsideTolerance is taken; failing that, the closest crossing INSIDE the body within
// insideTolerance; failing that, the point is dropped for this frame. The tangent direction is
// projected onto the tangent plane of the surface where it lands.
#include <clothtrack/mesh/SurfaceLocator.h>
#include <clothtrack/mesh/TriangleMesh.h>

#include <vector>

namespace clothtrack
{
struct OrientedPoint
{
  Vec3 position;
  Vec3 normal;    ///< outward unit normal of the body at the point
  Vec3 direction; ///< unit tangent direction
};

struct LandmarkTransferOptions
{
  double outsideTolerance = 0.05; ///< tau_o, metres
  double insideTolerance = 0.2;   ///< tau_i, metres
};

struct TransferredLandmark
{
  bool valid = false;
  SurfacePoint point; ///< on the frame: face, barycentric, position
  Vec3 direction = Vec3::Zero();
  double offset = 0.0; ///< signed distance along the normal (positive: outside the body)
};

/// Transfers each oriented body point onto the surface behind `locator`.
std::vector<TransferredLandmark> transferLandmarks(const std::vector<OrientedPoint>& bodyPoints,
                                                   const TriangleMesh& frame,
                                                   const SurfaceLocator& locator,
                                                   const LandmarkTransferOptions& options = {});

/// The landmarks found on a frame as oriented surface points (patch seeds): the valid ones,
/// their index as id.
std::vector<OrientedSurfacePoint> landmarkSeeds(const std::vector<TransferredLandmark>& landmarks);
} // namespace clothtrack
