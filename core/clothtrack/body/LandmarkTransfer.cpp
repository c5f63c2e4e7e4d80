#include "LandmarkTransfer.h"

#include <cmath>

namespace clothtrack
{
std::vector<TransferredLandmark> transferLandmarks(const std::vector<OrientedPoint>& bodyPoints,
                                                   const TriangleMesh& frame,
                                                   const SurfaceLocator& locator,
                                                   const LandmarkTransferOptions& options)
{
  std::vector<TransferredLandmark> out(bodyPoints.size());
  for (size_t k = 0; k < bodyPoints.size(); ++k)
  {
    const OrientedPoint& p = bodyPoints[k];
    const Vec3 n = p.normal.normalized();
    const auto hits = locator.intersectLine(p.position, n);
    const LineHit* chosen = nullptr;
    // Hits are sorted by the signed distance along the normal: the first positive one is the
    // closest outside, the last negative one the closest inside.
    for (const LineHit& h : hits)
      if (h.t >= 0)
      {
        if (h.t <= options.outsideTolerance) chosen = &h;
        break;
      }
    if (!chosen)
      for (auto it = hits.rbegin(); it != hits.rend(); ++it)
        if (it->t < 0)
        {
          if (-it->t <= options.insideTolerance) chosen = &*it;
          break;
        }
    if (!chosen) continue;
    TransferredLandmark& t = out[k];
    t.valid = true;
    t.point = chosen->point;
    t.offset = chosen->t;
    const Vec3 a = frame.vertex(frame.F(t.point.face, 0));
    Vec3 faceNormal = (frame.vertex(frame.F(t.point.face, 1)) - a)
                          .cross(frame.vertex(frame.F(t.point.face, 2)) - a);
    faceNormal = faceNormal.norm() > 0 ? faceNormal.normalized() : n;
    Vec3 d = p.direction - p.direction.dot(faceNormal) * faceNormal;
    // A direction along the surface normal has no tangent part: keep the body's.
    t.direction = d.norm() > 1e-9 ? d.normalized() : p.direction.normalized();
  }
  return out;
}
std::vector<OrientedSurfacePoint> landmarkSeeds(const std::vector<TransferredLandmark>& landmarks)
{
  std::vector<OrientedSurfacePoint> seeds;
  for (size_t k = 0; k < landmarks.size(); ++k)
    if (landmarks[k].valid)
      seeds.push_back({static_cast<int>(k), landmarks[k].point.face, landmarks[k].point.bary,
                       landmarks[k].direction, landmarks[k].offset});
  return seeds;
}
} // namespace clothtrack
