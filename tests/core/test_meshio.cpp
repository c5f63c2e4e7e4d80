#include "TestUtil.h"

#include <clothtrack/base/Error.h>
#include <clothtrack/io/FileBytes.h>
#include <clothtrack/io/FileContents.h>
#include <clothtrack/io/MeshIO.h>
#include <clothtrack/io/PointCloudIO.h>
#include <clothtrack/io/TextTokens.h>
#include <clothtrack/mesh/Primitives.h>

#include <gtest/gtest.h>

#include <cstdlib>
#include <cstring>
#include <functional>
#include <random>

using namespace clothtrack;
using clothtrack::test::scratchDir;
using clothtrack::test::writeText;

namespace
{
void expectSame(const TriangleMesh& a, const TriangleMesh& b)
{
  ASSERT_EQ(a.numVertices(), b.numVertices());
  ASSERT_EQ(a.numFaces(), b.numFaces());
  EXPECT_LT((a.V - b.V).cwiseAbs().maxCoeff(), 1e-8);
  EXPECT_EQ(a.F, b.F);
}

// The error message must name the file and say what is wrong.
void expectError(const std::function<void()>& read, const std::string& path,
                 const std::string& words)
{
  try
  {
    read();
    FAIL() << "no error for " << path;
  }
  catch (const Error& e)
  {
    const std::string message = e.what();
    EXPECT_NE(message.find(path), std::string::npos) << message;
    EXPECT_NE(message.find(words), std::string::npos) << message;
  }
}
} // namespace

TEST(MeshIO, ObjAndOffRoundTrip)
{
  const std::string dir = scratchDir("meshio");
  const TriangleMesh mesh = torus(1.0, 0.25, 12, 8);
  writeOBJ(dir + "/t.obj", mesh);
  writeOFF(dir + "/t.off", mesh);
  expectSame(readOBJ(dir + "/t.obj"), mesh);
  expectSame(readOFF(dir + "/t.off"), mesh);
}

TEST(MeshIO, ObjPolygonsNegativeIndicesAndSlashForms)
{
  const std::string dir = scratchDir("meshio-obj");
  const std::string path =
      writeText(dir + "/quad.obj", "# a quad and a triangle\n"
                                   "o thing\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\r\n"
                                   "vn 0 0 1\nvt 0 0\n"
                                   "f 1/1/1 2/1/1 3//1 4\n"
                                   "v 2 0 0\nf -4 -1 -3\n");
  const TriangleMesh mesh = readOBJ(path);
  EXPECT_EQ(mesh.numVertices(), 5);
  ASSERT_EQ(mesh.numFaces(), 3);
  EXPECT_EQ(mesh.F.row(0), Eigen::RowVector3i(0, 1, 2));
  EXPECT_EQ(mesh.F.row(1), Eigen::RowVector3i(0, 2, 3));
  EXPECT_EQ(mesh.F.row(2), Eigen::RowVector3i(1, 4, 2));
}

TEST(MeshIO, OffWithPolygonsAndColours)
{
  const std::string dir = scratchDir("meshio-off");
  const std::string path = writeText(
      dir + "/q.off", "OFF\n# comment\n4 1 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n4 0 1 2 3 255 0 0\n");
  const TriangleMesh mesh = readOFF(path);
  EXPECT_EQ(mesh.numFaces(), 2);
}

TEST(MeshIO, BadFilesGiveClearErrors)
{
  const std::string dir = scratchDir("meshio-bad");
  expectError([&] { readOBJ(dir + "/missing.obj"); }, dir + "/missing.obj", "cannot open");
  const std::string empty = writeText(dir + "/empty.obj", "");
  expectError([&] { readOBJ(empty); }, empty, "empty file");
  const std::string range = writeText(dir + "/range.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 7\n");
  expectError([&] { readOBJ(range); }, range, "out of range");
  const std::string zero = writeText(dir + "/zero.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 0 1 2\n");
  expectError([&] { readOBJ(zero); }, zero, "out of range");
  const std::string truncated = writeText(dir + "/trunc.obj", "v 0 0 0\nv 1 0 0\nv 0 1");
  expectError([&] { readOBJ(truncated); }, truncated, "malformed vertex");
  const std::string shortFace = writeText(dir + "/short.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2\n");
  expectError([&] { readOBJ(shortFace); }, shortFace, "fewer than 3");
  const std::string garbage =
      writeText(dir + "/garbage.obj", std::string("v 1 2 3\n\0\x01\x02", 11));
  expectError([&] { readOBJ(garbage); }, garbage, "NUL");
  const std::string offTruncated =
      writeText(dir + "/trunc.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1\n");
  expectError([&] { readOFF(offTruncated); }, offTruncated, "truncated");
  const std::string notOff = writeText(dir + "/not.off", "PLY\n3 1 0\n");
  expectError([&] { readOFF(notOff); }, notOff, "not an OFF file");
  const std::string offRange =
      writeText(dir + "/range.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 3\n");
  expectError([&] { readOFF(offRange); }, offRange, "out of range");
}

