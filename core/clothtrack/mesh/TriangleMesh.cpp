#include "TriangleMesh.h"

#include <clothtrack/base/Parallel.h>

#include <algorithm>
#include <cmath>

namespace clothtrack
{
namespace
{
/// Each row scaled to unit length; zero rows stay zero.
void normaliseRows(Points& rows)
{
  for (Eigen::Index i = 0; i < rows.rows(); ++i)
  {
    const double length = rows.row(i).norm();
    if (length > 0) rows.row(i) /= length;
  }
}
} // namespace

Eigen::VectorXd faceAreas(const TriangleMesh& mesh)
{
  Eigen::VectorXd areas(mesh.numFaces());
  for (int f = 0; f < mesh.numFaces(); ++f)
  {
    const Vec3 a = mesh.vertex(mesh.F(f, 0));
    const Vec3 b = mesh.vertex(mesh.F(f, 1));
    const Vec3 c = mesh.vertex(mesh.F(f, 2));
    areas[f] = 0.5 * (b - a).cross(c - a).norm();
  }
  return areas;
}

Points faceNormals(const TriangleMesh& mesh)
{
  Points normals(mesh.numFaces(), 3);
  parallelFor(
      0, mesh.numFaces(),
      [&](int f)
      {
        const Vec3 a = mesh.vertex(mesh.F(f, 0));
        const Vec3 n = (mesh.vertex(mesh.F(f, 1)) - a).cross(mesh.vertex(mesh.F(f, 2)) - a);
        const double len = n.norm();
        normals.row(f) = (len > 0 ? Vec3(n / len) : Vec3::Zero()).transpose();
      },
      4096);
  return normals;
}

Points vertexNormals(const TriangleMesh& mesh)
{
  // Angle weights make the normal independent of how a fan is triangulated.
  // The corner angles (the costly part) in parallel, then the sums in face order.
  const Points fn = faceNormals(mesh);
  Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor> angles(mesh.numFaces(), 3);
  parallelFor(
      0, mesh.numFaces(),
      [&](int f)
      {
        for (int k = 0; k < 3; ++k)
        {
          const int i = mesh.F(f, k);
          const Vec3 e1 = mesh.vertex(mesh.F(f, (k + 1) % 3)) - mesh.vertex(i);
          const Vec3 e2 = mesh.vertex(mesh.F(f, (k + 2) % 3)) - mesh.vertex(i);
          const double denom = e1.norm() * e2.norm();
          angles(f, k) = denom > 0 ? std::acos(std::clamp(e1.dot(e2) / denom, -1.0, 1.0)) : 0.0;
        }
      },
      2048);
  Points normals = Points::Zero(mesh.numVertices(), 3);
  for (int f = 0; f < mesh.numFaces(); ++f)
    for (int k = 0; k < 3; ++k)
      if (angles(f, k) != 0) normals.row(mesh.F(f, k)) += angles(f, k) * fn.row(f);
  normaliseRows(normals);
  return normals;
}

Points areaWeightedVertexNormals(const TriangleMesh& mesh)
{
  // A face's cross product is its normal times twice its area: summed as is.
  Points normals = Points::Zero(mesh.numVertices(), 3);
  for (int f = 0; f < mesh.numFaces(); ++f)
  {
    const Vec3 a = mesh.vertex(mesh.F(f, 0));
    const Vec3 n = (mesh.vertex(mesh.F(f, 1)) - a).cross(mesh.vertex(mesh.F(f, 2)) - a);
    for (int k = 0; k < 3; ++k) normals.row(mesh.F(f, k)) += n.transpose();
  }
  normaliseRows(normals);
  return normals;
}

double surfaceArea(const TriangleMesh& mesh)
{
  return faceAreas(mesh).sum();
}

double signedVolume(const TriangleMesh& mesh)
{
  double volume = 0;
  for (int f = 0; f < mesh.numFaces(); ++f)
    volume +=
        mesh.vertex(mesh.F(f, 0)).dot(mesh.vertex(mesh.F(f, 1)).cross(mesh.vertex(mesh.F(f, 2))));
  return volume / 6.0;
}

double meanEdgeLength(const TriangleMesh& mesh)
{
  if (mesh.numFaces() == 0) return 0.0;
  double sum = 0;
  for (int f = 0; f < mesh.numFaces(); ++f)
    for (int k = 0; k < 3; ++k)
      sum += (mesh.vertex(mesh.F(f, k)) - mesh.vertex(mesh.F(f, (k + 1) % 3))).norm();
  return sum / (3.0 * mesh.numFaces());
}
} // namespace clothtrack
