#include "../core/TestUtil.h"
#include "VtkTestUtil.h"

#include "ctMeshConversion.h"
#include "ctMeshSequenceReader.h"

#include <clothtrack/io/MeshIO.h>
#include <clothtrack/mesh/Primitives.h>

#include <vtkCallbackCommand.h>
#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkInformation.h>
#include <vtkMultiBlockDataSet.h>
#include <vtkNew.h>
#include <vtkPLYWriter.h>
#include <vtkPolyData.h>
#include <vtkPolyDataWriter.h>
#include <vtkSTLWriter.h>
#include <vtkStreamingDemandDrivenPipeline.h>
#include <vtkStringArray.h>
#include <vtkXMLPolyDataWriter.h>

#include <gtest/gtest.h>

#include <filesystem>

using namespace clothtrack;
using clothtrack::test::ErrorWatch;
using clothtrack::test::scratchDir;
using clothtrack::test::writeText;

namespace
{
template <class Writer> void writeWith(vtkPolyData* data, const std::string& path)
{
  vtkNew<Writer> writer;
  writer->SetInputData(data);
  writer->SetFileName(path.c_str());
  ASSERT_EQ(writer->Write(), 1) << path;
}

// Frame k of the test sequence: a torus shifted by k cm along x.
TriangleMesh testFrame(int k)
{
  TriangleMesh mesh = torus(0.5, 0.15, 16, 10);
  mesh.V.col(0).array() += 0.01 * k;
  return mesh;
}

double readX0(vtkPolyData* frame)
{
  return frame->GetPoint(0)[0];
}
} // namespace

TEST(SequenceReader, EveryFormatRoundTrips)
{
  const std::string dir = scratchDir("reader-formats");
  const TriangleMesh mesh = testFrame(0);
  vtkSmartPointer<vtkPolyData> poly = toPolyData(mesh);
  writeOBJ(dir + "/a.obj", mesh);
  writeOFF(dir + "/a.off", mesh);
  writeWith<vtkPLYWriter>(poly, dir + "/a.ply");
  writeWith<vtkSTLWriter>(poly, dir + "/a.stl");
  writeWith<vtkXMLPolyDataWriter>(poly, dir + "/a.vtp");
  writeWith<vtkPolyDataWriter>(poly, dir + "/a.vtk");
  for (const char* ext : {"obj", "off", "ply", "stl", "vtp", "vtk"})
  {
    SCOPED_TRACE(ext);
    vtkNew<ctMeshSequenceReader> reader;
    reader->SetFileName((dir + "/a." + ext).c_str());
    reader->Update();
    vtkPolyData* out = reader->GetOutput();
    ASSERT_EQ(out->GetNumberOfPoints(), mesh.numVertices());
    ASSERT_EQ(out->GetNumberOfPolys(), mesh.numFaces());
    // STL stores floats and renumbers the merged points: compare surfaces, not ids.
    const TriangleMesh back = toTriangleMesh(out, ext);
    double sum = back.V.colwise().sum().norm(), expected = mesh.V.colwise().sum().norm();
    EXPECT_NEAR(sum, expected, 1e-4);
    EXPECT_NEAR(surfaceArea(back), surfaceArea(mesh), 1e-5);
  }
}

