// Geodesic polar coordinates against analytic truth on a plane and a sphere.
#include <clothtrack/base/Error.h>
#include <clothtrack/mesh/ExponentialMap.h>
#include <clothtrack/mesh/Primitives.h>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

using namespace clothtrack;

TEST(ExponentialMap, ExactOnAPlane)
{
  const TriangleMesh mesh = grid(40, 1.0);
  const int face = 2 * (20 * 40 + 20);
  const Vec3 bary(0.2, 0.3, 0.5);
  const Vec3 seed = bary[0] * mesh.vertex(mesh.F(face, 0)) +
                    bary[1] * mesh.vertex(mesh.F(face, 1)) + bary[2] * mesh.vertex(mesh.F(face, 2));
  const Vec3 direction = Vec3(1, 1, 0.3).normalized(); // projected onto the plane
  const PolarPatch patch = exponentialMap(mesh, face, bary, direction, 0.3);
  ASSERT_GT(patch.vertices.size(), 200u);
  const Vec3 x = Vec3(1, 1, 0).normalized();
  // y completes a right-handed frame with the seed triangle's normal (the grid faces -z or +z).
  const Vec3 normal = (mesh.vertex(mesh.F(face, 1)) - mesh.vertex(mesh.F(face, 0)))
                          .cross(mesh.vertex(mesh.F(face, 2)) - mesh.vertex(mesh.F(face, 0)))
                          .normalized();
  const Vec3 y = normal.cross(x);
  double worst = 0;
  for (size_t k = 0; k < patch.vertices.size(); ++k)
  {
    const Vec3 d = mesh.vertex(patch.vertices[k]) - seed;
    worst = std::max(worst, (patch.coordinates[k] - Eigen::Vector2d(d.dot(x), d.dot(y))).norm());
    EXPECT_LE(d.norm(), 0.3 + 1e-9);
  }
  EXPECT_LT(worst, 1e-9);
}

TEST(ExponentialMap, PolarCoordinatesOnASphere)
{
  const TriangleMesh mesh = icosphere(5); // unit sphere
  // Seed near the north pole, direction along +x.
  int face = 0;
  double best = -1;
  for (int f = 0; f < mesh.numFaces(); ++f)
  {
    const double z =
        (mesh.vertex(mesh.F(f, 0)) + mesh.vertex(mesh.F(f, 1)) + mesh.vertex(mesh.F(f, 2))).z();
    if (z > best)
    {
      best = z;
      face = f;
    }
  }
  const Vec3 bary = Vec3::Constant(1.0 / 3);
  const Vec3 seed = ((mesh.vertex(mesh.F(face, 0)) + mesh.vertex(mesh.F(face, 1)) +
                      mesh.vertex(mesh.F(face, 2))) /
                     3)
                        .normalized();
  const PolarPatch patch = exponentialMap(mesh, face, bary, Vec3::UnitX(), 0.6);
  const Vec3 x0 = (Vec3::UnitX() - Vec3::UnitX().dot(seed) * seed).normalized();
  const Vec3 y0 = seed.cross(x0);
  double radiusError = 0, angleError = 0;
  int count = 0;
  for (size_t k = 0; k < patch.vertices.size(); ++k)
  {
    const Vec3 p = mesh.vertex(patch.vertices[k]).normalized();
    const double r = std::acos(std::clamp(p.dot(seed), -1.0, 1.0));
    if (r < 0.1) continue;
    const Vec3 t = p - p.dot(seed) * seed;
    const double theta = std::atan2(t.dot(y0), t.dot(x0));
    radiusError += std::abs(patch.radius(k) - r) / r;
    angleError += std::abs(std::remainder(patch.angle(k) - theta, 2 * M_PI));
    ++count;
  }
  radiusError /= count;
  angleError /= count;
  std::printf("[ measured ] exponential map on a unit sphere within 0.6: mean radius error %.2f "
              "%%, mean angle error "
              "%.2f degrees (%d vertices)\n",
              100 * radiusError, angleError * 180 / M_PI, count);
  EXPECT_LT(radiusError, 0.03);
  EXPECT_LT(angleError, 3 * M_PI / 180);
}

TEST(ExponentialMap, BadSeedsAreErrors)
{
  const TriangleMesh mesh = grid(4, 1.0);
  EXPECT_THROW(exponentialMap(mesh, -1, Vec3::Constant(1.0 / 3), Vec3::UnitX(), 0.5), Error);
  EXPECT_THROW(exponentialMap(mesh, 0, Vec3::Constant(1.0 / 3), Vec3::UnitZ(), 0.5), Error);
}
