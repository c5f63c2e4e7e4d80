// Strict reader for legacy VTK POLYDATA files, ASCII or binary, in both cell layouts: the one
// before version 5.0 (`POLYGONS n size` followed by counted index lists) and the one from 5.0 on
// (`OFFSETS` and `CONNECTIVITY` arrays). The layout is told by the file's content, not its version
// line, and every declared count is checked against the bytes left before anything is allocated:
// VTK's own reader trusts both and crashes on files that disagree with them.
#include "FileBytes.h"
#include "MeshIO.h"
#include <clothtrack/base/Error.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <sstream>
#include <vector>

namespace clothtrack
{
namespace
{
int valueSize(const std::string& type)
{
  if (type == "char" || type == "unsigned_char" || type == "bit") return 1;
  if (type == "short" || type == "unsigned_short") return 2;
  if (type == "int" || type == "unsigned_int" || type == "float" || type == "vtktypeint32")
    return 4;
  if (type == "long" || type == "unsigned_long" || type == "double" || type == "vtkIdType" ||
      type == "vtktypeint64" || type == "vtktypeuint64")
    return 8;
  return 0;
}

class LegacyCursor
{
public:
  LegacyCursor(const std::string& path, const std::string& data) : path_(path), data_(data) {}

  bool atEnd()
  {
    skipSpace();
    return pos_ >= data_.size();
  }

  /// Whether the next word is `word`, without moving on.
  bool nextIs(const std::string& word)
  {
    skipSpace();
    return data_.compare(pos_, word.size(), word) == 0;
  }

  /// The lines up to and with the first blank one (a METADATA block's end).
  void skipBlock()
  {
    while (pos_ < data_.size())
    {
      size_t end = data_.find('\n', pos_);
      if (end == std::string::npos) end = data_.size();
      bool blank = true;
      for (size_t i = pos_; i < end; ++i)
        blank = blank && std::isspace(static_cast<unsigned char>(data_[i]));
      pos_ = std::min(end + 1, data_.size());
      if (blank) return;
    }
  }

  /// The next non-blank line, without its line break.
  std::string line(const char* what)
  {
    skipSpace();
    if (pos_ >= data_.size()) throw Error(path_ + ": truncated file: missing " + what);
    size_t end = data_.find('\n', pos_);
    if (end == std::string::npos) end = data_.size();
    std::string text = data_.substr(pos_, end - pos_);
    pos_ = std::min(end + 1, data_.size());
    if (!text.empty() && text.back() == '\r') text.pop_back();
    return text;
  }

  /// Fails unless `count` values of `size` bytes (binary) or at least two characters each
  /// (ASCII: a digit and a separator) fit in what is left of the file.
  void expect(long count, int size, bool binary, const std::string& what) const
  {
    const size_t left = data_.size() - pos_;
    const size_t perValue = binary ? static_cast<size_t>(size) : 2;
    if (count < 0 || static_cast<unsigned long>(count) > (left + 1) / perValue)
      throw Error(path_ + ": " + what + " declares " + std::to_string(count) +
                  " values, more than the " + std::to_string(left) +
                  " bytes left in the file hold (truncated file or corrupt header)");
  }

  /// `count` values of `type`, big-endian when binary (the legacy format's byte order).
  std::vector<double> values(long count, const std::string& type, bool binary,
                             const std::string& what)
  {
    const int size = valueSize(type);
    if (size == 0) throw Error(path_ + ": " + what + " has unsupported type '" + type + "'");
    expect(count, size, binary, what);
    std::vector<double> out(static_cast<size_t>(count));
    if (!binary)
    {
      for (double& v : out) v = asciiValue(what);
      return out;
    }
    skipLineBreak();
    if (data_.size() - pos_ < static_cast<size_t>(count) * size)
      throw Error(path_ + ": truncated file (binary " + what + " ends early)");
    for (double& v : out)
    {
      v = binaryValue(type, size);
      pos_ += size;
    }
    return out;
  }

private:
  void skipSpace()
  {
    while (pos_ < data_.size() && std::isspace(static_cast<unsigned char>(data_[pos_]))) ++pos_;
  }

  void skipLineBreak()
  {
    while (pos_ < data_.size() && (data_[pos_] == ' ' || data_[pos_] == '\r')) ++pos_;
    if (pos_ < data_.size() && data_[pos_] == '\n') ++pos_;
  }

  double asciiValue(const std::string& what)
  {
    skipSpace();
    if (pos_ >= data_.size()) throw Error(path_ + ": truncated file (" + what + " ends early)");
    const char* start = data_.c_str() + pos_;
    char* end = nullptr;
    const double value = std::strtod(start, &end);
    if (end == start)
      throw Error(path_ + ": malformed number in " + what + " near byte " + std::to_string(pos_));
    pos_ += end - start;
    return value;
  }

