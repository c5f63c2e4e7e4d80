#pragma once
// Poisson surface reconstruction (Kazhdan et al. 2006, PCL's implementation): the watertight
// surface whose inside indicator best matches the oriented points. PCL's surface library links
// Debian's VTK 9.1, so this stage is left out of the ParaView plugin.
#include <clothtrack/mesh/PointCloud.h>

namespace clothtrack
{
struct PoissonOptions
{
  int depth = 7; ///< octree depth: cells of (bounding cube) / 2^depth, 1.5 cm for a person
  double samplesPerNode = 2.0; ///< more smooths noisy points more
  int threads = 0;             ///< 0: all cores
};

/// The watertight triangle surface of the oriented points (cloud.N must be set).
/// `unpairedEdges` (optional) receives the iso-surface edges PCL could not close, each a small
/// gap in the surface.
TriangleMesh poissonSurface(const PointCloud& cloud, const PoissonOptions& options = {},
                            int* unpairedEdges = nullptr);
} // namespace clothtrack
