#pragma once
// Stage 2a (Shehu et al. 2016, section 4.2): the template frame, chosen by topology, then by the
// fitted body's pose or the paper's area ratio (see selection/TemplateSelection.h).
#include <clothtrack/mesh/FrameSource.h>
#include <clothtrack/selection/TemplateSelection.h>

#include <vector>

namespace clothtrack
{
/// Chooses the template among `frames` (frames side by side). `restPoseDistance`: one per frame
/// (restPoseDistances of the body stage), or empty when the body was not fitted.
TemplateSelection chooseTemplateFrame(const std::vector<const TriangleMesh*>& frames,
                                      const TemplateSelectionOptions& options = {},
                                      const std::vector<double>& restPoseDistance = {});
/// The same over frames read when needed (mesh/FrameSource.h).
TemplateSelection chooseTemplateFrame(const FrameSource& frames,
                                      const TemplateSelectionOptions& options = {},
                                      const std::vector<double>& restPoseDistance = {});
} // namespace clothtrack
