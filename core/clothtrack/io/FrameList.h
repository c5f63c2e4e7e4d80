#pragma once
// Resolving what a user names as a sequence into an ordered list of frame files.
#include <string>
#include <vector>

namespace clothtrack
{
/// Natural order: digit runs compare by value, so "mesh_2" < "mesh_10".
bool naturalLess(const std::string& a, const std::string& b);

/// The last run of digits in a file's name (without folder and extension), -1 if none.
long frameNumberFromName(const std::string& path);

/// The file's extension in lower case, with its dot ("" when it has none).
std::string lowerCaseExtension(const std::string& path);

/// File extensions (lower case, with dot) that the sequence reader understands: meshes, and
/// point clouds (.xyz .pcd, and .ply without faces) that are reconstructed into meshes.
const std::vector<std::string>& supportedMeshExtensions();
bool hasSupportedMeshExtension(const std::string& path);

/// `spec` is a folder (every supported mesh file in it), a glob pattern (`frames/mesh_*.obj`)
/// or a text file listing one frame path per line (relative to the list's folder; `#`
/// comments). Returns the frames in natural order; throws Error when nothing is found.
std::vector<std::string> listFrames(const std::string& spec);
} // namespace clothtrack
