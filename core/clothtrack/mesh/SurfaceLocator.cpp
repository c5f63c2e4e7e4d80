#include "SurfaceLocator.h"

#include <clothtrack/base/Parallel.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <numeric>

namespace clothtrack
{
Vec3 closestPointOnTriangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c, Vec3& bary)
{
  const Vec3 ab = b - a, ac = c - a, ap = p - a;
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0 && d2 <= 0)
  {
    bary = {1, 0, 0};
    return a;
  }
  const Vec3 bp = p - b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0 && d4 <= d3)
  {
    bary = {0, 1, 0};
    return b;
  }
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0)
  {
    const double v = d1 / (d1 - d3);
    bary = {1 - v, v, 0};
    return a + v * ab;
  }
  const Vec3 cp = p - c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0 && d5 <= d6)
  {
    bary = {0, 0, 1};
    return c;
  }
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0)
  {
    const double w = d2 / (d2 - d6);
    bary = {1 - w, 0, w};
    return a + w * ac;
  }
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0)
  {
    const double w = (d4 - d3) / ((d4 - d3) + (d5 - d6));
    bary = {0, 1 - w, w};
    return b + w * (c - b);
  }
  const double denom = va + vb + vc;
  if (!(std::abs(denom) > 0)) // degenerate triangle: fall back to its first vertex
  {
    bary = {1, 0, 0};
    return a;
  }
  const double v = vb / denom, w = vc / denom;
  bary = {1 - v - w, v, w};
  return a + v * ab + w * ac;
}

SurfaceLocator::SurfaceLocator(const TriangleMesh& mesh) : mesh_(mesh)
{
  const int nf = mesh.numFaces();
  order_.resize(nf);
  std::iota(order_.begin(), order_.end(), 0);
  std::vector<Vec3> centroids(nf);
  for (int f = 0; f < nf; ++f)
    centroids[f] =
        (mesh.vertex(mesh.F(f, 0)) + mesh.vertex(mesh.F(f, 1)) + mesh.vertex(mesh.F(f, 2))) / 3.0;
  nodes_.reserve(2 * static_cast<size_t>(nf) / 2 + 1);
  if (nf > 0) build(0, nf, centroids);
  corners_.resize(nf);
  normals_.resize(nf);
  for (int i = 0; i < nf; ++i)
  {
    for (int k = 0; k < 3; ++k) corners_[i][k] = mesh.vertex(mesh.F(order_[i], k));
    // Degenerate triangles get a zero normal, which never excludes them.
    const Vec3 n = (corners_[i][1] - corners_[i][0]).cross(corners_[i][2] - corners_[i][0]);
    const double length = n.norm();
    normals_[i] = length > 0 ? Vec3(n / length) : Vec3::Zero();
  }
}

int SurfaceLocator::build(int begin, int end, const std::vector<Vec3>& centroids)
{
  const int id = static_cast<int>(nodes_.size());
  nodes_.emplace_back();
  Eigen::AlignedBox3d box, centroidBox;
  for (int i = begin; i < end; ++i)
  {
    const int f = order_[i];
    for (int k = 0; k < 3; ++k) box.extend(mesh_.vertex(mesh_.F(f, k)));
    centroidBox.extend(centroids[f]);
  }
  nodes_[id].box = box;
  constexpr int leafSize = 4;
  if (end - begin <= leafSize)
  {
    nodes_[id].begin = begin;
    nodes_[id].end = end;
    return id;
  }
  int axis;
  centroidBox.sizes().maxCoeff(&axis);
  const int mid = (begin + end) / 2;
  std::nth_element(order_.begin() + begin, order_.begin() + mid, order_.begin() + end,
                   [&](int a, int b) { return centroids[a][axis] < centroids[b][axis]; });
  const int left = build(begin, mid, centroids);
  const int right = build(mid, end, centroids);
  nodes_[id].left = left;
  nodes_[id].right = right;
  return id;
}

SurfacePoint SurfaceLocator::closestPoint(const Vec3& query, double maxDistance, int hintFace) const
{
  SurfacePoint best;
  if (nodes_.empty()) return best;
  double best2 = std::isfinite(maxDistance) ? maxDistance * maxDistance
                                            : std::numeric_limits<double>::infinity();
  auto tryTriangle = [&](int f, const Vec3& a, const Vec3& b, const Vec3& c)
  {
    Vec3 bary;
    const Vec3 p = closestPointOnTriangle(query, a, b, c, bary);
    const double d2 = (p - query).squaredNorm();
    if (d2 <= best2)
    {
      best2 = d2;
      best.face = f;
      best.bary = bary;
      best.position = p;
    }
  };
  // A good guess bounds the search from the start (queries that move little between calls).
  if (hintFace >= 0 && hintFace < mesh_.numFaces())
    tryTriangle(hintFace, mesh_.vertex(mesh_.F(hintFace, 0)), mesh_.vertex(mesh_.F(hintFace, 1)),
                mesh_.vertex(mesh_.F(hintFace, 2)));
  if (nodes_[0].box.squaredExteriorDistance(query) > best2) return best;
  // Depth first, nearer child first; the farther one waits on the stack with its distance, and
  // is dropped when the bound has shrunk below it. Median splits keep the depth below
  // log2(faces) + 1, so a fixed stack suffices.
  int stack[128];
  double stackDistance2[128];
  int top = 0;
  int current = 0;
  while (true)
  {
    const Node& node = nodes_[current];
    if (node.left < 0)
    {
      for (int i = node.begin; i < node.end; ++i)
      {
        // The triangle's plane is no farther than the triangle: a cheap bound first.
        const double plane = normals_[i].dot(query - corners_[i][0]);
        if (plane * plane <= best2)
          tryTriangle(order_[i], corners_[i][0], corners_[i][1], corners_[i][2]);
      }
    }
    else
    {
      int nearer = node.left, farther = node.right;
      double dNear = nodes_[nearer].box.squaredExteriorDistance(query),
             dFar = nodes_[farther].box.squaredExteriorDistance(query);
      if (dFar < dNear) std::swap(nearer, farther), std::swap(dNear, dFar);
      if (dNear <= best2)
      {
        if (dFar <= best2)
        {
          stack[top] = farther;
          stackDistance2[top++] = dFar;
        }
        current = nearer;
        continue;
      }
    }
    while (top > 0 && stackDistance2[top - 1] > best2) --top;
    if (top == 0) break;
    current = stack[--top];
  }
  if (best.valid()) best.distance = std::sqrt(best2);
  return best;
}

