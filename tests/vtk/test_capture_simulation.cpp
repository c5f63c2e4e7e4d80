// The capture simulator: re-meshing, topological noise where limbs touch, the source map.
#include "ctBuiltinBodyModel.h"
#include "ctCaptureSimulation.h"
#include "ctMeshConversion.h"
#include "ctNamedArrays.h"
#include "ctTemplateSelection.h"

#include <clothtrack/base/Error.h>
#include <clothtrack/body/Motion.h>
#include <clothtrack/mesh/Components.h>
#include <clothtrack/mesh/Primitives.h>

#include <vtkFieldData.h>
#include <vtkMultiBlockDataSet.h>
#include <vtkNew.h>
#include <vtkPolyData.h>
#include <vtkTable.h>
#include <vtkVariant.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

using namespace clothtrack;

namespace
{
struct CaptureStats
{
  int vertices, components, genus;
  double within1Voxel, maxDistance;
};

CaptureStats capture(const TriangleMesh& truth, const CaptureOptions& options)
{
  SourceMap map;
  const TriangleMesh captured = simulateCapture(truth, options, &map);
  const Components c = connectedComponents(captured, buildTopology(captured));
  int genus = 0;
  for (const auto& info : c.info) genus += info.genus();
  int within = 0;
  for (double d : map.distance) within += d <= options.voxelSize;
  return {captured.numVertices(), c.count(), genus,
          static_cast<double>(within) / map.distance.size(),
          *std::max_element(map.distance.begin(), map.distance.end())};
}
} // namespace

TEST(CaptureSimulation, LimbsTouchingTheBodyChangeTheTopology)
{
  const BodyModel& model = builtinBodyModel();
  const Eigen::VectorXd beta = Eigen::VectorXd::Zero(4);
  CaptureOptions options;
  options.voxelSize = 0.015;
  // Arm raise: arms hang against the sides at t = 0 and are overhead at t = 1.5 s.
  std::vector<CaptureStats> stats;
  for (double t : {0.0, 0.5, 1.5})
  {
    const TriangleMesh body =
        model.posed(beta, model.grounded(beta, motionPose(MotionType::ArmRaise, t)));
    stats.push_back(capture(body, options));
    std::printf("[ measured ] arm raise t=%.1f s: %d vertices, %d components, genus %d, %.1f %% of "
                "vertices within "
                "one voxel of the truth, max %.1f mm\n",
                t, stats.back().vertices, stats.back().components, stats.back().genus,
                100 * stats.back().within1Voxel, 1000 * stats.back().maxDistance);
  }
  // Arms overhead: one genus-0 shell, like the body itself.
  EXPECT_EQ(stats[2].components, 1);
  EXPECT_EQ(stats[2].genus, 0);
  // Arms against the body: they merge with the torso and close handles (the paper's Figure 3).
  EXPECT_GT(stats[0].genus, 0);
  for (const auto& s : stats)
  {
    EXPECT_GT(s.vertices, 3000);
    EXPECT_GT(s.within1Voxel, 0.99);
  }
  // Re-meshed independently: vertex counts differ from frame to frame.
  EXPECT_NE(stats[0].vertices, stats[2].vertices);
}

TEST(CaptureSimulation, HolesNoiseAndDeterminism)
{
  const BodyModel& model = builtinBodyModel();
  const TriangleMesh body = model.posed(Eigen::VectorXd(), BodyPose());
  CaptureOptions options;
  options.voxelSize = 0.02;
  options.holes = 3;
  options.noise = 0.002;
  options.seed = 11;
  const TriangleMesh a = simulateCapture(body, options);
  const TriangleMesh b = simulateCapture(body, options);
  EXPECT_EQ(a.V, b.V);
  EXPECT_EQ(a.F, b.F);
  const Components c = connectedComponents(a, buildTopology(a));
  int boundaries = 0;
  for (const auto& info : c.info) boundaries += info.numBoundaries;
  EXPECT_GE(boundaries, 1);
  options.seed = 12;
  EXPECT_NE(simulateCapture(body, options).V.rows(), 0);
  options.voxelSize = 0;
  EXPECT_THROW(simulateCapture(body, options), Error);
}

