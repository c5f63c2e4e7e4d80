// Files that crashed, hung or misled a reader. Each must give one Error naming the file and the
// problem, and the well-formed variants beside them must still read.
#include "../core/TestUtil.h"

#include "ctMeshConversion.h"

#include <clothtrack/base/Error.h>

#include <vtkNew.h>
#include <vtkPolyData.h>
#include <vtkPolyDataWriter.h>
#include <vtkXMLPolyDataWriter.h>

#include <clothtrack/mesh/MeshValidation.h>
#include <clothtrack/mesh/Primitives.h>

#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

using namespace clothtrack;
using clothtrack::test::scratchDir;
using clothtrack::test::writeText;

namespace
{
void expectError(const std::string& path, const std::string& phrase)
{
  try
  {
    readMeshFile(path);
    ADD_FAILURE() << "no error for " << path;
  }
  catch (const Error& e)
  {
    const std::string message = e.what();
    EXPECT_EQ(message.rfind(path, 0), 0u) << message;
    EXPECT_NE(message.find(phrase), std::string::npos) << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
  }
}

std::string bigEndian(std::initializer_list<float> values)
{
  std::string out;
  for (float v : values)
  {
    uint32_t bits;
    std::memcpy(&bits, &v, 4);
    for (int shift = 24; shift >= 0; shift -= 8) out.push_back(static_cast<char>(bits >> shift));
  }
  return out;
}

std::string bigEndian(std::initializer_list<int32_t> values)
{
  std::string out;
  for (int32_t v : values)
    for (int shift = 24; shift >= 0; shift -= 8)
      out.push_back(static_cast<char>(static_cast<uint32_t>(v) >> shift));
  return out;
}

const char* const tetrahedronPoints = "POINTS 4 float\n0 0 0 1 0 0 0 1 0 0 0 1\n";
const char* const newLayoutCells = "POLYGONS 5 12\nOFFSETS vtktypeint64\n0 3 6 9 12\n"
                                   "CONNECTIVITY vtktypeint64\n0 1 2 0 1 3 0 2 3 1 2 3\n";

std::string legacyTetrahedron(const std::string& version, const std::string& cells)
{
  return "# vtk DataFile Version " + version + "\ntet\nASCII\nDATASET POLYDATA\n" +
         tetrahedronPoints + cells;
}

std::string binaryTetrahedron(const std::string& points, const std::string& polygons)
{
  return "# vtk DataFile Version 3.0\ntet\nBINARY\nDATASET POLYDATA\nPOINTS " + points +
         " float\n" + bigEndian({0.f, 0.f, 0.f, 1.f, 0.f, 0.f, 0.f, 1.f, 0.f, 0.f, 0.f, 1.f}) +
         "\nPOLYGONS " + polygons + "\n" +
         bigEndian({3, 0, 1, 2, 3, 0, 1, 3, 3, 0, 2, 3, 3, 1, 2, 3}) + "\n";
}
} // namespace

