#include "ModelChoice.h"

#include <clothtrack/base/Error.h>

#include <cmath>

namespace clothtrack
{
double meanOverFrames(const std::vector<double>& perFrame)
{
  double sum = 0.0;
  int frames = 0;
  for (double value : perFrame)
    if (std::isfinite(value))
    {
      sum += value;
      ++frames;
    }
  if (frames == 0) throw Error("model choice: an alignment has no frame with the figure");
  return sum / frames;
}

int preferredAlignment(const std::vector<AlignmentFigures>& figures, double margin)
{
  if (figures.empty()) throw Error("model choice: no alignment to choose from");
  int kept = 0;
  for (int i = 1; i < static_cast<int>(figures.size()); ++i)
  {
    const AlignmentFigures& best = figures[kept];
    if (figures[i].stretch < best.stretch * (1.0 - margin) &&
        figures[i].surfaceDistance < best.surfaceDistance * (1.0 - margin))
      kept = i;
  }
  return kept;
}
} // namespace clothtrack