namespace
{
// Parameter range [tmin, tmax] of the line inside the box; false when it misses.
bool lineBoxRange(const Eigen::AlignedBox3d& box, const Vec3& o, const Vec3& d, double& tmin,
                  double& tmax)
{
  tmin = -std::numeric_limits<double>::infinity();
  tmax = std::numeric_limits<double>::infinity();
  for (int k = 0; k < 3; ++k)
  {
    if (d[k] == 0)
    {
      if (o[k] < box.min()[k] || o[k] > box.max()[k]) return false;
      continue;
    }
    double t0 = (box.min()[k] - o[k]) / d[k], t1 = (box.max()[k] - o[k]) / d[k];
    if (t0 > t1) std::swap(t0, t1);
    tmin = std::max(tmin, t0);
    tmax = std::min(tmax, t1);
  }
  return tmin <= tmax;
}
} // namespace

std::vector<LineHit> SurfaceLocator::intersectLine(const Vec3& origin, const Vec3& direction,
                                                   double minT) const
{
  std::vector<LineHit> hits;
  if (nodes_.empty() || !(direction.squaredNorm() > 0)) return hits;
  const double tol = 1e-9 / direction.norm();
  int stack[128]; // median splits: depth below log2(faces) + 1
  int top = 0;
  stack[top++] = 0;
  while (top > 0)
  {
    const Node& node = nodes_[stack[--top]];
    double t0, t1;
    // Boxes are inflated slightly so that a line grazing a flat box is not lost.
    Eigen::AlignedBox3d box = node.box;
    const Vec3 pad = Vec3::Constant(1e-9 * (1.0 + box.sizes().norm()));
    box.extend(box.min() - pad);
    box.extend(box.max() + pad);
    if (!lineBoxRange(box, origin, direction, t0, t1) || t1 < minT - tol) continue;
    if (node.left >= 0)
    {
      stack[top++] = node.left;
      stack[top++] = node.right;
      continue;
    }
    for (int i = node.begin; i < node.end; ++i)
    {
      // Moller-Trumbore without a range restriction on t; edges are closed (>= 0) so that a
      // line through a shared edge is caught by both sides and deduplicated below.
      const int f = order_[i];
      const Vec3& a = corners_[i][0];
      const Vec3 e1 = corners_[i][1] - a, e2 = corners_[i][2] - a;
      const Vec3 pvec = direction.cross(e2);
      const double det = e1.dot(pvec);
      if (std::abs(det) < 1e-300) continue;
      const double inv = 1.0 / det;
      const Vec3 tvec = origin - a;
      const double u = tvec.dot(pvec) * inv;
      if (u < 0 || u > 1) continue;
      const Vec3 qvec = tvec.cross(e1);
      const double v = direction.dot(qvec) * inv;
      if (v < 0 || u + v > 1) continue;
      LineHit hit;
      hit.t = e2.dot(qvec) * inv;
      if (hit.t < minT - tol) continue;
      hit.point.face = f;
      hit.point.bary = {1 - u - v, u, v};
      hit.point.position = origin + hit.t * direction;
      hit.point.distance = 0.0;
      hits.push_back(hit);
    }
  }
  std::sort(hits.begin(), hits.end(), [](const LineHit& x, const LineHit& y) { return x.t < y.t; });
  std::vector<LineHit> unique;
  for (const auto& h : hits)
    if (unique.empty() || h.t - unique.back().t > tol) unique.push_back(h);
  return unique;
}
double meanClosestDistance(const Points& points, const SurfaceLocator& surface, long stride)
{
  const long samples = (static_cast<long>(points.rows()) + stride - 1) / stride;
  if (samples == 0) return 0.0;
  return parallelSum(samples,
                     [&](long from, long to)
                     {
                       double part = 0;
                       for (long i = from; i < to; ++i)
                         part += surface.closestPoint(points.row(i * stride).transpose()).distance;
                       return part;
                     }) /
         samples;
}
} // namespace clothtrack