TEST(SequenceReader, TemporalFramesInNaturalOrder)
{
  const std::string dir = scratchDir("reader-sequence");
  for (int k : {0, 1, 2, 10}) writeOBJ(dir + "/frame_" + std::to_string(k) + ".obj", testFrame(k));
  vtkNew<ctMeshSequenceReader> reader;
  reader->SetFileName(dir.c_str());
  reader->SetFrameRate(10);
  reader->UpdateInformation();
  ASSERT_EQ(reader->GetNumberOfFrames(), 4);
  EXPECT_EQ(std::filesystem::path(reader->GetFrameFileName(3)).filename(), "frame_10.obj");

  vtkInformation* info = reader->GetOutputInformation(0);
  ASSERT_TRUE(info->Has(vtkStreamingDemandDrivenPipeline::TIME_STEPS()));
  EXPECT_EQ(info->Length(vtkStreamingDemandDrivenPipeline::TIME_STEPS()), 4);
  EXPECT_DOUBLE_EQ(info->Get(vtkStreamingDemandDrivenPipeline::TIME_STEPS())[3], 0.3);

  reader->UpdateTimeStep(0.3);
  vtkPolyData* out = reader->GetOutput();
  EXPECT_NEAR(readX0(out), testFrame(10).V(0, 0), 1e-9);
  EXPECT_EQ(out->GetFieldData()->GetArray("FrameIndex")->GetTuple1(0), 3);
  EXPECT_EQ(out->GetFieldData()->GetArray("FrameNumber")->GetTuple1(0), 10);
  auto* source = vtkStringArray::SafeDownCast(out->GetFieldData()->GetAbstractArray("SourceFile"));
  ASSERT_NE(source, nullptr);
  EXPECT_EQ(source->GetValue(0), dir + "/frame_10.obj");

  reader->UpdateTimeStep(0.1);
  EXPECT_NEAR(readX0(reader->GetOutput()), testFrame(1).V(0, 0), 1e-9);

  // The whole sequence on port 1, and port 0 still answers afterwards.
  reader->Update(1);
  vtkMultiBlockDataSet* all = reader->GetSequenceOutput();
  ASSERT_EQ(all->GetNumberOfBlocks(), 4u);
  EXPECT_NEAR(readX0(vtkPolyData::SafeDownCast(all->GetBlock(2))), testFrame(2).V(0, 0), 1e-9);
  reader->UpdateTimeStep(0.2);
  EXPECT_NEAR(readX0(reader->GetOutput()), testFrame(2).V(0, 0), 1e-9);
  EXPECT_EQ(reader->GetSequenceOutput()->GetNumberOfBlocks(), 4u);

  vtkSmartPointer<vtkPolyData> direct = vtk::TakeSmartPointer(reader->ReadFrame(1));
  ASSERT_NE(direct, nullptr);
  EXPECT_NEAR(readX0(direct), testFrame(1).V(0, 0), 1e-9);
}

TEST(SequenceReader, UnitsAndUpAxis)
{
  const std::string dir = scratchDir("reader-units");
  writeText(dir + "/tri.obj", "v 0 0 0\nv 1000 0 0\nv 0 0 1800\nf 1 2 3\n");
  vtkNew<ctMeshSequenceReader> reader;
  reader->SetFileName((dir + "/tri.obj").c_str());
  reader->SetLengthUnitToMillimetres();
  reader->SetUpAxis(ctMeshSequenceReader::Z_UP);
  reader->Update();
  double p[3];
  reader->GetOutput()->GetPoint(2, p);
  EXPECT_NEAR(p[0], 0.0, 1e-12);
  EXPECT_NEAR(p[1], 1.8, 1e-12); // the file's z is now y, in metres
  EXPECT_NEAR(p[2], 0.0, 1e-12);
  reader->GetOutput()->GetPoint(1, p);
  EXPECT_NEAR(p[0], 1.0, 1e-12);
}

TEST(SequenceReader, GlobPatternAndListFile)
{
  const std::string dir = scratchDir("reader-glob");
  for (int k = 0; k < 3; ++k) writeOBJ(dir + "/mesh_" + std::to_string(k) + ".obj", testFrame(k));
  writeOBJ(dir + "/other.obj", testFrame(5));
  vtkNew<ctMeshSequenceReader> reader;
  reader->SetFileName((dir + "/mesh_*.obj").c_str());
  EXPECT_EQ(reader->GetNumberOfFrames(), 3);
  writeText(dir + "/list.txt", "mesh_2.obj\nother.obj\n");
  reader->SetFileName((dir + "/list.txt").c_str());
  EXPECT_EQ(reader->GetNumberOfFrames(), 2);
  EXPECT_EQ(reader->CanReadFile((dir + "/list.txt").c_str()), 1);
  EXPECT_EQ(reader->CanReadFile((dir + "/none").c_str()), 0);
}

namespace
{
// Reading `spec` must fail with an error message containing every word in `words`.
void expectReadError(const std::string& spec, const std::vector<std::string>& words, int port = 0)
{
  vtkNew<ctMeshSequenceReader> reader;
  ErrorWatch watch(reader);
  reader->SetFileName(spec.c_str());
  reader->Update(port);
  ASSERT_FALSE(watch.message.empty()) << "no error for " << spec;
  for (const auto& w : words) EXPECT_NE(watch.message.find(w), std::string::npos) << watch.message;
  if (port == 0)
  {
    EXPECT_EQ(reader->GetOutput()->GetNumberOfPoints(), 0);
  }
}
} // namespace