TEST(HostileFiles, LegacyVtkLayoutIsReadFromTheContentNotTheVersionLine)
{
  const std::string dir = scratchDir("hostile-vtk");
  // VTK's reader took the cell layout from the version line and crashed on these.
  for (const char* version : {"5.1", "4.2", "1.0", "3.0"})
  {
    const std::string path =
        writeText(dir + "/v" + version + ".vtk", legacyTetrahedron(version, newLayoutCells));
    const TriangleMesh mesh = readMeshFile(path);
    EXPECT_EQ(mesh.numVertices(), 4) << path;
    EXPECT_EQ(mesh.numFaces(), 4) << path;
  }
  const std::string old =
      writeText(dir + "/old.vtk",
                legacyTetrahedron("3.0", "POLYGONS 4 16\n3 0 1 2\n3 0 1 3\n3 0 2 3\n3 1 2 3\n"));
  EXPECT_EQ(readMeshFile(old).numFaces(), 4);
  // Field data before the points (a time value) and point data after the cells are skipped.
  const std::string fields = writeText(
      dir + "/fields.vtk", "# vtk DataFile Version 5.1\ntet\nASCII\nDATASET POLYDATA\n"
                           "FIELD FieldData 1\nTimeValue 1 1 double\n0.5\n" +
                               std::string(tetrahedronPoints) + newLayoutCells +
                               "POINT_DATA 4\nSCALARS s float 1\nLOOKUP_TABLE default\n1 2 3 4\n");
  EXPECT_EQ(readMeshFile(fields).numFaces(), 4);
  const std::string binary = writeText(dir + "/binary.vtk", binaryTetrahedron("4", "4 16"));
  const TriangleMesh mesh = readMeshFile(binary);
  ASSERT_EQ(mesh.numFaces(), 4);
  EXPECT_EQ(mesh.V(3, 2), 1.0);
  EXPECT_EQ(mesh.F(3, 0), 1);

  expectError(writeText(dir + "/bad-version.vtk", legacyTetrahedron("x.y", newLayoutCells)),
              "not a legacy VTK file");
  expectError(writeText(dir + "/negative-points.vtk", binaryTetrahedron("-1", "4 16")),
              "malformed count '-1'");
  expectError(writeText(dir + "/negative-size.vtk", binaryTetrahedron("4", "5 -1")),
              "malformed count '-1'");
  expectError(writeText(dir + "/huge-points.vtk", binaryTetrahedron("100000000", "4 16")),
              "more than the");
  expectError(writeText(dir + "/overrun.vtk", binaryTetrahedron("4", "5 16")), "overruns");
  expectError(writeText(dir + "/index.vtk", legacyTetrahedron("3.0", "POLYGONS 1 4\n3 0 1 7\n")),
              "out of range");
  expectError(writeText(dir + "/grid.vtk", "# vtk DataFile Version 3.0\nx\nASCII\n"
                                           "DATASET STRUCTURED_POINTS\n"),
              "does not hold POLYDATA");
}

TEST(HostileFiles, LegacyVtkWrittenByVtkReadsBack)
{
  // Both encodings, with point data after the geometry (skipped).
  const std::string dir = scratchDir("hostile-vtk-roundtrip");
  const TriangleMesh torusMesh = torus(0.5, 0.15, 12, 8);
  for (bool binary : {false, true})
  {
    vtkSmartPointer<vtkPolyData> data = toPolyData(torusMesh);
    vtkNew<vtkPolyDataWriter> writer;
    writer->SetInputData(data);
    const std::string path = dir + (binary ? "/b.vtk" : "/a.vtk");
    writer->SetFileName(path.c_str());
    binary ? writer->SetFileTypeToBinary() : writer->SetFileTypeToASCII();
    ASSERT_EQ(writer->Write(), 1);
    const TriangleMesh back = readMeshFile(path);
    ASSERT_EQ(back.numFaces(), torusMesh.numFaces()) << path;
    EXPECT_TRUE(back.F == torusMesh.F) << path;
    EXPECT_LT((back.V - torusMesh.V).cwiseAbs().maxCoeff(), binary ? 1e-12 : 1e-5) << path;
  }
}