TEST(MeshIO, PlyAsciiWithExtraElementsAndProperties)
{
  const std::string dir = scratchDir("meshio-ply");
  const std::string path =
      writeText(dir + "/q.ply", "ply\nformat ascii 1.0\ncomment made by hand\n"
                                "element vertex 4\nproperty float x\nproperty float y\n"
                                "property float z\nproperty uchar red\n"
                                "element face 1\nproperty list uchar int vertex_indices\n"
                                "property int flags\n"
                                "element edge 1\nproperty int vertex1\nproperty int vertex2\n"
                                "end_header\n0 0 0 9\n1 0 0 9\n1 1 0 9\n0 1 0 9\n"
                                "4 0 1 2 3 7\n0 1\n");
  const TriangleMesh mesh = readPLY(path);
  EXPECT_EQ(mesh.numVertices(), 4);
  ASSERT_EQ(mesh.numFaces(), 2);
  EXPECT_EQ(mesh.F.row(1), Eigen::RowVector3i(0, 2, 3));
  EXPECT_DOUBLE_EQ(mesh.V(2, 1), 1.0);
}

// Triangles are read on a fast path; polygons, indices written otherwise (+2, 2.0) and bad
// indices go through the general one, mixed in one element, with the same result and errors.
TEST(MeshIO, PlyAsciiTrianglesAndOtherFacesReadAlike)
{
  const std::string dir = scratchDir("meshio-ply-faces");
  const std::string header = "ply\nformat ascii 1.0\nelement vertex 5\nproperty double x\n"
                             "property double y\nproperty double z\nelement face 4\n"
                             "property list uchar int vertex_indices\nend_header\n"
                             "0 0 0\n1 0 0\n1 1 0\n0 1 0\n0.5 0.5 1\n";
  const TriangleMesh mesh = readPLY(
      writeText(dir + "/mixed.ply", header + "3 0 1 4\n4 0 1 2 3\n3 +2 3.0 4\n 3\t3 0\r\n4\n"));
  ASSERT_EQ(mesh.numFaces(), 5);
  EXPECT_EQ(mesh.F.row(0), Eigen::RowVector3i(0, 1, 4));
  EXPECT_EQ(mesh.F.row(1), Eigen::RowVector3i(0, 1, 2));
  EXPECT_EQ(mesh.F.row(2), Eigen::RowVector3i(0, 2, 3));
  EXPECT_EQ(mesh.F.row(3), Eigen::RowVector3i(2, 3, 4));
  EXPECT_EQ(mesh.F.row(4), Eigen::RowVector3i(3, 0, 4));
  for (const char* bad : {"3 0 1 5\n", "3 0 -1 2\n", "3 0 1\n"})
  {
    const std::string path =
        writeText(dir + "/bad.ply", header + "3 0 1 4\n3 0 1 4\n3 0 1 4\n" + bad);
    EXPECT_THROW(readPLY(path), Error) << bad;
  }
  try
  {
    readPLY(writeText(dir + "/range.ply", header + "3 0 1 4\n3 0 1 4\n3 0 1 4\n3 0 9 4\n"));
    FAIL() << "an index out of range was read";
  }
  catch (const Error& e)
  {
    EXPECT_NE(std::string(e.what()).find("face 3 uses vertex index 9, out of range"),
              std::string::npos)
        << e.what();
  }
}

