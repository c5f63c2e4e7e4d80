#include "PclConversion.h"

namespace clothtrack
{
pcl::PointCloud<pcl::PointXYZRGBNormal>::Ptr toPcl(const PointCloud& cloud)
{
  auto points = pcl::make_shared<pcl::PointCloud<pcl::PointXYZRGBNormal>>();
  points->resize(cloud.size());
  for (int i = 0; i < cloud.size(); ++i)
  {
    auto& p = (*points)[i];
    p.x = static_cast<float>(cloud.P(i, 0));
    p.y = static_cast<float>(cloud.P(i, 1));
    p.z = static_cast<float>(cloud.P(i, 2));
    p.normal_x = cloud.hasNormals() ? static_cast<float>(cloud.N(i, 0)) : 0.f;
    p.normal_y = cloud.hasNormals() ? static_cast<float>(cloud.N(i, 1)) : 0.f;
    p.normal_z = cloud.hasNormals() ? static_cast<float>(cloud.N(i, 2)) : 0.f;
    p.r = cloud.hasColours() ? cloud.C(i, 0) : 0;
    p.g = cloud.hasColours() ? cloud.C(i, 1) : 0;
    p.b = cloud.hasColours() ? cloud.C(i, 2) : 0;
    p.a = 255;
  }
  return points;
}

PointCloud fromPcl(const pcl::PointCloud<pcl::PointXYZRGBNormal>& points, bool withNormals,
                   bool withColours)
{
  const int n = static_cast<int>(points.size());
  PointCloud cloud;
  cloud.P.resize(n, 3);
  if (withNormals) cloud.N.resize(n, 3);
  if (withColours) cloud.C.resize(n, 3);
  for (int i = 0; i < n; ++i)
  {
    const auto& p = points[i];
    cloud.P.row(i) << p.x, p.y, p.z;
    if (withNormals)
    {
      cloud.N.row(i) << p.normal_x, p.normal_y, p.normal_z;
      const double length = cloud.N.row(i).norm();
      if (length > 0) cloud.N.row(i) /= length;
    }
    if (withColours) cloud.C.row(i) << p.r, p.g, p.b;
  }
  return cloud;
}

pcl::PointCloud<pcl::PointXYZ>::Ptr toPclXYZ(const Points& points)
{
  auto out = pcl::make_shared<pcl::PointCloud<pcl::PointXYZ>>();
  out->resize(points.rows());
  for (long i = 0; i < points.rows(); ++i)
    (*out)[i] = pcl::PointXYZ(static_cast<float>(points(i, 0)), static_cast<float>(points(i, 1)),
                              static_cast<float>(points(i, 2)));
  return out;
}
} // namespace clothtrack
