#pragma once
// A mesh as its arrays in one binary file: what a long run keeps of each cleaned frame, so that
// reading it again costs a copy, not parsing and cleaning (io/MeshIO.h reads a capture's formats).
#include <clothtrack/mesh/TriangleMesh.h>

#include <string>

namespace clothtrack
{
/// Writes `mesh` to `path` beside and renames it (a file that exists is complete). Throws Error
/// naming the file.
void writeMeshBinary(const std::string& path, const TriangleMesh& mesh);
/// Reads a file writeMeshBinary wrote; throws Error naming the file when it is not one (another
/// format, truncated, indices out of range).
TriangleMesh readMeshBinary(const std::string& path);
} // namespace clothtrack
