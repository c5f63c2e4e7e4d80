// Point clouds through the VTK layer: the sequence reader opens cloud files as points (normals
// and colours kept), and ctSurfaceReconstruction makes them into a mesh that says how sure it is.
#include "ctMeshSequenceReader.h"
#include "ctPointCloudFile.h"
#include "ctSurfaceReconstruction.h"

#include <clothtrack/cloud/DepthCapture.h>
#include <clothtrack/mesh/Primitives.h>

#include <vtkCellArray.h>
#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkStringArray.h>

#include <gtest/gtest.h>

#include <filesystem>

using namespace clothtrack;

namespace
{
PointCloud sphereCloud()
{
  DepthRig rig;
  rig.centre = Vec3(0, 1, 0);
  rig.noise = 0.002;
  rig.outliers = 0.01;
  return captureDepth(icosphere(4, 0.3, rig.centre), rig);
}
} // namespace

TEST(PointCloudReader, ReadsCloudFramesAsPointsWithTheirArrays)
{
  const std::string dir = std::string(CLOTHTRACK_TEST_TMP) + "/cloud_reader";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  PointCloud cloud = sphereCloud();
  cloud.N = cloud.P.rowwise() - Eigen::RowVector3d(0, 1, 0);
  cloud.C.setConstant(cloud.size(), 3, 200);
  writePointCloudFile(dir + "/frame_0000.pcd", cloud);
  writePointCloudFile(dir + "/frame_0001.ply", cloud);
  writePointCloudFile(dir + "/frame_0002.xyz", cloud);
  vtkNew<ctMeshSequenceReader> reader;
  reader->SetFileName(dir.c_str());
  reader->UpdateInformation();
  ASSERT_EQ(reader->GetNumberOfFrames(), 3);
  for (int k = 0; k < 3; ++k)
  {
    SCOPED_TRACE(k);
    vtkPolyData* frame = reader->ReadFrame(k);
    ASSERT_NE(frame, nullptr);
    EXPECT_EQ(frame->GetNumberOfPoints(), cloud.size());
    EXPECT_EQ(frame->GetVerts()->GetNumberOfCells(), cloud.size());
    EXPECT_EQ(frame->GetNumberOfPolys(), 0);
    ASSERT_NE(frame->GetPointData()->GetNormals(), nullptr);
    EXPECT_EQ(frame->GetPointData()->GetArray("Colors") != nullptr, k < 2); // not in XYZ
    frame->Delete();
  }
}

TEST(SurfaceReconstructionFilter, MakesACloudIntoAClosedSurface)
{
  vtkNew<ctSurfaceReconstruction> filter;
  filter->SetInputData(toPolyData(sphereCloud()));
  filter->Update();
  vtkPolyData* mesh = filter->GetOutput();
  ASSERT_GT(mesh->GetNumberOfPolys(), 1000);
  double worst = 0;
  for (vtkIdType i = 0; i < mesh->GetNumberOfPoints(); ++i)
  {
    double p[3];
    mesh->GetPoint(i, p);
    worst = std::max(worst, std::abs((Vec3(p[0], p[1], p[2]) - Vec3(0, 1, 0)).norm() - 0.3));
  }
  EXPECT_LT(worst, 0.01);
  vtkFieldData* fields = mesh->GetFieldData();
  ASSERT_NE(fields->GetArray("ReconstructionPieces"), nullptr);
  EXPECT_EQ(fields->GetArray("ReconstructionPieces")->GetTuple1(0), 1);
  EXPECT_EQ(fields->GetArray("ReconstructionGenus")->GetTuple1(0), 0);
  EXPECT_LT(fields->GetArray("ReconstructionUnexplainedShare")->GetTuple1(0), 0.01);
  auto* doubts = vtkStringArray::SafeDownCast(fields->GetAbstractArray("ReconstructionDoubts"));
  ASSERT_NE(doubts, nullptr);
  EXPECT_EQ(doubts->GetNumberOfValues(), 0);
}

TEST(SurfaceReconstructionFilter, RefusesAnEmptyInput)
{
  vtkNew<ctSurfaceReconstruction> filter;
  vtkNew<vtkPolyData> empty;
  filter->SetInputData(empty);
  testing::internal::CaptureStderr();
  filter->Update();
  const std::string err = testing::internal::GetCapturedStderr();
  EXPECT_EQ(filter->GetOutput()->GetNumberOfPoints(), 0);
  EXPECT_NE(err.find("surface reconstruction input"), std::string::npos) << err;
}