TEST(SequenceReader, BadInputGivesClearErrors)
{
  const std::string dir = scratchDir("reader-bad");
  expectReadError(dir + "/missing", {"missing", "no such file"});
  std::filesystem::create_directories(dir + "/empty");
  expectReadError(dir + "/empty", {"empty", "no mesh file"});
  const std::string empty = writeText(dir + "/empty.obj", "");
  expectReadError(empty, {empty, "empty file"});
  const std::string trunc = writeText(dir + "/trunc.obj", "v 0 0 0\nv 1 0 0\nv 0 1");
  expectReadError(trunc, {trunc, "malformed vertex"});
  const std::string range = writeText(dir + "/range.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 4\n");
  expectReadError(range, {range, "out of range"});
  const std::string nan = writeText(dir + "/nan.obj", "v 0 0 0\nv nan 0 0\nv 0 1 0\nf 1 2 3\n");
  expectReadError(nan, {nan, "NaN"});
  const std::string inf =
      writeText(dir + "/inf.off", "OFF\n3 1 0\n0 0 0\ninf 0 0\n0 1 0\n3 0 1 2\n");
  expectReadError(inf, {inf, "NaN or infinite"});
  const std::string points = writeText(dir + "/points.obj", "v 0 0 0\nv 1 0 0\n");
  expectReadError(points, {points, "no face"});
  const std::string huge = writeText(dir + "/huge.obj", "v 1e308 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  expectReadError(huge, {huge, "beyond any capture's size"});
  const std::string flat = writeText(dir + "/flat.obj", "v 0 0 0\nv 1 0 0\nv 2 0 0\nf 1 2 3\n");
  expectReadError(flat, {flat, "zero area"});
  const std::string badPly =
      writeText(dir + "/bad.ply", "ply\nformat ascii 1.0\nelement vertex 3\n");
  expectReadError(badPly, {badPly});
  const std::string badVtp = writeText(dir + "/bad.vtp", "<VTKFile type=\"PolyData\"><PolyData>");
  expectReadError(badVtp, {badVtp});
  const std::string badVtk = writeText(
      dir + "/bad.vtk", "# vtk DataFile Version 3.0\nx\nASCII\nDATASET STRUCTURED_POINTS\n");
  expectReadError(badVtk, {badVtk});
  const std::string badStl =
      writeText(dir + "/bad.stl", "solid x\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\n");
  expectReadError(badStl, {badStl});
  // A corrupt frame inside a sequence is named when the whole sequence is read.
  const std::string seq = dir + "/seq";
  std::filesystem::create_directories(seq);
  writeOBJ(seq + "/f_0.obj", testFrame(0));
  writeText(seq + "/f_1.obj", "v 0 0 0\nf 1 2 3\n");
  expectReadError(seq, {seq + "/f_1.obj", "out of range"}, 1);
}

TEST(SequenceReader, DuplicatedVerticesAndZeroAreaFacesAreRepairedWithAWarning)
{
  const std::string dir = scratchDir("reader-repair");
  const std::string path =
      writeText(dir + "/dup.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 0 0\nv 1 1 0\nv 0 1 0\n"
                                  "v 2 0 0\nf 1 2 3\nf 4 5 6\nf 1 2 7\n");
  vtkNew<ctMeshSequenceReader> reader;
  ErrorWatch watch(reader);
  reader->SetFileName(path.c_str());
  reader->Update();
  EXPECT_NE(watch.message.find("merged 2 duplicated vertices"), std::string::npos) << watch.message;
  EXPECT_EQ(reader->GetOutput()->GetNumberOfPoints(), 4);
  EXPECT_EQ(reader->GetOutput()->GetNumberOfPolys(), 2);
}

TEST(SequenceReader, VlasicSambaHas175Frames)
{
  const std::string samba = std::string(CLOTHTRACK_SHARED_DATA) + "/vlasic-samba";
  if (!std::filesystem::exists(samba))
    GTEST_SKIP() << "shared data not found at " << samba << "; skipping the real-data check";
  vtkNew<ctMeshSequenceReader> reader;
  reader->SetFileName(samba.c_str());
  reader->UpdateInformation();
  EXPECT_EQ(reader->GetNumberOfFrames(), 175);
  reader->UpdateTimeStep(174 / 25.0);
  vtkPolyData* last = reader->GetOutput();
  EXPECT_EQ(last->GetNumberOfPoints(), 9971);
  EXPECT_EQ(last->GetNumberOfPolys(), 19938);
  double bounds[6];
  last->GetBounds(bounds);
  EXPECT_NEAR(bounds[3] - bounds[2], 1.75, 0.15); // ~1.78 m tall, Y up
}
