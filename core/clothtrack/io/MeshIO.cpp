#include "MeshIO.h"

#include <clothtrack/base/Error.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <vector>

namespace clothtrack
{
TriangleMesh meshFromArrays(const std::vector<double>& coords, const std::vector<int>& faces)
{
  TriangleMesh mesh;
  mesh.V = Eigen::Map<const Points>(coords.data(), static_cast<Eigen::Index>(coords.size() / 3), 3);
  mesh.F =
      Eigen::Map<const Triangles>(faces.data(), static_cast<Eigen::Index>(faces.size() / 3), 3);
  return mesh;
}

namespace
{
std::FILE* openForWrite(const std::string& path)
{
  std::FILE* out = std::fopen(path.c_str(), "w");
  if (!out) throw Error(path + ": cannot write file (" + std::strerror(errno) + ")");
  return out;
}

void closeChecked(std::FILE* out, const std::string& path)
{
  const bool failed = std::ferror(out) != 0;
  if (std::fclose(out) != 0 || failed) throw Error(path + ": write error (disk full?)");
}
} // namespace

void writeOBJ(const std::string& path, const TriangleMesh& mesh)
{
  std::FILE* out = openForWrite(path);
  for (int i = 0; i < mesh.numVertices(); ++i)
    std::fprintf(out, "v %.9g %.9g %.9g\n", mesh.V(i, 0), mesh.V(i, 1), mesh.V(i, 2));
  for (int f = 0; f < mesh.numFaces(); ++f)
    std::fprintf(out, "f %d %d %d\n", mesh.F(f, 0) + 1, mesh.F(f, 1) + 1, mesh.F(f, 2) + 1);
  closeChecked(out, path);
}

void writeOFF(const std::string& path, const TriangleMesh& mesh)
{
  std::FILE* out = openForWrite(path);
  std::fprintf(out, "OFF\n%d %d 0\n", mesh.numVertices(), mesh.numFaces());
  for (int i = 0; i < mesh.numVertices(); ++i)
    std::fprintf(out, "%.9g %.9g %.9g\n", mesh.V(i, 0), mesh.V(i, 1), mesh.V(i, 2));
  for (int f = 0; f < mesh.numFaces(); ++f)
    std::fprintf(out, "3 %d %d %d\n", mesh.F(f, 0), mesh.F(f, 1), mesh.F(f, 2));
  closeChecked(out, path);
}
} // namespace clothtrack
