#ifndef ctPointCloudFile_h
#define ctPointCloudFile_h
// Point-cloud frames on disk (not wrapped: C++ only): .pcd through PCL's io where the build has
// it (not inside ParaView, whose process carries another VTK), .ply vertices and .xyz text.
#include "ctMeshConversion.h"
#include "ctReadersModule.h"

#include <clothtrack/io/PointCloudIO.h> // isPointCloudFile
#include <clothtrack/mesh/PointCloud.h>

#include <string>

namespace clothtrack
{
/// The points of a cloud file, unit and up axis not yet applied. Throws Error naming the file.
CTREADERS_EXPORT PointCloud readPointCloudFile(const std::string& path);

/// readPointCloudFile, then the unit and up axis of `conventions` (metres, Y up after).
CTREADERS_EXPORT PointCloud loadPointCloud(const std::string& path,
                                           const FrameConventions& conventions);

/// A vtkPolyData of the points with one vertex cell each, "Normals" and "Colors" (RGB) point
/// arrays when the cloud has them.
CTREADERS_EXPORT vtkSmartPointer<vtkPolyData> toPolyData(const PointCloud& cloud);
/// The points of any vtkPolyData (cells ignored), with its normals and 3-component unsigned char
/// colours ("Colors", "RGB") when present. Throws Error naming `name` for a missing point set.
CTREADERS_EXPORT PointCloud toPointCloud(vtkPolyData* polyData, const std::string& name);

/// Writes .pcd (binary_compressed), .ply (binary) or .xyz by the extension, atomically.
CTREADERS_EXPORT void writePointCloudFile(const std::string& path, const PointCloud& cloud);
} // namespace clothtrack

#endif
