// The template bound to the fitted body (SkinnedTemplate) and the fit starts made from it.
#include "ctBuiltinBodyModel.h"

#include <clothtrack/base/Error.h>
#include <clothtrack/body/BodyModel.h>
#include <clothtrack/body/SkinnedTemplate.h>
#include <clothtrack/pipeline/BodyStartPrediction.h>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>

using namespace clothtrack;

namespace
{
const BodyModel& model()
{
  return builtinBodyModel();
}

BodyPose stepPose()
{
  BodyPose pose;
  pose.rotations.row(LeftShoulder) << 0.0, 0.0, -0.9;
  pose.rotations.row(LeftElbow) << -0.8, 0.0, 0.0;
  pose.rotations.row(RightHip) << -0.6, 0.0, 0.0;
  pose.rotations.row(RightKnee) << 0.7, 0.0, 0.0;
  return pose;
}

/// The body itself, in `pose`, as a template (its own mesh and weights).
SkinnedTemplate bodyAsTemplate(const BodyPose& pose, int smoothingRounds)
{
  const Eigen::VectorXd beta = Eigen::VectorXd::Zero(4);
  return SkinnedTemplate(model().posed(beta, pose), model().posed(beta, pose).V, model().weights,
                         posedSkeleton(model(), beta, pose), {smoothingRounds});
}
} // namespace

TEST(SkinnedTemplate, AtItsOwnFrameTheTemplateStaysWhereItIs)
{
  const BodyPose pose = stepPose();
  const SkinnedTemplate bound = bodyAsTemplate(pose, 10);
  const Points posed = bound.posed(posedSkeleton(model(), Eigen::VectorXd::Zero(4), pose));
  EXPECT_LT((posed - model().posed(Eigen::VectorXd::Zero(4), pose).V).cwiseAbs().maxCoeff(), 1e-12);
  EXPECT_LT((bound.weights().rowwise().sum().array() - 1.0).abs().maxCoeff(), 1e-12);
}

TEST(SkinnedTemplate, AMoveOfTheWholeBodyMovesTheTemplateRigidly)
{
  const BodyPose from = stepPose();
  BodyPose to = from;
  to.rotations.row(Pelvis) << 0.0, 2.5, 0.0; // more than a half-turn's worth of heading
  to.translation << 0.4, 0.1, -0.3;
  const SkinnedTemplate bound = bodyAsTemplate(from, 10);
  const Points moved = bound.posed(posedSkeleton(model(), Eigen::VectorXd::Zero(4), to));
  const Points expected = model().posed(Eigen::VectorXd::Zero(4), to).V;
  EXPECT_LT((moved - expected).cwiseAbs().maxCoeff(), 1e-9);
}

TEST(SkinnedTemplate, ABentBodyCarriesItsOwnSurfaceCloseToTheModelsSkinning)
{
  // Blending the joints' relative motions is not the model's skinning of rest positions, but
  // on the body's own surface the two agree within a few millimetres on average.
  const SkinnedTemplate bound = bodyAsTemplate(BodyPose(), 0);
  const BodyPose pose = stepPose();
  const Points carried = bound.posed(posedSkeleton(model(), Eigen::VectorXd::Zero(4), pose));
  const Points skinned = model().posed(Eigen::VectorXd::Zero(4), pose).V;
  const Eigen::VectorXd error = (carried - skinned).rowwise().norm();
  EXPECT_LT(error.mean(), 0.005);
  EXPECT_LT(error.maxCoeff(), 0.05);
}

namespace
{
/// A flared skirt round the body's hips: `rings` rings of `around` vertices from the pelvis
/// (radius `top`) down to `drop` below it (radius `hem`), the last ring the hem.
TriangleMesh skirt(const Vec3& pelvis, double drop, double top, double hem, int rings = 12,
                   int around = 48)
{
  TriangleMesh m;
  m.V.resize(rings * around, 3);
  for (int r = 0; r < rings; ++r)
    for (int a = 0; a < around; ++a)
    {
      const double t = r / (rings - 1.0), angle = 2 * M_PI * a / around;
      const double radius = top + t * (hem - top);
      m.V.row(r * around + a) << pelvis.x() + radius * std::cos(angle), pelvis.y() - t * drop,
          pelvis.z() + radius * std::sin(angle);
    }
  m.F.resize(2 * (rings - 1) * around, 3);
  for (int r = 0, f = 0; r + 1 < rings; ++r)
    for (int a = 0; a < around; ++a)
    {
      const int i = r * around + a, j = r * around + (a + 1) % around;
      m.F.row(f++) << i, j + around, j;
      m.F.row(f++) << i, i + around, j + around;
    }
  return m;
}
} // namespace

