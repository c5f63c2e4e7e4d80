#include "MeshIO.h"
#include "FileBytes.h"

#include <clothtrack/base/Error.h>

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>
#include <vector>

namespace clothtrack
{
namespace
{
std::string where(const std::string& path, int line)
{
  return path + ":" + std::to_string(line) + ": ";
}

bool isSpace(char c)
{
  return c == ' ' || c == '\t' || c == '\r';
}

// Splits one line into whitespace-separated tokens (views into the line).
void tokenize(const char* begin, const char* end, std::vector<std::string>& tokens)
{
  tokens.clear();
  const char* p = begin;
  while (p < end)
  {
    while (p < end && isSpace(*p)) ++p;
    const char* start = p;
    while (p < end && !isSpace(*p)) ++p;
    if (p > start) tokens.emplace_back(start, p);
  }
}

bool parseDouble(const std::string& s, double& value)
{
  char* endp = nullptr;
  errno = 0;
  value = std::strtod(s.c_str(), &endp);
  // ERANGE also flags an underflow to a denormal or zero, which is a fine coordinate.
  const bool overflow = errno == ERANGE && std::abs(value) > 1.0;
  return endp != s.c_str() && *endp == '\0' && !overflow;
}

bool parseInt(const std::string& s, long& value)
{
  char* endp = nullptr;
  errno = 0;
  value = std::strtol(s.c_str(), &endp, 10);
  return endp != s.c_str() && (*endp == '\0' || *endp == '/') && errno != ERANGE;
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
  std::vector<std::string> tokens;
  std::vector<int> polygon;
  // Faces are resolved after reading so that indices may refer to vertices defined later.
  std::vector<long> rawFaces;
  std::vector<int> faceLine, faceSize, faceVertexCount;
  int lineNo = 0;
  bool inGroup = onlyGroup.empty();
  const char* p = text.data();
  const char* end = p + text.size();
  while (p < end)
  {
    const char* eol = static_cast<const char*>(std::memchr(p, '\n', end - p));
    if (!eol) eol = end;
    ++lineNo;
    tokenize(p, eol, tokens);
    p = eol + 1;
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
      faceSize.push_back(static_cast<int>(tokens.size()) - 1);
      faceLine.push_back(lineNo);
      faceVertexCount.push_back(static_cast<int>(coords.size() / 3));
      for (size_t k = 1; k < tokens.size(); ++k)
      {
        long idx;
        if (!parseInt(tokens[k], idx))
          throw Error(where(path, lineNo) + "malformed face index '" + tokens[k] + "'");
        rawFaces.push_back(idx);
      }
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
  // Token stream without comments, remembering line numbers for messages.
  std::vector<std::pair<std::string, int>> tokens;
  {
    std::istringstream in(text);
    std::string line;
    int lineNo = 0;
    std::vector<std::string> parts;
    while (std::getline(in, line))
    {
      ++lineNo;
      const auto hash = line.find('#');
      if (hash != std::string::npos) line.resize(hash);
      tokenize(line.data(), line.data() + line.size(), parts);
      for (auto& t : parts) tokens.emplace_back(std::move(t), lineNo);
    }
  }
  size_t pos = 0;
  auto next = [&](const char* what) -> const std::pair<std::string, int>&
  {
    if (pos >= tokens.size()) throw Error(path + ": truncated file: missing " + std::string(what));
    return tokens[pos++];
  };
  const auto& header = next("header");
  if (header.first != "OFF")
    throw Error(path + ": not an OFF file (first word is '" + header.first.substr(0, 20) +
                "', expected 'OFF')");
  long counts[3];
  for (long& c : counts)
  {
    const auto& t = next("vertex/face/edge counts");
    if (!parseInt(t.first, c) || c < 0)
      throw Error(where(path, t.second) + "malformed count '" + t.first + "'");
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
    if (!parseDouble(t.first, coords[i]))
      throw Error(where(path, t.second) + "malformed coordinate '" + t.first + "'");
  }
  std::vector<int> faces, polygon;
  for (long f = 0; f < counts[1]; ++f)
  {
    const auto& nt = next("faces");
    const int line = nt.second;
    long n;
    if (!parseInt(nt.first, n) || n < 3)
      throw Error(where(path, line) + "face " + std::to_string(f) +
                  " has an invalid vertex count '" + nt.first + "'");
    polygon.clear();
    for (long k = 0; k < n; ++k)
    {
      const auto& t = next("face indices");
      long idx;
      if (!parseInt(t.first, idx))
        throw Error(where(path, t.second) + "malformed face index '" + t.first + "'");
      if (idx < 0 || idx >= counts[0])
        throw Error(where(path, t.second) + "face index " + std::to_string(idx) +
                    " out of range (file has " + std::to_string(counts[0]) + " vertices)");
      polygon.push_back(static_cast<int>(idx));
    }
    // Optional per-face colour values run to the end of the line.
    while (pos < tokens.size() && tokens[pos].second == line) ++pos;
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
