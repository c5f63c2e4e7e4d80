#pragma once
// Point sets without faces in the formats the core reads itself: PLY vertices (with optional
// nx ny nz and red green blue) and XYZ text. PCD goes through PCL (clothtrack/pcd).
#include <clothtrack/mesh/PointCloud.h>

#include <string>
#include <vector>

namespace clothtrack
{
/// The vertices of a PLY file (faces, if any, are ignored), with normals and colours when the
/// vertex element has them. Strict as readPLY.
PointCloud readPLYPoints(const std::string& path);
/// XYZ text: one point a line, "x y z" or "x y z nx ny nz" (the same count on every line);
/// '#' starts a comment. Errors name the file and line.
PointCloud readXYZ(const std::string& path);

/// Binary little-endian PLY with a vertex element only (x y z as float, normals and colours
/// when the cloud has them).
void writePLYPoints(const std::string& path, const PointCloud& cloud);
void writeXYZ(const std::string& path, const PointCloud& cloud);

/// True when the PLY file's header declares faces, or cannot be read as a PLY header.
bool plyDeclaresFaces(const std::string& path);

/// True for .xyz and .pcd files, and for a .ply file whose header declares no faces.
bool isPointCloudFile(const std::string& path);

/// A cloud from its positions and flat arrays of normals and colours (0-255), empty or 3 per point.
PointCloud cloudFromArrays(Points positions, const std::vector<double>& normals,
                           const std::vector<double>& colours);

/// Drops points with a non-finite coordinate (depth cameras mark missing pixels with NaN) and
/// refuses, naming `name`, a cloud left with fewer than `minimumPoints`. Returns the dropped
/// count.
int dropInvalidPoints(PointCloud& cloud, const std::string& name, int minimumPoints = 100);
} // namespace clothtrack
