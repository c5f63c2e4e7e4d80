#pragma once
// How far apart two surfaces lie: the mean distance from evenly spread vertices of each to the
// other surface, both ways. Consecutive frames of a capture lie within a few centimetres of each
// other even in fast motion (at most 4.5 cm on the sequences measured in BENCHMARKS.md); frames
// of unrelated poses lie tens of centimetres apart.
#include "SurfaceLocator.h"
#include "TriangleMesh.h"

namespace clothtrack
{
/// Symmetric mean closest-point distance between surfaces a and b (each with its locator), from
/// at most `samples` vertices of each (every vertex when fewer). Infinite when either is empty.
double meanSurfaceGap(const TriangleMesh& a, const SurfaceLocator& onA, const TriangleMesh& b,
                      const SurfaceLocator& onB, int samples = 1000);
} // namespace clothtrack
