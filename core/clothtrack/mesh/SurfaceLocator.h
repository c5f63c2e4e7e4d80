#pragma once
// Closest-point and line queries against a triangle surface, accelerated by a bounding
// volume hierarchy over the triangles.
#include "SurfacePoint.h"
#include "TriangleMesh.h"

#include <Eigen/Geometry>

#include <array>
#include <limits>
#include <vector>

namespace clothtrack
{
/// Intersection of a line origin + t * direction with a triangle.
struct LineHit
{
  double t;
  SurfacePoint point;
};

/// Closest point to p on triangle abc with its barycentric coordinates (Ericson 2005).
Vec3 closestPointOnTriangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c, Vec3& bary);

class SurfaceLocator
{
public:
  /// The mesh must outlive the locator.
  explicit SurfaceLocator(const TriangleMesh& mesh);

  /// Closest surface point; invalid (face -1) when the mesh is empty or nothing lies within
  /// maxDistance. `hintFace`, a face likely near the answer (the previous answer for a query
  /// that moved a little), only speeds the search up.
  SurfacePoint closestPoint(const Vec3& query,
                            double maxDistance = std::numeric_limits<double>::infinity(),
                            int hintFace = -1) const;

  /// Every crossing of the infinite line origin + t * direction with the surface, sorted by t
  /// (negative t lies behind the origin). Hits closer than a tiny tolerance (a line through a
  /// shared edge or vertex) are reported once.
  /// `minT` drops the crossings before origin + minT * direction (0: a ray).
  std::vector<LineHit> intersectLine(const Vec3& origin, const Vec3& direction,
                                     double minT = -std::numeric_limits<double>::infinity()) const;

private:
  struct Node
  {
    Eigen::AlignedBox3d box;
    int left = -1, right = -1; // children, or -1 for a leaf
    int begin = 0, end = 0;    // leaf range in order_
  };
  int build(int begin, int end, const std::vector<Vec3>& centroids);

  const TriangleMesh& mesh_;
  std::vector<Node> nodes_;
  std::vector<int> order_;
  std::vector<std::array<Vec3, 3>> corners_; // triangle corners in leaf order
  std::vector<Vec3> normals_;                // their unit normals
};

/// Mean distance to the surface of every `stride`-th point, in parallel; the same for any thread
/// count. 0 without points.
double meanClosestDistance(const Points& points, const SurfaceLocator& surface, long stride = 1);
} // namespace clothtrack
