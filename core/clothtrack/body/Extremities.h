#pragma once
// Extremities of a surface: the tips of its protrusions (head, hands, feet on a body), found
// as the persistent maxima of the geodesic distance from the surface's centre. A maximum's
// persistence is how far the distance drops before its region merges with a higher one, so
// bumps of noise (a fold of cloth) vanish while limbs, which stick out far, remain.
#include <clothtrack/mesh/TriangleMesh.h>

#include <vector>

namespace clothtrack
{
struct Extremity
{
  int vertex = -1;
  double distance = 0.0;    ///< geodesic distance from the centre
  double persistence = 0.0; ///< drop of the distance before the region merges (inf for the top)
};

/// The vertex nearest to the area-weighted centroid of the largest connected component.
int centralVertex(const TriangleMesh& mesh);

/// Persistent maxima (persistence >= minPersistence, metres) of the edge-path geodesic distance
/// from centralVertex(), most distant first. Parts not connected to the centre are ignored.
std::vector<Extremity> geodesicExtremities(const TriangleMesh& mesh, double minPersistence = 0.15);
} // namespace clothtrack
