#pragma once
// Whether points lie inside a closed surface, by the parity of ray crossings. Three rays in
// unrelated directions vote, so that a ray grazing an edge or leaving through a small hole
// does not decide alone.
#include "SurfaceLocator.h"

namespace clothtrack
{
bool insideByRayParity(const SurfaceLocator& surface, const Vec3& point);

/// Fraction of the rows of `points` inside the surface (0 for no point).
double fractionInside(const SurfaceLocator& surface, const Points& points);
} // namespace clothtrack
