#pragma once
// Cleaning a captured point cloud before a surface is fitted to it: isolated points (stray
// depth pixels, background) are removed and the density is evened out on a voxel grid.
#include <clothtrack/mesh/PointCloud.h>

namespace clothtrack
{
struct CloudCleaningOptions
{
  /// Statistical outlier removal: a point whose mean distance to its `outlierNeighbours`
  /// nearest points exceeds the cloud's mean by `outlierDeviations` standard deviations goes.
  int outlierNeighbours = 16;
  double outlierDeviations = 2.0;
  /// Voxel-grid thinning: one point (the centroid) per cube of this edge, metres; 0 keeps all.
  double voxelSize = 0.005;
};

struct CloudCleaningReport
{
  int input = 0;
  int outliers = 0; ///< removed as isolated
  int output = 0;   ///< after thinning
};

/// The cleaned cloud (normals and colours are averaged per voxel; normals renormalised).
PointCloud cleanCloud(const PointCloud& cloud, const CloudCleaningOptions& options,
                      CloudCleaningReport* report = nullptr);
} // namespace clothtrack
