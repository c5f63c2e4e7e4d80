#pragma once
// Geodesic polar coordinates around an oriented surface point: the discrete exponential map
// (after Schmidt, Grimm and Wyvill 2006). Vertices are visited in increasing geodesic distance
// from the seed; each gets the 2D coordinates of its already-placed neighbours plus the edge to
// it, expressed in their tangent frames (carried from the seed by minimal rotations), averaged
// with weights 1 / edge length. On a flat patch this is exact; on a curved one it approximates
// (distance, angle to the seed direction), which is what maps an oriented point correspondence
// to a near-isometry between two surfaces.
#include "TriangleMesh.h"

#include <cmath>
#include <vector>

namespace clothtrack
{
struct PolarPatch
{
  std::vector<int> vertices; ///< vertices reached, in increasing distance
  std::vector<Eigen::Vector2d>
      coordinates; ///< tangent-plane coordinates, x along the seed direction
  double radius(size_t k) const { return coordinates[k].norm(); }
  double angle(size_t k) const { return std::atan2(coordinates[k].y(), coordinates[k].x()); }
};

/// Coordinates of every vertex within geodesic distance `radius` of the point on triangle `face`
/// at barycentric `bary`, with the x axis along `direction` (projected onto the tangent plane).
PolarPatch exponentialMap(const TriangleMesh& mesh, int face, const Vec3& bary,
                          const Vec3& direction, double radius);
} // namespace clothtrack
