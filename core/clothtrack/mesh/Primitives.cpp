#include "Primitives.h"

#include <cmath>
#include <map>
#include <vector>

namespace clothtrack
{
TriangleMesh icosphere(int level, double radius, const Vec3& center)
{
  const double t = (1.0 + std::sqrt(5.0)) / 2.0;
  std::vector<Vec3> v = {{-1, t, 0},  {1, t, 0},  {-1, -t, 0}, {1, -t, 0}, {0, -1, t},  {0, 1, t},
                         {0, -1, -t}, {0, 1, -t}, {t, 0, -1},  {t, 0, 1},  {-t, 0, -1}, {-t, 0, 1}};
  std::vector<Eigen::Vector3i> f = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11},
                                    {1, 5, 9},  {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
                                    {3, 9, 4},  {3, 4, 2},  {3, 2, 6},   {3, 6, 8},  {3, 8, 9},
                                    {4, 9, 5},  {2, 4, 11}, {6, 2, 10},  {8, 6, 7},  {9, 8, 1}};
  for (auto& p : v) p.normalize();
  for (int l = 0; l < level; ++l)
  {
    std::map<std::pair<int, int>, int> midpoint;
    auto mid = [&](int a, int b)
    {
      const auto key = std::minmax(a, b);
      const auto it = midpoint.find(key);
      if (it != midpoint.end()) return it->second;
      v.push_back((v[a] + v[b]).normalized());
      return midpoint[key] = static_cast<int>(v.size()) - 1;
    };
    std::vector<Eigen::Vector3i> next;
    for (const auto& tri : f)
    {
      const int a = mid(tri[0], tri[1]), b = mid(tri[1], tri[2]), c = mid(tri[2], tri[0]);
      next.push_back({tri[0], a, c});
      next.push_back({tri[1], b, a});
      next.push_back({tri[2], c, b});
      next.push_back({a, b, c});
    }
    f = std::move(next);
  }
  TriangleMesh mesh;
  mesh.V.resize(static_cast<Eigen::Index>(v.size()), 3);
  for (size_t i = 0; i < v.size(); ++i)
    mesh.V.row(static_cast<Eigen::Index>(i)) = (center + radius * v[i]).transpose();
  mesh.F.resize(static_cast<Eigen::Index>(f.size()), 3);
  for (size_t i = 0; i < f.size(); ++i) mesh.F.row(static_cast<Eigen::Index>(i)) = f[i].transpose();
  return mesh;
}

TriangleMesh torus(double R, double r, int nu, int nv)
{
  TriangleMesh mesh;
  mesh.V.resize(nu * nv, 3);
  mesh.F.resize(2 * nu * nv, 3);
  for (int i = 0; i < nu; ++i)
    for (int j = 0; j < nv; ++j)
    {
      const double u = 2 * M_PI * i / nu, w = 2 * M_PI * j / nv;
      mesh.V.row(i * nv + j) << (R + r * std::cos(w)) * std::cos(u),
          (R + r * std::cos(w)) * std::sin(u), r * std::sin(w);
      const int a = i * nv + j, b = ((i + 1) % nu) * nv + j, c = ((i + 1) % nu) * nv + (j + 1) % nv,
                d = i * nv + (j + 1) % nv;
      mesh.F.row(2 * a) << a, b, c;
      mesh.F.row(2 * a + 1) << a, c, d;
    }
  return mesh;
}

TriangleMesh grid(int n, double width)
{
  TriangleMesh mesh;
  mesh.V.resize((n + 1) * (n + 1), 3);
  mesh.F.resize(2 * n * n, 3);
  for (int i = 0; i <= n; ++i)
    for (int j = 0; j <= n; ++j) mesh.V.row(i * (n + 1) + j) << width * i / n, width * j / n, 0.0;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
    {
      const int a = i * (n + 1) + j, b = a + n + 1;
      mesh.F.row(2 * (i * n + j)) << a, b, b + 1;
      mesh.F.row(2 * (i * n + j) + 1) << a, b + 1, a + 1;
    }
  return mesh;
}

TriangleMesh concatenate(const TriangleMesh& a, const TriangleMesh& b)
{
  TriangleMesh out;
  out.V.resize(a.numVertices() + b.numVertices(), 3);
  out.V << a.V, b.V;
  out.F.resize(a.numFaces() + b.numFaces(), 3);
  out.F << a.F, (b.F.array() + a.numVertices()).matrix();
  return out;
}
} // namespace clothtrack
