#include "FrameConfidence.h"

#include <clothtrack/base/Error.h>
#include <clothtrack/mesh/SurfaceLocator.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>
#include <unordered_map>

namespace clothtrack
{
namespace
{
Vec3 faceNormal(const Points& V, const Triangles& F, int f)
{
  const Vec3 a = V.row(F(f, 0)), b = V.row(F(f, 1)), c = V.row(F(f, 2));
  return (b - a).cross(c - a);
}

/// How a measure is shown in a doubt.
enum class Shown
{
  Centimetres,
  Percent,
  Number
};

/// The angle between two directions, radians; nullopt when either is zero.
std::optional<double> angleBetween(const Vec3& a, const Vec3& b)
{
  const double scale = a.norm() * b.norm();
  if (!(scale > 0)) return std::nullopt;
  return std::acos(std::clamp(a.dot(b) / scale, -1.0, 1.0));
}

std::string show(double value, Shown shown)
{
  char text[32];
  if (shown == Shown::Centimetres)
    std::snprintf(text, sizeof(text), "%.1f cm", 100.0 * value);
  else if (shown == Shown::Percent)
    std::snprintf(text, sizeof(text), "%.1f %%", 100.0 * value);
  else
    std::snprintf(text, sizeof(text), "%.3f", value);
  return text;
}
} // namespace

ConfidenceMeter::ConfidenceMeter(const TriangleMesh& templateMesh,
                                 const FrameConfidenceOptions& options)
    : faces_(templateMesh.F), vertices_(templateMesh.numVertices()), options_(options)
{
  const Points& T = templateMesh.V;
  const Triangles& F = templateMesh.F;
  // Each undirected edge once, with the faces on its two sides.
  std::unordered_map<long long, int> index;
  index.reserve(static_cast<size_t>(F.rows()) * 2);
  for (int f = 0; f < F.rows(); ++f)
    for (int c = 0; c < 3; ++c)
    {
      const int a = std::min(F(f, c), F(f, (c + 1) % 3)), b = std::max(F(f, c), F(f, (c + 1) % 3));
      const long long key = static_cast<long long>(a) * vertices_ + b;
      auto [it, inserted] = index.try_emplace(key, static_cast<int>(edges_.size()));
      if (inserted)
        edges_.push_back({a, b, f, -1, (T.row(a) - T.row(b)).norm(), 0.0});
      else
        edges_[it->second].right = f;
    }
  const Points sides = sideDirections(T);
  for (Edge& e : edges_)
    if (e.right >= 0) e.angle = angleBetween(sides.row(e.left), sides.row(e.right)).value_or(0.0);
}

Points ConfidenceMeter::sideDirections(const Points& positions) const
{
  Points cornerNormals = Points::Zero(vertices_, 3);
  for (int f = 0; f < faces_.rows(); ++f)
  {
    const Vec3 n = faceNormal(positions, faces_, f);
    for (int c = 0; c < 3; ++c) cornerNormals.row(faces_(f, c)) += n;
  }
  Points sides(faces_.rows(), 3);
  for (int f = 0; f < faces_.rows(); ++f)
    sides.row(f) = cornerNormals.row(faces_(f, 0)) + cornerNormals.row(faces_(f, 1)) +
                   cornerNormals.row(faces_(f, 2));
  return sides;
}

void ConfidenceMeter::measureDistortion(const Points& aligned, FrameConfidence& confidence) const
{
  if (aligned.rows() != vertices_)
    throw Error("Frame confidence: " + std::to_string(aligned.rows()) +
                " aligned vertices for a template of " + std::to_string(vertices_) + ".");
  const Points sides = sideDirections(aligned);
  double stretchSum = 0.0;
  int stretched = 0, interior = 0, folded = 0;
  for (const Edge& e : edges_)
  {
    const double after = (aligned.row(e.a) - aligned.row(e.b)).norm();
    if (e.length > 0 && after > 0)
    {
      stretchSum += std::abs(std::log(after / e.length));
      ++stretched;
    }
    if (e.right < 0) continue;
    const std::optional<double> angle = angleBetween(sides.row(e.left), sides.row(e.right));
    if (!angle) continue;
    ++interior;
    folded += *angle - e.angle > M_PI / 2;
  }
  confidence.stretch = stretched ? stretchSum / stretched : 0.0;
  confidence.folded = interior ? static_cast<double>(folded) / interior : 0.0;
}

void ConfidenceMeter::measureBodyDistance(const Points& aligned, const Points& posedByBody,
                                          FrameConfidence& confidence) const
{
  if (posedByBody.rows() != aligned.rows())
    throw Error("Frame confidence: the template posed by the body has " +
                std::to_string(posedByBody.rows()) + " vertices, the aligned template " +
                std::to_string(aligned.rows()) + ".");
  confidence.bodyDistance = (aligned - posedByBody).rowwise().norm().mean();
  const Eigen::VectorXd height = aligned * options_.up, posedHeight = posedByBody * options_.up;
  confidence.extentGap = std::max(std::abs(height.minCoeff() - posedHeight.minCoeff()),
                                  std::abs(height.maxCoeff() - posedHeight.maxCoeff()));
}

FrameConfidence ConfidenceMeter::operator()(const Points& aligned, const TriangleMesh& frame,
                                            double knownSurfaceDistance, int coverageSamples,
                                            const Points* posedByBody) const
{
  FrameConfidence c;
  measureDistortion(aligned, c);
  if (posedByBody) measureBodyDistance(aligned, *posedByBody, c);
  const TriangleMesh alignedMesh{aligned, faces_};
  c.surfaceDistance = knownSurfaceDistance >= 0
                          ? knownSurfaceDistance
                          : meanClosestDistance(aligned, SurfaceLocator(frame));
  const long stride = coverageSamples > 0 ? std::max<long>(1, frame.V.rows() / coverageSamples) : 1;
  c.coverageDistance = meanClosestDistance(frame.V, SurfaceLocator(alignedMesh), stride);
  judgeConfidence(c, options_);
  return c;
}

void judgeConfidence(FrameConfidence& c, const FrameConfidenceOptions& options)
{
  struct Measure
  {
    const char* name;
    double value, limit;
    Shown shown;
    bool measured = true;
  };
  const Measure measures[] = {
      {"surface distance", c.surfaceDistance, options.maximumSurfaceDistance, Shown::Centimetres},
      {"coverage", c.coverageDistance, options.maximumCoverageDistance, Shown::Centimetres},
      {"stretch", c.stretch, options.maximumStretch, Shown::Number},
      {"folds", c.folded, options.maximumFoldedFraction, Shown::Percent},
      {"body distance", c.bodyDistance, options.maximumBodyDistance, Shown::Centimetres,
       c.bodyDistance >= 0},
      {"body extent", c.extentGap, options.maximumExtentGap, Shown::Centimetres, c.extentGap >= 0}};
  c.severity = 0.0;
  c.doubt.clear();
  for (const Measure& m : measures)
  {
    if (!m.measured || !(m.limit > 0)) continue;
    const double ratio = m.value / m.limit;
    c.severity = std::isnan(ratio) ? INFINITY : std::max(c.severity, ratio);
    if (!(ratio <= 1.0)) // NaN is doubtful too
      c.doubt += (c.doubt.empty() ? "" : ", ") + std::string(m.name) + " " +
                 show(m.value, m.shown) + " > " + show(m.limit, m.shown);
  }
  c.confidence = std::clamp(2.0 - c.severity, 0.0, 1.0);
}

FrameConfidence frameConfidence(const Points& aligned, const TriangleMesh& templateMesh,
                                const TriangleMesh& frame, const FrameConfidenceOptions& options,
                                double knownSurfaceDistance)
{
  return ConfidenceMeter(templateMesh, options)(aligned, frame, knownSurfaceDistance);
}
} // namespace clothtrack
