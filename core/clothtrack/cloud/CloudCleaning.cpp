#include "CloudCleaning.h"
#include "PclConversion.h"

#include <pcl/filters/statistical_outlier_removal.h>
#include <pcl/filters/voxel_grid.h>

namespace clothtrack
{
PointCloud cleanCloud(const PointCloud& cloud, const CloudCleaningOptions& options,
                      CloudCleaningReport* report)
{
  using PointT = pcl::PointXYZRGBNormal;
  auto points = toPcl(cloud);
  auto kept = pcl::make_shared<pcl::PointCloud<PointT>>();
  if (options.outlierNeighbours > 0 && cloud.size() > options.outlierNeighbours)
  {
    pcl::StatisticalOutlierRemoval<PointT> outliers;
    outliers.setInputCloud(points);
    outliers.setMeanK(options.outlierNeighbours);
    outliers.setStddevMulThresh(options.outlierDeviations);
    outliers.filter(*kept);
  }
  else
    kept = points;
  pcl::PointCloud<PointT> thinned;
  if (options.voxelSize > 0 && !kept->empty())
  {
    pcl::VoxelGrid<PointT> grid;
    grid.setInputCloud(kept);
    const float leaf = static_cast<float>(options.voxelSize);
    grid.setLeafSize(leaf, leaf, leaf);
    grid.setDownsampleAllData(true);
    grid.filter(thinned);
  }
  else
    thinned = *kept;
  if (report)
  {
    report->input = cloud.size();
    report->outliers = cloud.size() - static_cast<int>(kept->size());
    report->output = static_cast<int>(thinned.size());
  }
  return fromPcl(thinned, cloud.hasNormals(), cloud.hasColours());
}
} // namespace clothtrack
