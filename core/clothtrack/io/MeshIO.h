#pragma once
// Strict readers and writers for the text formats the core handles itself (OBJ, OFF). They
// fail with an Error naming the file and line rather than guessing on a malformed file.
#include <clothtrack/mesh/TriangleMesh.h>

#include <string>
#include <vector>

namespace clothtrack
{
/// Wavefront OBJ: `v` and `f` records (indices may be negative, `v/vt/vn` forms accepted);
/// polygons are triangulated as fans. Other records are ignored. With `onlyGroup`, only the faces
/// of that `g` group are kept (all vertices are, so that indices keep their meaning).
TriangleMesh readOBJ(const std::string& path, const std::string& onlyGroup = {});
/// Object File Format (OFF); polygons are triangulated as fans.
TriangleMesh readOFF(const std::string& path);
/// Stanford PLY, ASCII or binary (either endianness): vertex x, y, z and the face
/// vertex_indices list; other elements and properties are skipped. Checked against truncation.
TriangleMesh readPLY(const std::string& path);
/// Legacy VTK POLYDATA, ASCII or binary, either cell layout (before and from version 5.0): the
/// POLYGONS and TRIANGLE_STRIPS; vertices, lines and attributes are skipped. Every declared count
/// is checked against the file before it is allocated.
TriangleMesh readLegacyVTK(const std::string& path);

/// A mesh from the flat arrays the readers collect: x y z per vertex, three indices per triangle.
TriangleMesh meshFromArrays(const std::vector<double>& coords, const std::vector<int>& faces);

void writeOBJ(const std::string& path, const TriangleMesh& mesh);
void writeOFF(const std::string& path, const TriangleMesh& mesh);
} // namespace clothtrack
