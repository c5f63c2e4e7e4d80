#include "ModelChoice.h"

#include <clothtrack/base/Error.h>

#include <algorithm>
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
  const AlignmentFigures& first = figures.front();
  int kept = 0;
  double keptGain = margin;
  for (int i = 1; i < static_cast<int>(figures.size()); ++i)
  {
    const double gain = std::min(1.0 - figures[i].stretch / first.stretch,
                                 1.0 - figures[i].surfaceDistance / first.surfaceDistance);
    if (gain > keptGain)
    {
      kept = i;
      keptGain = gain;
    }
  }
  return kept;
}

namespace
{
/// The rule both choices share, after the words naming the alternatives.
std::string marginRule(double margin)
{
  const std::string percent = std::to_string(static_cast<int>(std::lround(100 * margin)));
  return "each by more than " + percent +
         " %: then the one whose smaller gain of the two is the largest";
}
} // namespace

std::string modelChoiceCriterion(double margin)
{
  return "the first model, unless others' alignments are both less stretched and closer to the "
         "frames than its alignment, " +
         marginRule(margin);
}

std::string templateChoiceCriterion(double margin)
{
  return "the template frame chosen by pose, unless the alignment under a further one is both "
         "less stretched and closer to the frames, " +
         marginRule(margin);
}
} // namespace clothtrack