TEST(SkinnedTemplate, ClothHangingAwayFromTheBodyFollowsThePartItHangsFrom)
{
  // The hem of a wide skirt is nearest to one leg's surface, but hangs from the hips: bound to
  // the nearest body vertex, each side of the hem swings with one thigh; bound by part, it
  // follows the pelvis, and the skirt's top, close to the body, keeps its nearest vertices.
  const Eigen::VectorXd beta = Eigen::VectorXd::Zero(4);
  const TriangleMesh body = model().posed(beta, BodyPose());
  const PosedSkeleton skeleton = posedSkeleton(model(), beta, BodyPose());
  const Vec3 pelvis = skeleton.joints.row(Pelvis).transpose();
  const double drop = pelvis.y() - skeleton.joints(LeftKnee, 1);
  const TriangleMesh dress = skirt(pelvis, drop, 0.17, 0.45);
  SkinnedTemplateOptions nearestOnly{0};
  nearestOnly.partBindingDistance = std::numeric_limits<double>::infinity();
  const SkinnedTemplate byPart(dress, body.V, model().weights, skeleton, {0});
  const SkinnedTemplate nearest(dress, body.V, model().weights, skeleton, nearestOnly);
  const int around = 48, hemStart = dress.numVertices() - around;
  auto legShare = [&](const SkinnedTemplate& bound, int first, int count)
  {
    double legs = 0.0;
    for (int i = first; i < first + count; ++i)
      for (int j : {LeftHip, LeftKnee, RightHip, RightKnee}) legs += bound.weights()(i, j);
    return legs / count;
  };
  for (int i = hemStart; i < dress.numVertices(); ++i)
  {
    Eigen::Index hangsFrom, nearestJoint;
    byPart.weights().row(i).maxCoeff(&hangsFrom);
    nearest.weights().row(i).maxCoeff(&nearestJoint);
    EXPECT_EQ(hangsFrom, Pelvis) << "hem vertex " << i;
    const bool left = dress.V(i, 0) > pelvis.x() + 0.05, right = dress.V(i, 0) < pelvis.x() - 0.05;
    if (left || right)
    {
      EXPECT_TRUE(nearestJoint == LeftHip || nearestJoint == RightHip) << "hem vertex " << i;
    }
  }
  EXPECT_LT(legShare(byPart, hemStart, around), legShare(nearest, hemStart, around) - 0.3);
  EXPECT_GT(legShare(nearest, hemStart, around), 0.8);
  EXPECT_EQ(byPart.weights().topRows(around), nearest.weights().topRows(around));
}

TEST(SkinnedTemplate, WeightsOfTheWrongSizeAreAClearError)
{
  const TriangleMesh body = model().posed(Eigen::VectorXd(), BodyPose());
  EXPECT_THROW(SkinnedTemplate(body, body.V, model().weights.topRows(10),
                               posedSkeleton(model(), Eigen::VectorXd(), BodyPose())),
               Error);
  EXPECT_THROW(SkinnedTemplate(TriangleMesh(), body.V, model().weights,
                               posedSkeleton(model(), Eigen::VectorXd(), BodyPose())),
               Error);
}

TEST(BodyStartPrediction, FramesWithADoubtfulBodyStartFromTheFallback)
{
  BodyFitResult body;
  body.beta = Eigen::VectorXd::Zero(4);
  body.frames.resize(3);
  body.frames[1].pose = stepPose();
  body.frames[2].pose = stepPose();
  body.frames[2].status = BodyFitStatus::Poor;
  const TriangleMesh templ = model().posed(body.beta, BodyPose());
  const Points fallbackStart = Points::Constant(templ.numVertices(), 3, 7.0);
  const StartPrediction start = bodyStartPrediction(
      model(), body, templ, 0, [&](int, int, const Points&) { return fallbackStart; });
  const Points one = start(1, 0, templ.V);
  EXPECT_LT((one - model().posed(body.beta, stepPose()).V).rowwise().norm().mean(), 0.005);
  EXPECT_EQ(start(2, 1, one), fallbackStart);
  // Without a fallback, the neighbour's fit as it is.
  const StartPrediction plain = bodyStartPrediction(model(), body, templ, 0, {});
  EXPECT_EQ(plain(2, 1, one), one);
  // A doubtful body at the template frame binds nothing: the fallback itself is returned.
  body.frames[0].status = BodyFitStatus::Poor;
  EXPECT_FALSE(bodyStartPrediction(model(), body, templ, 0, {}));
  const StartPrediction fallback = bodyStartPrediction(
      model(), body, templ, 0, [&](int, int, const Points&) { return fallbackStart; });
  EXPECT_EQ(fallback(1, 0, templ.V), fallbackStart);
}

TEST(BodyStartPrediction, ADoubtfulBodyUnlikeItsPredecessorLeavesItsFrameUnplaced)
{
  BodyFitResult body;
  body.frames.resize(5);
  body.frames[1].status = BodyFitStatus::Poor; // tracked from its predecessor: placed by it
  body.frames[2].status = BodyFitStatus::Poor;
  body.frames[2].continuesPrevious = false;
  body.frames[3].continuesPrevious = false; // an unrelated pose with a body that fits
  body.frames[4].status = BodyFitStatus::Failed;
  body.frames[4].continuesPrevious = false;
  EXPECT_EQ(unplacedFrames(body), (std::vector<bool>{false, false, true, false, true}));
}

