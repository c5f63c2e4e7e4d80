#pragma once
// Points on a triangle surface: a triangle and barycentric coordinates, found by a query
// (SurfacePoint) or carried as an oriented landmark (OrientedSurfacePoint). Every stage passes
// surface points in these two forms.
#include "TriangleMesh.h"

#include <limits>

namespace clothtrack
{
/// A point on a triangle: face index, barycentric coordinates and position.
struct SurfacePoint
{
  int face = -1;
  Vec3 bary = Vec3::Zero();
  Vec3 position = Vec3::Zero();
  double distance = std::numeric_limits<double>::infinity();
  bool valid() const { return face >= 0; }
};

/// A landmark on a surface: identity, triangle + barycentric, tangent direction.
struct OrientedSurfacePoint
{
  int id = -1;
  int face = -1;
  Vec3 bary = Vec3::Zero();
  Vec3 direction = Vec3::Zero();
  /// Distance from the body the landmark was carried from (metres; 0 when unknown).
  double offset = 0.0;
};

/// Position of a surface point given by triangle + barycentric.
inline Vec3 surfacePosition(const TriangleMesh& mesh, int face, const Vec3& bary)
{
  return bary[0] * mesh.vertex(mesh.F(face, 0)) + bary[1] * mesh.vertex(mesh.F(face, 1)) +
         bary[2] * mesh.vertex(mesh.F(face, 2));
}
} // namespace clothtrack
