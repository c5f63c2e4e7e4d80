#pragma once
// 'clothtrack align' on a collection of unrelated poses: the whole alignment under the template
// frame chosen by pose, then under the next frames by pose, and one kept by its ground-truth-free
// figures (eval/ModelChoice.h: the first, unless another is both less stretched and closer to
// the frames). A body fitted to a frame with a limb left straight looks nearer the rest pose than
// the right fit would, so the pose alone can choose a template whose body is wrong, and every
// frame of a collection starts from that body (BENCHMARKS.md, "Collections of unrelated poses:
// the template chosen by the alignment").
//   OUT/templates/frame_<k>/   each further candidate's alignment (its own work folder)
//   OUT/aligned.pvd, aligned/, body_fit.json, run.json   the kept alignment's
//   OUT/metrics.json           the kept alignment's, with "template_choice" added
#include "AlignOptions.h"

#include <functional>

namespace clothtrack::app
{
/// Runs alignOnce, then, on a collection of poses (or with settings.templateCandidates above 1),
/// under the further template candidates, and keeps one; returns the exit code. A given
/// template, a partial run (correspond, fit) or several processes run alignOnce alone.
int alignChoosingTemplate(const AlignSettings& settings,
                          const std::function<int(const AlignSettings&)>& alignOnce);
} // namespace clothtrack::app