TEST(MeshIO, PlyAsciiPositionsAndOtherVerticesReadAlike)
{
  // Vertices holding x y z alone take a quicker path than the general one; words it does not take
  // (a '+' sign, an exponent, hexadecimal) fall back to the general path, which reads them as
  // strtod does, and a vertex element with more properties, in another order or as integers is
  // read by the general path from the start: all give the same positions.
  const std::string dir = scratchDir("meshio-ply-vertices");
  auto vertexHeader = [](const std::string& properties)
  {
    return "ply\nformat ascii 1.0\nelement vertex 3\n" + properties +
           "element face 1\nproperty list uchar int vertex_indices\nend_header\n";
  };
  const std::string xyz = "property float x\nproperty float y\nproperty float z\n";
  const TriangleMesh plain =
      readPLY(writeText(dir + "/plain.ply", vertexHeader(xyz) + "0.25 -1 2\n1.5 0 0\n0 1e-1 -3\n"
                                                                "3 0 1 2\n"));
  const TriangleMesh words = readPLY(writeText(
      dir + "/words.ply", vertexHeader(xyz) + "+0.25 -1.0 2e0\n1.5\t0 0\r\n0x0 0.1 -3\n3 0 1 2\n"));
  const TriangleMesh wider =
      readPLY(writeText(dir + "/wider.ply", vertexHeader(xyz + "property uchar red\n") +
                                                "0.25 -1 2 9\n1.5 0 0 9\n0 0.1 -3 9\n3 0 1 2\n"));
  const TriangleMesh reordered =
      readPLY(writeText(dir + "/reordered.ply",
                        vertexHeader("property float z\nproperty float x\nproperty float y\n") +
                            "2 0.25 -1\n0 1.5 0\n-3 0 0.1\n3 0 1 2\n"));
  Points expected(3, 3);
  expected << 0.25, -1, 2, 1.5, 0, 0, 0, 0.1, -3;
  for (const TriangleMesh* mesh : {&plain, &words, &wider, &reordered})
  {
    ASSERT_EQ(mesh->numVertices(), 3);
    EXPECT_EQ(mesh->V, expected);
  }
  EXPECT_THROW(readPLY(writeText(dir + "/bad.ply", vertexHeader(xyz) + "0 0 0\n1 x 0\n0 1 0\n"
                                                                       "3 0 1 2\n")),
               Error);
}

TEST(MeshIO, PlyBinaryBothEndiannesses)
{
  const std::string dir = scratchDir("meshio-plybin");
  auto be32 = [](uint32_t v) {
    return std::string{char(v >> 24), char((v >> 16) & 255), char((v >> 8) & 255), char(v & 255)};
  };
  auto le32 = [](uint32_t v) {
    return std::string{char(v & 255), char((v >> 8) & 255), char((v >> 16) & 255), char(v >> 24)};
  };
  for (bool big : {false, true})
  {
    std::string body;
    const float coords[9] = {0, 0, 0, 2, 0, 0, 0, 3, 0};
    for (float c : coords)
    {
      uint32_t bits;
      std::memcpy(&bits, &c, 4);
      body += big ? be32(bits) : le32(bits);
    }
    body += char(3);
    for (uint32_t i : {0u, 1u, 2u}) body += big ? be32(i) : le32(i);
    const std::string head =
        std::string("ply\nformat ") + (big ? "binary_big_endian" : "binary_little_endian") +
        " 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
        "element face 1\nproperty list uchar int vertex_indices\nend_header\n";
    const std::string path = writeText(dir + (big ? "/be.ply" : "/le.ply"), head + body);
    const TriangleMesh mesh = readPLY(path);
    ASSERT_EQ(mesh.numFaces(), 1);
    EXPECT_FLOAT_EQ(static_cast<float>(mesh.V(2, 1)), 3.0f);
    // Cut the file short: an error, not a crash.
    const std::string cut = writeText(dir + "/cut.ply", head + body.substr(0, body.size() - 3));
    expectError([&] { readPLY(cut); }, cut, "truncated");
  }
  const std::string noEnd =
      writeText(dir + "/noend.ply", "ply\nformat ascii 1.0\nelement vertex 3\n");
  expectError([&] { readPLY(noEnd); }, noEnd, "end_header");
  const std::string badIndex =
      writeText(dir + "/bad.ply", "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\n"
                                  "property float y\nproperty float z\nelement face 1\n"
                                  "property list uchar int vertex_indices\nend_header\n"
                                  "0 0 0\n1 0 0\n0 1 0\n3 0 1 5\n");
  expectError([&] { readPLY(badIndex); }, badIndex, "out of range");
}

