#include <clothtrack/base/Parallel.h>
#include <clothtrack/body/Extremities.h>
#include <clothtrack/mesh/InsideTest.h>
#include <clothtrack/mesh/Primitives.h>

#include <gtest/gtest.h>

#include <atomic>
#include <numeric>

using namespace clothtrack;

namespace
{
/// A sphere with n long spikes along the given directions (a crude "star-shaped body").
TriangleMesh spikyBall(const std::vector<Vec3>& directions, double length)
{
  TriangleMesh mesh = icosphere(4, 0.3);
  for (int v = 0; v < mesh.numVertices(); ++v)
  {
    const Vec3 p = mesh.vertex(v);
    double push = 0.0;
    for (const Vec3& d : directions)
    {
      const double c = p.normalized().dot(d.normalized());
      if (c > 0.9) push = std::max(push, length * (c - 0.9) / 0.1);
    }
    mesh.V.row(v) = (p + push * p.normalized()).transpose();
  }
  return mesh;
}
} // namespace

TEST(Extremities, TipsOfProtrusionsAreFoundAndNoiseIsNot)
{
  const std::vector<Vec3> directions = {Vec3(0, 1, 0), Vec3(1, -0.5, 0), Vec3(-1, -0.5, 0),
                                        Vec3(0.5, -1, 0.1), Vec3(-0.5, -1, -0.1)};
  // Five long spikes and a short bump (noise: must not count).
  std::vector<Vec3> withBump = directions;
  withBump.push_back(Vec3(0, 0, 1));
  TriangleMesh mesh = spikyBall(withBump, 0.6);
  const TriangleMesh bumpOnly = spikyBall({Vec3(0, 0, 1)}, 0.05);
  for (int v = 0; v < mesh.numVertices(); ++v)
    if (mesh.vertex(v).normalized().z() > 0.9) mesh.V.row(v) = bumpOnly.V.row(v);
  const std::vector<Extremity> found = geodesicExtremities(mesh, 0.1);
  ASSERT_EQ(found.size(), directions.size());
  for (const Vec3& d : directions)
  {
    // The spike's apex: its vertex furthest from the centre.
    Vec3 apex = Vec3::Zero();
    for (int v = 0; v < mesh.numVertices(); ++v)
      if (mesh.vertex(v).normalized().dot(d.normalized()) > 0.9 &&
          mesh.vertex(v).norm() > apex.norm())
        apex = mesh.vertex(v);
    // Exactly one extremity on the spike, in its outer part.
    int onSpike = 0;
    for (const Extremity& e : found)
    {
      const Vec3 p = mesh.vertex(e.vertex);
      if (p.normalized().dot(d.normalized()) > 0.9 && p.norm() > 0.75 * apex.norm()) ++onSpike;
    }
    EXPECT_EQ(onSpike, 1) << "spike towards " << d.transpose();
  }
  for (size_t k = 1; k < found.size(); ++k) EXPECT_GE(found[k - 1].distance, found[k].distance);
  // A plain sphere has no persistent protrusion beyond its single farthest point.
  EXPECT_EQ(geodesicExtremities(icosphere(3, 0.3), 0.15).size(), 1u);
  EXPECT_TRUE(geodesicExtremities(TriangleMesh{}, 0.15).empty());
}

TEST(InsideTest, RayParityOnAClosedSphere)
{
  const TriangleMesh sphere = icosphere(3, 1.0);
  const SurfaceLocator locator(sphere);
  EXPECT_TRUE(insideByRayParity(locator, Vec3(0.1, 0.2, -0.3)));
  EXPECT_TRUE(insideByRayParity(locator, Vec3(0.9, 0.0, 0.0)));
  EXPECT_FALSE(insideByRayParity(locator, Vec3(1.2, 0.0, 0.0)));
  EXPECT_FALSE(insideByRayParity(locator, Vec3(0.0, -3.0, 0.5)));
  Points points(4, 3);
  points << 0, 0, 0, 0.5, 0, 0, 2, 0, 0, 0, 0, 5;
  EXPECT_DOUBLE_EQ(fractionInside(locator, points), 0.5);
}

TEST(Parallel, EveryIndexVisitedOnceForAnyThreadCount)
{
  for (int threads : {1, 2, 3, 8})
  {
    setThreadCount(threads);
    std::vector<int> visits(1000, 0);
    parallelFor(
        0, 1000, [&](int i) { ++visits[i]; }, 1);
    EXPECT_EQ(std::accumulate(visits.begin(), visits.end(), 0), 1000);
    EXPECT_EQ(*std::min_element(visits.begin(), visits.end()), 1);
    EXPECT_EQ(threadCount(), threads);
  }
  setThreadCount(0);
  EXPECT_GE(threadCount(), 1);
}
