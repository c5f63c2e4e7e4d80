// ctPatchCorrespondence on simulated captures where the arms touch the body, against the
// ground truth carried by the capture simulator's source map.
#include "VtkTestUtil.h"
#include "ctBuiltinBodyModel.h"
#include "ctCaptureSimulation.h"
#include "ctLandmarkPolyData.h"
#include "ctMeshConversion.h"
#include "ctPatchCorrespondence.h"
#include "ctSyntheticSequence.h"

#include <clothtrack/body/OrientedLandmarks.h>
#include <clothtrack/correspondence/PatchCorrespondence.h>
#include <clothtrack/mesh/Primitives.h>

#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkMultiBlockDataSet.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkTable.h>

#include <gtest/gtest.h>

#include <cstdio>

using namespace clothtrack;
using clothtrack::test::ErrorWatch;

namespace
{
struct CapturedFrame
{
  TriangleMesh truth, capture;
  SourceMap source;
  vtkSmartPointer<vtkPolyData> landmarks;
};

/// Arms hanging against the sides (frame 0: the capture merges them with the torso) and raised
/// overhead (frame 1: free).
std::vector<CapturedFrame> armRaise()
{
  const BodyModel& model = builtinBodyModel();
  SyntheticOptions options;
  options.preset = "shirt-armraise";
  options.frames = 7;
  options.fps = 4.0; // frame 6 is t = 1.5 s, arms overhead
  std::vector<CapturedFrame> frames;
  generateSyntheticSequence(model, options,
                            [&](const SyntheticFrame& frame)
                            {
                              if (frame.index != 0 && frame.index != 6) return;
                              CapturedFrame f;
                              f.truth = frame.clothed;
                              CaptureOptions capture;
                              f.capture = simulateCapture(frame.clothed, capture, &f.source);
                              const auto points = orientedLandmarks(model, frame.body);
                              const SurfaceLocator locator(f.capture);
                              f.landmarks = transferredLandmarksToPolyData(
                                  points, transferLandmarks(points, f.capture, locator));
                              addLandmarkIdentity(model, f.landmarks);
                              frames.push_back(std::move(f));
                            });
  return frames;
}
} // namespace