TEST(MeshIO, NumbersReadInPlaceAsStrtodReadsThem)
{
  // Plain lines are read in place with std::from_chars; anything else takes the general path.
  // Both must agree: signs, exponents, hexadecimal, denormals, tabs, CRLF, v/vt/vn indices and
  // trailing values.
  const std::string dir = scratchDir("meshio-numbers");
  const TriangleMesh obj = readOBJ(writeText(dir + "/n.obj", "v +1.5 -0.25e1\t3 0.5 0.5 0.5\r\n"
                                                             "v 0x1p-1 1e-320 .5\n"
                                                             "v 7. -0 1E+2 # note\n"
                                                             "f +1 2/5/6 -1//2\n"
                                                             "f\t1 2 3 \r\n"));
  ASSERT_EQ(obj.numVertices(), 3);
  EXPECT_EQ(obj.V(0, 0), 1.5);
  EXPECT_EQ(obj.V(0, 1), -2.5);
  EXPECT_EQ(obj.V(0, 2), 3.0);
  EXPECT_EQ(obj.V(1, 0), 0.5);
  EXPECT_EQ(obj.V(1, 1), std::strtod("1e-320", nullptr));
  EXPECT_EQ(obj.V(1, 2), 0.5);
  EXPECT_EQ(obj.V(2, 0), 7.0);
  EXPECT_EQ(obj.V(2, 2), 100.0);
  EXPECT_EQ(std::strtod("0.1", nullptr), 0.1); // the reference rounding
  ASSERT_EQ(obj.numFaces(), 2);
  EXPECT_EQ(obj.F.row(0), Eigen::RowVector3i(0, 1, 2));
  EXPECT_EQ(obj.F.row(1), Eigen::RowVector3i(0, 1, 2));
  // What the general path refuses is refused wherever it is.
  EXPECT_THROW(readOBJ(writeText(dir + "/comment.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3 #\n")),
               Error);
  EXPECT_THROW(readOBJ(writeText(dir + "/huge.obj", "v 1e400 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n")),
               Error);
  EXPECT_THROW(readOBJ(writeText(dir + "/glued.obj", "v 1 2 3x\nv 1 0 0\nv 0 1 0\nf 1 2 3\n")),
               Error);
  // The same coordinates through OFF and ASCII PLY.
  const TriangleMesh off = readOFF(writeText(
      dir + "/n.off", "OFF\n3 1 0\n+1.5 -0.25e1 3\n0x1p-1 1e-320 .5\n7. -0 1E+2\n3 0 1 2\n"));
  const TriangleMesh ply = readPLY(
      writeText(dir + "/n.ply", "ply\nformat ascii 1.0\nelement vertex 3\nproperty double x\n"
                                "property double y\nproperty double z\nelement face 1\n"
                                "property list uchar int vertex_indices\nend_header\n"
                                "+1.5 -0.25e1 3\n0x1p-1 1e-320 .5\n7. -0 1E+2\n3 +0 1 2\n"));
  EXPECT_EQ(off.V, obj.V);
  EXPECT_EQ(ply.V, obj.V);
  EXPECT_EQ(ply.F.row(0), Eigen::RowVector3i(0, 1, 2));
}

TEST(MeshIO, ObjLinesOfEveryShapeReadAsTheGeneralPathReadsThem)
{
  const std::string dir = scratchDir("meshio-shapes");
  // CRLF endings, tabs, trailing spaces, vertex colours, a comment after a vertex, a face before
  // the vertex it names, a quad, and no newline at the end.
  const char* const shapes = "# made by hand\r\nf 1 2 5\r\nv 0 0 0 \r\n\tv\t1 0 0\t\n"
                             "v 1 1 0 0.5 0.5 0.5\nv 0 1 0 # corner\nf 1/1 2/2 3/3 4/4  \n"
                             "v 0.5 0.5 1";
  const TriangleMesh mesh = readOBJ(writeText(dir + "/shapes.obj", shapes));
  ASSERT_EQ(mesh.numVertices(), 5);
  EXPECT_EQ(mesh.V.row(4), Eigen::RowVector3d(0.5, 0.5, 1));
  EXPECT_EQ(mesh.V.row(2), Eigen::RowVector3d(1, 1, 0));
  ASSERT_EQ(mesh.numFaces(), 3);
  EXPECT_EQ(mesh.F.row(0), Eigen::RowVector3i(0, 1, 4));
  EXPECT_EQ(mesh.F.row(2), Eigen::RowVector3i(0, 2, 3));
  // A face naming a vertex past the last one is refused with its own line.
  const std::string forward = writeText(dir + "/forward.obj", "f 1 2 4\nv 0 0 0\nv 1 0 0\nv 0 1 0");
  expectError([&] { readOBJ(forward); }, forward + ":1:", "face index 4 out of range");
  // A negative index counts back from the vertices before it.
  const std::string back = writeText(dir + "/back.obj", "v 0 0 0\nv 1 0 0\nf -3 -2 -1\nv 0 1 0");
  expectError([&] { readOBJ(back); }, back + ":3:", "2 vertices before it");
}

