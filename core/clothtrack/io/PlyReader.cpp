// Strict Stanford PLY reader: every size is checked against the file so that a truncated or
// corrupt file is an error, not a crash.
#include "FileBytes.h"
#include "FileContents.h"
#include "MeshIO.h"
#include "PointCloudIO.h"
#include "RowAppender.h"
#include "TextTokens.h"
#include <clothtrack/base/Error.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <charconv>
#include <cstdint>
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
enum class Format
{
  Ascii,
  BinaryLittle,
  BinaryBig
};

/// A PLY value type, resolved from its name once, when the header is read.
enum class Scalar
{
  Int8,
  UInt8,
  Int16,
  UInt16,
  Int32,
  UInt32,
  Float32,
  Float64,
  Unknown
};

Scalar scalarNamed(const std::string& t)
{
  if (t == "char" || t == "int8") return Scalar::Int8;
  if (t == "uchar" || t == "uint8") return Scalar::UInt8;
  if (t == "short" || t == "int16") return Scalar::Int16;
  if (t == "ushort" || t == "uint16") return Scalar::UInt16;
  if (t == "int" || t == "int32") return Scalar::Int32;
  if (t == "uint" || t == "uint32") return Scalar::UInt32;
  if (t == "float" || t == "float32") return Scalar::Float32;
  if (t == "double" || t == "float64") return Scalar::Float64;
  return Scalar::Unknown;
}

int sizeOf(Scalar type)
{
  static constexpr int sizes[] = {1, 1, 2, 2, 4, 4, 4, 8, 0};
  return sizes[static_cast<int>(type)];
}

bool isIntegral(Scalar type)
{
  return type < Scalar::Float32;
}

struct Property
{
  std::string name;
  Scalar type = Scalar::Unknown; // value type (list item type for lists)
  Scalar countType = Scalar::Unknown;
  bool list = false;
};

struct Element
{
  std::string name;
  long count = 0;
  std::vector<Property> properties;
};

/// std::isspace in the C locale, without its call per character.
bool isAsciiSpace(char c)
{
  return c == ' ' || c == '\n' || c == '\t' || c == '\r' || c == '\v' || c == '\f';
}

class Cursor
{
public:
  Cursor(const std::string& path, std::string_view data, size_t pos, Format format)
      : path_(path), data_(data), pos_(pos), format_(format)
  {
  }

  // Inlined into the element loop, the cursor's position stays in a register: ASCII PLY reads
  // 11 % faster (bench_read, samba frames), binary 4 % slower.
  [[gnu::always_inline]] double read(Scalar type)
  {
    if (format_ == Format::Ascii) return readAscii(isIntegral(type));
    const int size = sizeOf(type);
    if (pos_ + size > data_.size())
      throw Error(path_ + ": truncated file (binary data ends early)");
    unsigned char bytes[8];
    std::memcpy(bytes, data_.data() + pos_, size);
    pos_ += size;
    const bool little = format_ == Format::BinaryLittle;
    const uint16_t one = 1;
    const bool hostLittle = *reinterpret_cast<const unsigned char*>(&one) == 1;
    if (little != hostLittle)
      for (int i = 0; i < size / 2; ++i) std::swap(bytes[i], bytes[size - 1 - i]);
    switch (type)
    {
    case Scalar::Int8:
      return static_cast<int8_t>(bytes[0]);
    case Scalar::UInt8:
      return bytes[0];
    case Scalar::Int16:
      return as<int16_t>(bytes);
    case Scalar::UInt16:
      return as<uint16_t>(bytes);
    case Scalar::Int32:
      return as<int32_t>(bytes);
    case Scalar::UInt32:
      return as<uint32_t>(bytes);
    case Scalar::Float32:
      return as<float>(bytes);
    default:
      return as<double>(bytes);
    }
  }

  size_t position() const { return pos_; }
  void seek(size_t position) { pos_ = position; }

  /// An ASCII word that is one whole number (long: a decimal integer; double: anything
  /// std::from_chars takes), read and passed; false (and nothing passed) for anything else, which
  /// read() then handles. readAscii keeps its own integer branch: calling this one there read
  /// ASCII PLY 8 % slower (bench_read, samba frames).
  template <class T> [[gnu::always_inline]] bool readAsciiWord(T& value)
  {
    const char* last = data_.data() + data_.size();
    const char* start = data_.data() + pos_;
    while (start < last && isAsciiSpace(*start)) ++start;
    const char* end = readInPlace(start, last, value);
    if (!end || (end < last && !isAsciiSpace(*end))) return false;
    pos_ = static_cast<size_t>(end - data_.data());
    return true;
  }

private:
  static const char* readInPlace(const char* p, const char* last, long& value)
  {
    return readIntegerInPlace(p, last, value);
  }
  static const char* readInPlace(const char* p, const char* last, double& value)
  {
    return readNumberInPlace(p, last, value);
  }