TEST(PatchCorrespondence, ArmsMergedWithTheTorsoDoNotCapturePatches)
{
  const std::vector<CapturedFrame> frames = armRaise();
  ASSERT_EQ(frames.size(), 2u);
  vtkNew<vtkMultiBlockDataSet> sequence, landmarks;
  for (unsigned k = 0; k < 2; ++k)
  {
    sequence->SetBlock(k, toPolyData(frames[k].capture));
    landmarks->SetBlock(k, frames[k].landmarks);
  }
  vtkNew<ctPatchCorrespondence> filter;
  filter->SetInputData(0, sequence);
  filter->SetInputData(1, landmarks);
  filter->SetTemplateFrame(1); // arms free
  ErrorWatch errors(filter);
  filter->Update();
  ASSERT_EQ(errors.message, "");
  EXPECT_EQ(filter->GetChosenFrame(), 1);

  auto* output = vtkMultiBlockDataSet::SafeDownCast(filter->GetOutputDataObject(0));
  ASSERT_EQ(output->GetNumberOfBlocks(), 2u);
  auto* atSides = vtkPolyData::SafeDownCast(output->GetBlock(0));
  ASSERT_NE(atSides, nullptr);
  vtkPointData* pd = atSides->GetPointData();
  for (const char* name : {"Matched", "TargetPosition", "TargetFace", "TargetBarycentric",
                           "PatchCount", "Spread", "PatchId"})
    EXPECT_NE(pd->GetArray(name), nullptr) << name;
  EXPECT_EQ(atSides->GetNumberOfPoints(), frames[1].capture.numVertices());
  EXPECT_EQ(filter->GetSummaryOutput()->GetNumberOfRows(), 2);

  // Errors against the truth: template vertex -> its true source point, followed to frame 0.
  const TriangleMesh& templ = frames[1].capture;
  const SourceMap& source = frames[1].source;
  vtkDataArray* matched = pd->GetArray("Matched");
  vtkDataArray* target = pd->GetArray("TargetPosition");
  const FrameCorrespondence baseline = rigidNearestCorrespondence(
      templ, landmarkSurfacePoints(frames[1].landmarks, templ.numFaces(), "template"),
      frames[0].capture,
      landmarkSurfacePoints(frames[0].landmarks, frames[0].capture.numFaces(), "frame"));
  double patchError = 0, baselineError = 0;
  int count = 0, armMatched = 0, armFar = 0, baselineArmFar = 0, arm = 0;
  for (int v = 0; v < templ.numVertices(); ++v)
  {
    const Vec3 truth = surfacePosition(frames[0].truth, source.face[v], source.barycentric[v]);
    const bool onRaisedArm = std::abs(templ.V(v, 0)) > 0.22 && templ.V(v, 1) > 1.45;
    arm += onRaisedArm;
    const double baseError = (baseline.vertices[v].position - truth).norm();
    if (onRaisedArm) baselineArmFar += baseError > 0.1;
    if (matched->GetTuple1(v) == 0) continue;
    double t[3];
    target->GetTuple(v, t);
    const double e = (Vec3(t[0], t[1], t[2]) - truth).norm();
    patchError += e;
    baselineError += baseError;
    ++count;
    if (onRaisedArm)
    {
      ++armMatched;
      armFar += e > 0.1;
    }
  }
  ASSERT_GT(arm, 300);
  ASSERT_GT(count, templ.numVertices() / 3);
  std::printf("[ measured ] arms at the sides vs overhead: %d of %d template vertices matched, "
              "mean error %.2f cm (rigid + nearest on the same vertices %.2f cm); arm vertices "
              "matched %d of %d, off by > 10 cm %d (rigid + nearest %d)\n",
              count, templ.numVertices(), 100 * patchError / count, 100 * baselineError / count,
              armMatched, arm, armFar, baselineArmFar);
  EXPECT_LT(patchError / count, 0.5 * baselineError / count);
  // Arm patches stop at the merge instead of spilling onto the torso.
  EXPECT_LT(armFar, 0.1 * std::max(1, armMatched));
  EXPECT_LT(armFar, baselineArmFar / 4);
}

namespace
{
/// Landmarks polydata with the arrays ctBodyFit writes, at the centres of the given faces.
vtkSmartPointer<vtkPolyData> landmarkData(const TriangleMesh& mesh, const std::vector<int>& faces)
{
  std::vector<OrientedPoint> points;
  std::vector<TransferredLandmark> transferred;
  for (int f : faces)
  {
    TransferredLandmark t;
    t.valid = true;
    t.point.face = f;
    t.point.bary = Vec3::Constant(1.0 / 3);
    t.point.position = surfacePosition(mesh, f, t.point.bary);
    t.direction = (mesh.vertex(mesh.F(f, 1)) - mesh.vertex(mesh.F(f, 0))).normalized();
    transferred.push_back(t);
    points.push_back({t.point.position, t.point.position.normalized(), t.direction});
  }
  return transferredLandmarksToPolyData(points, transferred);
}
} // namespace