  double binaryValue(const std::string& type, int size) const
  {
    unsigned char bytes[8];
    for (int i = 0; i < size; ++i) bytes[i] = data_[pos_ + size - 1 - i]; // big to little
    const uint16_t one = 1;
    if (*reinterpret_cast<const unsigned char*>(&one) != 1) // big-endian host: as stored
      for (int i = 0; i < size; ++i) bytes[i] = data_[pos_ + i];
    if (type == "float") return as<float>(bytes);
    if (type == "double") return as<double>(bytes);
    if (type == "char") return static_cast<int8_t>(bytes[0]);
    if (size == 1) return bytes[0];
    if (type == "short") return as<int16_t>(bytes);
    if (type == "unsigned_short") return as<uint16_t>(bytes);
    if (type == "unsigned_int") return as<uint32_t>(bytes);
    if (size == 4) return as<int32_t>(bytes);
    if (type == "unsigned_long" || type == "vtktypeuint64")
      return static_cast<double>(as<uint64_t>(bytes));
    return static_cast<double>(as<int64_t>(bytes));
  }

  template <class T> static double as(const unsigned char* bytes)
  {
    T value;
    std::memcpy(&value, bytes, sizeof(T));
    return static_cast<double>(value);
  }

  const std::string& path_;
  const std::string& data_;
  size_t pos_ = 0;
};

std::vector<std::string> words(const std::string& text)
{
  std::istringstream in(text);
  std::vector<std::string> out;
  for (std::string w; in >> w;) out.push_back(w);
  return out;
}

long count(const std::string& path, const std::string& word, const std::string& line)
{
  char* end = nullptr;
  errno = 0;
  const long value = std::strtol(word.c_str(), &end, 10);
  if (end == word.c_str() || *end != '\0' || errno == ERANGE || value < 0)
    throw Error(path + ": malformed count '" + word + "' in '" + line.substr(0, 60) + "'");
  return value;
}

/// A vertex index read from the file, checked against the vertex count.
int vertexIndex(const std::string& path, double value, long vertices, const std::string& what)
{
  if (!(value >= 0 && value < static_cast<double>(vertices)) || value != static_cast<long>(value))
  {
    char index[32];
    std::snprintf(index, sizeof(index), "%.17g", value);
    throw Error(path + ": " + what + " uses vertex index " + index + ", out of range [0, " +
                std::to_string(vertices) + ")");
  }
  return static_cast<int>(value);
}

/// One cell section's cells as index lists, in either layout; `header` is its split first line.
std::vector<std::vector<int>> readCells(const std::string& path, LegacyCursor& cursor,
                                        const std::vector<std::string>& header, bool binary,
                                        long vertices)
{
  const std::string what = header[0];
  if (header.size() < 3) throw Error(path + ": malformed " + what + " line");
  const long first = count(path, header[1], what), second = count(path, header[2], what);
  std::vector<std::vector<int>> cells;
  if (cursor.nextIs("OFFSETS"))
  {
    const std::vector<std::string> offsetsLine = words(cursor.line("OFFSETS"));
    if (offsetsLine.size() < 2) throw Error(path + ": malformed OFFSETS line");
    const std::vector<double> offsets =
        cursor.values(first, offsetsLine[1], binary, what + " offsets");
    const std::vector<std::string> conn = words(cursor.line("CONNECTIVITY"));
    if (conn.size() < 2 || conn[0] != "CONNECTIVITY")
      throw Error(path + ": " + what + " OFFSETS not followed by CONNECTIVITY");
    const std::vector<double> ids = cursor.values(second, conn[1], binary, what + " connectivity");
    for (long c = 0; c + 1 < first; ++c)
    {
      const double begin = offsets[c], end = offsets[c + 1];
      if (!(begin >= 0 && begin <= end && end <= static_cast<double>(second)))
        throw Error(path + ": " + what + " offsets are not increasing within [0, " +
                    std::to_string(second) + "] at cell " + std::to_string(c));
      std::vector<int> cell;
      for (long k = static_cast<long>(begin); k < static_cast<long>(end); ++k)
        cell.push_back(vertexIndex(path, ids[k], vertices, what));
      cells.push_back(std::move(cell));
    }
    return cells;
  }
  // Before 5.0: `second` integers, each cell its vertex count and then its indices.
  const std::vector<double> list = cursor.values(second, "int", binary, what);
  size_t k = 0;
  for (long c = 0; c < first; ++c)
  {
    const double n = k < list.size() ? list[k++] : -1;
    if (!(n >= 0 && n <= static_cast<double>(list.size() - k)))
      throw Error(path + ": " + what + " cell " + std::to_string(c) +
                  " has a vertex count that overruns the section's " + std::to_string(second) +
                  " values");
    std::vector<int> cell;
    for (long i = 0; i < static_cast<long>(n); ++i)
      cell.push_back(vertexIndex(path, list[k++], vertices, what));
    cells.push_back(std::move(cell));
  }
  return cells;
}

void addPolygons(const std::vector<std::vector<int>>& cells, std::vector<int>& faces)
{
  for (const std::vector<int>& cell : cells)
    for (size_t k = 1; k + 1 < cell.size(); ++k)
      faces.insert(faces.end(), {cell[0], cell[k], cell[k + 1]});
}

void addStrips(const std::vector<std::vector<int>>& cells, std::vector<int>& faces)
{
  for (const std::vector<int>& cell : cells)
    for (size_t k = 0; k + 2 < cell.size(); ++k) // alternate the winding: one facing for all
      if (k % 2 == 0)
        faces.insert(faces.end(), {cell[k], cell[k + 1], cell[k + 2]});
      else
        faces.insert(faces.end(), {cell[k + 1], cell[k], cell[k + 2]});
}

/// A FIELD section (`FIELD name arrays`, then per array `name components tuples type` and its
/// values, each perhaps followed by METADATA): skipped, the geometry does not need it.
void skipFieldData(const std::string& path, LegacyCursor& cursor,
                   const std::vector<std::string>& header, bool binary)
{
  if (header.size() < 3) throw Error(path + ": malformed FIELD line");
  const long arrays = count(path, header[2], "FIELD");
  for (long a = 0; a < arrays; ++a)
  {
    const std::string text = cursor.line("FIELD array");
    const std::vector<std::string> array = words(text);
    if (array.size() < 4) throw Error(path + ": malformed FIELD array line '" + text + "'");
    const long components = count(path, array[1], text), tuples = count(path, array[2], text);
    if (components > 0 && tuples > (1L << 40) / components)
      throw Error(path + ": FIELD array '" + array[0] + "' declares too many values");
    cursor.values(components * tuples, array[3], binary, "FIELD array " + array[0]);
    if (cursor.nextIs("METADATA"))
    {
      cursor.line("METADATA");
      cursor.skipBlock();
    }
  }
}

/// The header: version line, title, ASCII or BINARY, DATASET POLYDATA. Returns whether binary.
bool readHeader(const std::string& path, LegacyCursor& cursor)
{
  const std::string version = cursor.line("version line");
  const std::string prefix = "# vtk DataFile Version ";
  char* end = nullptr;
  if (version.compare(0, prefix.size(), prefix) != 0 ||
      (std::strtod(version.c_str() + prefix.size(), &end), end == version.c_str() + prefix.size()))
    throw Error(path + ": not a legacy VTK file (first line is not '# vtk DataFile Version N')");
  cursor.line("title line");
  const std::vector<std::string> encoding = words(cursor.line("ASCII or BINARY line"));
  if (encoding.empty() || (encoding[0] != "ASCII" && encoding[0] != "BINARY"))
    throw Error(path + ": legacy VTK file lacks its ASCII or BINARY line");
  const std::vector<std::string> dataset = words(cursor.line("DATASET line"));
  if (dataset.size() < 2 || dataset[0] != "DATASET")
    throw Error(path + ": legacy VTK file lacks its DATASET line");
  if (dataset[1] != "POLYDATA")
    throw Error(path + ": legacy VTK file does not hold POLYDATA (it holds " + dataset[1] + ")");
  return encoding[0] == "BINARY";
}
} // namespace

TriangleMesh readLegacyVTK(const std::string& path)
{
  const std::string data = readFileBytes(path);
  if (data.empty()) throw Error(path + ": empty file");
  LegacyCursor cursor(path, data);
  const bool binary = readHeader(path, cursor);
  std::vector<double> coords;
  std::vector<int> faces;
  bool havePoints = false;
  // Point and cell attributes follow the geometry; they are not needed.
  while (!cursor.atEnd() && !cursor.nextIs("POINT_DATA") && !cursor.nextIs("CELL_DATA"))
  {
    const std::string text = cursor.line("section");
    const std::vector<std::string> section = words(text);
    if (section.empty()) continue;
    if (section[0] == "POINTS")
    {
      if (section.size() < 3) throw Error(path + ": malformed POINTS line");
      const long n = count(path, section[1], text);
      if (n > (1L << 31) / 3) throw Error(path + ": POINTS declares too many points");
      coords = cursor.values(3 * n, section[2], binary, "POINTS");
      havePoints = true;
    }
    else if (section[0] == "POLYGONS" || section[0] == "TRIANGLE_STRIPS" ||
             section[0] == "VERTICES" || section[0] == "LINES")
    {
      if (!havePoints) throw Error(path + ": " + section[0] + " before POINTS");
      const auto cells = readCells(path, cursor, section, binary, coords.size() / 3);
      if (section[0] == "POLYGONS") addPolygons(cells, faces);
      if (section[0] == "TRIANGLE_STRIPS") addStrips(cells, faces);
    }
    else if (section[0] == "METADATA") // information keys, up to a blank line
      cursor.skipBlock();
    else if (section[0] == "FIELD")
      skipFieldData(path, cursor, section, binary);
    else
      throw Error(path + ": unknown legacy VTK section '" + section[0].substr(0, 30) + "'");
  }
  if (!havePoints) throw Error(path + ": empty mesh (no POINTS section)");
  return meshFromArrays(coords, faces);
}
} // namespace clothtrack