  template <class T> static double as(const unsigned char* bytes)
  {
    T value;
    std::memcpy(&value, bytes, sizeof(T));
    return static_cast<double>(value);
  }

  [[gnu::always_inline]] double readAscii(bool integral)
  {
    const char* last = data_.data() + data_.size();
    const char* start = data_.data() + pos_;
    while (start < last && isAsciiSpace(*start)) ++start;
    if (start == last) throw Error(path_ + ": truncated file (ASCII data ends early)");
    // Integer types (char, uchar, short, ..., uint32) are read as integers first: faster.
    double value = 0;
    const char* stop = nullptr;
    if (integral)
    {
      long whole = 0;
      stop = readIntegerInPlace(start, last, whole);
      value = static_cast<double>(whole);
    }
    if (!stop) stop = readNumberInPlace(start, last, value);
    if (!stop || (stop < last && !isAsciiSpace(*stop))) return readWord(start, last);
    pos_ = static_cast<size_t>(stop - data_.data());
    return value;
  }

  /// The word at `start` as strtod reads it (a '+' sign, hexadecimal), on a copy: the file's bytes
  /// have no terminating NUL.
  double readWord(const char* start, const char* last)
  {
    const char* wordEnd = start;
    while (wordEnd < last && !isAsciiSpace(*wordEnd)) ++wordEnd;
    double value = 0;
    if (!parseDouble(std::string_view(start, static_cast<size_t>(wordEnd - start)), value))
      throw Error(path_ + ": malformed number near byte " + std::to_string(start - data_.data()));
    pos_ = static_cast<size_t>(wordEnd - data_.data());
    return value;
  }

  const std::string& path_;
  std::string_view data_;
  size_t pos_;
  Format format_;
};
[[noreturn]] void throwIndexOutOfRange(const std::string& path, long face, double index,
                                       long numVertices)
{
  char text[32]; // any double: the file's value may exceed every integer type
  std::snprintf(text, sizeof(text), "%.17g", index);
  throw Error(path + ": face " + std::to_string(face) + " uses vertex index " + text +
              ", out of range (file has " + std::to_string(numVertices) + " vertices)");
}

/// What a PLY file holds for the core: positions and triangles, and per vertex the optional
/// normals (nx ny nz) and colours (red green blue).
struct PlyContents
{
  TriangleMesh mesh;
  std::vector<double> normals;
  std::vector<double> colours; // 0-255
  long numVertices = 0;
};

/// Index of each named vertex property in `e`, -1 where absent.
template <size_t N>
void findProperties(const Element& e, const char* const (&names)[N], int (&index)[N])
{
  for (size_t k = 0; k < N; ++k)
  {
    index[k] = -1;
    for (size_t p = 0; p < e.properties.size(); ++p)
      if (!e.properties[p].list && e.properties[p].name == names[k]) index[k] = static_cast<int>(p);
  }
}

bool allFound(const int (&index)[3])
{
  return index[0] >= 0 && index[1] >= 0 && index[2] >= 0;
}

/// The header of a PLY file whose bytes (at least up to the line after end_header) are `data`.
struct PlyHeader
{
  Format format;
  std::vector<Element> elements;
  size_t bodyStart; ///< offset of the first byte after the header
};

