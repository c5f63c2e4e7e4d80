#include <clothtrack/base/Error.h>
#include <clothtrack/eval/FrameConfidence.h>
#include <clothtrack/eval/SequenceQuality.h>
#include <clothtrack/mesh/Primitives.h>

#include <gtest/gtest.h>

#include <limits>

#include <cmath>

using namespace clothtrack;

namespace
{
const TriangleMesh kSphere = icosphere(3, 0.2);
} // namespace

TEST(FrameConfidence, TheTemplateOnItsOwnFrameIsConfident)
{
  const FrameConfidence c = frameConfidence(kSphere.V, kSphere, kSphere);
  EXPECT_NEAR(c.surfaceDistance, 0.0, 1e-12);
  EXPECT_NEAR(c.coverageDistance, 0.0, 1e-12);
  EXPECT_NEAR(c.stretch, 0.0, 1e-12);
  EXPECT_EQ(c.folded, 0.0);
  EXPECT_EQ(c.confidence, 1.0);
  EXPECT_FALSE(c.doubtful());
}

TEST(FrameConfidence, ARigidMotionIsNotADistortion)
{
  const Eigen::Matrix3d R = Eigen::AngleAxisd(1.1, Vec3(1, 2, 3).normalized()).toRotationMatrix();
  Points moved = (kSphere.V * R.transpose()).rowwise() + Vec3(0.5, -0.2, 1.0).transpose();
  const TriangleMesh frame{moved, kSphere.F};
  const FrameConfidence c = frameConfidence(moved, kSphere, frame);
  EXPECT_NEAR(c.stretch, 0.0, 1e-9);
  EXPECT_EQ(c.folded, 0.0);
  EXPECT_FALSE(c.doubtful()) << c.doubt;
}

TEST(FrameConfidence, ATemplateCrumpledOntoTheFrameIsDoubtful)
{
  // A sheet folded flat like an accordion every six columns: no edge changes length and the
  // folded sheet lies on the frame, which the folds alone reveal. The sheet is meshed about as
  // finely for its size as a captured body.
  const TriangleMesh sheet = grid(60, 1.0);
  Points folded = sheet.V;
  for (Eigen::Index v = 0; v < folded.rows(); ++v)
  {
    const double x = sheet.V(v, 0) * 10.0; // in strips of width 1
    const double within = x - 2.0 * std::floor(x / 2.0);
    folded(v, 0) = (within <= 1.0 ? within : 2.0 - within) / 10.0;
  }
  const TriangleMesh frame{folded, sheet.F};
  const FrameConfidence c = frameConfidence(folded, sheet, frame);
  EXPECT_NEAR(c.surfaceDistance, 0.0, 1e-12);
  EXPECT_NEAR(c.stretch, 0.0, 1e-9);
  EXPECT_GT(c.folded, 4 * FrameConfidenceOptions{}.maximumFoldedFraction);
  ASSERT_TRUE(c.doubtful());
  EXPECT_EQ(c.doubt.find("folds"), 0u) << c.doubt;
  EXPECT_EQ(c.confidence, 0.0);
  // Folded in one place only: a fold the limit tolerates.
  Points once = sheet.V;
  for (Eigen::Index v = 0; v < once.rows(); ++v)
    if (once(v, 0) > 0.5) once(v, 0) = 1.0 - once(v, 0);
  const FrameConfidence single = frameConfidence(once, sheet, TriangleMesh{once, sheet.F});
  EXPECT_GT(single.folded, 0.0);
  EXPECT_FALSE(single.doubtful()) << single.doubt;
}

TEST(FrameConfidence, AStretchedTemplateIsDoubtful)
{
  const Points bigger = 1.5 * kSphere.V;
  const FrameConfidence c = frameConfidence(bigger, kSphere, TriangleMesh{bigger, kSphere.F});
  EXPECT_NEAR(c.stretch, std::log(1.5), 1e-9);
  EXPECT_EQ(c.folded, 0.0);
  ASSERT_TRUE(c.doubtful());
  EXPECT_NE(c.doubt.find("stretch"), std::string::npos) << c.doubt;
  // Between once and twice the limit: confidence falls linearly.
  const double limit = FrameConfidenceOptions{}.maximumStretch;
  EXPECT_NEAR(c.severity, std::log(1.5) / limit, 1e-12);
  EXPECT_NEAR(c.confidence, std::clamp(2.0 - std::log(1.5) / limit, 0.0, 1.0), 1e-12);
}

TEST(FrameConfidence, PartOfTheFrameTheTemplateMissesShowsInCoverage)
{
  // The frame has a second body part 1 m away that the template does not reach.
  const TriangleMesh frame = concatenate(kSphere, icosphere(3, 0.2, Vec3(1.0, 0, 0)));
  const FrameConfidence c = frameConfidence(kSphere.V, kSphere, frame);
  EXPECT_NEAR(c.surfaceDistance, 0.0, 1e-12);
  EXPECT_GT(c.coverageDistance, 0.3);
  ASSERT_TRUE(c.doubtful());
  EXPECT_EQ(c.doubt.find("coverage"), 0u) << c.doubt;
  EXPECT_EQ(c.confidence, 0.0);
}

