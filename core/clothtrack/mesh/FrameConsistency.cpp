#include "FrameConsistency.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace clothtrack
{
namespace
{
double median(std::vector<double> values)
{
  if (values.empty()) return 0.0;
  const size_t middle = values.size() / 2;
  std::nth_element(values.begin(), values.begin() + middle, values.end());
  return values[middle];
}

/// "in a unit 1000 times smaller" when `ratio` is within 20 % of a power of ten, else "".
std::string unitHint(double ratio)
{
  const double decades = std::log10(ratio);
  const double nearest = std::round(decades);
  if (nearest == 0 || std::abs(decades - nearest) > std::log10(1.2)) return "";
  char text[96];
  std::snprintf(text, sizeof(text), " (a unit %g times %s?)", std::pow(10.0, std::abs(nearest)),
                nearest > 0 ? "smaller" : "larger");
  return text;
}
} // namespace

FrameExtent frameExtent(const TriangleMesh& mesh)
{
  FrameExtent e;
  if (mesh.numVertices() == 0) return e;
  e.size = std::sqrt(surfaceArea(mesh));
  const Vec3 low = mesh.V.colwise().minCoeff().transpose();
  const Vec3 high = mesh.V.colwise().maxCoeff().transpose();
  e.centre = 0.5 * (low + high);
  e.height = high.y() - low.y();
  return e;
}

std::vector<FrameJump> frameJumps(const std::vector<const TriangleMesh*>& frames,
                                  const ConsistencyOptions& options)
{
  std::vector<FrameExtent> extents;
  for (const TriangleMesh* frame : frames) extents.push_back(frameExtent(*frame));
  return frameJumps(extents, options);
}

std::vector<FrameJump> frameJumps(const std::vector<FrameExtent>& extents,
                                  const ConsistencyOptions& options)
{
  std::vector<double> sizes, heights;
  for (const FrameExtent& e : extents)
  {
    sizes.push_back(e.size);
    heights.push_back(e.height);
  }
  const double typicalSize = median(sizes), typicalHeight = median(heights);
  std::vector<FrameJump> jumps;
  if (!(typicalSize > 0)) return jumps;
  auto sizeOk = [&](size_t k)
  {
    const double r = extents[k].size / typicalSize;
    return r <= options.sizeTolerance && r >= 1 / options.sizeTolerance;
  };
  for (size_t k = 0; k < extents.size(); ++k)
  {
    FrameJump jump;
    jump.frame = static_cast<int>(k);
    jump.sizeRatio = extents[k].size / typicalSize;
    char text[512];
    if (!sizeOk(k))
    {
      jump.refused =
          jump.sizeRatio > options.sizeRefusal || jump.sizeRatio < 1 / options.sizeRefusal;
      std::snprintf(text, sizeof(text),
                    "its surface is %.3g times the size of the other frames'%s%s", jump.sizeRatio,
                    unitHint(jump.sizeRatio).c_str(),
                    jump.refused ? "" : ": another subject or scene in the frame? Check it");
      jump.problem = text;
    }
    // A frame of another size is its own problem; its neighbours' shifts would only repeat it.
    else if (k > 0 && sizeOk(k - 1))
    {
      jump.shift = (extents[k].centre - extents[k - 1].centre).norm();
      if (jump.shift > options.maximumShift * typicalHeight)
      {
        std::snprintf(text, sizeof(text),
                      "its centre is %.3g m from the previous frame's, more than a person moves "
                      "between two frames (%.2g m): another coordinate origin, or frames missing? "
                      "Check it",
                      jump.shift, options.maximumShift * typicalHeight);
        jump.problem = text;
      }
    }
    if (!jump.problem.empty()) jumps.push_back(jump);
  }
  return jumps;
}

std::string groundTruthMismatch(const TriangleMesh& input, const TriangleMesh& truth, bool& refused,
                                const ConsistencyOptions& options)
{
  refused = false;
  const FrameExtent a = frameExtent(input), b = frameExtent(truth);
  char text[512];
  const double ratio = a.size > 0 ? b.size / a.size : 0.0;
  if (!(ratio <= options.sizeTolerance && ratio >= 1 / options.sizeTolerance))
  {
    refused = !(ratio <= options.sizeRefusal && ratio >= 1 / options.sizeRefusal);
    std::snprintf(text, sizeof(text),
                  "the ground truth's surface is %.3g times the size of the "
                  "input frame's%s; %s",
                  ratio, unitHint(ratio).c_str(),
                  refused
                      ? "it is read with the input's --unit, --scale and --up: convert one of them"
                      : "is it the same subject? Check it");
    return text;
  }
  const double apart = (a.centre - b.centre).norm();
  if (apart > options.maximumShift * std::max(a.height, b.height))
  {
    std::snprintf(text, sizeof(text),
                  "the ground truth lies %.3g m from the input frame: the errors measure that "
                  "offset (another coordinate origin?)",
                  apart);
    return text;
  }
  return "";
}
} // namespace clothtrack
