#include "OrientedLandmarks.h"

namespace clothtrack
{
std::vector<OrientedPoint> orientedLandmarks(const BodyModel& model, const TriangleMesh& posed)
{
  const Points normals = vertexNormals(posed);
  std::vector<OrientedPoint> points;
  points.reserve(model.landmarks.size());
  for (const OrientedLandmark& l : model.landmarks)
  {
    const Vec3 p = posed.vertex(l.vertex), n = normals.row(l.vertex).transpose();
    const Vec3 d = posed.vertex(l.directionVertex) - p;
    points.push_back({p, n, (d - d.dot(n) * n).normalized()});
  }
  return points;
}
} // namespace clothtrack
