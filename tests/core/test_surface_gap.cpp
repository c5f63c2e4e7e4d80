// The gap between two surfaces, which tells consecutive frames of a capture from unrelated poses.
#include <clothtrack/mesh/Primitives.h>
#include <clothtrack/mesh/SurfaceGap.h>

#include <gtest/gtest.h>

#include <cmath>

using namespace clothtrack;

TEST(SurfaceGap, IsTheOffsetBetweenParallelSheets)
{
  const TriangleMesh lower = grid(20, 1.0);
  TriangleMesh upper = lower;
  upper.V.col(2).array() += 0.05;
  const SurfaceLocator onLower(lower), onUpper(upper);
  EXPECT_NEAR(meanSurfaceGap(lower, onLower, upper, onUpper), 0.05, 1e-9);
  EXPECT_NEAR(meanSurfaceGap(lower, onLower, lower, onLower), 0.0, 1e-12);
}

TEST(SurfaceGap, IsSymmetricAndCountsBothSides)
{
  // A small sphere beside a large one: from the small one the large is near, from most of the
  // large one the small is far. The mean of both sides sees the part the small one leaves out.
  const TriangleMesh big = icosphere(3, 1.0);
  const TriangleMesh small = icosphere(3, 0.2, Vec3(0.0, 0.0, 0.85));
  const SurfaceLocator onBig(big), onSmall(small);
  const double gap = meanSurfaceGap(big, onBig, small, onSmall);
  EXPECT_DOUBLE_EQ(gap, meanSurfaceGap(small, onSmall, big, onBig));
  EXPECT_GT(gap, 0.5); // most of the big sphere lies over a metre from the small one
  // Evenly strided samples of each side give nearly the mean of every vertex.
  EXPECT_NEAR(meanSurfaceGap(big, onBig, small, onSmall, 200), gap, 0.05);
}

TEST(SurfaceGap, EmptySurfacesAreInfinitelyFar)
{
  const TriangleMesh sphere = icosphere(1);
  const TriangleMesh empty;
  const SurfaceLocator onSphere(sphere), onEmpty(empty);
  EXPECT_TRUE(std::isinf(meanSurfaceGap(sphere, onSphere, empty, onEmpty)));
}
