#include <clothtrack/base/Error.h>
#include <clothtrack/mesh/Primitives.h>
#include <clothtrack/pipeline/BodyStage.h>
#include <clothtrack/selection/TemplateSelection.h>

#include <gtest/gtest.h>

#include <cmath>

using namespace clothtrack;

namespace
{
FrameTopology frame(int shells, int genus, double ratio)
{
  FrameTopology t;
  t.components = t.shells = shells;
  t.genus = genus;
  t.areaRatio = ratio;
  return t;
}
} // namespace

TEST(TemplateSelection, PersistentSplitsThenGenusThenAreaRatio)
{
  // Frame 2 shows a split for one frame only (noise); frames 5-7 show a lasting split.
  const std::vector<FrameTopology> frames = {frame(1, 0, 5.0), frame(1, 0, 4.0), frame(2, 0, 1.0),
                                             frame(1, 0, 3.0), frame(1, 1, 2.0), frame(2, 1, 9.0),
                                             frame(2, 0, 8.0), frame(2, 0, 7.5)};
  const TemplateSelection s = selectTemplate(frames, {0.1, 3});
  EXPECT_EQ(s.persistentShells[2], 1); // the one-frame split does not count
  EXPECT_EQ(s.persistentShells[6], 2);
  EXPECT_FALSE(s.candidate[5]); // genus 1 loses against genus 0
  EXPECT_TRUE(s.candidate[6]);
  EXPECT_EQ(s.chosen, 7); // lowest area ratio among the candidates
  // With persistence 1 every split counts: frame 2 wins on area ratio.
  EXPECT_EQ(selectTemplate(frames, {0.1, 1}).chosen, 2);
  EXPECT_THROW(selectTemplate({}, {}), Error);
}

TEST(TemplateSelection, FrameCriteriaFromMeshes)
{
  // A torus and a small sphere: one shell above the area threshold, genus 1.
  const TriangleMesh mesh = concatenate(torus(1.0, 0.3, 40, 16), icosphere(2, 0.1, Vec3(5, 0, 0)));
  const FrameTopology t = frameTopology(mesh, 0.5);
  EXPECT_EQ(t.components, 2);
  EXPECT_EQ(t.shells, 1);
  EXPECT_EQ(t.genus, 1);
  EXPECT_GT(t.areaRatio, 1.0);
  EXPECT_LT(t.areaRatio, 3.0); // a regular torus grid is nearly uniform
}

TEST(TemplateSelection, RestPoseAmongTheTopologicalCandidates)
{
  // Frame 1 is not a candidate (genus 1) although its pose is the closest to rest.
  const std::vector<FrameTopology> frames = {frame(1, 0, 2.0), frame(1, 1, 1.0), frame(1, 0, 9.0),
                                             frame(1, 0, 3.0), frame(1, 0, 1.5)};
  const std::vector<double> pose = {2.0, 0.1, 0.5, 0.5, NAN};
  TemplateSelectionOptions options;
  TemplateSelection s = selectTemplate(frames, options, pose);
  EXPECT_EQ(s.decidedBy, TemplateCriterion::RestPose);
  EXPECT_EQ(s.chosen, 3); // frames 2 and 3 tie on pose; 3 has the smaller area ratio
  // Frame 4's pose is unknown (failed fit): it ranks after every known pose.
  EXPECT_NE(s.chosen, 4);

  options.templateCriterion = TemplateCriterion::AreaRatio;
  s = selectTemplate(frames, options, pose);
  EXPECT_EQ(s.decidedBy, TemplateCriterion::AreaRatio);
  EXPECT_EQ(s.chosen, 4);

  // No pose known for any candidate: the area ratio decides.
  options.templateCriterion = TemplateCriterion::RestPose;
  s = selectTemplate(frames, options, {NAN, 0.1, NAN, NAN, NAN});
  EXPECT_EQ(s.decidedBy, TemplateCriterion::AreaRatio);
  EXPECT_EQ(s.chosen, 4);
  EXPECT_EQ(selectTemplate(frames, options).chosen, 4);
  EXPECT_THROW(selectTemplate(frames, options, {1.0, 2.0}), Error);
}

