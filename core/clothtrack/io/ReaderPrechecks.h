#pragma once
// Checks made before a file is handed to one of VTK's readers. Those trust the sizes a file
// declares: a negative or huge count crashes them or asks for terabytes. Each check throws an
// Error naming the file and the problem.
#include <string>

namespace clothtrack
{
/// A binary STL (80-byte header, triangle count, 50 bytes a triangle) must hold exactly the
/// triangles its count declares; an ASCII STL must start with `solid` and hold only printable
/// text, tabs and line breaks (VTK's reader takes any other file for binary).
void checkSTLFile(const std::string& path);

/// The `NumberOf...` attributes of a VTK XML file (points, cells, components, tuples) must be
/// non-negative integers, and the points declared must fit in the file even at the best
/// compression ratio its compressors reach.
void checkVTKXMLFile(const std::string& path);
} // namespace clothtrack
