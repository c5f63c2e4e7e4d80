#pragma once
// Stage 2b (Shehu et al. 2016, section 4.2): dense correspondences of the template on every
// frame, from geodesic patches grown around the landmark pairs.
#include <clothtrack/base/Progress.h>
#include <clothtrack/correspondence/PatchCorrespondence.h>
#include <clothtrack/mesh/FrameSource.h>

#include <functional>
#include <vector>

namespace clothtrack
{
/// The template frame's correspondence to itself: every vertex on itself.
FrameCorrespondence selfCorrespondence(const TriangleMesh& templateMesh);

/// Frame k of a sequence and its landmarks; called from several threads at once.
using FrameAccess = std::function<FramePtr(int k)>;
using LandmarkAccess = std::function<const std::vector<OrientedSurfacePoint>&(int k)>;

/// Correspondences of the template on the frames `which`, several frames at once (the template
/// frame, if listed, gets selfCorrespondence). `done(k, c)` receives each frame's result, in the
/// order of `which`, on the calling thread, as do progress calls: it keeps or writes it. Throws
/// Error when cancelled.
void correspondFrames(const TemplatePatches& patches, int templateFrame,
                      const std::vector<int>& which, const FrameAccess& frame,
                      const LandmarkAccess& landmarks,
                      const std::function<void(int, FrameCorrespondence&&)>& done,
                      const StageProgress& progress = {});
} // namespace clothtrack
