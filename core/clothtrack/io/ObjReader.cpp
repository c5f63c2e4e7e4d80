// Wavefront OBJ, read in place from the file's bytes: vertex and face lines without tokens.
#include "FileContents.h"
#include "MeshIO.h"
#include "RowAppender.h"
#include "TextTokens.h"

#include <clothtrack/base/Error.h>

#include <algorithm>
#include <charconv>
#include <cstdint>
#include <cstring>
#include <limits>
#include <string_view>
#include <vector>

namespace clothtrack
{
namespace
{
/// Whether `p` ends a word of an OBJ line: a separator, the newline or the end of the text.
bool endsWord(const char* p, const char* end)
{
  return p == end || *p == '\n' || isSpace(*p);
}

/// The start of the next line when `p`, after spaces, is at the end of this one; null otherwise.
const char* nextLine(const char* p, const char* end)
{
  skipSpaces(p, end);
  if (p == end) return end;
  return *p == '\n' ? p + 1 : nullptr;
}

/// The common OBJ vertex line, "x y z" after the "v", read in place to its newline (no search for
/// it first). Returns the start of the next line, or null when the line is anything else: the
/// general path then reads it, or says what is wrong with it.
const char* readVertexQuickly(const char* p, const char* end, double xyz[3])
{
  for (int k = 0; k < 3; ++k)
  {
    skipSpaces(p, end);
    const char* stop = readNumberInPlace(p, end, xyz[k]);
    if (!stop || !endsWord(stop, end)) return nullptr;
    p = stop;
  }
  return nextLine(p, end);
}

/// The common OBJ face line, indices "i", "i/t", "i//n" or "i/t/n" after the "f", read in place
/// into `indices`. Returns the start of the next line, or null when the line is anything else
/// (the general path decides).
const char* readFaceQuickly(const char* p, const char* end, std::vector<long>& indices)
{
  indices.clear();
  for (skipSpaces(p, end); p < end && *p != '\n'; skipSpaces(p, end))
  {
    long index = 0;
    const auto [stop, error] = std::from_chars(p, end, index);
    if (error != std::errc() || stop == p) return nullptr;
    p = stop;
    if (p < end && *p == '/')
      while (!endsWord(p, end)) ++p;
    else if (!endsWord(p, end))
      return nullptr;
    indices.push_back(index);
  }
  if (indices.size() < 3) return nullptr;
  return p == end ? end : p + 1;
}

struct ObjRecordCounts
{
  Eigen::Index vertices = 0, faces = 0;
};

/// The vertex and face records of an OBJ text, estimated from the lines that start with 'v ' or
/// 'f ' in its first 256 kB, scaled to its size with 5 % to spare: the arrays' first sizes, grown
/// or trimmed after (trimming reallocates in place). Without a branch a byte and with 32-bit
/// counts, the compiler vectorises the loop; counting the whole file took an eighth of readOBJ's
/// time.
ObjRecordCounts estimateObjRecords(std::string_view text)
{
  const auto* bytes = reinterpret_cast<const unsigned char*>(text.data());
  const size_t sampled = std::min<size_t>(text.size(), 256 << 10);
  std::uint32_t vertexLines = sampled > 1 && bytes[0] == 'v' && bytes[1] == ' ';
  std::uint32_t faceLines = sampled > 1 && bytes[0] == 'f' && bytes[1] == ' ';
  for (size_t i = 0; i + 2 < sampled; ++i)
  {
    const std::uint32_t lineStart = bytes[i] == '\n', spaceAfter = bytes[i + 2] == ' ';
    vertexLines += lineStart & spaceAfter & (bytes[i + 1] == 'v');
    faceLines += lineStart & spaceAfter & (bytes[i + 1] == 'f');
  }
  if (sampled == text.size()) return {vertexLines, faceLines};
  const double scale = 1.05 * static_cast<double>(text.size()) / static_cast<double>(sampled);
  return {static_cast<Eigen::Index>(scale * vertexLines) + 16,
          static_cast<Eigen::Index>(scale * faceLines) + 16};
}

[[noreturn]] void throwIndexOutOfRange(const std::string& location, long raw,
                                       const std::string& why)
{
  throw Error(location + "face index " + std::to_string(raw) + " out of range (" + why + ")");
}
} // namespace

TriangleMesh readOBJ(const std::string& path, const std::string& onlyGroup)
{
  const FileContents file(path);
  const std::string_view text = file.bytes();
  if (text.empty()) throw Error(path + ": empty file");
  if (std::memchr(text.data(), '\0', text.size()))
    throw Error(path + ": not a text OBJ file (contains NUL bytes)");
  const ObjRecordCounts expected = estimateObjRecords(text);
  TriangleMesh mesh;
  RowAppender<Points> vertices(mesh.V, expected.vertices);
  RowAppender<Triangles> triangles(mesh.F, expected.faces);
  std::vector<std::string_view> tokens;
  std::vector<long> faceIndices;
  int lineNo = 0;
  bool inGroup = onlyGroup.empty();
  // Positive indices may name vertices defined later: the largest is checked at the end.
  long largestIndex = 0;
  int largestIndexLine = 0;
  auto resolve = [&](long raw)
  {
    if (raw > largestIndex)
    {
      largestIndex = raw;
      largestIndexLine = lineNo;
    }
    if (raw > 0) // beyond any int: refused at the end, as beyond the vertex count
      return raw <= std::numeric_limits<int>::max() ? static_cast<int>(raw - 1) : 0;
    if (raw == 0) throwIndexOutOfRange(lineLocation(path, lineNo), raw, "indices start at 1");
    // Negative indices count back from the vertices read so far.
    const long idx = static_cast<long>(vertices.size()) + raw;
    if (idx < 0)
      throwIndexOutOfRange(lineLocation(path, lineNo), raw,
                           std::to_string(vertices.size()) + " vertices before it");
    return static_cast<int>(idx);
  };
  auto addFace = [&]()
  {
    const int first = resolve(faceIndices[0]);
    int previous = resolve(faceIndices[1]);
    for (size_t k = 2; k < faceIndices.size(); ++k)
    {
      const int current = resolve(faceIndices[k]);
      triangles.add(first, previous, current);
      previous = current;
    }
  };
  const char* p = text.data();
  const char* end = p + text.size();
  while (p < end)
  {
    ++lineNo;
    const char* line = p;
    skipSpaces(line, end);
    // Most lines are plain vertices and faces: read in place, without tokens.
    if (end - line > 1 && isSpace(line[1]))
    {
      double xyz[3];
      if (line[0] == 'v' && (p = readVertexQuickly(line + 1, end, xyz)))
      {
        vertices.add(xyz[0], xyz[1], xyz[2]);
        continue;
      }
      if (line[0] == 'f' && inGroup && (p = readFaceQuickly(line + 1, end, faceIndices)))
      {
        addFace();
        continue;
      }
    }
    const char* eol = static_cast<const char*>(std::memchr(line, '\n', end - line));
    if (!eol) eol = end;
    p = eol + 1;
    tokenize(line, eol, tokens);
    if (tokens.empty() || tokens[0][0] == '#') continue;
    if (tokens[0] == "v")
    {
      double xyz[3];
      if (tokens.size() < 4 || !parseDouble(tokens[1], xyz[0]) || !parseDouble(tokens[2], xyz[1]) ||
          !parseDouble(tokens[3], xyz[2]))
        throw Error(lineLocation(path, lineNo) +
                    "malformed vertex record (expected 'v x y z'; truncated file?)");
      vertices.add(xyz[0], xyz[1], xyz[2]);
    }
    else if (tokens[0] == "g" && !onlyGroup.empty())
      inGroup = tokens.size() > 1 && tokens[1] == onlyGroup;
    else if (tokens[0] == "f" && inGroup)
    {
      if (tokens.size() < 4)
        throw Error(lineLocation(path, lineNo) +
                    "face with fewer than 3 vertices (truncated file?)");
      faceIndices.clear();
      for (size_t k = 1; k < tokens.size(); ++k)
      {
        long idx;
        if (!parseIndex(tokens[k], idx))
          throw Error(lineLocation(path, lineNo) + "malformed face index '" +
                      std::string(tokens[k]) + "'");
        faceIndices.push_back(idx);
      }
      addFace();
    }
  }
  if (largestIndex > vertices.size())
    throwIndexOutOfRange(lineLocation(path, largestIndexLine), largestIndex,
                         "file has " + std::to_string(vertices.size()) + " vertices");
  vertices.finish();
  triangles.finish();
  return mesh;
}
} // namespace clothtrack