TEST(MeshIO, NumbersEndingAFileAreReadWithinIt)
{
  // A file's bytes have no terminating NUL, and the buffer they are read into may still hold the
  // digits of a longer file read before: a number that ends a file ends with it. Each file ends in
  // a number only strtod's reading takes ('+' or hexadecimal).
  const std::string dir = scratchDir("meshio-end");
  const std::string longer = writeText(dir + "/longer.txt", std::string(8192, '7'));
  const std::string off = "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 +2";
  FileContents{longer};
  EXPECT_EQ(readOFF(writeText(dir + "/end.off", off)).F.row(0), Eigen::RowVector3i(0, 1, 2));
  const std::string ply = "ply\nformat ascii 1.0\nelement vertex 3\nproperty double x\n"
                          "property double y\nproperty double z\nend_header\n0 0 0\n1 0 0\n"
                          "0 1 0x1p-1";
  FileContents{longer};
  EXPECT_EQ(readPLYPoints(writeText(dir + "/end.ply", ply)).P(2, 2), 0.5);
  const std::string obj = "v 0 0 0\nv 1 0 0\nv 0 1 +0.5\nf 1 2 +3";
  FileContents{longer};
  const TriangleMesh mesh = readOBJ(writeText(dir + "/end.obj", obj));
  EXPECT_EQ(mesh.V(2, 2), 0.5);
  EXPECT_EQ(mesh.F.row(0), Eigen::RowVector3i(0, 1, 2));
}

TEST(MeshIO, FileContentsHoldsWholeFiles)
{
  const std::string dir = scratchDir("meshio-contents");
  const FileContents bom(writeText(dir + "/bom.obj", "\xEF\xBB\xBFv 0 0 0\n"));
  EXPECT_EQ(bom.bytes(), "v 0 0 0\n");
  const FileContents raw(dir + "/bom.obj", /*text=*/false);
  EXPECT_EQ(raw.bytes().size(), 11u);
  // Two files held at once in one thread: the second does not take the first's buffer.
  const FileContents first(writeText(dir + "/first.off", "OFF\n"));
  const FileContents second(writeText(dir + "/second.obj", "v 1 2 3\n"));
  EXPECT_EQ(first.bytes(), "OFF\n");
  EXPECT_EQ(second.bytes(), "v 1 2 3\n");
  // /proc files claim a size of 0: read to their end.
  const FileContents status("/proc/self/status");
  EXPECT_NE(status.bytes().find("Name:"), std::string_view::npos);
  expectError([&] { FileContents missing(dir + "/missing.obj"); }, dir + "/missing.obj",
              "cannot open");
}

TEST(MeshIO, PlainDecimalsReadAsStrtodReadsThem)
{
  // The fast path for plain decimals against strtod, bit for bit, on random numbers of 1-18
  // digits (past 15, and with an exponent, std::from_chars reads them).
  std::mt19937 random(7);
  std::uniform_int_distribution<int> digit(0, 9), length(0, 9), coin(0, 3);
  int quick = 0;
  for (int trial = 0; trial < 200000; ++trial)
  {
    std::string text = coin(random) == 0 ? "-" : "";
    for (int k = length(random); k > 0; --k) text += static_cast<char>('0' + digit(random));
    if (coin(random) != 0)
    {
      text += '.';
      for (int k = length(random); k > 0; --k) text += static_cast<char>('0' + digit(random));
    }
    if (coin(random) == 0) text += "e-" + std::to_string(digit(random));
    char* stop = nullptr;
    const double expected = std::strtod(text.c_str(), &stop);
    if (*stop != '\0' || stop == text.c_str()) continue; // not a number ("-", ".", "-.")
    double value = 0;
    const char* end = text.data() + text.size();
    quick += readPlainDecimal(text.data(), end, value) != nullptr;
    ASSERT_EQ(readNumberInPlace(text.data(), end, value), end) << text;
    ASSERT_EQ(std::memcmp(&value, &expected, sizeof(double)), 0) << text;
  }
  EXPECT_GT(quick, 100000); // most took the fast path
}

