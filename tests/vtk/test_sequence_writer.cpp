#include "../core/TestUtil.h"

#include "ctMeshConversion.h"
#include "ctMeshSequenceReader.h"
#include "ctMeshSequenceWriter.h"

#include <clothtrack/io/MeshIO.h>
#include <clothtrack/mesh/Primitives.h>

#include <vtkMultiBlockDataSet.h>
#include <vtkNew.h>
#include <vtkPolyData.h>

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

using namespace clothtrack;
using clothtrack::test::scratchDir;
namespace fs = std::filesystem;

namespace
{
TriangleMesh shifted(int k)
{
  TriangleMesh mesh = icosphere(2, 0.3);
  mesh.V.col(1).array() += 0.05 * k;
  return mesh;
}

std::string slurp(const std::string& path)
{
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}
} // namespace

TEST(SequenceWriter, TemporalInputWritesEveryStep)
{
  const std::string in = scratchDir("writer-in"), out = scratchDir("writer-out");
  for (int k = 0; k < 5; ++k) writeOBJ(in + "/s_" + std::to_string(k) + ".obj", shifted(k));
  vtkNew<ctMeshSequenceReader> reader;
  reader->SetFileName(in.c_str());
  vtkNew<ctMeshSequenceWriter> writer;
  writer->SetInputConnection(reader->GetOutputPort(0));
  writer->SetFileName((out + "/seq.pvd").c_str());
  writer->WriteOBJOn();
  ASSERT_EQ(writer->Write(), 1);
  EXPECT_EQ(writer->GetNumberOfFramesWritten(), 5);
  for (int k = 0; k < 5; ++k)
  {
    char name[32];
    std::snprintf(name, sizeof(name), "seq_%04d", k);
    EXPECT_TRUE(fs::exists(out + "/seq/" + name + ".vtp"));
    EXPECT_TRUE(fs::exists(out + "/seq/" + name + ".obj"));
  }
  EXPECT_FALSE(fs::exists(out + "/seq.pvd.part"));
  const std::string pvd = slurp(out + "/seq.pvd");
  EXPECT_NE(pvd.find("timestep=\"0.16\" part=\"0\" file=\"seq/seq_0004.vtp\""), std::string::npos)
      << pvd;

  // Read back the written collection's frames: same geometry, same order.
  vtkNew<ctMeshSequenceReader> back;
  back->SetFileName((out + "/seq/*.vtp").c_str());
  back->Update(1);
  vtkMultiBlockDataSet* all = back->GetSequenceOutput();
  ASSERT_EQ(all->GetNumberOfBlocks(), 5u);
  for (unsigned k = 0; k < 5; ++k)
  {
    const TriangleMesh frame = toTriangleMesh(vtkPolyData::SafeDownCast(all->GetBlock(k)), "back");
    EXPECT_LT((frame.V - shifted(static_cast<int>(k)).V).cwiseAbs().maxCoeff(), 1e-9);
  }
}

TEST(SequenceWriter, MultiBlockInput)
{
  const std::string out = scratchDir("writer-mb");
  vtkNew<vtkMultiBlockDataSet> blocks;
  blocks->SetNumberOfBlocks(3);
  for (unsigned k = 0; k < 3; ++k) blocks->SetBlock(k, toPolyData(shifted(static_cast<int>(k))));
  vtkNew<ctMeshSequenceWriter> writer;
  writer->SetInputData(blocks);
  writer->SetFrameRate(2);
  writer->SetFileName((out + "/mb.pvd").c_str());
  ASSERT_EQ(writer->Write(), 1);
  EXPECT_EQ(writer->GetNumberOfFramesWritten(), 3);
  EXPECT_NE(slurp(out + "/mb.pvd").find("timestep=\"1\" part=\"0\" file=\"mb/mb_0002.vtp\""),
            std::string::npos);
}

TEST(SequenceWriter, UnwritableFolderFails)
{
  vtkNew<ctMeshSequenceWriter> writer;
  writer->SetInputData(toPolyData(shifted(0)));
  writer->SetFileName("/proc/clothtrack-not-writable/x.pvd");
  writer->GlobalWarningDisplayOff();
  vtkObject::GlobalWarningDisplayOff();
  EXPECT_EQ(writer->Write(), 0);
  vtkObject::GlobalWarningDisplayOn();
}
