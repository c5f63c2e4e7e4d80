#pragma once
// Between the core's PointCloud and PCL's point clouds. Include only from .cpp files: PCL's
// headers are heavy.
#include <clothtrack/mesh/PointCloud.h>

#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

namespace clothtrack
{
/// Positions, normals (zero when the cloud has none) and colours (black when none).
pcl::PointCloud<pcl::PointXYZRGBNormal>::Ptr toPcl(const PointCloud& cloud);
/// The cloud back; normals and colours kept when `withNormals` / `withColours`.
PointCloud fromPcl(const pcl::PointCloud<pcl::PointXYZRGBNormal>& points, bool withNormals,
                   bool withColours);
/// Positions only.
pcl::PointCloud<pcl::PointXYZ>::Ptr toPclXYZ(const Points& points);
} // namespace clothtrack
