#pragma once
// Checks and repairs applied to every mesh read from disk, so that later stages can rely on
// finite coordinates, valid indices and non-degenerate triangles.
#include "TriangleMesh.h"

#include <string>
#include <vector>

namespace clothtrack
{
struct CleaningOptions
{
  /// Vertices closer than this (relative to the bounding-box diagonal) are merged.
  double mergeTolerance = 1e-10;
  bool mergeDuplicateVertices = true;
  bool removeDegenerateFaces = true;
  bool removeUnusedVertices = true;
  /// validateAndClean only: drop faces beyond two per edge and split bow-tie vertices.
  bool makeManifold = true;
};

struct CleaningReport
{
  int mergedVertices = 0;
  int degenerateFaces = 0;
  int duplicateFaces = 0;
  int unusedVertices = 0;
  int nonManifoldFacesRemoved = 0;
  int bowTieVerticesSplit = 0;
  /// Human-readable lines for each repair made (empty when the mesh was already clean).
  std::vector<std::string> warnings;
};

/// Throws Error (message prefixed by `name`) on a mesh that cannot be repaired: no vertex or
/// no face, NaN or infinite coordinates, face indices out of range, no face left after
/// removing degenerate ones.
void validateMesh(const TriangleMesh& mesh, const std::string& name);

/// Merges duplicated vertices, drops zero-area and repeated faces and unused vertices.
/// vertexMap (optional) receives, for each input vertex, its index in the cleaned mesh (-1 if
/// dropped).
CleaningReport cleanMesh(TriangleMesh& mesh, const CleaningOptions& options = {},
                         std::vector<int>* vertexMap = nullptr);

/// validateMesh, then cleanMesh, then a final check that a usable surface remains.
CleaningReport validateAndClean(TriangleMesh& mesh, const std::string& name,
                                const CleaningOptions& options = {});
} // namespace clothtrack
