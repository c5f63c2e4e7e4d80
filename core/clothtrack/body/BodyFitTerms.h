#pragma once
// The frame side of the body fit's energy: closest points, their residuals, extremity pairs.
// Internal to the body fit (BodyFit.cpp).
#include "BodySamples.h"
#include "Extremities.h"

#include <clothtrack/mesh/Geodesic.h>
#include <clothtrack/mesh/SurfaceLocator.h>

#include <limits>
#include <memory>

namespace clothtrack::bodyfit
{
/// A frame ready for closest-point queries, with its detected extremities.
struct FrameSurface
{
  const TriangleMesh* mesh = nullptr;
  std::unique_ptr<SurfaceLocator> locator;
  Points normals;
  Vec3 centroid = Vec3::Zero();
  std::vector<Vec3> extremities;
  mutable std::vector<int> hints; ///< last closest face of each body sample
  /// At most 1000 evenly spread vertices: the frame side of the cover term and frameToBody.
  std::vector<int> spread;

  /// Detects the extremities unless `known` gives them.
  FrameSurface(const TriangleMesh& frame, double persistence, const std::vector<Vec3>* known)
      : mesh(&frame)
  {
    locator = std::make_unique<SurfaceLocator>(frame);
    normals = vertexNormals(frame);
    if (signedVolume(frame) < 0.0) normals = -normals; // inward-facing triangles
    const Eigen::VectorXd areas = faceAreas(frame);
    for (int f = 0; f < frame.numFaces(); ++f)
      centroid += areas[f] *
                  (frame.vertex(frame.F(f, 0)) + frame.vertex(frame.F(f, 1)) +
                   frame.vertex(frame.F(f, 2))) /
                  3.0;
    centroid /= std::max(areas.sum(), 1e-12);
    const int n = frame.numVertices();
    const int count = std::min(n, 1000);
    for (int i = 0; i < count; ++i)
      spread.push_back(static_cast<int>(static_cast<long long>(i) * n / count));
    if (known)
    {
      extremities = *known;
      return;
    }
    for (const Extremity& e : geodesicExtremities(frame, persistence))
      extremities.push_back(frame.vertex(e.vertex));
    if (extremities.size() > 7) extremities.resize(7);
  }

  /// Closest point and the (outward) surface normal there.
  bool closest(int sample, const Vec3& p, double maxDistance, Vec3& point, Vec3& normal) const
  {
    // hints is sized by the caller before parallel queries (one slot per sample).
    const SurfacePoint s = locator->closestPoint(p, maxDistance, hints[sample]);
    if (!s.valid()) return false;
    hints[sample] = s.face;
    normal = Vec3::Zero();
    for (int k = 0; k < 3; ++k) normal += s.bary[k] * normals.row(mesh->F(s.face, k)).transpose();
    if (normal.squaredNorm() < 1e-20) return false;
    normal.normalize();
    point = s.position;
    return true;
  }
};

/// Residuals at fixed assignments: plane rows r = n.(p - target) (hinge rows count only
/// when positive) and point rows r = p - target.
struct Assignments
{
  struct PlaneRow
  {
    int point;
    Vec3 target, normal;
    double weight;
    bool hinge;
  };
  struct PointRow
  {
    int point;
    Vec3 target;
    double weight;
  };
  std::vector<PlaneRow> planes;
  std::vector<PointRow> points;
  int matchedExtremities = 0;

  double energy(const Points& p) const
  {
    double e = 0.0;
    for (const PlaneRow& r : planes)
    {
      double s = r.normal.dot(p.row(r.point).transpose() - r.target);
      if (r.hinge) s = std::max(0.0, s);
      e += r.weight * s * s;
    }
    for (const PointRow& r : points)
      e += r.weight * (p.row(r.point).transpose() - r.target).squaredNorm();
    return e;
  }

  /// Adds J^T W J and J^T W r, J's columns being the point displacements per unit parameter.
  void accumulate(const Points& p, const std::vector<Points>& columns, Eigen::MatrixXd& h,
                  Eigen::VectorXd& g) const
  {
    const int n = static_cast<int>(columns.size());
    Eigen::MatrixXd j(planes.size() + 3 * points.size(), n);
    Eigen::VectorXd r(j.rows());
    int row = 0;
    for (const PlaneRow& pr : planes)
    {
      const double s = pr.normal.dot(p.row(pr.point).transpose() - pr.target);
      if (pr.hinge && s <= 0.0) continue;
      const double w = std::sqrt(pr.weight);
      for (int c = 0; c < n; ++c)
        j(row, c) = w * pr.normal.dot(columns[c].row(pr.point).transpose());
      r[row++] = w * s;
    }
    for (const PointRow& pr : points)
    {
      const double w = std::sqrt(pr.weight);
      for (int c = 0; c < n; ++c) j.block(row, c, 3, 1) = w * columns[c].row(pr.point).transpose();
      r.segment<3>(row) = w * (p.row(pr.point).transpose() - pr.target);
      row += 3;
    }
    const auto used = j.topRows(row);
    h.noalias() += used.transpose() * used;
    g.noalias() += used.transpose() * r.head(row);
  }
};

/// Pairs detected extremities with the body's (head top, hands, toes) by proximity under the
/// current estimate, each used at most once. A detection is a candidate for a label only within
/// the gate and within reach of the joint the extremity hangs from (a hand cannot be further
/// from its shoulder than reachTolerance times the arm's length): tips of cloth folds or of
/// merged parts are left out.
inline void matchExtremities(const Points& p, const BodySamples& samples,
                             const std::array<Vec3, kNumExtremities>& roots,
                             const std::vector<Vec3>& detected, double gate, double handGate,
                             double reachTolerance, std::array<int, 5>& match)
{
  match.fill(-1);
  std::array<int, 5> current;
  current.fill(-1);
  std::vector<bool> used(detected.size(), false);
  double bestScore = -1.0;
  // Exhaustive over at most 5 labels x 8 choices: maximise matched count, then closeness.
  std::function<void(int, int, double)> search = [&](int label, int count, double cost)
  {
    if (label == kNumExtremities)
    {
      const double score = count * 100.0 - cost;
      if (score > bestScore) bestScore = score, match = current;
      return;
    }
    current[label] = -1;
    search(label + 1, count, cost);
    const Vec3 body = p.row(samples.extremityPoint(label)).transpose();
    for (size_t d = 0; d < detected.size(); ++d)
    {
      if (used[d]) continue;
      const double distance = (detected[d] - body).norm();
      const bool hand = label == 1 || label == 2;
      if (distance > (hand ? std::max(gate, handGate) : gate)) continue;
      if ((detected[d] - roots[label]).norm() > reachTolerance * samples.reach()[label] + 0.03)
        continue;
      used[d] = true;
      current[label] = static_cast<int>(d);
      search(label + 1, count + 1, cost + distance);
      used[d] = false;
      current[label] = -1;
    }
  };
  search(0, 0, 0.0);
}

} // namespace clothtrack::bodyfit