PlyHeader parsePlyHeader(const std::string& path, std::string_view data)
{
  if (data.empty()) throw Error(path + ": empty file");
  if (data.compare(0, 3, "ply") != 0)
    throw Error(path + ": not a PLY file (does not start with 'ply')");
  const size_t headerEnd = data.find("end_header");
  if (headerEnd == std::string::npos) throw Error(path + ": truncated PLY header (no end_header)");
  size_t bodyStart = data.find('\n', headerEnd);
  if (bodyStart == std::string::npos)
    throw Error(path + ": truncated file (nothing after end_header)");
  ++bodyStart;

  Format format = Format::Ascii;
  bool haveFormat = false;
  std::vector<Element> elements;
  std::istringstream header(std::string(data.substr(0, headerEnd)));
  std::string line;
  int lineNo = 0;
  while (std::getline(header, line))
  {
    ++lineNo;
    std::istringstream words(line);
    std::string keyword;
    words >> keyword;
    const std::string where = path + ":" + std::to_string(lineNo) + ": ";
    if (keyword == "format")
    {
      std::string name;
      words >> name;
      if (name == "ascii")
        format = Format::Ascii;
      else if (name == "binary_little_endian")
        format = Format::BinaryLittle;
      else if (name == "binary_big_endian")
        format = Format::BinaryBig;
      else
        throw Error(where + "unknown PLY format '" + name + "'");
      haveFormat = true;
    }
    else if (keyword == "element")
    {
      Element e;
      if (!(words >> e.name >> e.count) || e.count < 0)
        throw Error(where + "malformed element line");
      elements.push_back(e);
    }
    else if (keyword == "property")
    {
      if (elements.empty()) throw Error(where + "property before any element");
      Property p;
      std::string type, countType;
      words >> type;
      p.list = type == "list";
      if (p.list) words >> countType >> type;
      words >> p.name;
      p.type = scalarNamed(type);
      p.countType = p.list ? scalarNamed(countType) : Scalar::Unknown;
      if (p.type == Scalar::Unknown || (p.list && p.countType == Scalar::Unknown) || p.name.empty())
        throw Error(where + "malformed property line");
      elements.back().properties.push_back(p);
    }
  }
  if (!haveFormat) throw Error(path + ": PLY header has no format line");
  return {format, elements, bodyStart};
}