TEST(FrameConfidence, SequenceQualityListsTheDoubtfulFrames)
{
  const Points flat = 1.5 * kSphere.V; // stretched
  const TriangleMesh flatFrame{flat, kSphere.F};
  const std::vector<const Points*> aligned = {&kSphere.V, &flat, &kSphere.V};
  const std::vector<const TriangleMesh*> frames = {&kSphere, &flatFrame, &kSphere};
  const SequenceQuality q = sequenceQuality(aligned, kSphere.F, frames, {}, 0);
  ASSERT_EQ(q.confidence.size(), 3u);
  EXPECT_EQ(q.doubtfulFrames, std::vector<int>{1});
  EXPECT_TRUE(sequenceQuality(aligned, kSphere.F, frames).confidence.empty());
  EXPECT_THROW(sequenceQuality(aligned, kSphere.F, frames, {}, 3), Error);
}

TEST(FrameConfidence, ATemplateSlidingAlongTheSurfaceIsSeenOnlyByTheBody)
{
  // The template turned 30 degrees about its own axis still lies on the frame, undistorted;
  // only the body, which did not turn, says that every vertex is on the wrong place.
  const Eigen::Matrix3d R = Eigen::AngleAxisd(M_PI / 6, Vec3::UnitZ()).toRotationMatrix();
  const Points slid = kSphere.V * R.transpose();
  const ConfidenceMeter meter(kSphere);
  const FrameConfidence unjudged = meter(slid, kSphere);
  EXPECT_LT(unjudged.bodyDistance, 0.0); // not measured
  EXPECT_FALSE(unjudged.doubtful()) << unjudged.doubt;
  const FrameConfidence c = meter(slid, kSphere, -1.0, 0, &kSphere.V);
  EXPECT_NEAR(c.surfaceDistance, 0.0, 0.002);
  EXPECT_LT(c.coverageDistance, 0.002);
  EXPECT_NEAR(c.stretch, 0.0, 1e-9);
  EXPECT_EQ(c.folded, 0.0);
  // Mean |R v - v| over the sphere: 2 r sin(15 degrees) times the mean of sin(polar angle).
  EXPECT_NEAR(c.bodyDistance, 2 * 0.2 * std::sin(M_PI / 12) * M_PI / 4, 0.003);
  ASSERT_TRUE(c.doubtful());
  EXPECT_EQ(c.doubt.find("body distance"), 0u) << c.doubt;
  // Where the body stays with the template, nothing is doubtful.
  EXPECT_FALSE(meter(slid, kSphere, -1.0, 0, &slid).doubtful());
  const Points fewer = kSphere.V.topRows(10);
  EXPECT_THROW(meter(slid, kSphere, -1.0, 0, &fewer), Error);
}

TEST(FrameConfidence, ABodyStandingHigherInItsFrameShowsInItsExtent)
{
  // A 1 m tall body whose fitted feet rose by `rise` in this frame while the template stayed on
  // the frame (its lower half carried up the surface with them, the head where it was): the mean
  // distance to the posed template stays under its limit, the lowest points do not.
  Points tall = kSphere.V;
  tall.col(1) *= 2.5;
  const TriangleMesh body{tall, kSphere.F};
  const ConfidenceMeter meter(body);
  auto raised = [&](double rise)
  {
    Points posed = tall;
    for (Eigen::Index v = 0; v < posed.rows(); ++v)
      posed(v, 1) += rise * std::max(0.0, -tall(v, 1)) / 0.5;
    return posed;
  };
  const Points floated = raised(0.17);
  const FrameConfidence c = meter(tall, body, -1.0, 0, &floated);
  EXPECT_LT(c.bodyDistance, FrameConfidenceOptions{}.maximumBodyDistance);
  EXPECT_NEAR(c.extentGap, 0.17, 1e-9);
  ASSERT_TRUE(c.doubtful());
  EXPECT_EQ(c.doubt.find("body extent 17.0 cm"), 0u) << c.doubt;
  const Points risen = raised(0.10);
  const FrameConfidence within = meter(tall, body, -1.0, 0, &risen);
  EXPECT_NEAR(within.extentGap, 0.10, 1e-9);
  EXPECT_FALSE(within.doubtful()) << within.doubt;
  // Along another up axis the same rise is sideways: the extent along it hardly changes.
  FrameConfidenceOptions zUp;
  zUp.up = Vec3::UnitZ();
  EXPECT_LT(ConfidenceMeter(body, zUp)(tall, body, -1.0, 0, &floated).extentGap, 1e-9);
}

