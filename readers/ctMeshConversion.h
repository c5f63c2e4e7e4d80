#ifndef ctMeshConversion_h
#define ctMeshConversion_h
// Conversions between vtkPolyData and the core's TriangleMesh (not wrapped: C++ only).
#include "ctReadersModule.h"

#include <clothtrack/mesh/TriangleMesh.h>

#include <vtkSmartPointer.h>

#include <string>
#include <utility>
#include <vector>

class vtkPolyData;

namespace clothtrack
{
/// Triangles of the polygons and strips of `polyData` (vertices and lines are ignored;
/// polygons are triangulated as fans). Throws Error, naming `name`, when a cell refers to a
/// point that does not exist.
CTREADERS_EXPORT TriangleMesh toTriangleMesh(vtkPolyData* polyData, const std::string& name);

/// A vtkPolyData with double-precision points and triangle cells.
CTREADERS_EXPORT vtkSmartPointer<vtkPolyData> toPolyData(const TriangleMesh& mesh);

/// Reads one mesh file (.obj .ply .stl .off .vtp .vtk) with the strict core readers or VTK's
/// readers (no validation: see clothtrack::validateAndClean). Throws Error naming the file.
CTREADERS_EXPORT TriangleMesh readMeshFile(const std::string& path);

/// Reads a VTK XML PolyData file (.vtp) with its arrays, guarded as readMeshFile reads it.
/// Throws Error naming the file.
CTREADERS_EXPORT vtkSmartPointer<vtkPolyData> readVTPFile(const std::string& path);

/// Writes a mesh in the format given by the extension (.obj .off .ply .stl .vtp .vtk),
/// through a temporary file renamed at the end so that no half-written file is left behind.
CTREADERS_EXPORT void writeMeshFile(const std::string& path, vtkPolyData* polyData);
/// Unit scale and up axis applied to each frame read from disk.
struct FrameConventions
{
  double unitScale = 1.0; ///< file units to metres
  int upAxis = 1;         ///< 0 = +X, 1 = +Y, 2 = +Z is up in the file; output is Y-up
};

/// Points (or normals, with unitScale 1) from a file's unit and up axis to metres, Y up.
CTREADERS_EXPORT void toMetresYUp(Points& points, const FrameConventions& conventions);

/// readMeshFile, then units and up axis, then validateAndClean. Repairs made (merged
/// vertices, removed zero-area faces) are appended to `warnings` as "path: what".
CTREADERS_EXPORT TriangleMesh loadFrame(const std::string& path,
                                        const FrameConventions& conventions,
                                        std::vector<std::string>* warnings = nullptr);

/// Writes frame `index` of the collection `pvdPath` (out/name.pvd) as out/name/name_NNNN.vtp, and
/// as .obj beside it when `alsoOBJ`; creates the folder. Returns the .vtp path relative to the
/// .pvd, for the collection entry.
CTREADERS_EXPORT std::string writeCollectionFrame(const std::string& pvdPath, int index,
                                                  vtkPolyData* frame, bool alsoOBJ);

/// Writes a ParaView collection file listing (time, relative path) entries, atomically.
CTREADERS_EXPORT void writeCollection(const std::string& pvdPath,
                                      const std::vector<std::pair<double, std::string>>& entries);
} // namespace clothtrack

#endif
