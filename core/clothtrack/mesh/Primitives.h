#pragma once
// Analytic test surfaces with known geometry and topology.
#include "TriangleMesh.h"

namespace clothtrack
{
/// Icosahedron subdivided `level` times and projected on the sphere: 10 * 4^level + 2 vertices.
TriangleMesh icosphere(int level, double radius = 1.0, const Vec3& center = Vec3::Zero());
/// Torus around the z axis: major radius R, minor radius r, nu x nv grid (genus 1).
TriangleMesh torus(double R, double r, int nu, int nv);
/// Flat n x n grid of size width x width in the z = 0 plane (one boundary loop).
TriangleMesh grid(int n, double width);
/// Disjoint union: the faces of b are re-indexed after the vertices of a.
TriangleMesh concatenate(const TriangleMesh& a, const TriangleMesh& b);
} // namespace clothtrack
