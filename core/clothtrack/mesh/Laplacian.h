#pragma once
// Discrete differential operators on triangle meshes.
#include "TriangleMesh.h"

#include <Eigen/SparseCore>

namespace clothtrack
{
using SparseMatrix = Eigen::SparseMatrix<double>;

/// Mixed Voronoi vertex areas (Meyer et al. 2003): Voronoi regions clipped at obtuse
/// triangles, so that the areas sum exactly to the surface area.
Eigen::VectorXd mixedVoronoiAreas(const TriangleMesh& mesh);

/// Cotangent Laplacian as a positive semi-definite matrix: L_ij = -(cot a + cot b)/2 for an
/// edge ij, L_ii = -sum_j L_ij.
SparseMatrix cotanLaplacian(const TriangleMesh& mesh);
} // namespace clothtrack