TEST(HostileFiles, DeclaredSizesAreCheckedBeforeAllocating)
{
  const std::string dir = scratchDir("hostile-sizes");
  // An OFF tetrahedron declaring 1e8 vertices grew past 700 MB before it failed.
  expectError(writeText(dir + "/huge.off", "OFF\n100000000 4 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n"
                                           "3 0 1 2\n"),
              "the header declares 100000000 vertices");

  const std::string triangle(50, '\0');
  auto binarySTL = [&](uint32_t declared)
  {
    std::string data(80, '\0');
    for (int k = 0; k < 4; ++k) data.push_back(static_cast<char>(declared >> (8 * k)));
    return data + triangle;
  };
  expectError(writeText(dir + "/zero.stl", binarySTL(0)), "declares 0 triangles");
  expectError(writeText(dir + "/max.stl", binarySTL(4294967295u)), "declares 4294967295 triangles");

  // VTK XML: a negative count crashed in memcpy, a huge one asked for terabytes.
  vtkSmartPointer<vtkPolyData> data = toPolyData(torus(0.5, 0.15, 12, 8));
  vtkNew<vtkXMLPolyDataWriter> writer;
  writer->SetInputData(data);
  writer->SetDataModeToBinary();
  const std::string good = dir + "/good.vtp";
  writer->SetFileName(good.c_str());
  ASSERT_EQ(writer->Write(), 1);
  EXPECT_EQ(readMeshFile(good).numVertices(), 96);
  std::ifstream in(good);
  const std::string xml((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::string attribute = "NumberOfPoints=\"96\"";
  ASSERT_NE(xml.find(attribute), std::string::npos);
  for (const std::string& count : {std::string("-1"), std::string("400000000000")})
  {
    std::string bad = xml;
    bad.replace(bad.find(attribute), attribute.size(), "NumberOfPoints=\"" + count + "\"");
    expectError(writeText(dir + "/count" + count + ".vtp", bad), "NumberOfPoints is");
  }
  // A truncated XML file: the parser's own message, as one line.
  expectError(writeText(dir + "/truncated.vtp", xml.substr(0, xml.size() / 2)), "XML");
  const std::string polys = "NumberOfPolys=\"192\"";
  ASSERT_NE(xml.find(polys), std::string::npos);
  std::string manyPolys = xml;
  manyPolys.replace(manyPolys.find(polys), polys.size(), "NumberOfPolys=\"900000000000\"");
  expectError(writeText(dir + "/polys.vtp", manyPolys), "NumberOfPolys is 900000000000");

  // VTK sizes the connectivity by the last offset before reading it: one far past the
  // connectivity asked for gigabytes.
  writer->SetDataModeToAscii();
  const std::string ascii = dir + "/ascii.vtp";
  writer->SetFileName(ascii.c_str());
  ASSERT_EQ(writer->Write(), 1);
  EXPECT_EQ(readMeshFile(ascii).numFaces(), 192);
  std::ifstream asciiIn(ascii);
  std::string text((std::istreambuf_iterator<char>(asciiIn)), std::istreambuf_iterator<char>());
  const size_t offsets = text.rfind("Name=\"offsets\""); // the polygons', after the others
  ASSERT_NE(offsets, std::string::npos);
  // Its values (past the element's attributes) end with 3 x 192, the connectivity's length.
  const size_t last = text.find("576", text.find('>', offsets));
  ASSERT_NE(last, std::string::npos);
  text.replace(last, 3, "2147483660");
  expectError(writeText(dir + "/offsets.vtp", text),
              "Polys: the offsets ask for 2147483660 connectivity values, more than the "
              "connectivity array holds");
}

TEST(HostileFiles, TextQuirksReadAsMeant)
{
  const std::string dir = scratchDir("hostile-text");
  const std::string bom = "\xEF\xBB\xBF";
  // A byte order mark had hidden the first OBJ vertex and made OFF and PLY unreadable.
  EXPECT_EQ(readMeshFile(writeText(dir + "/bom.obj", bom + "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n"))
                .numVertices(),
            3);
  EXPECT_EQ(
      readMeshFile(writeText(dir + "/bom.off", bom + "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n"))
          .numFaces(),
      1);
  EXPECT_EQ(readMeshFile(writeText(dir + "/bom.ply",
                                   bom + "ply\nformat ascii 1.0\nelement vertex 3\nproperty float "
                                         "x\nproperty float y\nproperty float z\nelement face "
                                         "1\nproperty list uchar int vertex_indices\nend_header\n"
                                         "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n"))
                .numFaces(),
            1);
  // A denormal coordinate is a number, not a truncated record.
  const TriangleMesh tiny =
      readMeshFile(writeText(dir + "/denormal.obj", "v 1e-320 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n"));
  EXPECT_GT(tiny.V(0, 0), 0.0);
  expectError(writeText(dir + "/overflow.obj", "v 1e400 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n"),
              "malformed vertex");
}

TEST(HostileFiles, EveryFuzzFindingReadsOrIsRefused)
{
  // tests/fuzz/regressions/FORMAT/: each file that once crashed, hung or exhausted memory in a
  // reader (scripts/fuzz keeps new ones). Reading must end in a mesh or an Error, nothing else.
  const std::filesystem::path root(CLOTHTRACK_FUZZ_REGRESSIONS);
  if (!std::filesystem::is_directory(root)) GTEST_SKIP() << "no folder " << root;
  const std::string dir = scratchDir("hostile-regressions");
  int files = 0;
  for (const auto& format : std::filesystem::directory_iterator(root))
    for (const auto& entry : std::filesystem::directory_iterator(format.path()))
    {
      // The reader goes by the extension: the folder's name, whatever the file is called.
      const std::string path =
          dir + "/" + entry.path().stem().string() + "." + format.path().filename().string();
      std::filesystem::copy_file(entry.path(), path,
                                 std::filesystem::copy_options::overwrite_existing);
      try
      {
        TriangleMesh mesh = readMeshFile(path);
        validateAndClean(mesh, path);
      }
      catch (const Error& e)
      {
        EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos) << e.what();
      }
      ++files;
    }
  EXPECT_GE(files, 10);
}
