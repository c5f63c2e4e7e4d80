#pragma once
// Sequences with ground truth shared by the benchmarks: synthetic captures, and a
// consistent-connectivity sequence (e.g. samba) either as it is or re-meshed by the capture
// simulator; stage 1 landmarks from the fitted (or true) body.
#include "ctCaptureSimulation.h"

#include <clothtrack/correspondence/PatchCorrespondence.h>

#include <chrono>
#include <string>
#include <vector>

namespace clothtrack::bench
{
/// Template vertices further than this from the true surface have no ground truth: the capture
/// closed a region cameras cannot see into (between the legs, inside a hem) with a surface of
/// its own. They are left out of the errors (two voxels of the simulated capture).
constexpr double kNoTruth = 0.03;

double seconds(std::chrono::steady_clock::time_point since);

struct Sequence
{
  std::vector<TriangleMesh> truth;    ///< consistent connectivity
  std::vector<TriangleMesh> captures; ///< the input: independent meshes
  /// Capture vertex -> truth surface point; empty when the captures are the truth themselves.
  std::vector<SourceMap> sources;
  std::vector<std::vector<OrientedSurfacePoint>> landmarks;

  /// True position in frame k of capture vertex v of frame j; false when v has no truth.
  bool truthOf(int j, int v, int k, Vec3& position) const;
};

/// Synthetic preset through the capture simulator; landmarks from the fitted body, or from the
/// true body when `trueLandmarks`.
Sequence syntheticSequence(const std::string& preset, int frames, bool trueLandmarks);
/// Every `stride`-th frame of a directory (at most `maxFrames`, 0: all), as it is or re-meshed.
Sequence directorySequence(const std::string& path, int stride, int maxFrames, bool remesh);
/// Stage 1 on the captures: fills s.landmarks.
void fitLandmarks(Sequence& s);
/// The automatically chosen template frame.
int chooseTemplate(const Sequence& s);
} // namespace clothtrack::bench