TEST(TemplateSelectionFilter, PicksAFrameWhereTheArmsAreFree)
{
  const BodyModel& model = builtinBodyModel();
  const Eigen::VectorXd beta = Eigen::VectorXd::Zero(2);
  vtkNew<vtkMultiBlockDataSet> sequence;
  const std::vector<double> times = {0.0, 0.1, 0.2, 1.2, 1.5, 1.8};
  sequence->SetNumberOfBlocks(static_cast<unsigned>(times.size()));
  CaptureOptions options;
  options.voxelSize = 0.02;
  std::vector<int> genus;
  for (size_t k = 0; k < times.size(); ++k)
  {
    const TriangleMesh body =
        model.posed(beta, model.grounded(beta, motionPose(MotionType::ArmRaise, times[k])));
    const TriangleMesh captured = simulateCapture(body, options);
    genus.push_back(connectedComponents(captured, buildTopology(captured)).info[0].genus());
    sequence->SetBlock(static_cast<unsigned>(k), toPolyData(captured));
  }
  vtkNew<ctTemplateSelection> selection;
  selection->SetInputData(sequence);
  selection->SetPersistence(2);
  selection->Update();
  const int chosen = selection->GetChosenFrame();
  ASSERT_GE(chosen, 0);
  EXPECT_EQ(genus[chosen], *std::min_element(genus.begin(), genus.end()));
  EXPECT_GE(chosen, 3); // arms raised, not hanging against the body
  vtkTable* table = selection->GetCriteriaOutput();
  ASSERT_EQ(table->GetNumberOfRows(), 6);
  EXPECT_EQ(table->GetValueByName(chosen, "Chosen").ToInt(), 1);
  EXPECT_EQ(selection->GetOutput()->GetNumberOfPoints(),
            vtkPolyData::SafeDownCast(sequence->GetBlock(static_cast<unsigned>(chosen)))
                ->GetNumberOfPoints());
  // The override wins; an index out of range is an error.
  selection->SetTemplateFrame(1);
  selection->Update();
  EXPECT_EQ(selection->GetChosenFrame(), 1);
  selection->SetTemplateFrame(99);
  selection->GlobalWarningDisplayOff();
  selection->Update();
  selection->GlobalWarningDisplayOn();
  EXPECT_EQ(selection->GetOutput()->GetNumberOfPoints(), 0);
}

TEST(TemplateSelectionFilter, RestPoseFromTheBodyFitDecidesAmongCandidates)
{
  // Four closed spheres (one shell, genus 0, near-uniform areas) and a body fit whose frame 2 is
  // the closest to the rest pose; frame 3's fit failed (NaN).
  vtkNew<vtkMultiBlockDataSet> sequence, bodies;
  const std::vector<double> restPose = {1.5, 0.9, 0.4, NAN};
  for (unsigned k = 0; k < 4; ++k)
  {
    sequence->SetBlock(k, toPolyData(icosphere(3 - (k == 1), 0.5)));
    vtkNew<vtkPolyData> body;
    addFieldValue(body->GetFieldData(), "RestPoseDistance", restPose[k]);
    bodies->SetBlock(k, body);
  }
  vtkNew<ctTemplateSelection> selection;
  auto decidedBy = [&]
  {
    vtkAbstractArray* array =
        selection->GetOutput()->GetFieldData()->GetAbstractArray("TemplateCriterion");
    return array ? array->GetVariantValue(0).ToString() : std::string("none");
  };
  selection->SetInputData(0, sequence);
  selection->Update();
  const int byArea = selection->GetChosenFrame();
  EXPECT_NE(byArea, 2);
  EXPECT_EQ(decidedBy(), "area-ratio");

  selection->SetInputData(1, bodies);
  selection->Update();
  EXPECT_EQ(selection->GetChosenFrame(), 2);
  EXPECT_EQ(decidedBy(), "rest-pose");
  vtkTable* table = selection->GetCriteriaOutput();
  EXPECT_DOUBLE_EQ(table->GetValueByName(1, "RestPoseDistance").ToDouble(), 0.9);
  EXPECT_TRUE(std::isnan(table->GetValueByName(3, "RestPoseDistance").ToDouble()));
  // The order the pose would choose the frames in; frame 3 has no trusted pose.
  auto poseOrder = [&](int k) { return table->GetValueByName(k, "PoseOrder").ToInt(); };
  EXPECT_EQ(poseOrder(2), 0);
  EXPECT_EQ(poseOrder(1), 1);
  EXPECT_EQ(poseOrder(0), 2);
  EXPECT_EQ(poseOrder(3), -1);
  auto collection = [&]
  { return selection->GetOutput()->GetFieldData()->GetArray("CollectionOfPoses")->GetTuple1(0); };
  auto defaultCandidates = [&]
  {
    return selection->GetOutput()
        ->GetFieldData()
        ->GetArray("DefaultTemplateCandidates")
        ->GetTuple1(0);
  };
  EXPECT_EQ(collection(), 0.0) << "bodies without ContinuesPrevious continue their predecessor";
  EXPECT_EQ(defaultCandidates(), 1.0);
  for (unsigned k = 1; k < 3; ++k)
    addFieldValue(vtkPolyData::SafeDownCast(bodies->GetBlock(k))->GetFieldData(),
                  "ContinuesPrevious", 0);
  bodies->Modified();
  selection->Update();
  EXPECT_EQ(collection(), 1.0) << "two of the three frames after the first are unrelated";
  EXPECT_EQ(defaultCandidates(), 3.0);

  // The paper's criterion ignores the poses, and gives no order by pose.
  selection->SetTemplateCriterion(0);
  selection->Update();
  EXPECT_EQ(selection->GetChosenFrame(), byArea);
  EXPECT_EQ(selection->GetCriteriaOutput()->GetValueByName(2, "PoseOrder").ToInt(), -1);

  // A body fit of another length is an error.
  bodies->SetNumberOfBlocks(3);
  selection->SetTemplateCriterion(1);
  selection->GlobalWarningDisplayOff();
  selection->Update();
  selection->GlobalWarningDisplayOn();
  EXPECT_EQ(selection->GetOutput()->GetNumberOfPoints(), 0);
}
