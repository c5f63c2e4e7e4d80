#include "TemplateStage.h"

#include <clothtrack/base/Error.h>
#include <clothtrack/base/Parallel.h>

#include <string>

namespace clothtrack
{
TemplateSelection chooseTemplateFrame(const std::vector<const TriangleMesh*>& frames,
                                      const TemplateSelectionOptions& options,
                                      const std::vector<double>& restPoseDistance)
{
  return chooseTemplateFrame(FramesInMemory(frames), options, restPoseDistance);
}

TemplateSelection chooseTemplateFrame(const FrameSource& frames,
                                      const TemplateSelectionOptions& options,
                                      const std::vector<double>& restPoseDistance)
{
  std::vector<FrameTopology> topology(frames.count());
  parallelFor(
      0, frames.count(),
      [&](int k)
      {
        const FramePtr frame = frames.frame(k);
        if (!frame) throw Error("Template selection: frame " + std::to_string(k) + " is missing.");
        topology[k] = frameTopology(*frame, options.minimumShellArea);
      },
      1);
  TemplateSelection selection = selectTemplate(topology, options, restPoseDistance);
  selection.frames = std::move(topology);
  return selection;
}
} // namespace clothtrack
