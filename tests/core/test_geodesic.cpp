// Geodesic distances against analytic truth. The measured errors are printed (and recorded
// as test properties) so that the accuracy of each method is visible in the test log.
#include <clothtrack/base/Error.h>
#include <clothtrack/mesh/Geodesic.h>
#include <clothtrack/mesh/Primitives.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

using namespace clothtrack;

namespace
{
struct ErrorStats
{
  double meanRelative = 0, maxAbsolute = 0;
};

// Errors against the great-circle distance on the unit sphere, ignoring the source's own
// neighbourhood (distances below 0.1) where relative errors are meaningless.
ErrorStats sphereErrors(const TriangleMesh& mesh, int source, const Eigen::VectorXd& d)
{
  ErrorStats s;
  int count = 0;
  const Vec3 p0 = mesh.vertex(source).normalized();
  for (int v = 0; v < mesh.numVertices(); ++v)
  {
    const double exact = std::acos(std::clamp(p0.dot(mesh.vertex(v).normalized()), -1.0, 1.0));
    s.maxAbsolute = std::max(s.maxAbsolute, std::abs(d[v] - exact));
    if (exact > 0.1)
    {
      s.meanRelative += std::abs(d[v] - exact) / exact;
      ++count;
    }
  }
  s.meanRelative /= count;
  return s;
}

void report(const char* method, const ErrorStats& s)
{
  std::printf("[ measured ] sphere (10242 vertices) %-13s mean relative error %.3f %%, max abs "
              "error %.4f (radius 1)\n",
              method, 100 * s.meanRelative, s.maxAbsolute);
  testing::Test::RecordProperty(std::string(method) + "_mean_relative_error",
                                std::to_string(s.meanRelative));
}
} // namespace

TEST(Geodesic, SphereAgainstGreatCircle)
{
  const TriangleMesh mesh = icosphere(5); // 10242 vertices
  const int source = 0;
  const ErrorStats dijkstra = sphereErrors(
      mesh, source,
      WavefrontGeodesic(mesh, WavefrontGeodesic::Method::Dijkstra).distances({source}));
  const ErrorStats marching = sphereErrors(
      mesh, source,
      WavefrontGeodesic(mesh, WavefrontGeodesic::Method::FastMarching).distances({source}));
  const ErrorStats heat = sphereErrors(mesh, source, HeatGeodesic(mesh).distances({source}));
  report("Dijkstra", dijkstra);
  report("FastMarching", marching);
  report("Heat", heat);
  EXPECT_LT(dijkstra.meanRelative, 0.10);
  EXPECT_LT(marching.meanRelative, 0.02);
  EXPECT_LT(heat.meanRelative, 0.02);
  // Fast marching must beat plain Dijkstra clearly: that is its purpose.
  EXPECT_LT(marching.meanRelative, 0.5 * dijkstra.meanRelative);
}

TEST(Geodesic, FastMarchingIsNearExactOnAPlane)
{
  const int n = 40;
  const TriangleMesh mesh = grid(n, 1.0);
  const int center = (n / 2) * (n + 1) + n / 2;
  const Eigen::VectorXd d = WavefrontGeodesic(mesh).distances({center});
  double worst = 0;
  for (int v = 0; v < mesh.numVertices(); ++v)
  {
    const double exact = (mesh.vertex(v) - mesh.vertex(center)).norm();
    if (exact > 0) worst = std::max(worst, std::abs(d[v] - exact) / exact);
  }
  std::printf("[ measured ] flat grid fast marching worst relative error %.4f %%\n", 100 * worst);
  EXPECT_LT(worst, 0.01);
}

TEST(Geodesic, DistanceLimitKeepsItLocal)
{
  const TriangleMesh mesh = icosphere(4);
  WavefrontGeodesic geodesic(mesh);
  const Eigen::VectorXd full = geodesic.distances({0});
  const double limit = 0.5;
  const Eigen::VectorXd local = geodesic.distances({0}, limit);
  int reached = 0;
  for (int v = 0; v < mesh.numVertices(); ++v)
  {
    if (std::isfinite(local[v]))
    {
      ++reached;
      EXPECT_LE(local[v], limit);
      EXPECT_DOUBLE_EQ(local[v], full[v]);
    }
    else
      EXPECT_GT(full[v], limit - 1e-12);
  }
  EXPECT_EQ(static_cast<size_t>(reached), geodesic.lastReached().size());
  // A cap of geodesic radius 0.5 on the unit sphere holds 2*pi*(1-cos 0.5)/(4*pi) of the area.
  const double fraction = (1 - std::cos(limit)) / 2;
  EXPECT_NEAR(static_cast<double>(reached) / mesh.numVertices(), fraction, 0.2 * fraction);
  // Nearest first.
  for (size_t i = 1; i < geodesic.lastReached().size(); ++i)
    EXPECT_LE(local[geodesic.lastReached()[i - 1]], local[geodesic.lastReached()[i]]);
}

TEST(Geodesic, MultipleSourcesGiveTheNearest)
{
  const TriangleMesh mesh = icosphere(4);
  // Two antipodal vertices: every point is at most pi/2 from one of them.
  int antipode = 0;
  double best = 1e9;
  for (int v = 0; v < mesh.numVertices(); ++v)
  {
    const double dot = mesh.vertex(v).dot(mesh.vertex(0));
    if (dot < best)
    {
      best = dot;
      antipode = v;
    }
  }
  for (bool heat : {false, true})
  {
    const Eigen::VectorXd d = heat ? HeatGeodesic(mesh).distances({0, antipode})
                                   : WavefrontGeodesic(mesh).distances({0, antipode});
    EXPECT_LT(d.maxCoeff(), M_PI / 2 * 1.03);
    EXPECT_EQ(d[0], 0.0);
    EXPECT_EQ(d[antipode], 0.0);
  }
}

TEST(Geodesic, UnreachedComponentsAreInfinite)
{
  const TriangleMesh a = icosphere(2);
  const TriangleMesh both = concatenate(a, icosphere(2, 1.0, Vec3(5, 0, 0)));
  const Eigen::VectorXd heat = HeatGeodesic(both).distances({0});
  const Eigen::VectorXd wave = WavefrontGeodesic(both).distances({0});
  for (int v = 0; v < both.numVertices(); ++v)
  {
    EXPECT_EQ(std::isfinite(heat[v]), v < a.numVertices());
    EXPECT_EQ(std::isfinite(wave[v]), v < a.numVertices());
  }
}

TEST(Geodesic, SeedsAtASurfacePoint)
{
  const TriangleMesh mesh = grid(20, 1.0);
  const int face = 2 * (10 * 20 + 10);
  const Vec3 bary(0.2, 0.3, 0.5);
  const Vec3 p = bary[0] * mesh.vertex(mesh.F(face, 0)) + bary[1] * mesh.vertex(mesh.F(face, 1)) +
                 bary[2] * mesh.vertex(mesh.F(face, 2));
  const Eigen::VectorXd d =
      WavefrontGeodesic(mesh).distancesFromSeeds(seedsAtSurfacePoint(mesh, face, bary));
  for (int v = 0; v < mesh.numVertices(); ++v)
  {
    const double exact = (mesh.vertex(v) - p).norm();
    EXPECT_NEAR(d[v], exact, 0.02 * exact + 1e-12);
  }
}

TEST(Geodesic, RejectsOutOfRangeSources)
{
  const TriangleMesh mesh = icosphere(1);
  EXPECT_THROW(WavefrontGeodesic(mesh).distances(std::vector<int>{mesh.numVertices()}), Error);
  EXPECT_THROW(HeatGeodesic(mesh).distances({-1}), Error);
}
