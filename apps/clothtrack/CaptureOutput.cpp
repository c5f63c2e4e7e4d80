#include "CaptureOutput.h"

#include "Commands.h"

#include "ctMeshConversion.h"

#include <vtkPolyData.h>

#include <cstdio>
#include <filesystem>

namespace fs = std::filesystem;

namespace clothtrack::app
{
std::string frameStem(long k)
{
  char name[32];
  std::snprintf(name, sizeof(name), "frame_%04ld", k);
  return name;
}

void makeOutputFolders(const std::string& output, std::initializer_list<const char*> extra,
                       bool withSourceMap)
{
  std::vector<const char*> folders = {"frames"};
  if (withSourceMap) folders.push_back("source_map");
  folders.insert(folders.end(), extra.begin(), extra.end());
  for (const char* sub : folders)
  {
    std::error_code ec;
    fs::create_directories(fs::path(output) / sub, ec);
    if (ec) throw UsageError{output + ": cannot create folder (" + ec.message() + ")"};
  }
}

void captureAndWrite(const std::string& output, long k, const TriangleMesh& truth,
                     CaptureOptions options, unsigned seed)
{
  // Every frame gets its own noise, reproducibly.
  options.seed = seed * 1000003u + static_cast<unsigned>(k);
  SourceMap map;
  const TriangleMesh captured = simulateCapture(truth, options, &map);
  vtkSmartPointer<vtkPolyData> mesh = toPolyData(captured);
  writeMeshFile((fs::path(output) / "frames" / (frameStem(k) + ".obj")).string(), mesh);
  addSourceMapArrays(map, mesh);
  writeMeshFile((fs::path(output) / "source_map" / (frameStem(k) + ".vtp")).string(), mesh);
}
} // namespace clothtrack::app
