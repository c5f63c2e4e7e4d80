#include "Geodesic.h"

#include "Components.h"
#include "Laplacian.h"
#include <clothtrack/base/Error.h>

#include <Eigen/Geometry>
#include <Eigen/SparseCholesky>

#include <cmath>
#include <queue>
#include <string>

namespace clothtrack
{
std::vector<GeodesicSeed> seedsAtSurfacePoint(const TriangleMesh& mesh, int face, const Vec3& bary)
{
  const Vec3 p = bary[0] * mesh.vertex(mesh.F(face, 0)) + bary[1] * mesh.vertex(mesh.F(face, 1)) +
                 bary[2] * mesh.vertex(mesh.F(face, 2));
  std::vector<GeodesicSeed> seeds;
  for (int k = 0; k < 3; ++k)
    seeds.push_back({mesh.F(face, k), (mesh.vertex(mesh.F(face, k)) - p).norm()});
  return seeds;
}

WavefrontGeodesic::WavefrontGeodesic(const TriangleMesh& mesh, Method method)
    : mesh_(mesh), topology_(buildTopology(mesh)), method_(method)
{
}

Eigen::VectorXd WavefrontGeodesic::distances(const std::vector<int>& sources, double limit) const
{
  std::vector<GeodesicSeed> seeds;
  seeds.reserve(sources.size());
  for (int s : sources) seeds.push_back({s, 0.0});
  return distancesFromSeeds(seeds, limit);
}

double WavefrontGeodesic::triangleUpdate(int a, int b, int c, const Eigen::VectorXd& d) const
{
  // Unfold the triangle with A at the origin and B on the x axis, place the virtual source S
  // at distances d[a], d[b] from A and B on the far side of AB, and go straight from S to C
  // when that segment crosses AB.
  const Vec3 pa = mesh_.vertex(a), pb = mesh_.vertex(b), pc = mesh_.vertex(c);
  const double ab = (pb - pa).norm();
  if (ab <= 0) return kUnreached;
  const double ac2 = (pc - pa).squaredNorm(), bc2 = (pc - pb).squaredNorm();
  const double cx = (ac2 - bc2 + ab * ab) / (2 * ab);
  const double cy = std::sqrt(std::max(0.0, ac2 - cx * cx));
  const double da = d[a], db = d[b];
  const double sx = (da * da - db * db + ab * ab) / (2 * ab);
  const double sy2 = da * da - sx * sx;
  if (sy2 < 0 || cy <= 0) return kUnreached;
  const double sy = -std::sqrt(sy2);
  const double crossX = sx + (cx - sx) * (-sy) / (cy - sy);
  if (crossX < 0 || crossX > ab) return kUnreached;
  return std::hypot(cx - sx, cy - sy);
}

Eigen::VectorXd WavefrontGeodesic::distancesFromSeeds(const std::vector<GeodesicSeed>& seeds,
                                                      double limit) const
{
  return distancesFromSeeds(seeds, limit, reached_);
}

Eigen::VectorXd WavefrontGeodesic::distancesFromSeeds(const std::vector<GeodesicSeed>& seeds,
                                                      double limit, std::vector<int>& reached) const
{
  const int n = mesh_.numVertices();
  Eigen::VectorXd d = Eigen::VectorXd::Constant(n, kUnreached);
  std::vector<char> done(n, 0);
  using Entry = std::pair<double, int>;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> queue;
  for (const auto& s : seeds)
  {
    if (s.vertex < 0 || s.vertex >= n)
      throw Error("geodesic seed vertex " + std::to_string(s.vertex) + " is out of range [0, " +
                  std::to_string(n) + ")");
    if (s.distance < d[s.vertex])
    {
      d[s.vertex] = s.distance;
      queue.emplace(s.distance, s.vertex);
    }
  }
  reached.clear();
  auto relax = [&](int v, double candidate)
  {
    if (candidate < d[v])
    {
      d[v] = candidate;
      queue.emplace(candidate, v);
    }
  };
  while (!queue.empty())
  {
    const auto [dist, v] = queue.top();
    queue.pop();
    if (done[v] || dist > d[v]) continue;
    if (dist > limit) break;
    done[v] = 1;
    reached.push_back(v);
    const Vec3 pv = mesh_.vertex(v);
    for (const int* w = topology_.vertexVertices.begin(v); w != topology_.vertexVertices.end(v);
         ++w)
      if (!done[*w]) relax(*w, dist + (mesh_.vertex(*w) - pv).norm());
    if (method_ != Method::FastMarching) continue;
    for (const int* f = topology_.vertexFaces.begin(v); f != topology_.vertexFaces.end(v); ++f)
    {
      int k = 0;
      while (mesh_.F(*f, k) != v) ++k;
      const int a = mesh_.F(*f, (k + 1) % 3), b = mesh_.F(*f, (k + 2) % 3);
      if (!done[a] && done[b])
        relax(a, triangleUpdate(v, b, a, d));
      else if (!done[b] && done[a])
        relax(b, triangleUpdate(v, a, b, d));
    }
  }
  for (int v = 0; v < n; ++v)
    if (!done[v]) d[v] = kUnreached;
  return d;
}

struct HeatGeodesic::Impl
{
  const TriangleMesh& mesh;
  Points faceNormal;
  Eigen::VectorXd faceArea;
  Eigen::SimplicialLDLT<SparseMatrix> heat;
  Eigen::SimplicialLDLT<SparseMatrix> poisson;
  Components components;

