#pragma once
// How far an aligned frame can be trusted without a ground truth. A template that lost its
// frame shows in one of four ways: it lies off the frame's surface (surface distance), part of
// the frame has no template near it (coverage distance: a limb the template missed), its
// triangles are stretched or squeezed (cloth barely stretches), or it is folded over itself (a
// template crumpled into a sheet keeps a small surface distance, so this has to be looked at
// separately). Each measure has a limit; a frame past any limit is doubtful, and says why.
#include <clothtrack/mesh/TriangleMesh.h>

#include <string>

namespace clothtrack
{
struct FrameConfidenceOptions
{
  double maximumSurfaceDistance = 0.02;  ///< metres, mean over the template's vertices
  double maximumCoverageDistance = 0.02; ///< metres, mean over the frame's vertices
  double maximumStretch = 0.35;          ///< mean |log(edge length / template's)|
  double maximumFoldedFraction = 0.025;  ///< edges folded (see FrameConfidence::folded)
};

struct FrameConfidence
{
  double surfaceDistance = 0.0;  ///< aligned template to the frame, mean, metres
  double coverageDistance = 0.0; ///< frame to the aligned template, mean, metres
  double stretch = 0.0;          ///< mean |log(edge length / the template's)|
  /// Fraction of the template's interior edges whose two triangles face more than 90 degrees
  /// further apart than on the template: folds the template did not have.
  double folded = 0.0;
  /// The largest measure relative to its limit: at most 1 is trusted.
  double severity = 0.0;
  /// 1 while every measure is within its limit, falling linearly to 0 at twice a limit
  /// (clamp(2 - severity, 0, 1)).
  double confidence = 1.0;
  std::string doubt; ///< empty, or the measures past their limits (e.g. "coverage 6.6 cm > 2 cm")
  bool doubtful() const { return !doubt.empty(); }
};

/// Measures frames against one template; the template's edges, lengths and fold angles are
/// computed once. Safe to use from several threads at once.
class ConfidenceMeter
{
public:
  /// `templateMesh`: the template as it was at the template frame (the aligned frames'
  /// connectivity).
  explicit ConfidenceMeter(const TriangleMesh& templateMesh,
                           const FrameConfidenceOptions& options = {});

  /// The template's vertices `aligned` in `frame`. `knownSurfaceDistance`, when not negative, is
  /// the surface distance already measured; `coverageSamples` (0: all) frame vertices, evenly
  /// spread, estimate the coverage distance.
  FrameConfidence operator()(const Points& aligned, const TriangleMesh& frame,
                             double knownSurfaceDistance = -1.0, int coverageSamples = 0) const;

  /// The stretch and folds alone (no frame needed): fills `stretch` and `folded`.
  void measureDistortion(const Points& aligned, FrameConfidence& confidence) const;

private:
  struct Edge
  {
    int a, b;        ///< vertices
    int left, right; ///< faces on either side (right -1 on a boundary)
    double length;   ///< on the template
    double angle;    ///< between the two faces' normals on the template, radians
  };
  Triangles faces_;
  int vertices_;
  std::vector<Edge> edges_;
  FrameConfidenceOptions options_;
};

/// ConfidenceMeter(templateMesh, options)(aligned, frame, knownSurfaceDistance): one frame.
FrameConfidence frameConfidence(const Points& aligned, const TriangleMesh& templateMesh,
                                const TriangleMesh& frame,
                                const FrameConfidenceOptions& options = {},
                                double knownSurfaceDistance = -1.0);

/// Sets `severity`, `confidence` and `doubt` from the four measures.
void judgeConfidence(FrameConfidence& confidence, const FrameConfidenceOptions& options = {});
} // namespace clothtrack
