#pragma once
// Error of an aligned sequence against a consistent-connectivity ground truth (the protocol of
// Shehu et al. 2016, section 5): each template vertex is tied, at the template frame, to its
// closest ground-truth surface point (triangle + barycentric; the vertex itself when the
// template frame is a ground-truth frame), and its error in frame k is the distance between the
// aligned vertex and that point's position in frame k.
#include <clothtrack/mesh/TriangleMesh.h>

#include <vector>

namespace clothtrack
{
/// Template vertex -> ground-truth surface point at the template frame.
struct TruthAnchors
{
  std::vector<int> face;    ///< -1: no ground truth (further than the limit)
  std::vector<Vec3> bary;   ///< barycentric coordinates in `face`
  Eigen::VectorXd distance; ///< template vertex to its anchor, metres
  int count() const;        ///< vertices with ground truth
};

struct TruthAnchorOptions
{
  /// Template vertices further than this from the ground truth at the template frame have no
  /// error (metres): e.g. surface a capture made up between the legs.
  double maximumTruthDistance = 0.03;
};

/// Ties every template vertex to the closest point of `truthAtTemplate`; vertices further than
/// `maxDistance` (metres) have no ground truth, e.g. surface a capture made up between the legs.
TruthAnchors anchorToTruth(const Points& templateVertices, const TriangleMesh& truthAtTemplate,
                           double maxDistance = TruthAnchorOptions{}.maximumTruthDistance);

/// Per-vertex error of `aligned` (the template's vertices in frame k) against `truthFrame`
/// (ground truth of frame k, same connectivity as the anchors' mesh); NaN without ground truth.
/// Throws Error when sizes disagree.
Eigen::VectorXd vertexErrors(const Points& aligned, const TriangleMesh& truthFrame,
                             const TruthAnchors& anchors);

/// Statistics of a set of errors (NaN entries are skipped), metres and fractions.
struct ErrorStatistics
{
  int count = 0;
  double mean = 0, median = 0, p90 = 0, max = 0;
  double within5cm = 0, within10cm = 0;
};
ErrorStatistics errorStatistics(const std::vector<double>& errors);
ErrorStatistics errorStatistics(const Eigen::VectorXd& errors);

/// Fraction of errors at or below each threshold (a cumulative error curve).
std::vector<double> cumulativeCurve(const std::vector<double>& errors,
                                    const std::vector<double>& thresholds);

/// A whole sequence's errors (one vector per frame, from vertexErrors).
struct SequenceErrors
{
  std::vector<ErrorStatistics> perFrame;
  /// Every vertex of every frame but the template frame, whose error is only that of the
  /// ground truth's own surface against the capture.
  ErrorStatistics pooled;
  int worstFrame = 0;       ///< highest per-frame mean
  double driftPerFrame = 0; ///< least-squares slope of the per-frame mean against |k - template|
  std::vector<double> thresholds, fractions; ///< cumulative curve of the pooled errors, 0-20 cm
};
SequenceErrors sequenceErrors(const std::vector<Eigen::VectorXd>& perFrame, int templateFrame);
} // namespace clothtrack
