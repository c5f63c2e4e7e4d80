#pragma once
// What one frame's reconstruction cannot tell: whether the cameras saw all of the subject. A
// frame that lost part of the subject (a walk out of some cameras' field) still reconstructs as a
// clean surface, only a smaller one than its sequence's other frames.
#include <string>
#include <vector>

namespace clothtrack
{
/// One doubt per frame (empty when none): a frame whose reconstructed surface area is below
/// `minimumShare` of the median over the sequence's frames. Areas that are not positive
/// (frames not reconstructed) are left out of the median and get no doubt. Fewer than three
/// frames: no doubt.
std::vector<std::string> areaDoubts(const std::vector<double>& areas, double minimumShare = 0.8);
} // namespace clothtrack
