#include "MotionPrediction.h"

#include <clothtrack/base/Error.h>
#include <clothtrack/base/Parallel.h>
#include <clothtrack/mesh/SurfacePoint.h>

#include <Eigen/SVD>

#include <cmath>
#include <string>

namespace clothtrack
{
namespace
{
/// Weighted least-squares rigid motion (Kabsch): x -> R x + t.
void rigidMotion(const std::vector<Vec3>& before, const std::vector<Vec3>& after,
                 const std::vector<double>& weight, Eigen::Matrix3d& R, Vec3& t)
{
  double total = 0;
  Vec3 cb = Vec3::Zero(), ca = Vec3::Zero();
  for (size_t l = 0; l < before.size(); ++l)
  {
    total += weight[l];
    cb += weight[l] * before[l];
    ca += weight[l] * after[l];
  }
  cb /= total;
  ca /= total;
  Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();
  for (size_t l = 0; l < before.size(); ++l)
    covariance += weight[l] * (after[l] - ca) * (before[l] - cb).transpose();
  const Eigen::JacobiSVD<Eigen::Matrix3d> svd(covariance,
                                              Eigen::ComputeFullU | Eigen::ComputeFullV);
  Eigen::Matrix3d D = Eigen::Matrix3d::Identity();
  D(2, 2) = (svd.matrixU() * svd.matrixV().transpose()).determinant() < 0 ? -1.0 : 1.0;
  R = svd.matrixU() * D * svd.matrixV().transpose();
  t = ca - R * cb;
}
} // namespace

void pairLandmarks(const TriangleMesh& a, const std::vector<OrientedSurfacePoint>& onA,
                   const TriangleMesh& b, const std::vector<OrientedSurfacePoint>& onB,
                   std::vector<Vec3>& before, std::vector<Vec3>& after, double maxOffset)
{
  before.clear();
  after.clear();
  for (const OrientedSurfacePoint& p : onA)
    for (const OrientedSurfacePoint& q : onB)
      if (p.id == q.id && std::abs(p.offset) <= maxOffset && std::abs(q.offset) <= maxOffset)
      {
        before.push_back(surfacePosition(a, p.face, p.bary));
        after.push_back(surfacePosition(b, q.face, q.bary));
      }
}

Points predictMotion(const Points& points, const std::vector<Vec3>& before,
                     const std::vector<Vec3>& after, double radius)
{
  if (before.size() != after.size())
    throw Error("Motion prediction: " + std::to_string(before.size()) + " landmarks before, " +
                std::to_string(after.size()) + " after.");
  if (!(radius > 0)) throw Error("Motion prediction: the radius must be positive.");
  const size_t m = before.size();
  if (m == 0) return points;
  if (m < 3)
  {
    Vec3 shift = Vec3::Zero();
    for (size_t l = 0; l < m; ++l) shift += (after[l] - before[l]) / static_cast<double>(m);
    return points.rowwise() + shift.transpose();
  }
  Points out(points.rows(), 3);
  const double scale = 1.0 / (2.0 * radius * radius);
  parallelFor(0, static_cast<int>(points.rows()),
              [&](int i)
              {
                const Vec3 p = points.row(i).transpose();
                std::vector<double> weight(m);
                double total = 0;
                for (size_t l = 0; l < m; ++l)
                  total += weight[l] = std::exp(-(p - before[l]).squaredNorm() * scale);
                // Far from every landmark the weights underflow: all landmarks, equally.
                if (!(total > 1e-12)) std::fill(weight.begin(), weight.end(), 1.0);
                Eigen::Matrix3d R;
                Vec3 t;
                rigidMotion(before, after, weight, R, t);
                out.row(i) = (R * p + t).transpose();
              });
  return out;
}

StartPrediction landmarkStartPrediction(
    const std::function<FramePtr(int)>& frames,
    const std::function<const std::vector<OrientedSurfacePoint>&(int)>& landmarks, double radius,
    const LandmarkPairFilter& trusted)
{
  return [=](int k, int from, const Points& fitOfFrom)
  {
    std::vector<Vec3> before, after;
    const FramePtr a = frames(from), b = frames(k);
    if (!a || !b)
      throw Error("Start prediction: frame " + std::to_string(!a ? from : k) + " is missing.");
    pairLandmarks(*a, landmarks(from), *b, landmarks(k), before, after);
    if (trusted)
    {
      const std::vector<bool> keep = trusted(before, after);
      size_t kept = 0;
      for (size_t i = 0; i < before.size(); ++i)
        if (keep.at(i))
        {
          before[kept] = before[i];
          after[kept++] = after[i];
        }
      before.resize(kept);
      after.resize(kept);
    }
    return predictMotion(fitOfFrom, before, after, radius);
  };
}
} // namespace clothtrack
