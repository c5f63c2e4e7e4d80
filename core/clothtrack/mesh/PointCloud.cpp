#include "PointCloud.h"

namespace clothtrack
{
PointCloud selectPoints(const PointCloud& cloud, const std::vector<bool>& keep)
{
  int count = 0;
  for (int i = 0; i < cloud.size(); ++i) count += keep[i];
  PointCloud out;
  out.P.resize(count, 3);
  if (cloud.hasNormals()) out.N.resize(count, 3);
  if (cloud.hasColours()) out.C.resize(count, 3);
  for (int i = 0, j = 0; i < cloud.size(); ++i)
  {
    if (!keep[i]) continue;
    out.P.row(j) = cloud.P.row(i);
    if (cloud.hasNormals()) out.N.row(j) = cloud.N.row(i);
    if (cloud.hasColours()) out.C.row(j) = cloud.C.row(i);
    ++j;
  }
  return out;
}
} // namespace clothtrack
