#include "AlignmentError.h"

#include <clothtrack/base/Error.h>
#include <clothtrack/base/Parallel.h>
#include <clothtrack/mesh/SurfaceLocator.h>
#include <clothtrack/mesh/SurfacePoint.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace clothtrack
{
int TruthAnchors::count() const
{
  return static_cast<int>(std::count_if(face.begin(), face.end(), [](int f) { return f >= 0; }));
}

TruthAnchors anchorToTruth(const Points& templateVertices, const TriangleMesh& truthAtTemplate,
                           double maxDistance)
{
  if (truthAtTemplate.numFaces() == 0) throw Error("Alignment error: the ground truth is empty.");
  if (!templateVertices.allFinite())
    throw Error("Alignment error: the template has non-finite vertices.");
  const int n = static_cast<int>(templateVertices.rows());
  TruthAnchors anchors;
  anchors.face.assign(n, -1);
  anchors.bary.assign(n, Vec3::Zero());
  anchors.distance = Eigen::VectorXd::Constant(n, std::numeric_limits<double>::infinity());
  const SurfaceLocator locator(truthAtTemplate);
  parallelFor(0, n,
              [&](int i)
              {
                const SurfacePoint p =
                    locator.closestPoint(templateVertices.row(i).transpose(), maxDistance);
                if (!p.valid()) return;
                anchors.face[i] = p.face;
                anchors.bary[i] = p.bary;
                anchors.distance[i] = p.distance;
              });
  return anchors;
}

Eigen::VectorXd vertexErrors(const Points& aligned, const TriangleMesh& truthFrame,
                             const TruthAnchors& anchors)
{
  const int n = static_cast<int>(aligned.rows());
  if (n != static_cast<int>(anchors.face.size()))
    throw Error("Alignment error: " + std::to_string(n) + " aligned vertices but " +
                std::to_string(anchors.face.size()) + " anchored template vertices.");
  Eigen::VectorXd errors(n);
  for (int i = 0; i < n; ++i)
  {
    const int f = anchors.face[i];
    if (f < 0)
    {
      errors[i] = std::numeric_limits<double>::quiet_NaN();
      continue;
    }
    if (f >= truthFrame.numFaces())
      throw Error("Alignment error: a ground-truth frame has fewer triangles than the one at "
                  "the template frame (its connectivity must be the same in every frame).");
    errors[i] =
        (aligned.row(i).transpose() - surfacePosition(truthFrame, f, anchors.bary[i])).norm();
  }
  return errors;
}

ErrorStatistics errorStatistics(const std::vector<double>& errors)
{
  std::vector<double> e;
  e.reserve(errors.size());
  for (double x : errors)
    if (!std::isnan(x)) e.push_back(x);
  ErrorStatistics s;
  s.count = static_cast<int>(e.size());
  if (e.empty()) return s;
  double sum = 0;
  for (double x : e)
  {
    sum += x;
    s.max = std::max(s.max, x);
    s.within5cm += x <= 0.05;
    s.within10cm += x <= 0.10;
  }
  s.mean = sum / s.count;
  s.within5cm /= s.count;
  s.within10cm /= s.count;
  auto quantile = [&](double q)
  {
    const size_t k = std::min(e.size() - 1, static_cast<size_t>(q * (e.size() - 1) + 0.5));
    std::nth_element(e.begin(), e.begin() + k, e.end());
    return e[k];
  };
  s.median = quantile(0.5);
  s.p90 = quantile(0.9);
  return s;
}

ErrorStatistics errorStatistics(const Eigen::VectorXd& errors)
{
  return errorStatistics(std::vector<double>(errors.data(), errors.data() + errors.size()));
}

std::vector<double> cumulativeCurve(const std::vector<double>& errors,
                                    const std::vector<double>& thresholds)
{
  std::vector<double> e;
  for (double x : errors)
    if (!std::isnan(x)) e.push_back(x);
  std::sort(e.begin(), e.end());
  std::vector<double> fractions;
  for (double t : thresholds)
    fractions.push_back(
        e.empty()
            ? 0.0
            : static_cast<double>(std::upper_bound(e.begin(), e.end(), t) - e.begin()) / e.size());
  return fractions;
}

SequenceErrors sequenceErrors(const std::vector<Eigen::VectorXd>& perFrame, int templateFrame)
{
  const int n = static_cast<int>(perFrame.size());
  SequenceErrors out;
  std::vector<double> pooled;
  for (int k = 0; k < n; ++k)
  {
    out.perFrame.push_back(errorStatistics(perFrame[k]));
    if (k != templateFrame)
      pooled.insert(pooled.end(), perFrame[k].data(), perFrame[k].data() + perFrame[k].size());
    if (out.perFrame[k].mean > out.perFrame[out.worstFrame].mean) out.worstFrame = k;
  }
  out.pooled = errorStatistics(pooled);
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  for (int k = 0; k < n; ++k)
  {
    const double x = std::abs(k - templateFrame), y = out.perFrame[k].mean;
    sx += x, sy += y, sxx += x * x, sxy += x * y;
  }
  const double denominator = n * sxx - sx * sx;
  out.driftPerFrame = denominator > 0 ? (n * sxy - sx * sy) / denominator : 0.0;
  for (int t = 0; t <= 40; ++t) out.thresholds.push_back(0.005 * t);
  out.fractions = cumulativeCurve(pooled, out.thresholds);
  return out;
}
} // namespace clothtrack
