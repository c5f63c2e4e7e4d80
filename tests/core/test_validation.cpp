#include <clothtrack/base/Error.h>
#include <clothtrack/mesh/MeshTopology.h>
#include <clothtrack/mesh/MeshValidation.h>
#include <clothtrack/mesh/Primitives.h>

#include <gtest/gtest.h>

#include <limits>

using namespace clothtrack;

TEST(Validation, RejectsNaNEmptyAndBadIndices)
{
  TriangleMesh mesh = icosphere(1);
  mesh.V(3, 1) = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(validateMesh(mesh, "nan"), Error);
  mesh.V(3, 1) = std::numeric_limits<double>::infinity();
  EXPECT_THROW(validateMesh(mesh, "inf"), Error);
  EXPECT_THROW(validateMesh(TriangleMesh{}, "empty"), Error);
  TriangleMesh noFaces = icosphere(1);
  noFaces.F.resize(0, 3);
  EXPECT_THROW(validateMesh(noFaces, "points"), Error);
  TriangleMesh badIndex = icosphere(1);
  badIndex.F(0, 2) = badIndex.numVertices();
  try
  {
    validateMesh(badIndex, "frame_0001.obj");
    FAIL();
  }
  catch (const Error& e)
  {
    EXPECT_NE(std::string(e.what()).find("frame_0001.obj"), std::string::npos);
    EXPECT_NE(std::string(e.what()).find("out of range"), std::string::npos);
  }
}

TEST(Validation, MergesDuplicatedVertices)
{
  // Two triangles of a square, each with its own copy of the shared diagonal.
  TriangleMesh mesh;
  mesh.V.resize(6, 3);
  mesh.V << 0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 0, 0, 1, 1, 0, 0, 1, 0;
  mesh.F.resize(2, 3);
  mesh.F << 0, 1, 2, 3, 4, 5;
  std::vector<int> map;
  const CleaningReport report = cleanMesh(mesh, {}, &map);
  EXPECT_EQ(report.mergedVertices, 2);
  EXPECT_EQ(mesh.numVertices(), 4);
  EXPECT_EQ(mesh.numFaces(), 2);
  EXPECT_EQ(map[3], map[0]);
  EXPECT_EQ(map[4], map[2]);
  ASSERT_FALSE(report.warnings.empty());
  EXPECT_NE(report.warnings[0].find("merged 2"), std::string::npos);
}

TEST(Validation, RemovesZeroAreaRepeatedFacesAndUnusedVertices)
{
  TriangleMesh mesh = grid(3, 1.0);
  const int faces = mesh.numFaces();
  Triangles f(faces + 3, 3);
  f.topRows(faces) = mesh.F;
  f.row(faces) << 0, 1, 2;                    // collinear: zero area
  f.row(faces + 1) << 5, 5, 6;                // collapsed
  f.row(faces + 2) = mesh.F.row(0).reverse(); // same triangle, other winding
  mesh.F = f;
  Points v(mesh.numVertices() + 1, 3);
  v << mesh.V, Eigen::RowVector3d(9, 9, 9); // unused
  mesh.V = v;
  const CleaningReport report = validateAndClean(mesh, "grid");
  EXPECT_EQ(report.degenerateFaces, 2);
  EXPECT_EQ(report.duplicateFaces, 1);
  EXPECT_EQ(report.unusedVertices, 1);
  EXPECT_EQ(mesh.numFaces(), faces);
  EXPECT_EQ(mesh.numVertices(), 16);
}

TEST(Validation, AllDegenerateIsAnError)
{
  TriangleMesh mesh;
  mesh.V.resize(3, 3);
  mesh.V << 0, 0, 0, 1, 0, 0, 2, 0, 0;
  mesh.F.resize(1, 3);
  mesh.F << 0, 1, 2;
  EXPECT_THROW(validateAndClean(mesh, "line"), Error);
}

TEST(Validation, NonManifoldEdgesAndBowTiesAreRepaired)
{
  // Three triangles on one edge, plus a separate bow-tie pair touching at one vertex.
  TriangleMesh mesh;
  mesh.V.resize(9, 3);
  mesh.V << 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, -1, 0, 0, 0, 1, //
      5, 0, 0, 6, 0, 0, 6, 1, 0, 4, 0, 0;
  mesh.V.conservativeResize(10, 3);
  mesh.V.row(9) << 4, -1, 0;
  mesh.F.resize(5, 3);
  mesh.F << 0, 1, 2, 1, 0, 3, 0, 1, 4, 5, 6, 7, 5, 8, 9;
  const CleaningReport report = validateAndClean(mesh, "fin");
  EXPECT_EQ(report.nonManifoldFacesRemoved, 1);
  EXPECT_EQ(report.bowTieVerticesSplit, 1);
  EXPECT_EQ(mesh.numFaces(), 4);
  EXPECT_TRUE(checkManifold(mesh, buildTopology(mesh)).isManifold());
  ASSERT_EQ(report.warnings.size(), 2u); // removed face, split vertex
}
