#pragma once
// The one progress callback of every stage.
#include <functional>

namespace clothtrack
{
/// Called with the fraction of a stage's work done, in [0, 1]; returning false cancels the stage,
/// which then throws Error. An empty function reports nothing.
using StageProgress = std::function<bool(double)>;
} // namespace clothtrack