TEST(FrameConfidence, SequenceQualityJudgesFramesWithATrustedBodyByIt)
{
  const Eigen::Matrix3d R = Eigen::AngleAxisd(M_PI / 6, Vec3::UnitZ()).toRotationMatrix();
  const Points slid = kSphere.V * R.transpose();
  const std::vector<const Points*> aligned = {&kSphere.V, &slid, &slid};
  const std::vector<const TriangleMesh*> frames = {&kSphere, &kSphere, &kSphere};
  // Frame 1's body did not turn; frame 2's body is not trusted.
  const TemplatePosedByBody posed = [](int k) -> std::optional<Points>
  {
    if (k == 2) return std::nullopt;
    return kSphere.V;
  };
  const SequenceQuality q = sequenceQuality(aligned, kSphere.F, frames, {}, 0, {}, posed);
  EXPECT_EQ(q.doubtfulFrames, std::vector<int>{1});
  EXPECT_NEAR(q.confidence[0].bodyDistance, 0.0, 1e-12);
  EXPECT_LT(q.confidence[2].bodyDistance, 0.0);
  EXPECT_TRUE(sequenceQuality(aligned, kSphere.F, frames, {}, 0).doubtfulFrames.empty());
}

TEST(FrameConfidence, AFrameNothingPlacedIsDoubtfulWhateverItMeasures)
{
  // Frame 1 is the slid template of the test above, with no body to show it: every measure is
  // within its limit. Frame 2 is stretched and doubtful already.
  const Eigen::Matrix3d R = Eigen::AngleAxisd(M_PI / 6, Vec3::UnitZ()).toRotationMatrix();
  const Points slid = kSphere.V * R.transpose();
  const Points stretched = 2.0 * kSphere.V;
  const TriangleMesh stretchedFrame{stretched, kSphere.F};
  const std::vector<const Points*> aligned = {&kSphere.V, &slid, &stretched, &kSphere.V};
  const std::vector<const TriangleMesh*> frames = {&kSphere, &kSphere, &stretchedFrame, &kSphere};
  SequenceQuality q = sequenceQuality(aligned, kSphere.F, frames, {}, 0);
  ASSERT_EQ(q.doubtfulFrames, std::vector<int>{2});
  const double stretchedSeverity = q.confidence[2].severity;
  ASSERT_GT(stretchedSeverity, kUnplacedSeverity);

  doubtUnplacedFrames(q, {false, true, true, false});
  EXPECT_EQ(q.doubtfulFrames, (std::vector<int>{1, 2}));
  EXPECT_EQ(q.confidence[1].severity, kUnplacedSeverity);
  EXPECT_EQ(q.confidence[1].confidence, 0.5);
  EXPECT_EQ(q.confidence[1].doubt, "no trusted body, and unlike the frame before it");
  // A frame past its limits keeps its severity and says both.
  EXPECT_EQ(q.confidence[2].severity, stretchedSeverity);
  EXPECT_NE(q.confidence[2].doubt.find("stretch"), std::string::npos);
  EXPECT_NE(q.confidence[2].doubt.find(", no trusted body"), std::string::npos);
  EXPECT_EQ(q.confidence[3].confidence, 1.0);
  EXPECT_THROW(doubtUnplacedFrames(q, {true}), Error);
}

TEST(FrameConfidence, AmbiguousBodiesAreDoubtful)
{
  // Four accurate frames; the second's body has a rival pose just within the ratio, the third's
  // just beyond it, the fourth's none measured.
  SequenceQuality q;
  q.confidence.resize(4);
  const double inf = std::numeric_limits<double>::infinity();
  doubtAmbiguousBodies(q, {0.9, 0.99 * kAmbiguousBodyRatio, 1.01 * kAmbiguousBodyRatio, inf});
  EXPECT_EQ(q.doubtfulFrames, (std::vector<int>{0, 1}));
  EXPECT_EQ(q.confidence[1].severity, kAmbiguousBodySeverity);
  EXPECT_DOUBLE_EQ(q.confidence[1].confidence, 2.0 - kAmbiguousBodySeverity);
  EXPECT_NE(q.confidence[1].doubt.find("another pose of the body"), std::string::npos);
  EXPECT_EQ(q.confidence[2].confidence, 1.0);
  EXPECT_TRUE(q.confidence[3].doubt.empty());
  // An unplaced frame keeps its higher severity and says both.
  doubtUnplacedFrames(q, {true, false, false, false});
  EXPECT_EQ(q.confidence[0].severity, kUnplacedSeverity);
  EXPECT_NE(q.confidence[0].doubt.find(", no trusted body"), std::string::npos);
  EXPECT_THROW(doubtAmbiguousBodies(q, {1.0}), Error);
}

TEST(FrameConfidence, MismatchedVertexCountsAreAnError)
{
  const Points fewer = kSphere.V.topRows(10);
  EXPECT_THROW(frameConfidence(fewer, kSphere, kSphere), Error);
}
