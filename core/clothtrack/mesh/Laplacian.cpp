#include "Laplacian.h"

#include <vector>

namespace clothtrack
{
namespace
{
double cotangent(const Vec3& a, const Vec3& b)
{
  const double s = a.cross(b).norm();
  return s > 0 ? a.dot(b) / s : 0.0;
}
} // namespace

Eigen::VectorXd mixedVoronoiAreas(const TriangleMesh& mesh)
{
  Eigen::VectorXd areas = Eigen::VectorXd::Zero(mesh.numVertices());
  for (int f = 0; f < mesh.numFaces(); ++f)
  {
    const int id[3] = {mesh.F(f, 0), mesh.F(f, 1), mesh.F(f, 2)};
    const Vec3 p[3] = {mesh.vertex(id[0]), mesh.vertex(id[1]), mesh.vertex(id[2])};
    const double area = 0.5 * (p[1] - p[0]).cross(p[2] - p[0]).norm();
    if (area <= 0) continue;
    int obtuse = -1;
    for (int k = 0; k < 3; ++k)
      if ((p[(k + 1) % 3] - p[k]).dot(p[(k + 2) % 3] - p[k]) < 0) obtuse = k;
    for (int k = 0; k < 3; ++k)
    {
      if (obtuse >= 0)
      {
        areas[id[k]] += (k == obtuse ? 0.5 : 0.25) * area;
        continue;
      }
      const int q = (k + 1) % 3, r = (k + 2) % 3;
      const double cotQ = cotangent(p[k] - p[q], p[r] - p[q]);
      const double cotR = cotangent(p[k] - p[r], p[q] - p[r]);
      areas[id[k]] +=
          ((p[r] - p[k]).squaredNorm() * cotQ + (p[q] - p[k]).squaredNorm() * cotR) / 8.0;
    }
  }
  return areas;
}

SparseMatrix cotanLaplacian(const TriangleMesh& mesh)
{
  std::vector<Eigen::Triplet<double>> triplets;
  triplets.reserve(12 * static_cast<size_t>(mesh.numFaces()));
  for (int f = 0; f < mesh.numFaces(); ++f)
    for (int k = 0; k < 3; ++k)
    {
      const int i = mesh.F(f, (k + 1) % 3), j = mesh.F(f, (k + 2) % 3);
      const Vec3 o = mesh.vertex(mesh.F(f, k));
      const double w = 0.5 * cotangent(mesh.vertex(i) - o, mesh.vertex(j) - o);
      triplets.emplace_back(i, j, -w);
      triplets.emplace_back(j, i, -w);
      triplets.emplace_back(i, i, w);
      triplets.emplace_back(j, j, w);
    }
  SparseMatrix L(mesh.numVertices(), mesh.numVertices());
  L.setFromTriplets(triplets.begin(), triplets.end());
  return L;
}
} // namespace clothtrack
