#include "InsideTest.h"

namespace clothtrack
{
bool insideByRayParity(const SurfaceLocator& surface, const Vec3& point)
{
  static const Vec3 directions[3] = {Vec3(0.5774, 0.5774, 0.5774).normalized(),
                                     Vec3(-0.3122, 0.8913, -0.3287).normalized(),
                                     Vec3(0.7071, -0.2588, -0.6580).normalized()};
  int votes = 0;
  for (const Vec3& d : directions)
  {
    int crossings = 0;
    for (const LineHit& hit : surface.intersectLine(point, d, 0.0)) crossings += hit.t > 1e-9;
    votes += crossings % 2;
  }
  return votes >= 2;
}

double fractionInside(const SurfaceLocator& surface, const Points& points)
{
  if (points.rows() == 0) return 0.0;
  int inside = 0;
  for (Eigen::Index i = 0; i < points.rows(); ++i)
    inside += insideByRayParity(surface, points.row(i).transpose());
  return static_cast<double>(inside) / points.rows();
}
} // namespace clothtrack
