#pragma once
// Geodesic polar coordinates around an oriented surface point: the discrete exponential map
// (after Schmidt, Grimm and Wyvill 2006). Vertices are visited in increasing geodesic distance
// from the seed; each gets the 2D coordinates of its already-placed neighbours plus the edge to
// it, expressed in their tangent frames (carried from the seed by minimal rotations), averaged
// with weights 1 / edge length. On a flat patch this is exact; on a curved one it approximates
// (distance, angle to the seed direction), which is what maps an oriented point correspondence
// to a near-isometry between two surfaces.
#include "Geodesic.h"
#include "MeshTopology.h"
#include "TriangleMesh.h"

#include <cmath>
#include <vector>

namespace clothtrack
{
struct PolarPatch
{
  std::vector<int> vertices; ///< vertices reached, in increasing distance
  std::vector<Eigen::Vector2d>
      coordinates;               ///< tangent-plane coordinates, x along the seed direction
  std::vector<double> distances; ///< fast-marching geodesic distance from the seed point
  double radius(size_t k) const { return coordinates[k].norm(); }
  double angle(size_t k) const { return std::atan2(coordinates[k].y(), coordinates[k].x()); }
};

/// Exponential maps around many points of one mesh: normals, topology and the geodesic
/// propagation are prepared once. map() is safe to call from several threads at once.
class ExponentialMapper
{
public:
  /// The mesh must outlive the mapper.
  explicit ExponentialMapper(const TriangleMesh& mesh);

  /// Coordinates of every vertex within geodesic distance `radius` of the point on triangle
  /// `face` at barycentric `bary`, x along `direction` (projected onto the tangent plane).
  PolarPatch map(int face, const Vec3& bary, const Vec3& direction, double radius) const;

  const TriangleMesh& mesh() const { return mesh_; }
  const MeshTopology& topology() const { return topology_; }
  const WavefrontGeodesic& geodesic() const { return geodesic_; }
  const Points& normals() const { return normals_; }

private:
  const TriangleMesh& mesh_;
  Points normals_;
  MeshTopology topology_;
  WavefrontGeodesic geodesic_;
};

/// One exponential map (see ExponentialMapper::map).
PolarPatch exponentialMap(const TriangleMesh& mesh, int face, const Vec3& bary,
                          const Vec3& direction, double radius);
} // namespace clothtrack
