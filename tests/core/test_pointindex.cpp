#include <clothtrack/mesh/PointIndex.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <random>

using namespace clothtrack;

namespace
{
Points randomPoints(int n, unsigned seed)
{
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-1, 1);
  Points p(n, 3);
  for (int i = 0; i < n; ++i) p.row(i) << u(rng), u(rng), u(rng);
  return p;
}
} // namespace

TEST(PointIndex, MatchesBruteForce)
{
  const Points points = randomPoints(2000, 1);
  const Points queries = randomPoints(200, 2);
  const PointIndex index(points);
  EXPECT_EQ(index.size(), 2000);
  for (int q = 0; q < queries.rows(); ++q)
  {
    const Vec3 query = queries.row(q).transpose();
    std::vector<std::pair<double, int>> all;
    for (int i = 0; i < points.rows(); ++i)
      all.emplace_back((points.row(i).transpose() - query).norm(), i);
    std::sort(all.begin(), all.end());

    const Neighbour nn = index.nearest(query);
    EXPECT_EQ(nn.index, all[0].second);
    EXPECT_NEAR(nn.distance, all[0].first, 1e-12);

    const auto knn = index.nearest(query, 5);
    ASSERT_EQ(knn.size(), 5u);
    for (int k = 0; k < 5; ++k) EXPECT_NEAR(knn[k].distance, all[k].first, 1e-12);

    const double radius = 0.2;
    const auto within = index.withinRadius(query, radius);
    const auto expected =
        std::count_if(all.begin(), all.end(), [&](const auto& a) { return a.first <= radius; });
    EXPECT_NEAR(static_cast<double>(within.size()), static_cast<double>(expected),
                1.0); // float radius bound
    for (const auto& n : within) EXPECT_LE(n.distance, radius * (1 + 1e-6));
  }
}

TEST(PointIndex, EmptySetAndLargeK)
{
  const PointIndex empty{Points(0, 3)};
  EXPECT_EQ(empty.nearest(Vec3::Zero()).index, -1);
  EXPECT_TRUE(empty.withinRadius(Vec3::Zero(), 1.0).empty());
  const PointIndex three(randomPoints(3, 5));
  EXPECT_EQ(three.nearest(Vec3::Zero(), 10).size(), 3u);
}