PlyContents readPLYContents(const std::string& path)
{
  const FileContents file(path);
  const std::string_view data = file.bytes();
  const auto [format, elements, bodyStart] = parsePlyHeader(path, data);
  PlyContents contents;
  Eigen::Index vertexCount = 0;
  for (const Element& e : elements)
    if (e.name == "vertex" && static_cast<size_t>(e.count) <= data.size()) vertexCount = e.count;
  RowAppender<Points> coords(contents.mesh.V, vertexCount);
  RowAppender<Triangles> faces(contents.mesh.F, 0);
  long& numVertices = contents.numVertices;
  bool haveVertices = false;
  Cursor cursor(path, data, bodyStart, format);
  for (const Element& e : elements)
  {
    const bool isVertex = e.name == "vertex", isFace = e.name == "face";
    int xyz[3], normal[3], colour[3];
    findProperties(e, {"x", "y", "z"}, xyz);
    findProperties(e, {"nx", "ny", "nz"}, normal);
    findProperties(e, {"red", "green", "blue"}, colour);
    const bool withNormals = isVertex && allFound(normal);
    const bool withColours = isVertex && allFound(colour);
    // Colours stored as floats are fractions of full intensity.
    const double colourScale =
        withColours && !isIntegral(e.properties[colour[0]].type) ? 255.0 : 1.0;
    int indexProperty = -1;
    for (size_t p = 0; p < e.properties.size(); ++p)
    {
      const auto& name = e.properties[p].name;
      if (isFace && (name == "vertex_indices" || name == "vertex_index") && e.properties[p].list)
        indexProperty = static_cast<int>(p);
    }
    if (isVertex && !allFound(xyz)) throw Error(path + ": PLY vertex element lacks x, y or z");
    if (isFace && indexProperty < 0)
      throw Error(path + ": PLY face element lacks a vertex_indices list");
    // An element without properties holds no data, whatever its count: nothing to read (a
    // count of 2e10 once looped that many times over nothing). One with properties takes at
    // least a byte an instance.
    if (e.properties.empty()) continue;
    if (static_cast<size_t>(e.count) > data.size())
      throw Error(path + ": truncated file (declares " + std::to_string(e.count) + " '" + e.name +
                  "' elements)");
    if (isVertex)
    {
      haveVertices = true;
      numVertices = e.count;
      if (withNormals) contents.normals.reserve(3 * e.count);
      if (withColours) contents.colours.reserve(3 * e.count);
    }
    if (isFace) faces.reserve(faces.size() + e.count); // triangles mostly
    // Where each property's value goes in a vertex record: position 0-2, normal 3-5, colour 6-8.
    std::vector<int> slot(e.properties.size(), -1);
    for (int k = 0; k < 3 && isVertex; ++k)
    {
      slot[xyz[k]] = k;
      if (withNormals) slot[normal[k]] = 3 + k;
      if (withColours) slot[colour[k]] = 6 + k;
    }
    std::vector<int> polygon;
    // ASCII triangles of a face element holding only its index list: read as integers straight
    // into the mesh. Anything else (a polygon, an index out of range, a word that is not a plain
    // integer) is read again by the general path below, which also names what is wrong.
    const bool asciiFaceList = format == Format::Ascii && isFace && e.properties.size() == 1 &&
                               indexProperty == 0 && isIntegral(e.properties[0].countType) &&
                               isIntegral(e.properties[0].type);
    auto readTriangle = [&]()
    {
      const size_t start = cursor.position();
      long n = 0, a = 0, b = 0, c = 0;
      if (cursor.readAsciiWord(n) && n == 3 && cursor.readAsciiWord(a) && cursor.readAsciiWord(b) &&
          cursor.readAsciiWord(c) && haveVertices && std::max({a, b, c}) < numVertices &&
          std::min({a, b, c}) >= 0)
      {
        faces.add(static_cast<int>(a), static_cast<int>(b), static_cast<int>(c));
        return true;
      }
      cursor.seek(start);
      return false;
    };
    // ASCII vertices holding x, y and z alone, in that order and as floating-point numbers (ints
    // may hold a '3.5' the general path reads differently): read straight into the mesh.
    const bool asciiPositionsOnly =
        format == Format::Ascii && isVertex && e.properties.size() == 3 && xyz[0] == 0 &&
        xyz[1] == 1 && xyz[2] == 2 && !isIntegral(e.properties[0].type) &&
        !isIntegral(e.properties[1].type) && !isIntegral(e.properties[2].type);
    auto readPosition = [&]()
    {
      const size_t start = cursor.position();
      double x = 0, y = 0, z = 0;
      if (cursor.readAsciiWord(x) && cursor.readAsciiWord(y) && cursor.readAsciiWord(z))
      {
        coords.add(x, y, z);
        return true;
      }
      cursor.seek(start);
      return false;
    };
    for (long i = 0; i < e.count; ++i)
    {
      if (asciiFaceList && readTriangle()) continue;
      if (asciiPositionsOnly && readPosition()) continue;
      double record[9] = {0, 0, 0, 0, 0, 0, 0, 0, 0};
      for (size_t p = 0; p < e.properties.size(); ++p)
      {
        const Property& prop = e.properties[p];
        if (!prop.list)
        {
          const double value = cursor.read(prop.type);
          if (slot[p] >= 0) record[slot[p]] = value;
          continue;
        }
        const double n = cursor.read(prop.countType);
        if (!(n >= 0 && n <= 1e6)) // NaN too: a float count type reads one
          throw Error(path + ": corrupt list length " + std::to_string(n) + " in element '" +
                      e.name + "'");
        polygon.clear();
        for (long k = 0; k < static_cast<long>(n); ++k)
        {
          const double index = cursor.read(prop.type);
          if (isFace && static_cast<int>(p) == indexProperty)
          {
            if (!haveVertices || !(index >= 0 && index < numVertices))
              throwIndexOutOfRange(path, i, index, numVertices);
            polygon.push_back(static_cast<int>(index));
          }
        }
        if (isFace && static_cast<int>(p) == indexProperty)
        {
          if (polygon.size() < 3)
            throw Error(path + ": face " + std::to_string(i) + " has fewer than 3 vertices");
          addFan(polygon, faces);
        }
      }
      if (isVertex)
      {
        coords.add(record[0], record[1], record[2]);
        if (withNormals) contents.normals.insert(contents.normals.end(), record + 3, record + 6);
        for (int k = 6; k < 9 && withColours; ++k)
          contents.colours.push_back(record[k] * colourScale);
      }
    }
  }
  coords.finish();
  faces.finish();
  return contents;
}
} // namespace

TriangleMesh readPLY(const std::string& path)
{
  return readPLYContents(path).mesh;
}

bool plyDeclaresFaces(const std::string& path)
{
  try
  {
    // The header is all that is needed: read up to its end, not the body behind it.
    auto headerRead = [](const std::string& bytes)
    {
      const size_t end = bytes.find("end_header");
      return end != std::string::npos && bytes.find('\n', end) != std::string::npos;
    };
    const std::string head = readFileStart(path, headerRead);
    const PlyHeader header = parsePlyHeader(path, head);
    return std::any_of(header.elements.begin(), header.elements.end(),
                       [](const Element& e) { return e.name == "face" && e.count > 0; });
  }
  catch (const Error&)
  {
    return true; // not a readable PLY header: read as a mesh, whose reader says what is wrong
  }
}

PointCloud readPLYPoints(const std::string& path)
{
  PlyContents contents = readPLYContents(path);
  return cloudFromArrays(std::move(contents.mesh.V), contents.normals, contents.colours);
}
} // namespace clothtrack
