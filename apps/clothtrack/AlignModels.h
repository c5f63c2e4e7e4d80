#pragma once
// 'clothtrack align --model A --model B ...': the whole alignment under each body model, and one
// kept by its ground-truth-free figures (eval/ModelChoice.h: the first, unless another is both
// less stretched and closer to the frames).
//   OUT/models/<i>_<name>/   each model's alignment (its own work folder, metrics.json)
//   OUT/aligned.pvd, aligned/, body_fit.json, run.json   moved from the kept model's folder
//   OUT/metrics.json         the kept model's, with "model" and "model_choice" added
#include "AlignOptions.h"

#include <functional>

namespace clothtrack::app
{
/// Runs alignOnce under each of settings.modelPaths, then keeps one; returns the exit code.
int alignUnderEachModel(const AlignSettings& settings,
                        const std::function<int(const AlignSettings&)>& alignOnce);
} // namespace clothtrack::app
