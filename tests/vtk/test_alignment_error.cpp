// ctAlignmentError: per-vertex errors, the per-frame table and the cumulative curve against a
// ground truth, chained after ctTemplateFit, and clear errors for inputs that do not fit.
#include "VtkTestUtil.h"
#include "ctAlignmentError.h"
#include "ctMeshConversion.h"

#include <clothtrack/mesh/Primitives.h>

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

#include <cmath>

using namespace clothtrack;
using clothtrack::test::ErrorWatch;

namespace
{
/// Three frames of a sphere moving 5 cm per frame; the "aligned" frame k is the truth lifted
/// by k cm, template frame 1 (so its own error is 1 cm).
struct Inputs
{
  vtkNew<vtkMultiBlockDataSet> aligned, truth;
};

void fill(Inputs& in, bool withTemplateFrame = true)
{
  const TriangleMesh t = icosphere(3, 0.15);
  in.aligned->SetNumberOfBlocks(3);
  in.truth->SetNumberOfBlocks(3);
  for (int k = 0; k < 3; ++k)
  {
    TriangleMesh m = t;
    m.V.col(0).array() += 0.05 * k;
    in.truth->SetBlock(k, toPolyData(m));
    m.V.col(1).array() += 0.01 * k;
    vtkSmartPointer<vtkPolyData> block = toPolyData(m);
    if (withTemplateFrame)
    {
      vtkNew<vtkIntArray> templateFrame;
      templateFrame->SetName("TemplateFrame");
      templateFrame->InsertNextValue(1);
      block->GetFieldData()->AddArray(templateFrame);
    }
    in.aligned->SetBlock(k, block);
  }
}
} // namespace

TEST(AlignmentErrorFilter, ErrorsTableAndCurve)
{
  Inputs in;
  fill(in);
  vtkNew<ctAlignmentError> error;
  error->SetInputData(0, in.aligned);
  error->SetInputData(1, in.truth);
  error->SetMaximumTruthDistance(0.05); // the template frame itself is 1 cm off the truth
  ErrorWatch watch(error);
  error->Update();
  ASSERT_TRUE(watch.message.empty()) << watch.message;

  auto* out = vtkMultiBlockDataSet::SafeDownCast(error->GetOutputDataObject(0));
  ASSERT_EQ(out->GetNumberOfBlocks(), 3u);
  // At the template frame each vertex, 1 cm above the truth along y, is anchored to the truth
  // point closest to it: its error is the normal part of that offset, at most 1 cm.
  vtkDataArray* e1 = vtkPolyData::SafeDownCast(out->GetBlock(1))->GetPointData()->GetArray("Error");
  ASSERT_NE(e1, nullptr);
  double range[2];
  e1->GetRange(range);
  EXPECT_GE(range[0], 0.0);
  EXPECT_LT(range[1], 0.0101);

  vtkTable* table = error->GetFrameErrorOutput();
  ASSERT_EQ(table->GetNumberOfRows(), 3);
  const double mean0 = table->GetValueByName(0, "Mean").ToDouble();
  const double mean1 = table->GetValueByName(1, "Mean").ToDouble();
  const double mean2 = table->GetValueByName(2, "Mean").ToDouble();
  // Frame 0 lies 1 cm below the template's offset and frame 2 1 cm above it: errors of
  // 1 cm (tangential part) and between 1 and 2 cm.
  EXPECT_GT(mean0, 0.002);
  EXPECT_LT(mean0, 0.0101);
  EXPECT_LT(mean1, 0.0101);
  EXPECT_GT(mean2, mean1);
  EXPECT_LT(mean2, 0.0201);
  EXPECT_EQ(table->GetValueByName(0, "Vertices").ToInt(), 642);
  EXPECT_NEAR(table->GetValueByName(1, "Within10cm").ToDouble(), 1.0, 1e-12);
  // The sequence figures pool frames 0 and 2 (same vertex count): the mean of their means.
  vtkFieldData* sequence = table->GetFieldData();
  ASSERT_NE(sequence->GetArray("SequenceMean"), nullptr);
  EXPECT_NEAR(sequence->GetArray("SequenceMean")->GetTuple1(0), (mean0 + mean2) / 2, 1e-12);
  EXPECT_EQ(sequence->GetArray("WorstFrame")->GetTuple1(0), 2);
  EXPECT_NEAR(sequence->GetArray("SequenceWithin10cm")->GetTuple1(0), 1.0, 1e-12);

  vtkTable* curve = error->GetCumulativeOutput();
  ASSERT_EQ(curve->GetNumberOfRows(), 41);
  // Only the vertices whose offset was purely normal (the poles) have no error at all.
  EXPECT_LT(curve->GetValueByName(0, "Fraction").ToDouble(), 0.01);
  EXPECT_DOUBLE_EQ(curve->GetValueByName(40, "Fraction").ToDouble(), 1.0);
  for (vtkIdType r = 1; r < curve->GetNumberOfRows(); ++r)
    EXPECT_GE(curve->GetValueByName(r, "Fraction").ToDouble(),
              curve->GetValueByName(r - 1, "Fraction").ToDouble());
}

TEST(AlignmentErrorFilter, ExactOnTheTruthItself)
{
  Inputs in;
  fill(in);
  // Aligned = truth: every error is zero.
  for (int k = 0; k < 3; ++k)
  {
    vtkNew<vtkPolyData> copy;
    copy->DeepCopy(in.truth->GetBlock(k));
    copy->GetFieldData()->AddArray(vtkPolyData::SafeDownCast(in.aligned->GetBlock(k))
                                       ->GetFieldData()
                                       ->GetArray("TemplateFrame"));
    in.aligned->SetBlock(k, copy);
  }
  vtkNew<ctAlignmentError> error;
  error->SetInputData(0, in.aligned);
  error->SetInputData(1, in.truth);
  error->Update();
  vtkTable* table = error->GetFrameErrorOutput();
  for (vtkIdType k = 0; k < 3; ++k) EXPECT_LT(table->GetValueByName(k, "Max").ToDouble(), 1e-12);
}

TEST(AlignmentErrorFilter, RefusesInputsThatDoNotFit)
{
  {
    Inputs in;
    fill(in, false);
    vtkNew<ctAlignmentError> error;
    error->SetInputData(0, in.aligned);
    error->SetInputData(1, in.truth);
    ErrorWatch watch(error);
    error->Update();
    EXPECT_NE(watch.message.find("no TemplateFrame"), std::string::npos) << watch.message;
  }
  {
    Inputs in;
    fill(in);
    in.truth->SetNumberOfBlocks(2);
    vtkNew<ctAlignmentError> error;
    error->SetInputData(0, in.aligned);
    error->SetInputData(1, in.truth);
    ErrorWatch watch(error);
    error->Update();
    EXPECT_NE(watch.message.find("one block per frame"), std::string::npos) << watch.message;
  }
  {
    // Ground truth in centimetres: nothing within 3 cm of the template.
    Inputs in;
    fill(in);
    for (int k = 0; k < 3; ++k)
    {
      TriangleMesh m = toTriangleMesh(vtkPolyData::SafeDownCast(in.truth->GetBlock(k)), "t");
      m.V *= 100.0;
      in.truth->SetBlock(k, toPolyData(m));
    }
    vtkNew<ctAlignmentError> error;
    error->SetInputData(0, in.aligned);
    error->SetInputData(1, in.truth);
    ErrorWatch watch(error);
    error->Update();
    EXPECT_NE(watch.message.find("units or frames mismatched"), std::string::npos) << watch.message;
  }
}
