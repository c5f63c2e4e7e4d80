#include "MeshIO.h"
#include "FileBytes.h"
#include "TextTokens.h"

#include <clothtrack/base/Error.h>

#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <string_view>
#include <vector>

namespace clothtrack
{
namespace
{
std::string where(const std::string& path, int line)
{
  return path + ":" + std::to_string(line) + ": ";
}

/// A face index: an integer, alone or followed by '/' (OBJ's v/vt/vn).
bool parseInt(std::string_view token, long& value)
{
  const char* begin = token.data();
  const char* end = begin + token.size();
  if (begin != end && *begin == '+' && end - begin > 1 && begin[1] != '-') ++begin;
  const auto [stop, error] = std::from_chars(begin, end, value);
  return error == std::errc() && stop != begin && (stop == end || *stop == '/');
}

void skipSpaces(const char*& p, const char* end)
{
  while (p < end && isSpace(*p)) ++p;
}

/// The common OBJ vertex line, "x y z" after the "v", read in place. False when it is anything
/// else: the general path then reads it, or says what is wrong with it.
bool readVertexQuickly(const char* p, const char* eol, double xyz[3])
{
  for (int k = 0; k < 3; ++k)
  {
    skipSpaces(p, eol);
    const auto [stop, error] = std::from_chars(p, eol, xyz[k]);
    if (error != std::errc() || stop == p || (stop < eol && !isSpace(*stop))) return false;
    p = stop;
  }
  return true;
}

/// The common OBJ face line, indices "i", "i/t", "i//n" or "i/t/n" after the "f", read in place
/// into `indices`. False when it is anything else (the general path decides).
bool readFaceQuickly(const char* p, const char* eol, std::vector<long>& indices)
{
  indices.clear();
  for (skipSpaces(p, eol); p < eol; skipSpaces(p, eol))
  {
    long index = 0;
    const auto [stop, error] = std::from_chars(p, eol, index);
    if (error != std::errc() || stop == p) return false;
    p = stop;
    if (p < eol && *p == '/')
      while (p < eol && !isSpace(*p)) ++p;
    else if (p < eol && !isSpace(*p))
      return false;
    indices.push_back(index);
  }
  return indices.size() >= 3;
}

void addFan(const std::vector<int>& polygon, std::vector<int>& faces)
{
  for (size_t k = 1; k + 1 < polygon.size(); ++k)
  {
    faces.push_back(polygon[0]);
    faces.push_back(polygon[k]);
    faces.push_back(polygon[k + 1]);
  }
}

} // namespace

TriangleMesh meshFromArrays(const std::vector<double>& coords, const std::vector<int>& faces)
{
  TriangleMesh mesh;
  mesh.V = Eigen::Map<const Points>(coords.data(), static_cast<Eigen::Index>(coords.size() / 3), 3);
  mesh.F =
      Eigen::Map<const Triangles>(faces.data(), static_cast<Eigen::Index>(faces.size() / 3), 3);
  return mesh;
}

TriangleMesh readOBJ(const std::string& path, const std::string& onlyGroup)
{
  const std::string text = readFileBytes(path);
  if (text.empty()) throw Error(path + ": empty file");
  if (text.find('\0') != std::string::npos)
    throw Error(path + ": not a text OBJ file (contains NUL bytes)");
  std::vector<double> coords;
  std::vector<int> faces;
  std::vector<std::string_view> tokens;
  std::vector<int> polygon;
  // Faces are resolved after reading so that indices may refer to vertices defined later.
  std::vector<long> rawFaces;
  std::vector<int> faceLine, faceSize, faceVertexCount;
  int lineNo = 0;
  bool inGroup = onlyGroup.empty();
  const char* p = text.data();
  const char* end = p + text.size();
  std::vector<long> faceIndices;
  auto recordFace = [&]()
  {
    faceSize.push_back(static_cast<int>(faceIndices.size()));
    faceLine.push_back(lineNo);
    faceVertexCount.push_back(static_cast<int>(coords.size() / 3));
    rawFaces.insert(rawFaces.end(), faceIndices.begin(), faceIndices.end());
  };
  {
    // A line is a vertex or a face, mostly: room for one of each per line saves the regrowing.
    size_t lines = 1;
    for (const char* q = p; (q = static_cast<const char*>(std::memchr(q, '\n', end - q))); ++q)
      ++lines;
    coords.reserve(3 * lines);
    rawFaces.reserve(3 * lines);
  }
  while (p < end)
  {
    const char* eol = static_cast<const char*>(std::memchr(p, '\n', end - p));
    if (!eol) eol = end;
    ++lineNo;
    const char* line = p;
    p = eol + 1;
    skipSpaces(line, eol);
    // Most lines are plain vertices and faces: read in place, without tokens.
    if (eol - line > 1 && isSpace(line[1]))
    {
      double xyz[3];
      if (line[0] == 'v' && readVertexQuickly(line + 1, eol, xyz))
      {
        coords.insert(coords.end(), xyz, xyz + 3);
        continue;
      }
      if (line[0] == 'f' && inGroup && readFaceQuickly(line + 1, eol, faceIndices))
      {
        recordFace();
        continue;
      }
    }
    tokenize(line, eol, tokens);
    if (tokens.empty() || tokens[0][0] == '#') continue;
    if (tokens[0] == "v")
    {
      double xyz[3];
      if (tokens.size() < 4 || !parseDouble(tokens[1], xyz[0]) || !parseDouble(tokens[2], xyz[1]) ||
          !parseDouble(tokens[3], xyz[2]))
        throw Error(where(path, lineNo) +
                    "malformed vertex record (expected 'v x y z'; truncated file?)");
      coords.insert(coords.end(), xyz, xyz + 3);
    }
    else if (tokens[0] == "g" && !onlyGroup.empty())
      inGroup = tokens.size() > 1 && tokens[1] == onlyGroup;
    else if (tokens[0] == "f" && inGroup)
    {
      if (tokens.size() < 4)
        throw Error(where(path, lineNo) + "face with fewer than 3 vertices (truncated file?)");
      faceIndices.clear();
      for (size_t k = 1; k < tokens.size(); ++k)
      {
        long idx;
        if (!parseInt(tokens[k], idx))
          throw Error(where(path, lineNo) + "malformed face index '" + std::string(tokens[k]) +
                      "'");
        faceIndices.push_back(idx);
      }
      recordFace();
    }
  }
  const long nv = static_cast<long>(coords.size() / 3);
  size_t cursor = 0;
  for (size_t f = 0; f < faceSize.size(); ++f)
  {
    polygon.clear();
    for (int k = 0; k < faceSize[f]; ++k)
    {
      const long raw = rawFaces[cursor++];
      // Negative indices count back from the vertices read so far.
      const long idx = raw > 0 ? raw - 1 : faceVertexCount[f] + raw;
      if (raw == 0 || idx < 0 || idx >= nv)
        throw Error(where(path, faceLine[f]) + "face index " + std::to_string(raw) +
                    " out of range (file has " + std::to_string(nv) + " vertices)");
      polygon.push_back(static_cast<int>(idx));
    }
    addFan(polygon, faces);
  }
  return meshFromArrays(coords, faces);
}

TriangleMesh readOFF(const std::string& path)
{
  const std::string text = readFileBytes(path);
  if (text.empty()) throw Error(path + ": empty file");
  // Token stream without comments, remembering line numbers for messages (views into `text`).
  struct Token
  {
    std::string_view text;
    int line;
  };
  std::vector<Token> tokens;
  tokens.reserve(text.size() / 6); // a number and its separator take 6 bytes or more, mostly
  {
    std::vector<std::string_view> parts;
    int lineNo = 0;
    const char* p = text.data();
    const char* end = p + text.size();
    while (p < end)
    {
      const char* eol = static_cast<const char*>(std::memchr(p, '\n', end - p));
      if (!eol) eol = end;
      ++lineNo;
      const char* hash = static_cast<const char*>(std::memchr(p, '#', eol - p));
      tokenize(p, hash ? hash : eol, parts);
      for (std::string_view t : parts) tokens.push_back({t, lineNo});
      p = eol + 1;
    }
  }
  size_t pos = 0;
  auto next = [&](const char* what) -> const Token&
  {
    if (pos >= tokens.size()) throw Error(path + ": truncated file: missing " + std::string(what));
    return tokens[pos++];
  };
  const auto& header = next("header");
  if (header.text != "OFF")
    throw Error(path + ": not an OFF file (first word is '" +
                std::string(header.text.substr(0, 20)) + "', expected 'OFF')");
  long counts[3];
  for (long& c : counts)
  {
    const auto& t = next("vertex/face/edge counts");
    if (!parseInt(t.text, c) || c < 0)
      throw Error(where(path, t.line) + "malformed count '" + std::string(t.text) + "'");
  }
  // Each vertex takes 3 values and each face at least 4: a header that declares more than the
  // file holds is refused before anything is allocated.
  const size_t left = tokens.size() - pos;
  if (static_cast<unsigned long>(counts[0]) > left / 3 ||
      static_cast<unsigned long>(counts[1]) > (left - 3 * counts[0]) / 4)
    throw Error(path + ": the header declares " + std::to_string(counts[0]) + " vertices and " +
                std::to_string(counts[1]) + " faces, more than the file's " + std::to_string(left) +
                " remaining values hold (truncated file or wrong header)");
  std::vector<double> coords(3 * counts[0]);
  for (long i = 0; i < 3 * counts[0]; ++i)
  {
    const auto& t = next("vertex coordinates");
    if (!parseDouble(t.text, coords[i]))
      throw Error(where(path, t.line) + "malformed coordinate '" + std::string(t.text) + "'");
  }
  std::vector<int> faces, polygon;
  for (long f = 0; f < counts[1]; ++f)
  {
    const auto& nt = next("faces");
    const int line = nt.line;
    long n;
    if (!parseInt(nt.text, n) || n < 3)
      throw Error(where(path, line) + "face " + std::to_string(f) +
                  " has an invalid vertex count '" + std::string(nt.text) + "'");
    polygon.clear();
    for (long k = 0; k < n; ++k)
    {
      const auto& t = next("face indices");
      long idx;
      if (!parseInt(t.text, idx))
        throw Error(where(path, t.line) + "malformed face index '" + std::string(t.text) + "'");
      if (idx < 0 || idx >= counts[0])
        throw Error(where(path, t.line) + "face index " + std::to_string(idx) +
                    " out of range (file has " + std::to_string(counts[0]) + " vertices)");
      polygon.push_back(static_cast<int>(idx));
    }
    // Optional per-face colour values run to the end of the line.
    while (pos < tokens.size() && tokens[pos].line == line) ++pos;
    addFan(polygon, faces);
  }
  return meshFromArrays(coords, faces);
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