TEST(PatchCorrespondence, FilterFlagsFramesWithoutLandmarksAndRejectsBadLandmarks)
{
  const TriangleMesh sphere = icosphere(3, 0.5);
  vtkNew<vtkMultiBlockDataSet> sequence, landmarks;
  for (unsigned k = 0; k < 2; ++k) sequence->SetBlock(k, toPolyData(sphere));
  landmarks->SetBlock(0, landmarkData(sphere, {0, 400, 800}));
  landmarks->SetBlock(1, landmarkData(sphere, {}));
  {
    vtkNew<ctPatchCorrespondence> filter;
    filter->SetInputData(0, sequence);
    filter->SetInputData(1, landmarks);
    filter->SetTemplateFrame(0);
    ErrorWatch warnings(filter);
    filter->Update();
    EXPECT_NE(warnings.message.find("no landmark"), std::string::npos) << warnings.message;
    auto* output = vtkMultiBlockDataSet::SafeDownCast(filter->GetOutputDataObject(0));
    auto* self = vtkPolyData::SafeDownCast(output->GetBlock(0));
    auto* other = vtkPolyData::SafeDownCast(output->GetBlock(1));
    ASSERT_NE(self, nullptr);
    ASSERT_NE(other, nullptr);
    EXPECT_EQ(self->GetFieldData()->GetArray("MatchedFraction")->GetTuple1(0), 1.0);
    EXPECT_EQ(other->GetFieldData()->GetArray("MatchedFraction")->GetTuple1(0), 0.0);
  }
  // A landmark on a face the frame does not have: an error naming the frame.
  landmarks->SetBlock(1, landmarkData(icosphere(4, 0.5), {5000}));
  {
    vtkNew<ctPatchCorrespondence> filter;
    filter->SetInputData(0, sequence);
    filter->SetInputData(1, landmarks);
    filter->SetTemplateFrame(0);
    ErrorWatch errors(filter);
    filter->Update();
    EXPECT_NE(errors.message.find("landmarks of frame 1"), std::string::npos) << errors.message;
  }
  // One landmark block for two frames.
  vtkNew<vtkMultiBlockDataSet> tooFew;
  tooFew->SetBlock(0, landmarkData(sphere, {0}));
  {
    vtkNew<ctPatchCorrespondence> filter;
    filter->SetInputData(0, sequence);
    filter->SetInputData(1, tooFew);
    ErrorWatch errors(filter);
    filter->Update();
    EXPECT_NE(errors.message.find("one block per frame"), std::string::npos) << errors.message;
  }
}

TEST(PatchCorrespondence, FilterCountsOutvotedSeeds)
{
  // Eight landmarks on a sphere; on the frame (the same sphere) the first one sits 30 cm from
  // where it belongs.
  const TriangleMesh sphere = icosphere(3, 0.5);
  std::vector<int> faces;
  for (int f = 0; f < sphere.numFaces(); f += 160) faces.push_back(f);
  std::vector<int> moved = faces;
  const Vec3 right = surfacePosition(sphere, faces[0], Vec3::Constant(1.0 / 3));
  for (int f = 0; f < sphere.numFaces(); ++f)
    if (std::abs((surfacePosition(sphere, f, Vec3::Constant(1.0 / 3)) - right).norm() - 0.3) < 0.02)
      moved[0] = f;
  ASSERT_NE(moved[0], faces[0]);
  vtkNew<vtkMultiBlockDataSet> sequence, landmarks;
  for (unsigned k = 0; k < 2; ++k) sequence->SetBlock(k, toPolyData(sphere));
  landmarks->SetBlock(0, landmarkData(sphere, faces));
  landmarks->SetBlock(1, landmarkData(sphere, moved));
  for (const double minimum : {0.7, 0.0})
  {
    vtkNew<ctPatchCorrespondence> filter;
    filter->SetInputData(0, sequence);
    filter->SetInputData(1, landmarks);
    filter->SetTemplateFrame(0);
    filter->SetMinimumSeedConsensus(minimum);
    ErrorWatch errors(filter);
    filter->Update();
    ASSERT_EQ(errors.message, "");
    vtkTable* summary = filter->GetSummaryOutput();
    ASSERT_NE(summary->GetColumnByName("SeedsOutvoted"), nullptr);
    EXPECT_EQ(summary->GetValueByName(0, "SeedsOutvoted").ToInt(), 0);
    EXPECT_EQ(summary->GetValueByName(1, "SeedsOutvoted").ToInt(), minimum > 0 ? 1 : 0);
    EXPECT_EQ(summary->GetValueByName(1, "PatchesKept").ToInt(), minimum > 0 ? 7 : 8);
  }
}
