#include "SequenceCoverage.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace clothtrack
{
std::vector<std::string> areaDoubts(const std::vector<double>& areas, double minimumShare)
{
  std::vector<std::string> doubts(areas.size());
  std::vector<double> known;
  for (double a : areas)
    if (a > 0) known.push_back(a);
  if (known.size() < 3) return doubts;
  std::nth_element(known.begin(), known.begin() + known.size() / 2, known.end());
  const double median = known[known.size() / 2];
  for (size_t k = 0; k < areas.size(); ++k)
  {
    if (!(areas[k] > 0) || areas[k] >= minimumShare * median) continue;
    char text[200];
    std::snprintf(text, sizeof text,
                  "surface area %.2f m^2, %.0f %% of the sequence's median: part of the subject "
                  "was not seen (out of the cameras' field?)",
                  areas[k], 100.0 * areas[k] / median);
    doubts[k] = text;
  }
  return doubts;
}
} // namespace clothtrack
