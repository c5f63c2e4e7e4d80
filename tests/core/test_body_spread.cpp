#include <clothtrack/base/Error.h>
#include <clothtrack/body/ProceduralBody.h>

#include <gtest/gtest.h>

#include <limits>

using namespace clothtrack;

TEST(BodySpread, ScalesOneProportionsDeviationsAndLeavesTheOthers)
{
  BodySpread wider;
  setBodySpread(wider, "neckLength", 2.5);
  setBodySpread(wider, "headSize", 0.0);
  std::mt19937 rngBuiltin(7), rngWider(7);
  for (int k = 0; k < 200; ++k)
  {
    const BodyParameters a = sampleBodyParameters(rngBuiltin);
    const BodyParameters b = sampleBodyParameters(rngWider, wider);
    // The same draws: only the factor differs, so each body's deviation scales exactly.
    EXPECT_NEAR(b.neckLength - 1.0, 2.5 * (a.neckLength - 1.0), 1e-12);
    EXPECT_NEAR(b.headSize, 1.0 - 0.03 * (b.femininity - 0.5), 1e-12); // no spread left
    EXPECT_DOUBLE_EQ(b.stature, a.stature);
    EXPECT_DOUBLE_EQ(b.legLength, a.legLength);
    EXPECT_DOUBLE_EQ(b.shoulderWidth, a.shoulderWidth);
    EXPECT_DOUBLE_EQ(b.chestGirth, a.chestGirth);
  }
}

TEST(BodySpread, UnknownNamesAndFactorsOutOfRangeAreErrors)
{
  BodySpread spread;
  EXPECT_THROW(setBodySpread(spread, "neck", 2.0), Error);
  EXPECT_THROW(setBodySpread(spread, "headSize", -1.0), Error);
  EXPECT_THROW(setBodySpread(spread, "headSize", 11.0), Error);
  EXPECT_THROW(setBodySpread(spread, "headSize", std::numeric_limits<double>::quiet_NaN()), Error);
  EXPECT_DOUBLE_EQ(spread.headSize, 1.0);
  setBodySpread(spread, "shoulderWidth", 1.5);
  EXPECT_DOUBLE_EQ(spread.shoulderWidth, 1.5);
}
