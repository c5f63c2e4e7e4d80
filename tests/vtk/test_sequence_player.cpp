#include "VtkTestUtil.h"
#include "ctSequencePlayer.h"

#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkMultiBlockDataSet.h>
#include <vtkMultiBlockDataSetAlgorithm.h>
#include <vtkNew.h>
#include <vtkObjectFactory.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkStreamingDemandDrivenPipeline.h>

#include <gtest/gtest.h>

namespace
{
// A whole-sequence producer that counts its executions: frame k is one point at x = k.
class CountingSequence : public vtkMultiBlockDataSetAlgorithm
{
public:
  static CountingSequence* New();
  vtkTypeMacro(CountingSequence, vtkMultiBlockDataSetAlgorithm);
  int executions = 0;
  int frames = 4;
  bool withTimes = true;

protected:
  CountingSequence() { this->SetNumberOfInputPorts(0); }
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector* out) override
  {
    ++executions;
    auto* output = vtkMultiBlockDataSet::GetData(out);
    output->SetNumberOfBlocks(frames);
    for (int k = 0; k < frames; ++k)
    {
      vtkNew<vtkPolyData> frame;
      vtkNew<vtkPoints> points;
      points->InsertNextPoint(k, 0, 0);
      frame->SetPoints(points);
      if (withTimes)
      {
        vtkNew<vtkDoubleArray> time;
        time->SetName("TimeValue");
        time->InsertNextValue(0.5 + 0.1 * k);
        frame->GetFieldData()->AddArray(time);
      }
      output->SetBlock(k, frame);
    }
    return 1;
  }
};
vtkStandardNewMacro(CountingSequence);
} // namespace

TEST(SequencePlayer, StepsThroughTheFramesWithoutRecomputingThem)
{
  vtkNew<CountingSequence> source;
  vtkNew<ctSequencePlayer> player;
  player->SetInputConnection(source->GetOutputPort());
  player->UpdateInformation();
  vtkInformation* info = player->GetOutputInformation(0);
  ASSERT_TRUE(info->Has(vtkStreamingDemandDrivenPipeline::TIME_STEPS()));
  ASSERT_EQ(info->Length(vtkStreamingDemandDrivenPipeline::TIME_STEPS()), 4);
  EXPECT_DOUBLE_EQ(info->Get(vtkStreamingDemandDrivenPipeline::TIME_STEPS())[3], 0.8);

  const double times[][2] = {{0.5, 0}, {0.65, 1}, {0.7, 2}, {0.0, 0}, {5.0, 3}, {0.8, 3}};
  for (const auto& [t, frame] : times)
  {
    player->UpdateTimeStep(t);
    ASSERT_EQ(player->GetOutput()->GetNumberOfPoints(), 1);
    EXPECT_DOUBLE_EQ(player->GetOutput()->GetPoint(0)[0], frame) << "time " << t;
  }
  EXPECT_EQ(source->executions, 1);

  // A new input result gives new time steps.
  source->frames = 6;
  source->withTimes = false;
  source->Modified();
  player->SetFrameRate(10);
  player->UpdateTimeStep(0.35);
  EXPECT_EQ(player->GetFrameTimes().size(), 6u);
  EXPECT_DOUBLE_EQ(player->GetOutput()->GetPoint(0)[0], 3.0);
  EXPECT_EQ(source->executions, 2);
}

TEST(SequencePlayer, AnEmptySequenceIsAnError)
{
  vtkNew<CountingSequence> source;
  source->frames = 0;
  vtkNew<ctSequencePlayer> player;
  player->SetInputConnection(source->GetOutputPort());
  clothtrack::test::ErrorWatch watch(player);
  player->Update();
  EXPECT_NE(watch.message.find("no frames"), std::string::npos) << watch.message;
}
