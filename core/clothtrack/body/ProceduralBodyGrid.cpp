#include "ProceduralBodyGrid.h"

#include "ProceduralBody.h"

#include <clothtrack/base/Parallel.h>

#include <algorithm>
#include <cmath>

namespace clothtrack
{
namespace
{
constexpr int kBlock = 4; // samples along each side of a block
// How much faster than 1 per metre the distance may change. Its ellipsoids are bound
// approximations, not exact distances; on the built-in grid a bound of 1 keeps every crossing edge
// exact and 0.8 does not (test_procedural_body_grid), so 2 leaves a factor of two.
constexpr double kSlopeBound = 2.0;
} // namespace

DistanceGrid builtinBodyGrid(double stature)
{
  DistanceGrid grid;
  grid.origin = Vec3(-0.45, -0.01, -0.12) * stature;
  grid.spacing = 0.0035 * stature;
  const Vec3 hi = Vec3(0.45, 1.01, 0.16) * stature;
  for (int a = 0; a < 3; ++a)
    grid.dims[a] = static_cast<int>((hi[a] - grid.origin[a]) / grid.spacing) + 1;
  return grid;
}

std::vector<float> proceduralBodyDistanceGrid(const SkeletonGeometry& skeleton, double stature,
                                              const DistanceGrid& grid)
{
  const auto& dims = grid.dims;
  const double h = grid.spacing;
  std::array<int, 3> blocks;
  for (int a = 0; a < 3; ++a) blocks[a] = (dims[a] + kBlock - 1) / kBlock;
  // From a block's centre to the furthest sample one step outside it, along each axis.
  const double reach = std::sqrt(3.0) * (0.5 * (kBlock - 1) + 1.0) * h;
  std::vector<float> values(static_cast<size_t>(dims[0]) * dims[1] * dims[2]);
  auto at = [&](int i, int j, int k) -> float&
  { return values[i + static_cast<size_t>(dims[0]) * (j + static_cast<size_t>(dims[1]) * k)]; };
  auto distance = [&](double i, double j, double k)
  { return proceduralBodyDistance(skeleton, stature, grid.origin + h * Vec3(i, j, k)); };
  parallelFor(
      0, blocks[2],
      [&](int bk)
      {
        for (int bj = 0; bj < blocks[1]; ++bj)
          for (int bi = 0; bi < blocks[0]; ++bi)
          {
            const int i0 = bi * kBlock, j0 = bj * kBlock, k0 = bk * kBlock;
            const int i1 = std::min(i0 + kBlock, dims[0]), j1 = std::min(j0 + kBlock, dims[1]),
                      k1 = std::min(k0 + kBlock, dims[2]);
            const double centre =
                distance(i0 + 0.5 * (kBlock - 1), j0 + 0.5 * (kBlock - 1), k0 + 0.5 * (kBlock - 1));
            const bool far = std::abs(centre) > kSlopeBound * reach;
            for (int k = k0; k < k1; ++k)
              for (int j = j0; j < j1; ++j)
                for (int i = i0; i < i1; ++i)
                  at(i, j, k) = static_cast<float>(far ? centre : distance(i, j, k));
          }
      },
      1);
  return values;
}
} // namespace clothtrack
