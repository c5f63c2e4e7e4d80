// ctTemplateFit: one connectivity through the sequence, with its point data and summary, and
// clear errors for inputs that do not fit together.
#include "VtkTestUtil.h"
#include "ctMeshConversion.h"
#include "ctTemplateFit.h"

#include <clothtrack/mesh/Primitives.h>

#include <vtkCharArray.h>
#include <vtkDataArray.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkIntArray.h>
#include <vtkMultiBlockDataSet.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkTable.h>

#include <gtest/gtest.h>

using namespace clothtrack;
using clothtrack::test::ErrorWatch;

namespace
{
/// Three frames of a sphere moving 5 cm per frame; frame 1 is the template. Correspondence
/// blocks are template copies pointing at every third vertex's true position.
struct Inputs
{
  vtkNew<vtkMultiBlockDataSet> frames, correspondence;
  std::vector<TriangleMesh> truth;
};

void fill(Inputs& in, bool withCorrespondence = true)
{
  const TriangleMesh t = icosphere(3, 0.15);
  in.frames->SetNumberOfBlocks(3);
  in.correspondence->SetNumberOfBlocks(3);
  for (int k = 0; k < 3; ++k)
  {
    TriangleMesh m = t;
    m.V.col(0).array() += 0.05 * (k - 1);
    m.V.col(1).array() *= 1.0 + 0.1 * (k - 1);
    in.truth.push_back(m);
    in.frames->SetBlock(k, toPolyData(m));
  }
  for (int k = 0; k < 3; ++k)
  {
    vtkSmartPointer<vtkPolyData> block = toPolyData(t);
    vtkNew<vtkCharArray> matched;
    matched->SetName("Matched");
    vtkNew<vtkDoubleArray> target;
    target->SetName("TargetPosition");
    target->SetNumberOfComponents(3);
    for (int v = 0; v < t.numVertices(); ++v)
    {
      matched->InsertNextValue(withCorrespondence && v % 3 == 0);
      target->InsertNextTuple(in.truth[k].V.row(v).data());
    }
    block->GetPointData()->AddArray(matched);
    block->GetPointData()->AddArray(target);
    vtkNew<vtkIntArray> templateFrame;
    templateFrame->SetName("TemplateFrame");
    templateFrame->InsertNextValue(1);
    block->GetFieldData()->AddArray(templateFrame);
    in.correspondence->SetBlock(k, block);
  }
}
} // namespace

TEST(TemplateFitFilter, AlignsEveryFrameWithOneConnectivity)
{
  Inputs in;
  fill(in);
  vtkNew<ctTemplateFit> fit;
  fit->SetInputData(0, in.frames);
  fit->SetInputData(1, in.correspondence);
  ErrorWatch watch(fit);
  fit->Update();
  ASSERT_TRUE(watch.message.empty()) << watch.message;
  auto* out = vtkMultiBlockDataSet::SafeDownCast(fit->GetOutputDataObject(0));
  ASSERT_EQ(out->GetNumberOfBlocks(), 3u);
  for (int k = 0; k < 3; ++k)
  {
    auto* aligned = vtkPolyData::SafeDownCast(out->GetBlock(k));
    ASSERT_NE(aligned, nullptr);
    ASSERT_EQ(aligned->GetNumberOfPoints(), in.truth[k].numVertices());
    EXPECT_EQ(aligned->GetNumberOfCells(), in.truth[k].numFaces());
    double error = 0;
    for (vtkIdType v = 0; v < aligned->GetNumberOfPoints(); ++v)
      error += (Vec3(aligned->GetPoint(v)) - in.truth[k].vertex(static_cast<int>(v))).norm();
    EXPECT_LT(error / aligned->GetNumberOfPoints(), 0.005) << "frame " << k;
    vtkDataArray* displacement = aligned->GetPointData()->GetArray("Displacement");
    ASSERT_NE(displacement, nullptr);
    // The sphere moved 5 cm along x per frame.
    EXPECT_NEAR(displacement->GetComponent(7, 0), 0.05 * (k - 1), 0.01);
    vtkDataArray* used = aligned->GetPointData()->GetArray("CorrespondenceUsed");
    ASSERT_NE(used, nullptr);
    EXPECT_EQ(used->GetComponent(3, 0), k == 1 ? 0 : 1);
    EXPECT_EQ(used->GetComponent(4, 0), 0);
    vtkDataArray* distance = aligned->GetPointData()->GetArray("SurfaceDistance");
    ASSERT_NE(distance, nullptr);
    EXPECT_LT(distance->GetRange()[1], 0.01);
    EXPECT_EQ(aligned->GetFieldData()->GetArray("FrameIndex")->GetComponent(0, 0), k);
  }
  vtkTable* table = fit->GetSummaryOutput();
  ASSERT_EQ(table->GetNumberOfRows(), 3);
  EXPECT_EQ(table->GetValueByName(1, "Rounds").ToInt(), 0); // the template frame
  EXPECT_GT(table->GetValueByName(0, "Rounds").ToInt(), 1);
  EXPECT_GT(table->GetValueByName(2, "CorrespondencesUsed").ToInt(), 100);
}