  explicit Impl(const TriangleMesh& m) : mesh(m) {}
};

HeatGeodesic::HeatGeodesic(const TriangleMesh& mesh, double timeFactor)
    : impl_(std::make_unique<Impl>(mesh))
{
  const SparseMatrix L = cotanLaplacian(mesh);
  const Eigen::VectorXd area = mixedVoronoiAreas(mesh);
  SparseMatrix M(mesh.numVertices(), mesh.numVertices());
  std::vector<Eigen::Triplet<double>> diag;
  for (int i = 0; i < mesh.numVertices(); ++i)
    diag.emplace_back(i, i, area[i] > 0 ? area[i] : 1e-12);
  M.setFromTriplets(diag.begin(), diag.end());

  const double h = meanEdgeLength(mesh);
  const double t = timeFactor * h * h;
  impl_->heat.compute(M + t * L);
  // A tiny mass term makes L positive definite on every component without changing the
  // gradient of the solution noticeably.
  impl_->poisson.compute(L + 1e-10 * M);
  if (impl_->heat.info() != Eigen::Success || impl_->poisson.info() != Eigen::Success)
    throw Error("heat method: sparse Cholesky factorisation failed (degenerate mesh?)");
  impl_->faceNormal = faceNormals(mesh);
  impl_->faceArea = faceAreas(mesh);
  impl_->components = connectedComponents(mesh, buildTopology(mesh));
}

HeatGeodesic::~HeatGeodesic() = default;

Eigen::VectorXd HeatGeodesic::distances(const std::vector<int>& sources, double limit) const
{
  const TriangleMesh& mesh = impl_->mesh;
  const int n = mesh.numVertices();
  Eigen::VectorXd delta = Eigen::VectorXd::Zero(n);
  std::vector<char> componentHasSource(impl_->components.count(), 0);
  for (int s : sources)
  {
    if (s < 0 || s >= n)
      throw Error("geodesic source vertex " + std::to_string(s) + " is out of range [0, " +
                  std::to_string(n) + ")");
    delta[s] = 1.0;
    if (impl_->components.vertexLabel[s] >= 0)
      componentHasSource[impl_->components.vertexLabel[s]] = 1;
  }
  const Eigen::VectorXd u = impl_->heat.solve(delta);

  // Integrated divergence of the normalised, reversed heat gradient.
  Eigen::VectorXd div = Eigen::VectorXd::Zero(n);
  for (int f = 0; f < mesh.numFaces(); ++f)
  {
    if (impl_->faceArea[f] <= 0) continue;
    const int id[3] = {mesh.F(f, 0), mesh.F(f, 1), mesh.F(f, 2)};
    const Vec3 p[3] = {mesh.vertex(id[0]), mesh.vertex(id[1]), mesh.vertex(id[2])};
    const Vec3 normal = impl_->faceNormal.row(f).transpose();
    Vec3 grad = Vec3::Zero();
    for (int k = 0; k < 3; ++k) grad += u[id[k]] * normal.cross(p[(k + 2) % 3] - p[(k + 1) % 3]);
    grad /= 2 * impl_->faceArea[f];
    const double len = grad.norm();
    if (!(len > 0)) continue;
    const Vec3 X = -grad / len;
    for (int k = 0; k < 3; ++k)
    {
      const Vec3 e1 = p[(k + 1) % 3] - p[k], e2 = p[(k + 2) % 3] - p[k];
      const Vec3 o1 = p[k] - p[(k + 2) % 3], o2 = p[(k + 1) % 3] - p[(k + 2) % 3];
      const Vec3 q1 = p[k] - p[(k + 1) % 3], q2 = p[(k + 2) % 3] - p[(k + 1) % 3];
      const double cot2 = o1.dot(o2) / o1.cross(o2).norm(); // angle opposite e1
      const double cot1 = q1.dot(q2) / q1.cross(q2).norm(); // angle opposite e2
      div[id[k]] += 0.5 * (cot2 * e1.dot(X) + cot1 * e2.dot(X));
    }
  }
  // With the positive semi-definite L, L phi = -div gives phi growing away from the sources.
  Eigen::VectorXd phi = impl_->poisson.solve(-div);

  std::vector<double> shift(impl_->components.count(), kUnreached);
  for (int s : sources)
  {
    const int c = impl_->components.vertexLabel[s];
    if (c >= 0) shift[c] = std::min(shift[c], phi[s]);
  }
  for (int v = 0; v < n; ++v)
  {
    const int c = impl_->components.vertexLabel[v];
    if (c < 0 || !componentHasSource[c])
    {
      phi[v] = kUnreached;
      continue;
    }
    phi[v] = std::max(0.0, phi[v] - shift[c]);
    if (phi[v] > limit) phi[v] = kUnreached;
  }
  for (int s : sources) phi[s] = 0.0;
  return phi;
}
} // namespace clothtrack
