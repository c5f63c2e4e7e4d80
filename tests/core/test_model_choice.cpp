#include <clothtrack/base/Error.h>
#include <clothtrack/eval/ModelChoice.h>

#include <gtest/gtest.h>

#include <limits>

using namespace clothtrack;

namespace
{
const double kNaN = std::numeric_limits<double>::quiet_NaN();
} // namespace

TEST(ModelChoice, TheMeanLeavesOutFramesWithoutAFigure)
{
  EXPECT_DOUBLE_EQ(meanOverFrames({0.0, 0.1, kNaN, 0.2}), 0.1);
  EXPECT_THROW(meanOverFrames({kNaN}), Error);
  EXPECT_THROW(meanOverFrames({}), Error);
}

TEST(ModelChoice, ALaterModelMustBeBetterOnBothFigures)
{
  // pjump (metres): the MakeHuman model's alignment is less stretched and closer.
  EXPECT_EQ(preferredAlignment({{0.0815, 0.00132}, {0.0752, 0.00119}}), 1);
  // trousers-squat: less stretched but as far from the frames, and less accurate.
  EXPECT_EQ(preferredAlignment({{0.1127, 0.002635}, {0.1039, 0.002652}}), 0);
  // Closer but more stretched.
  EXPECT_EQ(preferredAlignment({{0.08, 0.002}, {0.09, 0.001}}), 0);
  // Of three, the last beats the kept first on both; the second only on one.
  EXPECT_EQ(preferredAlignment({{0.1, 0.003}, {0.05, 0.004}, {0.09, 0.002}}), 2);
}

TEST(ModelChoice, TheFirstStaysWhenTwoAreAsGood)
{
  EXPECT_EQ(preferredAlignment({{0.05, 0.002}, {0.05, 0.002}}), 0);
  EXPECT_EQ(preferredAlignment({{0.1, 0.002}, {0.099, 0.00199}}), 0) << "within the margin";
  EXPECT_EQ(preferredAlignment({{0.1, 0.002}, {0.099, 0.00199}}, 0.0), 1) << "no margin";
  EXPECT_EQ(preferredAlignment({{0.3, 0.01}}), 0);
  EXPECT_THROW(preferredAlignment({}), Error);
}
