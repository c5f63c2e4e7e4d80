#include "MeshBinary.h"

#include <clothtrack/base/Error.h>

#include <cstdint>
#include <cstdio>
#include <cstring>
#include <memory>

namespace clothtrack
{
namespace
{
constexpr char kMagic[8] = {'C', 'T', 'M', 'E', 'S', 'H', '0', '1'};

struct Header
{
  char magic[8];
  std::int64_t vertices = 0, faces = 0;
};

using File = std::unique_ptr<std::FILE, int (*)(std::FILE*)>;
} // namespace

void writeMeshBinary(const std::string& path, const TriangleMesh& mesh)
{
  const std::string part = path + ".part";
  {
    File file(std::fopen(part.c_str(), "wb"), &std::fclose);
    if (!file) throw Error(path + ": cannot be written");
    Header header;
    std::memcpy(header.magic, kMagic, sizeof(kMagic));
    header.vertices = mesh.numVertices();
    header.faces = mesh.numFaces();
    const bool written = std::fwrite(&header, sizeof(header), 1, file.get()) == 1 &&
                         std::fwrite(mesh.V.data(), sizeof(double), mesh.V.size(), file.get()) ==
                             static_cast<size_t>(mesh.V.size()) &&
                         std::fwrite(mesh.F.data(), sizeof(int), mesh.F.size(), file.get()) ==
                             static_cast<size_t>(mesh.F.size());
    if (!written || std::fflush(file.get()) != 0)
      throw Error(path + ": writing failed (disk full?)");
  }
  if (std::rename(part.c_str(), path.c_str()) != 0) throw Error(path + ": cannot be written");
}

TriangleMesh readMeshBinary(const std::string& path)
{
  File file(std::fopen(path.c_str(), "rb"), &std::fclose);
  if (!file) throw Error(path + ": cannot be opened");
  Header header;
  if (std::fread(&header, sizeof(header), 1, file.get()) != 1 ||
      std::memcmp(header.magic, kMagic, sizeof(kMagic)) != 0)
    throw Error(path + ": not a ClothTrack binary mesh");
  std::fseek(file.get(), 0, SEEK_END);
  const long size = std::ftell(file.get());
  const std::int64_t expected =
      static_cast<std::int64_t>(sizeof(header)) + 24 * header.vertices + 12 * header.faces;
  if (header.vertices < 0 || header.faces < 0 || header.vertices > (1 << 28) ||
      header.faces > (1 << 28) || size != expected)
    throw Error(path + ": truncated or damaged binary mesh");
  std::fseek(file.get(), sizeof(header), SEEK_SET);
  TriangleMesh mesh;
  mesh.V.resize(header.vertices, 3);
  mesh.F.resize(header.faces, 3);
  if (std::fread(mesh.V.data(), sizeof(double), mesh.V.size(), file.get()) !=
          static_cast<size_t>(mesh.V.size()) ||
      std::fread(mesh.F.data(), sizeof(int), mesh.F.size(), file.get()) !=
          static_cast<size_t>(mesh.F.size()))
    throw Error(path + ": truncated binary mesh");
  if (mesh.F.size() > 0 && (mesh.F.minCoeff() < 0 || mesh.F.maxCoeff() >= header.vertices))
    throw Error(path + ": a face index is out of range");
  return mesh;
}
} // namespace clothtrack
