#pragma once
// Plain triangle mesh: n x 3 vertex positions and m x 3 vertex indices, row-major so that a
// row is one point or one triangle in memory (cheap to hand to FLANN and VTK).
#include <Eigen/Core>
#include <Eigen/Geometry>

namespace clothtrack
{
using Vec3 = Eigen::Vector3d;
using Points = Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>;
using Triangles = Eigen::Matrix<int, Eigen::Dynamic, 3, Eigen::RowMajor>;

struct TriangleMesh
{
  Points V;
  Triangles F;

  int numVertices() const { return static_cast<int>(V.rows()); }
  int numFaces() const { return static_cast<int>(F.rows()); }
  Vec3 vertex(int i) const { return V.row(i).transpose(); }
};

/// Area of each triangle.
Eigen::VectorXd faceAreas(const TriangleMesh& mesh);
/// Unit normal of each triangle (zero for a degenerate triangle).
Points faceNormals(const TriangleMesh& mesh);
/// Angle-weighted unit vertex normals (zero for an isolated vertex).
Points vertexNormals(const TriangleMesh& mesh);
/// Area-weighted unit vertex normals (zero for an isolated vertex): a tenth of the cost of the
/// angle-weighted ones, for normals recomputed many times where a few degrees do not matter.
Points areaWeightedVertexNormals(const TriangleMesh& mesh);
/// Sum of triangle areas.
double surfaceArea(const TriangleMesh& mesh);
/// Volume enclosed by a closed mesh, positive when its triangles face outward.
double signedVolume(const TriangleMesh& mesh);
/// Mean edge length over all triangle edges (each interior edge counted twice).
double meanEdgeLength(const TriangleMesh& mesh);
} // namespace clothtrack
