#include <clothtrack/mesh/Primitives.h>
#include <clothtrack/mesh/TriangleMesh.h>

#include <gtest/gtest.h>

using namespace clothtrack;

namespace
{
// Two triangles meeting at vertex 0 with right angles there: one of area 2 facing +z, one of
// area 0.5 facing +x.
TriangleMesh unequalFan()
{
  TriangleMesh mesh;
  mesh.V.resize(5, 3);
  mesh.V << 0, 0, 0, 2, 0, 0, 0, 2, 0, 0, 1, 0, 0, 0, 1;
  mesh.F.resize(2, 3);
  mesh.F << 0, 1, 2, 0, 3, 4;
  return mesh;
}
} // namespace

TEST(TriangleMesh, VertexNormalWeights)
{
  const TriangleMesh mesh = unequalFan();
  // Equal angles: the two face normals count equally.
  EXPECT_TRUE(vertexNormals(mesh).row(0).isApprox(Vec3(1, 0, 1).normalized().transpose(), 1e-12));
  // Areas 0.5 and 2: the larger face counts four times as much.
  EXPECT_TRUE(areaWeightedVertexNormals(mesh).row(0).isApprox(
      Vec3(1, 0, 4).normalized().transpose(), 1e-12));
  EXPECT_TRUE(areaWeightedVertexNormals(mesh).row(1).isApprox(Vec3(0, 0, 1).transpose(), 1e-12));
}

TEST(TriangleMesh, VertexNormalsOfASphereAreRadial)
{
  const TriangleMesh sphere = icosphere(3);
  const Points angle = vertexNormals(sphere), area = areaWeightedVertexNormals(sphere);
  for (int i = 0; i < sphere.numVertices(); ++i)
  {
    const Vec3 radial = sphere.vertex(i).normalized();
    EXPECT_GT(angle.row(i).dot(radial), std::cos(1.0 * M_PI / 180));
    EXPECT_GT(area.row(i).dot(radial), std::cos(1.0 * M_PI / 180));
  }
}

TEST(TriangleMesh, IsolatedVertexHasZeroNormal)
{
  TriangleMesh mesh = unequalFan();
  mesh.V.conservativeResize(6, 3);
  mesh.V.row(5) << 5, 5, 5;
  EXPECT_EQ(areaWeightedVertexNormals(mesh).row(5).norm(), 0.0);
  EXPECT_EQ(vertexNormals(mesh).row(5).norm(), 0.0);
}