TEST(TemplateSelection, FramesByPoseAreTheCandidatesNearestRestFirst)
{
  // Frame 1 is not a candidate (genus 1); frame 4's pose is unknown.
  const std::vector<FrameTopology> frames = {frame(1, 0, 2.0), frame(1, 1, 1.0), frame(1, 0, 9.0),
                                             frame(1, 0, 3.0), frame(1, 0, 1.5)};
  const std::vector<double> pose = {2.0, 0.1, 0.5, 0.5, NAN};
  const TemplateSelection s = selectTemplate(frames, {}, pose);
  EXPECT_EQ(templateFramesByPose(s, pose), (std::vector<int>{2, 3, 0}));
  EXPECT_TRUE(templateFramesByPose(s, {1.0, 2.0}).empty());
}

TEST(TemplateSelection, ACollectionOfPosesMostlyBreaksWithItsPredecessor)
{
  EXPECT_FALSE(isCollectionOfPoses({true, true, true, false, true}));
  EXPECT_TRUE(isCollectionOfPoses({true, false, true, false, true}));
  EXPECT_TRUE(isCollectionOfPoses({true, false, false, false}));
  EXPECT_FALSE(isCollectionOfPoses({false}));
  EXPECT_FALSE(isCollectionOfPoses({}));
  EXPECT_EQ(defaultTemplateCandidates({true, false, false, false}), 3);
  EXPECT_EQ(defaultTemplateCandidates({true, true, true, false, true}), 1);
}

TEST(TemplateSelection, RestPoseOnlyFromBodiesThatExplainTheirFrame)
{
  // Four ok fits; the one nearest the rest pose left a raised arm of its frame unexplained (its
  // frame distance twice the others'), so it binds no template. A poor fit never does.
  BodyFitResult body;
  const double bend[] = {0.8, 0.6, 0.2, 0.7, 0.1};
  const double explained[] = {0.060, 0.065, 0.130, 0.070, 0.060};
  for (int k = 0; k < 5; ++k)
  {
    BodyFrameFit f;
    f.pose.rotations(LeftElbow, 0) = bend[k];
    f.frameDistance = explained[k];
    f.continuesPrevious = false; // unrelated poses: each frame's distance is its own
    body.frames.push_back(f);
  }
  body.frames[4].status = BodyFitStatus::Poor;
  const std::vector<double> d = restPoseDistances(body);
  ASSERT_EQ(d.size(), 5u);
  EXPECT_TRUE(std::isnan(d[2]));
  EXPECT_TRUE(std::isnan(d[4]));
  EXPECT_NEAR(d[1], restPoseDistance(body.frames[1].pose), 1e-12);
  const std::vector<FrameTopology> frames(5, frame(1, 0, 1.0));
  EXPECT_EQ(selectTemplate(frames, {}, d).chosen, 1);
  // Without the guard the collapsed body wins.
  EXPECT_EQ(selectTemplate(frames, {}, restPoseDistances(body, 10.0)).chosen, 2);
}

TEST(TemplateSelection, RestPoseConfirmedByTheNeighbouringFrames)
{
  // Frame 2's fit dips towards the rest pose between two bent neighbours that it continues;
  // frames 4-6 hold a pose a little further from it. The dip counts at its neighbours' distance.
  BodyFitResult body;
  const double own[] = {0.9, 0.8, 0.2, 0.7, 0.45, 0.4, 0.42};
  body.frames.resize(7);
  std::vector<double> distances(own, own + 7);
  std::vector<double> d = confirmedByNeighbours(body.frames, distances);
  const double confirmed[] = {0.9, 0.9, 0.8, 0.7, 0.7, 0.45, 0.42};
  for (int k = 0; k < 7; ++k) EXPECT_DOUBLE_EQ(d[k], confirmed[k]) << "frame " << k;
  const std::vector<FrameTopology> frames(7, frame(1, 0, 1.0));
  EXPECT_EQ(selectTemplate(frames, {}, d).chosen, 6);
  EXPECT_EQ(selectTemplate(frames, {}, distances).chosen, 2);

  // A doubtful neighbour (NaN) confirms nothing; a frame that starts anew (a cut) is not
  // confirmed by the frame before it, nor does it confirm that frame.
  distances[1] = NAN;
  body.frames[3].continuesPrevious = false;
  d = confirmedByNeighbours(body.frames, distances);
  EXPECT_TRUE(std::isnan(d[1]));
  EXPECT_DOUBLE_EQ(d[2], 0.2);
  EXPECT_DOUBLE_EQ(d[3], 0.7);
}
