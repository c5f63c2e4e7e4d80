#include <clothtrack/mesh/Primitives.h>
#include <clothtrack/mesh/SubjectSize.h>

#include <gtest/gtest.h>

using namespace clothtrack;

namespace
{
/// An ellipsoid of a standing person's bounding box: 0.5 wide, 1.75 tall, 0.3 deep, Y up.
TriangleMesh standingPerson(double scale = 1.0)
{
  TriangleMesh mesh = icosphere(2);
  mesh.V.col(0) *= 0.25 * scale;
  mesh.V.col(1) *= 0.875 * scale;
  mesh.V.col(2) *= 0.15 * scale;
  return mesh;
}

/// The same with Z up: (x, y, z) -> (x, -z, y).
TriangleMesh zUp(const TriangleMesh& yUp)
{
  TriangleMesh mesh = yUp;
  mesh.V.col(1) = -yUp.V.col(2);
  mesh.V.col(2) = yUp.V.col(1);
  return mesh;
}

bool mentions(const std::vector<std::string>& warnings, const std::string& text)
{
  for (const std::string& w : warnings)
    if (w.find(text) != std::string::npos) return true;
  return false;
}
} // namespace

TEST(SubjectSize, InfersUnitAndUpAxis)
{
  EXPECT_EQ(inferUpAxis(standingPerson()), 1);
  EXPECT_EQ(inferUpAxis(zUp(standingPerson())), 2);
  EXPECT_EQ(inferUnitScale(standingPerson(), 1), 1.0);
  EXPECT_EQ(inferUnitScale(standingPerson(10), 1), 0.1); // a subject 17.5 units tall: dm
  EXPECT_EQ(inferUnitScale(standingPerson(100), 1), 0.01);
  EXPECT_EQ(inferUnitScale(zUp(standingPerson(1000)), 2), 0.001);
  EXPECT_EQ(inferUnitScale(standingPerson(0.01), 1), 0.0); // 1.75 cm in metres: none fits
  EXPECT_STREQ(unitName(0.1), "dm");
}

TEST(SubjectSize, WarnsAboutAHeightOrAnAxisNoPersonHas)
{
  EXPECT_TRUE(subjectWarnings(standingPerson()).empty());
  const std::vector<std::string> giant = subjectWarnings(standingPerson(100));
  ASSERT_EQ(giant.size(), 1u);
  EXPECT_TRUE(mentions(giant, "175 m tall")) << giant[0];
  EXPECT_TRUE(mentions(giant, "100 times smaller: try --unit auto")) << giant[0];
  const std::vector<std::string> lying = subjectWarnings(zUp(standingPerson()));
  ASSERT_EQ(lying.size(), 1u); // 0.5 m tall is under a person's height too, but it is lying
  EXPECT_TRUE(mentions(lying, "1.75 m across but 0.3 m tall")) << lying[0];
  const std::vector<std::string> both = subjectWarnings(zUp(standingPerson(10)));
  ASSERT_EQ(both.size(), 2u);
  EXPECT_TRUE(mentions(both, "its longest side would be 1.75 m in a unit 10 times smaller"))
      << both[0];
}
