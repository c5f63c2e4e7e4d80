#ifndef ctPointCloudFile_h
#define ctPointCloudFile_h
// Point-cloud frames on disk (not wrapped: C++ only): .pcd through PCL's io where the build has
// it (not inside ParaView, whose process carries another VTK), .ply vertices and .xyz text.
#include "ctMeshConversion.h"
#include "ctReadersModule.h"

#include <clothtrack/mesh/PointCloud.h>

#include <string>

namespace clothtrack
{
/// True for .xyz and .pcd files, and for .ply files whose header declares no faces.
CTREADERS_EXPORT bool isPointCloudPath(const std::string& path);

/// The points of a cloud file, unit and up axis not yet applied. Throws Error naming the file.
CTREADERS_EXPORT PointCloud readPointCloudFile(const std::string& path);

/// readPointCloudFile, then the unit and up axis of `conventions` (metres, Y up after).
CTREADERS_EXPORT PointCloud loadPointCloud(const std::string& path,
                                           const FrameConventions& conventions);

/// Writes .pcd (binary_compressed), .ply (binary) or .xyz by the extension, atomically.
CTREADERS_EXPORT void writePointCloudFile(const std::string& path, const PointCloud& cloud);
} // namespace clothtrack

#endif
