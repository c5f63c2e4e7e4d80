#include "SurfaceGap.h"

#include <clothtrack/base/Parallel.h>

#include <algorithm>
#include <limits>
#include <vector>

namespace clothtrack
{
namespace
{
/// Mean distance from up to `samples` vertices of `from`, evenly strided, to the surface `to`.
double meanDistanceTo(const TriangleMesh& from, const SurfaceLocator& to, int samples)
{
  const int n = from.numVertices();
  const int count = std::min(n, std::max(1, samples));
  std::vector<double> distances(count, 0.0);
  parallelFor(0, count,
              [&](int i)
              {
                const int v = static_cast<int>(static_cast<long long>(i) * n / count);
                const SurfacePoint s = to.closestPoint(from.vertex(v));
                distances[i] = s.valid() ? (s.position - from.vertex(v)).norm()
                                         : std::numeric_limits<double>::infinity();
              });
  double total = 0.0;
  for (double d : distances) total += d;
  return total / count;
}
} // namespace

double meanSurfaceGap(const TriangleMesh& a, const SurfaceLocator& onA, const TriangleMesh& b,
                      const SurfaceLocator& onB, int samples)
{
  if (a.numVertices() == 0 || b.numVertices() == 0 || a.numFaces() == 0 || b.numFaces() == 0)
    return std::numeric_limits<double>::infinity();
  return 0.5 * (meanDistanceTo(a, onB, samples) + meanDistanceTo(b, onA, samples));
}
} // namespace clothtrack
