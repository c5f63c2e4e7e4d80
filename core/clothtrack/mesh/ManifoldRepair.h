#pragma once
// Repairs that make a triangle mesh manifold, so that topology (components, genus, boundaries)
// is well defined: faces beyond the first two on an edge are removed, then a vertex whose faces
// form several fans ("bow-tie") is split into one vertex per fan.
#include "TriangleMesh.h"

namespace clothtrack
{
struct ManifoldRepairReport
{
  int removedFaces = 0;  ///< faces dropped from edges shared by more than two faces
  int splitVertices = 0; ///< vertex copies added at bow-ties
};

ManifoldRepairReport makeManifold(TriangleMesh& mesh);
} // namespace clothtrack