TEST(BodyStartPrediction, TheStartIsStretchedToItsFramesHeight)
{
  BodyFitResult body;
  body.beta = Eigen::VectorXd::Zero(4);
  body.frames.resize(2);
  body.frames[1].pose = stepPose();
  const TriangleMesh templ = model().posed(body.beta, BodyPose());
  const TemplatePosedByBody posed = bodyPosedTemplate(model(), body, templ, 0);
  const Points posedStart = *posed(1);
  // Frame 1: the posed body itself, 10 % taller and standing 5 cm higher: a body fitted short
  // in it, its feet above the frame's.
  auto frame = std::make_shared<TriangleMesh>(model().posed(body.beta, stepPose()));
  const double low = frame->V.col(1).minCoeff();
  frame->V.col(1) = ((frame->V.col(1).array() - low) * 1.1 + low + 0.05).matrix();
  const StartPrediction stretched =
      bodyStartPrediction(posed, {}, [&](int) -> FramePtr { return frame; });
  const Points start = stretched(1, 0, templ.V);
  EXPECT_NEAR(start.col(1).minCoeff(), frame->V.col(1).minCoeff(), 1e-9);
  EXPECT_NEAR(start.col(1).maxCoeff(), frame->V.col(1).maxCoeff(), 1e-9);
  EXPECT_LT((start - frame->V).rowwise().norm().mean(), 0.005); // the same surface points
  EXPECT_EQ(start.leftCols(1), posedStart.leftCols(1));         // only heights change
  EXPECT_EQ(start.rightCols(1), posedStart.rightCols(1));
  // Without frames, or where the heights differ by more than a fifth, the start is the posed
  // template as it is.
  EXPECT_EQ(bodyStartPrediction(posed, {})(1, 0, templ.V), posedStart);
  frame->V.col(1) *= 1.3;
  EXPECT_EQ(stretched(1, 0, templ.V), posedStart);
  Points unchanged = posedStart;
  EXPECT_FALSE(stretchToFrameExtent(unchanged, *frame));
  EXPECT_EQ(unchanged, posedStart);
}

TEST(BodyStartPrediction, CorrespondencesTheBodyContradictsAreDropped)
{
  BodyFitResult body;
  body.beta = Eigen::VectorXd::Zero(4);
  body.frames.resize(3);
  body.frames[1].pose = stepPose();
  body.frames[2].status = BodyFitStatus::Poor;
  const TriangleMesh templ = model().posed(body.beta, BodyPose());
  const TemplatePosedByBody posed = bodyPosedTemplate(model(), body, templ, 0);
  const Points posedStart = *posed(1);
  // Every target where the body puts its vertex, but every third slid 8 cm down the surface
  // and every seventh 3 cm.
  VertexTargets targets;
  targets.position = posedStart;
  targets.matched.assign(templ.numVertices(), 1);
  int slid = 0, kept = 0;
  for (int i = 0; i < templ.numVertices(); ++i)
  {
    if (i % 3 == 0)
      targets.position(i, 1) -= 0.08, ++slid;
    else if (i % 7 == 0)
      targets.position(i, 1) -= 0.03;
    if (i % 5 == 0)
      targets.matched[i] = 0; // never matched
    else if (i % 3 != 0)
      ++kept;
  }
  const auto narrow = targetsAgreeingWithBodyStart(posed, {}, 0.05);
  ASSERT_TRUE(narrow);
  const VertexTargets one = narrow(1, targets);
  EXPECT_EQ(one.count(), kept);
  EXPECT_GT(slid, 0);
  for (int i = 0; i < templ.numVertices(); ++i)
    EXPECT_EQ(one.matched[i], i % 5 != 0 && i % 3 != 0) << i;
  EXPECT_EQ(one.position, targets.position);
  // A frame without a trusted body keeps its targets; a gate of 0 narrows nothing; a negative
  // gate is refused.
  EXPECT_EQ(narrow(2, targets).count(), targets.count());
  EXPECT_FALSE(targetsAgreeingWithBodyStart(posed, {}, 0.0));
  EXPECT_THROW(targetsAgreeingWithBodyStart(posed, {}, -1.0), Error);
  // The sequence fit's hook, narrowed for every fit of the frame.
  SequenceFitHooks hooks;
  hooks.targets = [&](int) -> const VertexTargets* { return &targets; };
  narrowTargetsToBodyStart(hooks, posed, {}, 0.05);
  EXPECT_EQ(hooks.targets(1)->count(), kept);
  EXPECT_EQ(hooks.targets(2)->count(), targets.count());
  SequenceFitHooks untouched;
  untouched.targets = [&](int) -> const VertexTargets* { return &targets; };
  narrowTargetsToBodyStart(untouched, posed, {}, 0.0);
  EXPECT_EQ(untouched.targets(1), &targets);
}
