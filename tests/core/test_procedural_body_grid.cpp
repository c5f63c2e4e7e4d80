#include <clothtrack/body/ProceduralBody.h>
#include <clothtrack/body/ProceduralBodyGrid.h>

#include <gtest/gtest.h>

using namespace clothtrack;

// The narrow-band grid against every sample evaluated, on the built-in body's own grid: the same
// sign everywhere and the same value at both ends of every edge the surface crosses, so the
// contour (and the built-in body model) is the fully sampled one, bit for bit.
TEST(ProceduralBodyGrid, ContoursAsTheFullySampledGrid)
{
  const double stature = 1.72;
  const SkeletonGeometry skeleton = proceduralSkeleton(stature);
  const DistanceGrid grid = builtinBodyGrid(stature);
  const std::vector<float> banded = proceduralBodyDistanceGrid(skeleton, stature, grid);
  const auto& d = grid.dims;
  std::vector<float> full(banded.size());
  for (int k = 0; k < d[2]; ++k)
    for (int j = 0; j < d[1]; ++j)
      for (int i = 0; i < d[0]; ++i)
        full[i + static_cast<size_t>(d[0]) * (j + static_cast<size_t>(d[1]) * k)] =
            static_cast<float>(proceduralBodyDistance(skeleton, stature,
                                                      grid.origin + grid.spacing * Vec3(i, j, k)));
  ASSERT_EQ(banded.size(), full.size());
  const size_t strides[3] = {1, static_cast<size_t>(d[0]), static_cast<size_t>(d[0]) * d[1]};
  size_t wrongSign = 0, crossingsDiffering = 0, crossings = 0, shortcut = 0;
  for (int k = 0; k < d[2]; ++k)
    for (int j = 0; j < d[1]; ++j)
      for (int i = 0; i < d[0]; ++i)
      {
        const size_t s = i + strides[1] * j + strides[2] * k;
        wrongSign += (banded[s] < 0) != (full[s] < 0);
        shortcut += banded[s] != full[s];
        const int index[3] = {i, j, k};
        for (int a = 0; a < 3; ++a)
          if (index[a] + 1 < d[a] && (full[s] < 0) != (full[s + strides[a]] < 0))
          {
            ++crossings;
            crossingsDiffering +=
                banded[s] != full[s] || banded[s + strides[a]] != full[s + strides[a]];
          }
      }
  EXPECT_EQ(wrongSign, 0u);
  EXPECT_GT(crossings, 50000u); // the whole body surface
  EXPECT_EQ(crossingsDiffering, 0u);
  // Most samples lie far from the surface and were not evaluated one by one.
  EXPECT_GT(shortcut, banded.size() / 2);
}
