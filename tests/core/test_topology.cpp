#include <clothtrack/mesh/MeshTopology.h>
#include <clothtrack/mesh/Primitives.h>

#include <gtest/gtest.h>

using namespace clothtrack;

TEST(Topology, IcosphereEdgesAndDegrees)
{
  const TriangleMesh mesh = icosphere(2);
  const MeshTopology topo = buildTopology(mesh);
  EXPECT_EQ(mesh.numVertices(), 162);
  EXPECT_EQ(topo.numEdges(), 3 * mesh.numFaces() / 2);
  EXPECT_EQ(mesh.numVertices() - topo.numEdges() + mesh.numFaces(), 2);
  int degree5 = 0;
  for (int v = 0; v < mesh.numVertices(); ++v)
  {
    EXPECT_EQ(topo.vertexVertices.degree(v), topo.vertexFaces.degree(v));
    degree5 += topo.vertexVertices.degree(v) == 5;
  }
  EXPECT_EQ(degree5, 12); // the icosahedron's original vertices
  EXPECT_TRUE(boundaryLoops(mesh, topo).empty());
  EXPECT_TRUE(checkManifold(mesh, topo).isManifold());
}

TEST(Topology, GridHasOneBoundaryLoop)
{
  const int n = 6;
  const TriangleMesh mesh = grid(n, 1.0);
  const MeshTopology topo = buildTopology(mesh);
  const auto loops = boundaryLoops(mesh, topo);
  ASSERT_EQ(loops.size(), 1u);
  EXPECT_EQ(loops[0].size(), static_cast<size_t>(4 * n));
  // Consecutive loop vertices share a boundary edge.
  for (size_t i = 0; i < loops[0].size(); ++i)
  {
    const int a = loops[0][i], b = loops[0][(i + 1) % loops[0].size()];
    EXPECT_NEAR((mesh.vertex(a) - mesh.vertex(b)).norm(), 1.0 / n, 1e-12);
  }
}

TEST(Topology, FaceAdjacencyOfTwoTriangles)
{
  TriangleMesh mesh;
  mesh.V.resize(4, 3);
  mesh.V << 0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0;
  mesh.F.resize(2, 3);
  mesh.F << 0, 1, 2, 1, 3, 2;
  const MeshTopology topo = buildTopology(mesh);
  const Adjacency ff = faceFaceAdjacency(topo, 2);
  ASSERT_EQ(ff.degree(0), 1);
  EXPECT_EQ(*ff.begin(0), 1);
  EXPECT_EQ(topo.numEdges(), 5);
}

TEST(Topology, DetectsNonManifoldEdgeAndBowTie)
{
  TriangleMesh fin; // three triangles on one edge
  fin.V.resize(5, 3);
  fin.V << 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, -1, 0, 0, 0, 1;
  fin.F.resize(3, 3);
  fin.F << 0, 1, 2, 1, 0, 3, 0, 1, 4;
  EXPECT_EQ(checkManifold(fin, buildTopology(fin)).nonManifoldEdges, 1);

  TriangleMesh bowtie; // two triangles touching at vertex 0 only
  bowtie.V.resize(5, 3);
  bowtie.V << 0, 0, 0, 1, 0, 0, 1, 1, 0, -1, 0, 0, -1, -1, 0;
  bowtie.F.resize(2, 3);
  bowtie.F << 0, 1, 2, 0, 3, 4;
  const ManifoldReport report = checkManifold(bowtie, buildTopology(bowtie));
  EXPECT_EQ(report.nonManifoldEdges, 0);
  EXPECT_EQ(report.nonManifoldVertices, 1);
}
