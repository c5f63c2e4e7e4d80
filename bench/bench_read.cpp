// Mesh reading speed, measured.
//   bench_read FILE... [--repeat N]
// For each file format among the files: the bytes read, the time of the strict core reader alone
// (readMeshFile), of a frame as align loads it (loadFrame: reader, units, validation and
// repairs), and of counting the lines of the same bytes (the floor a text parser cannot beat),
// each as MB/s over all files. The first pass warms the file cache and is not counted.
#include "ctMeshConversion.h"

#include <clothtrack/base/MemoryReuse.h>
#include <clothtrack/io/FileBytes.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

using namespace clothtrack;

namespace
{
double seconds(std::chrono::steady_clock::time_point since)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - since).count();
}

struct Totals
{
  double bytes = 0, read = 0, load = 0, lines = 0;
  int files = 0;
};
} // namespace

int main(int argc, char** argv)
{
  keepFreedMemoryForReuse(); // as the app does
  std::vector<std::string> files;
  int repeat = 3;
  for (int i = 1; i < argc; ++i)
  {
    if (std::strcmp(argv[i], "--repeat") == 0 && i + 1 < argc)
      repeat = std::max(1, std::atoi(argv[++i]));
    else
      files.push_back(argv[i]);
  }
  if (files.empty())
  {
    std::fprintf(stderr, "usage: bench_read FILE... [--repeat N]\n");
    return 1;
  }
  std::map<std::string, Totals> byFormat;
  for (int pass = 0; pass <= repeat; ++pass)
    for (const std::string& file : files)
    {
      Totals& t = byFormat[std::filesystem::path(file).extension().string()];
      auto start = std::chrono::steady_clock::now();
      const std::string bytes = readFileBytes(file, false);
      size_t lines = 0;
      for (const char* p = bytes.data();
           (p = static_cast<const char*>(std::memchr(p, '\n', bytes.data() + bytes.size() - p)));
           ++p)
        ++lines;
      const double countSeconds = seconds(start);
      start = std::chrono::steady_clock::now();
      const TriangleMesh mesh = readMeshFile(file);
      const double readSeconds = seconds(start);
      start = std::chrono::steady_clock::now();
      const TriangleMesh frame = loadFrame(file, FrameConventions());
      const double loadSeconds = seconds(start);
      if (pass == 0 || mesh.numVertices() == 0 || lines == 0) continue; // warm-up
      t.bytes += static_cast<double>(bytes.size());
      t.lines += countSeconds;
      t.read += readSeconds;
      t.load += loadSeconds;
      ++t.files;
    }
  std::printf("%-6s %6s %9s %14s %14s %14s\n", "format", "files", "MB/file", "lines MB/s",
              "reader MB/s", "loadFrame MB/s");
  for (const auto& [format, t] : byFormat)
  {
    const double mb = t.bytes / 1e6;
    std::printf("%-6s %6d %9.2f %14.0f %14.1f %14.1f\n", format.c_str(), t.files / repeat,
                mb / t.files, mb / t.lines, mb / t.read, mb / t.load);
  }
  return 0;
}
