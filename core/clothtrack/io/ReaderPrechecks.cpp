#include "ReaderPrechecks.h"
#include "FileBytes.h"

#include <clothtrack/base/Error.h>

#include <algorithm>
#include <cerrno>
#include <cstdint>
#include <cstdlib>
#include <cstring>

namespace clothtrack
{
namespace
{
bool startsWithSolid(const std::string& data)
{
  size_t p = 0;
  while (p < data.size() &&
         (data[p] == ' ' || data[p] == '\t' || data[p] == '\r' || data[p] == '\n'))
    ++p;
  return data.compare(p, 5, "solid") == 0;
}
} // namespace

void checkSTLFile(const std::string& path)
{
  // Binary: little-endian triangle count after the 80-byte header, checked against the file's
  // size without reading the triangles (VTK's reader reads them next).
  const std::uintmax_t size = fileSizeOf(path);
  uint32_t declared = 0;
  if (size >= 84)
  {
    const std::string head =
        readFileStart(path, [](const std::string& bytes) { return bytes.size() >= 84; });
    if (head.size() < 84) throw Error(path + ": read error (the file shrank while read)");
    const auto* b = reinterpret_cast<const unsigned char*>(head.data() + 80);
    declared = b[0] | (b[1] << 8) | (b[2] << 16) | (static_cast<uint32_t>(b[3]) << 24);
    if (84 + 50 * static_cast<uint64_t>(declared) == size)
    {
      if (declared == 0) throw Error(path + ": binary STL with no triangle");
      return;
    }
  }
  const std::string data = readFileBytes(path, /*text=*/false);
  // Not a consistent binary file: ASCII, or a binary one whose count disagrees with its size.
  // VTK's reader takes a file with a few bytes other than printable text and line breaks for
  // binary, whatever its first word: any such file must be a consistent binary one.
  const bool ascii = std::all_of(data.begin(), data.end(),
                                 [](char c)
                                 {
                                   const auto byte = static_cast<unsigned char>(c);
                                   return (byte >= 32 && byte <= 126) || byte == '\n' ||
                                          byte == '\r' || byte == '\t';
                                 });
  if (startsWithSolid(data) && ascii) return;
  if (data.size() < 84) throw Error(path + ": not an STL file (too short, no 'solid' header)");
  throw Error(path + ": binary STL header declares " + std::to_string(declared) +
              " triangles but the file has room for " + std::to_string((data.size() - 84) / 50) +
              " (truncated or corrupt file)");
}

void checkVTKXMLFile(const std::string& path)
{
  // The XML part ends where raw appended data begins: only that much is read here (the data
  // behind it is VTK's reader's to read), the file's size from the file system.
  const std::string marker = "<AppendedData";
  size_t searched = 0; // each chunk searched once, from the marker's length before it
  auto holdsMarker = [&](const std::string& bytes)
  {
    const size_t from = searched > marker.size() ? searched - marker.size() : 0;
    searched = bytes.size();
    return bytes.find(marker, from) != std::string::npos;
  };
  const std::string data = readFileStart(path, holdsMarker);
  const std::uintmax_t fileSize = fileSizeOf(path);
  const size_t xmlEnd = std::min(data.size(), data.find(marker));
  const std::string key = "NumberOf";
  for (size_t p = data.find(key); p < xmlEnd; p = data.find(key, p + 1))
  {
    const size_t quote = data.find('"', p);
    const size_t eq = data.find('=', p);
    if (quote >= xmlEnd || eq >= quote) continue;
    const std::string name = data.substr(p, eq - p);
    if (name.find_first_of(" \t\n<>") != std::string::npos) continue;
    const char* start = data.c_str() + quote + 1;
    char* end = nullptr;
    errno = 0;
    const long long value = std::strtoll(start, &end, 10);
    if (end == start || *end != '"' || errno == ERANGE || value < 0)
      throw Error(path + ": " + name + " is '" +
                  std::string(start, std::strcspn(start, "\"")).substr(0, 30) +
                  "', not a count (corrupt file)");
    // A point is 3 coordinates of at least 4 bytes, a cell at least one offset of 1 byte; no
    // compressor of VTK's shrinks data more than about a thousand times.
    const bool cells = name == "NumberOfVerts" || name == "NumberOfLines" ||
                       name == "NumberOfStrips" || name == "NumberOfPolys" ||
                       name == "NumberOfCells";
    const double bytesPer = name == "NumberOfPoints" ? 12.0 : cells ? 1.0 : 0.0;
    if (static_cast<double>(value) * bytesPer / 1100.0 > static_cast<double>(fileSize))
      throw Error(path + ": " + name + " is " + std::to_string(value) + ", more than the file's " +
                  std::to_string(fileSize) + " bytes can hold (corrupt file)");
  }
}
} // namespace clothtrack