TEST(MeshIO, PlainIntegersReadAsFromCharsReadsThem)
{
  // The fast path for plain integers against std::from_chars<long>: where each stops, the value,
  // and a refusal where it refuses (no digit, out of range), on random words of 0-21 digits with
  // signs and trailing text.
  std::mt19937 random(11);
  std::uniform_int_distribution<int> digit(0, 9), length(0, 21), coin(0, 3);
  const char* tails[] = {"", " 7", ".5", "/3", "e2", "x"};
  int quick = 0, refused = 0;
  for (int trial = 0; trial < 200000; ++trial)
  {
    std::string text = coin(random) == 0 ? "-" : coin(random) == 0 ? "+" : "";
    for (int k = length(random) % (coin(random) == 0 ? 22 : 7); k > 0; --k)
      text += static_cast<char>('0' + digit(random));
    text += tails[trial % 6];
    const char* begin = text.data();
    const char* end = begin + text.size();
    long expected = 0, value = 0;
    const auto [stop, error] = std::from_chars(begin, end, expected);
    const char* got = readIntegerInPlace(begin, end, value);
    quick += readPlainInteger(begin, end, value) != nullptr;
    if (error != std::errc() || stop == begin)
    {
      ++refused;
      ASSERT_EQ(got, nullptr) << text;
      continue;
    }
    ASSERT_EQ(got, stop) << text;
    readIntegerInPlace(begin, end, value);
    ASSERT_EQ(value, expected) << text;
  }
  EXPECT_GT(quick, 100000);
  EXPECT_GT(refused, 1000);
}

TEST(MeshIO, ObjArraysGrowAndShrinkFromTheirEstimate)
{
  // The arrays are sized from the file's first 256 kB: a file whose records come later grows
  // them, one whose records stop early has them trimmed.
  const std::string dir = scratchDir("meshio-estimate");
  const TriangleMesh mesh = torus(1.0, 0.25, 120, 80); // 9,600 vertices, 0.5 MB as OBJ
  writeOBJ(dir + "/t.obj", mesh);
  const std::string records = readFileBytes(dir + "/t.obj");
  const std::string comments(300 << 10, '#');
  expectSame(readOBJ(writeText(dir + "/late.obj", comments + "\n" + records)), mesh);
  expectSame(readOBJ(writeText(dir + "/early.obj", records + comments + "\n")), mesh);
}

TEST(MeshIO, PlyBinaryReadsEveryScalarType)
{
  // Each property type moves the reader by its own size: a wrong size would shift every value after
  // it. The skipped properties come between the coordinates.
  std::string body;
  auto put = [&body](auto value)
  { body.append(reinterpret_cast<const char*>(&value), sizeof(value)); };
  for (int i = 0; i < 3; ++i)
  {
    put(static_cast<int8_t>(-5));
    put(0.25 + i);                      // x, double
    put(static_cast<uint16_t>(7));      // skipped
    put(static_cast<float>(-1.5f * i)); // y, float
    put(static_cast<int32_t>(-9));      // skipped
    put(static_cast<int16_t>(-3 * i));  // z, short
    put(static_cast<uint32_t>(11));     // skipped
    put(static_cast<uint8_t>(200));     // skipped
  }
  put(static_cast<uint16_t>(3));
  for (uint32_t index : {2u, 0u, 1u}) put(index);
  const std::string header =
      "ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty int8 a\n"
      "property double x\nproperty ushort b\nproperty float y\nproperty int c\n"
      "property int16 z\nproperty uint32 d\nproperty uchar e\nelement face 1\n"
      "property list ushort uint vertex_indices\nend_header\n";
  const std::string dir = scratchDir("meshio-plytypes");
  const TriangleMesh mesh = readPLY(writeText(dir + "/types.ply", header + body));
  ASSERT_EQ(mesh.numVertices(), 3);
  EXPECT_EQ(mesh.V.row(2), Eigen::RowVector3d(2.25, -3.0, -6.0));
  ASSERT_EQ(mesh.numFaces(), 1);
  EXPECT_EQ(mesh.F.row(0), Eigen::RowVector3i(2, 0, 1));
}
