#include <clothtrack/base/Error.h>
#include <clothtrack/eval/AlignmentError.h>
#include <clothtrack/mesh/Primitives.h>

#include <gtest/gtest.h>

#include <cmath>

using namespace clothtrack;

TEST(AlignmentError, TemplateOnTheTruthAnchorsEveryVertexToItself)
{
  const TriangleMesh truth = icosphere(3, 0.5);
  const TruthAnchors anchors = anchorToTruth(truth.V, truth);
  EXPECT_EQ(anchors.count(), truth.numVertices());
  EXPECT_LT(anchors.distance.maxCoeff(), 1e-12);
  // An alignment one centimetre off along x in the next frame: every error is 1 cm.
  TriangleMesh moved = truth;
  moved.V.col(0).array() += 0.2;
  Points aligned = moved.V;
  aligned.col(0).array() += 0.01;
  const Eigen::VectorXd e = vertexErrors(aligned, moved, anchors);
  EXPECT_NEAR(e.minCoeff(), 0.01, 1e-9);
  EXPECT_NEAR(e.maxCoeff(), 0.01, 1e-9);
}

TEST(AlignmentError, AnchorsFollowTheTruthSurfaceBetweenVertices)
{
  // A template denser than the truth: its vertices lie inside truth triangles, and follow them.
  const TriangleMesh truth = grid(4, 1.0);
  const TriangleMesh dense = grid(9, 1.0);
  const TruthAnchors anchors = anchorToTruth(dense.V, truth);
  ASSERT_EQ(anchors.count(), dense.numVertices());
  TriangleMesh stretched = truth;
  stretched.V *= 2.0;
  const Eigen::VectorXd e = vertexErrors(2.0 * dense.V, stretched, anchors);
  EXPECT_LT(e.maxCoeff(), 1e-9);
}

TEST(AlignmentError, VerticesFarFromTheTruthHaveNoError)
{
  const TriangleMesh truth = grid(4, 1.0);
  Points templ = truth.V;
  templ(0, 2) = 0.5; // lifted half a metre off the plane
  const TruthAnchors anchors = anchorToTruth(templ, truth, 0.03);
  EXPECT_EQ(anchors.count(), truth.numVertices() - 1);
  const Eigen::VectorXd e = vertexErrors(truth.V, truth, anchors);
  EXPECT_TRUE(std::isnan(e[0]));
  const ErrorStatistics s = errorStatistics(e);
  EXPECT_EQ(s.count, truth.numVertices() - 1);
  EXPECT_NEAR(s.mean, 0.0, 1e-12);
}

TEST(AlignmentError, StatisticsAndCumulativeCurve)
{
  const std::vector<double> e = {0.01,         0.02, 0.04, 0.06, 0.08, 0.12,
                                 std::nan(""), 0.03, 0.05, 0.2,  0.07};
  const ErrorStatistics s = errorStatistics(e);
  EXPECT_EQ(s.count, 10);
  EXPECT_NEAR(s.mean, 0.068, 1e-12);
  EXPECT_NEAR(s.median, 0.06, 1e-12); // nearest rank of 10 sorted values
  EXPECT_NEAR(s.max, 0.2, 1e-12);
  EXPECT_NEAR(s.within5cm, 0.5, 1e-12);
  EXPECT_NEAR(s.within10cm, 0.8, 1e-12);
  EXPECT_NEAR(s.p90, 0.12, 1e-12);
  const std::vector<double> c = cumulativeCurve(e, {0.0, 0.05, 0.1, 1.0});
  EXPECT_DOUBLE_EQ(c[0], 0.0);
  EXPECT_DOUBLE_EQ(c[1], 0.5);
  EXPECT_DOUBLE_EQ(c[2], 0.8);
  EXPECT_DOUBLE_EQ(c[3], 1.0);
}

TEST(AlignmentError, MismatchedSizesAreErrors)
{
  const TriangleMesh truth = grid(4, 1.0);
  const TruthAnchors anchors = anchorToTruth(truth.V, truth);
  EXPECT_THROW(vertexErrors(truth.V.topRows(3), truth, anchors), Error);
  EXPECT_THROW(anchorToTruth(truth.V, TriangleMesh()), Error);
  Points bad = truth.V;
  bad(1, 1) = std::nan("");
  EXPECT_THROW(anchorToTruth(bad, truth), Error);
}

TEST(AlignmentError, SequenceSummaryLeavesTheTemplateFrameOutOfThePool)
{
  // Frame k's errors are all 1 cm times its distance from the template frame 1, plus a large
  // error on the template frame itself that the pool must not see.
  std::vector<Eigen::VectorXd> frames = {
      Eigen::VectorXd::Constant(4, 0.01), Eigen::VectorXd::Constant(4, 0.5),
      Eigen::VectorXd::Constant(4, 0.01), Eigen::VectorXd::Constant(4, 0.02)};
  frames[2][3] = std::nan(""); // no ground truth
  const SequenceErrors s = sequenceErrors(frames, 1);
  ASSERT_EQ(s.perFrame.size(), 4u);
  EXPECT_EQ(s.pooled.count, 11);
  EXPECT_NEAR(s.pooled.mean, (4 * 0.01 + 3 * 0.01 + 4 * 0.02) / 11, 1e-12);
  EXPECT_EQ(s.worstFrame, 1);
  EXPECT_EQ(s.perFrame[2].count, 3);
  EXPECT_NEAR(s.fractions.back(), 1.0, 1e-12);
  EXPECT_NEAR(s.thresholds[2], 0.01, 1e-12);
  // Means 0.01, 0.5, 0.01, 0.02 at distances 1, 0, 1, 2: the template frame's 0.5 at distance 0
  // makes the slope negative.
  EXPECT_LT(s.driftPerFrame, 0.0);
}
