#pragma once
// Normals for a point cloud that has none: a plane fitted to each point's neighbours (PCL's
// NormalEstimationOMP), then one consistent side for all, chosen by propagation along a
// minimum spanning tree of the neighbour graph (Hoppe et al. 1992) from the topmost point,
// whose normal points up. A surface reconstruction needs the outside to be one side.
#include <clothtrack/mesh/PointCloud.h>

namespace clothtrack
{
struct NormalOptions
{
  int neighbours = 20;           ///< points in each fitted plane
  int orientationNeighbours = 8; ///< edges per point of the propagation graph
};

struct NormalReport
{
  /// Share of propagation steps across a sharp turn of the normal (|cos| < 0.5): where the
  /// propagation may have flipped a side, a sign of thin parts closer than the point spacing.
  double uncertainShare = 0;
  int trees = 0; ///< connected parts of the neighbour graph, each oriented on its own
  /// Median surface variation, smallest over summed eigenvalue of the neighbourhoods'
  /// covariance: near 0 for points on a surface, 1/3 for points filling a volume (noise).
  double medianSurfaceVariation = 0;
};

/// Sets cloud.N (unit normals, consistently oriented, pointing away from the interior).
void estimateNormals(PointCloud& cloud, const NormalOptions& options = {},
                     NormalReport* report = nullptr);
} // namespace clothtrack
