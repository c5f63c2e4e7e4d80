#include <clothtrack/mesh/Components.h>
#include <clothtrack/mesh/Primitives.h>

#include <gtest/gtest.h>

#include <cmath>

using namespace clothtrack;

namespace
{
Components analyse(const TriangleMesh& mesh)
{
  return connectedComponents(mesh, buildTopology(mesh));
}
} // namespace

TEST(Components, SphereIsGenusZero)
{
  const Components c = analyse(icosphere(3));
  ASSERT_EQ(c.count(), 1);
  EXPECT_EQ(c.info[0].eulerCharacteristic(), 2);
  EXPECT_EQ(c.info[0].genus(), 0);
  EXPECT_EQ(c.info[0].numBoundaries, 0);
  EXPECT_NEAR(c.info[0].area, 4 * M_PI, 0.05 * 4 * M_PI); // polyhedral area is slightly smaller
}

TEST(Components, TorusIsGenusOne)
{
  const Components c = analyse(torus(1.0, 0.3, 40, 20));
  ASSERT_EQ(c.count(), 1);
  EXPECT_EQ(c.info[0].eulerCharacteristic(), 0);
  EXPECT_EQ(c.info[0].genus(), 1);
  EXPECT_NEAR(c.info[0].area, 4 * M_PI * M_PI * 1.0 * 0.3, 0.02 * 4 * M_PI * M_PI * 0.3);
}

TEST(Components, TwoSpheresAreTwoComponentsSortedByArea)
{
  const TriangleMesh small = icosphere(2, 0.5, Vec3(3, 0, 0));
  const TriangleMesh big = icosphere(2, 1.0);
  const TriangleMesh both = concatenate(small, big);
  const Components c = analyse(both);
  ASSERT_EQ(c.count(), 2);
  EXPECT_GT(c.info[0].area, c.info[1].area);
  EXPECT_NEAR(c.info[0].area / c.info[1].area, 4.0, 1e-9);
  EXPECT_EQ(c.info[0].genus(), 0);
  EXPECT_EQ(c.info[1].genus(), 0);
  // The big sphere's vertices come second in the input but form component 0.
  EXPECT_EQ(c.vertexLabel[small.numVertices()], 0);
  EXPECT_EQ(c.vertexLabel[0], 1);
  const TriangleMesh extracted = extractComponent(both, c, 1);
  EXPECT_EQ(extracted.numVertices(), small.numVertices());
  EXPECT_EQ(extracted.numFaces(), small.numFaces());
}

TEST(Components, HolesAreBoundaries)
{
  TriangleMesh mesh = icosphere(2);
  // Remove two faces far apart: two boundary loops, still genus 0.
  Triangles kept(mesh.numFaces() - 2, 3);
  int row = 0;
  for (int f = 0; f < mesh.numFaces(); ++f)
    if (f != 0 && f != mesh.numFaces() - 1) kept.row(row++) = mesh.F.row(f);
  mesh.F = kept;
  const Components c = analyse(mesh);
  ASSERT_EQ(c.count(), 1);
  EXPECT_EQ(c.info[0].numBoundaries, 2);
  EXPECT_EQ(c.info[0].genus(), 0);
}

TEST(Components, GridIsADisk)
{
  const Components c = analyse(grid(5, 2.0));
  ASSERT_EQ(c.count(), 1);
  EXPECT_EQ(c.info[0].numBoundaries, 1);
  EXPECT_EQ(c.info[0].genus(), 0);
  EXPECT_NEAR(c.info[0].area, 4.0, 1e-12);
}
