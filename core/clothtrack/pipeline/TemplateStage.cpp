#include "TemplateStage.h"

#include <clothtrack/base/Parallel.h>

namespace clothtrack
{
TemplateSelection chooseTemplateFrame(const std::vector<const TriangleMesh*>& frames,
                                      const TemplateSelectionOptions& options,
                                      const std::vector<double>& restPoseDistance)
{
  std::vector<FrameTopology> topology(frames.size());
  parallelFor(
      0, static_cast<int>(frames.size()),
      [&](int k) { topology[k] = frameTopology(*frames[k], options.minimumShellArea); }, 1);
  TemplateSelection selection = selectTemplate(topology, options, restPoseDistance);
  selection.frames = std::move(topology);
  return selection;
}
} // namespace clothtrack
