#pragma once
// The model's oriented anatomical points on a posed body: position, outward normal, and the
// tangent direction towards each landmark's direction vertex.
#include "BodyModel.h"
#include "LandmarkTransfer.h"

#include <vector>

namespace clothtrack
{
/// One oriented point per model landmark; `posed` has the model's connectivity.
std::vector<OrientedPoint> orientedLandmarks(const BodyModel& model, const TriangleMesh& posed);
} // namespace clothtrack