TEST(TemplateFitFilter, LbfgsAndStagesAreParameters)
{
  Inputs in;
  fill(in);
  vtkNew<ctTemplateFit> fit;
  fit->SetInputData(0, in.frames);
  fit->SetInputData(1, in.correspondence);
  fit->SetSolver(ctTemplateFit::LBFGS);
  fit->RemoveAllStages();
  fit->AddStage(1, 100, 0, 0.1);
  ASSERT_EQ(fit->GetNumberOfStages(), 1);
  fit->Update();
  vtkTable* table = fit->GetSummaryOutput();
  EXPECT_EQ(table->GetValueByName(0, "Rounds").ToInt(), 1);
  EXPECT_EQ(table->GetValueByName(0, "Iterations").ToInt(), 20);
  fit->RemoveAllStages();
  ErrorWatch watch(fit);
  fit->Update();
  EXPECT_NE(watch.message.find("no stage"), std::string::npos) << watch.message;
}

TEST(TemplateFitFilter, WarnsAboutFramesWithoutCorrespondence)
{
  Inputs in;
  fill(in, false);
  vtkNew<ctTemplateFit> fit;
  fit->SetInputData(0, in.frames);
  fit->SetInputData(1, in.correspondence);
  ErrorWatch watch(fit);
  fit->Update();
  EXPECT_NE(watch.message.find("has no correspondence"), std::string::npos) << watch.message;
  // Frames 5 cm away are still reached by nearest points.
  auto* aligned = vtkPolyData::SafeDownCast(
      vtkMultiBlockDataSet::SafeDownCast(fit->GetOutputDataObject(0))->GetBlock(2));
  EXPECT_LT(aligned->GetPointData()->GetArray("SurfaceDistance")->GetRange()[1], 0.02);
}

TEST(TemplateFitFilter, RefusesMismatchedInputs)
{
  Inputs in;
  fill(in);
  {
    // One correspondence block too few.
    vtkNew<vtkMultiBlockDataSet> two;
    two->SetNumberOfBlocks(2);
    two->SetBlock(0, in.correspondence->GetBlock(0));
    two->SetBlock(1, in.correspondence->GetBlock(1));
    vtkNew<ctTemplateFit> fit;
    fit->SetInputData(0, in.frames);
    fit->SetInputData(1, two);
    ErrorWatch watch(fit);
    fit->Update();
    EXPECT_NE(watch.message.find("one block per frame"), std::string::npos) << watch.message;
  }
  {
    // A correspondence block of another mesh.
    in.correspondence->SetBlock(2, toPolyData(icosphere(1, 0.1)));
    vtkNew<ctTemplateFit> fit;
    fit->SetInputData(0, in.frames);
    fit->SetInputData(1, in.correspondence);
    ErrorWatch watch(fit);
    fit->Update();
    EXPECT_NE(watch.message.find("frame 2"), std::string::npos) << watch.message;
    EXPECT_NE(watch.message.find("one point per template vertex"), std::string::npos)
        << watch.message;
  }
  {
    // A frame with a NaN coordinate.
    Inputs bad;
    fill(bad);
    TriangleMesh m = bad.truth[0];
    m.V(0, 0) = std::nan("");
    bad.frames->SetBlock(0, toPolyData(m));
    vtkNew<ctTemplateFit> fit;
    fit->SetInputData(0, bad.frames);
    fit->SetInputData(1, bad.correspondence);
    ErrorWatch watch(fit);
    fit->Update();
    EXPECT_NE(watch.message.find("frame 0"), std::string::npos) << watch.message;
  }
}
