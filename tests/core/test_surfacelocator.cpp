#include <clothtrack/mesh/Primitives.h>
#include <clothtrack/mesh/SurfaceLocator.h>

#include <gtest/gtest.h>

#include <random>

using namespace clothtrack;

TEST(SurfaceLocator, ClosestPointMatchesBruteForce)
{
  const TriangleMesh mesh = torus(1.0, 0.3, 30, 15);
  const SurfaceLocator locator(mesh);
  std::mt19937 rng(4);
  std::uniform_real_distribution<double> u(-1.6, 1.6);
  for (int q = 0; q < 300; ++q)
  {
    const Vec3 query(u(rng), u(rng), u(rng) * 0.5);
    double best = 1e300;
    for (int f = 0; f < mesh.numFaces(); ++f)
    {
      Vec3 bary;
      const Vec3 p =
          closestPointOnTriangle(query, mesh.vertex(mesh.F(f, 0)), mesh.vertex(mesh.F(f, 1)),
                                 mesh.vertex(mesh.F(f, 2)), bary);
      best = std::min(best, (p - query).norm());
    }
    const SurfacePoint sp = locator.closestPoint(query);
    ASSERT_TRUE(sp.valid());
    EXPECT_NEAR(sp.distance, best, 1e-12);
    // Barycentric coordinates reproduce the position.
    const Vec3 rebuilt = sp.bary[0] * mesh.vertex(mesh.F(sp.face, 0)) +
                         sp.bary[1] * mesh.vertex(mesh.F(sp.face, 1)) +
                         sp.bary[2] * mesh.vertex(mesh.F(sp.face, 2));
    EXPECT_LT((rebuilt - sp.position).norm(), 1e-12);
    EXPECT_NEAR(sp.bary.sum(), 1.0, 1e-12);
    EXPECT_GE(sp.bary.minCoeff(), -1e-12);
  }
}

TEST(SurfaceLocator, MaxDistanceAndEmptyMesh)
{
  const TriangleMesh mesh = icosphere(2);
  const SurfaceLocator locator(mesh);
  EXPECT_FALSE(locator.closestPoint(Vec3(3, 0, 0), 1.0).valid());
  EXPECT_TRUE(locator.closestPoint(Vec3(3, 0, 0), 2.5).valid());
  const TriangleMesh empty;
  EXPECT_FALSE(SurfaceLocator(empty).closestPoint(Vec3::Zero()).valid());
}

TEST(SurfaceLocator, LineThroughSphereHitsTwiceSorted)
{
  const TriangleMesh mesh = icosphere(4);
  const SurfaceLocator locator(mesh);
  const Vec3 direction = Vec3(0.3, 0.5, 0.8).normalized();
  const auto hits = locator.intersectLine(Vec3::Zero(), direction);
  ASSERT_EQ(hits.size(), 2u);
  EXPECT_NEAR(hits[0].t, -1.0, 0.01);
  EXPECT_NEAR(hits[1].t, 1.0, 0.01);
  for (const auto& h : hits) EXPECT_LT((h.point.position - h.t * direction).norm(), 1e-12);
}

TEST(SurfaceLocator, LineThroughTorus)
{
  const TriangleMesh mesh = torus(1.0, 0.3, 48, 24);
  const SurfaceLocator locator(mesh);
  // Along the x axis: in and out of the tube on both sides.
  const auto hits = locator.intersectLine(Vec3(0, 0, 0.01), Vec3(1, 0.001, 0));
  ASSERT_EQ(hits.size(), 4u);
  EXPECT_NEAR(hits[0].t, -1.3, 0.01);
  EXPECT_NEAR(hits[1].t, -0.7, 0.01);
  EXPECT_NEAR(hits[2].t, 0.7, 0.01);
  EXPECT_NEAR(hits[3].t, 1.3, 0.01);
  // Along the axis of symmetry: through the hole, no hit.
  EXPECT_TRUE(locator.intersectLine(Vec3::Zero(), Vec3(0, 0, 1)).empty());
}

TEST(SurfaceLocator, LineThroughASharedVertexIsReportedOnce)
{
  const TriangleMesh mesh = grid(4, 1.0);
  const SurfaceLocator locator(mesh);
  // (0.5, 0.5) is a grid vertex shared by six triangles.
  const auto hits = locator.intersectLine(Vec3(0.5, 0.5, 1.0), Vec3(0, 0, -1));
  ASSERT_EQ(hits.size(), 1u);
  EXPECT_NEAR(hits[0].t, 1.0, 1e-12);
}

TEST(SurfaceLocator, HintFaceOnlySpeedsUpTheSearch)
{
  const TriangleMesh mesh = torus(1.0, 0.3, 30, 15);
  const SurfaceLocator locator(mesh);
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-1.6, 1.6);
  std::uniform_int_distribution<int> face(0, mesh.numFaces() - 1);
  for (int q = 0; q < 300; ++q)
  {
    const Vec3 query(u(rng), u(rng), u(rng) * 0.5);
    const SurfacePoint plain = locator.closestPoint(query);
    const SurfacePoint hinted = locator.closestPoint(query, 10.0, face(rng));
    ASSERT_TRUE(hinted.valid());
    EXPECT_NEAR(hinted.distance, plain.distance, 1e-12);
    // A far hint must not be returned when nothing lies within the limit.
    EXPECT_FALSE(locator.closestPoint(query, plain.distance * 0.5, face(rng)).valid());
  }
}
