#pragma once
// Combinatorial structure of a triangle mesh: unique edges with their incident faces, vertex
// and face adjacency in compressed (CSR) form, and boundary loops.
#include "TriangleMesh.h"

#include <array>
#include <vector>

namespace clothtrack
{
/// Compressed adjacency lists: the neighbours of item i are items[offsets[i] .. offsets[i+1]).
struct Adjacency
{
  std::vector<int> offsets;
  std::vector<int> items;

  int size() const { return offsets.empty() ? 0 : static_cast<int>(offsets.size()) - 1; }
  int degree(int i) const { return offsets[i + 1] - offsets[i]; }
  const int* begin(int i) const { return items.data() + offsets[i]; }
  const int* end(int i) const { return items.data() + offsets[i + 1]; }
};

struct MeshTopology
{
  /// Unique undirected edges (v0 < v1).
  std::vector<std::array<int, 2>> edges;
  /// Faces incident to each edge, in the order met.
  Adjacency edgeFaces;
  /// Edge of each face side k (from F(f,k) to F(f,(k+1)%3)).
  std::vector<std::array<int, 3>> faceEdges;
  /// Vertices sharing an edge with each vertex.
  Adjacency vertexVertices;
  /// Faces incident to each vertex.
  Adjacency vertexFaces;

  int numEdges() const { return static_cast<int>(edges.size()); }
  bool isBoundaryEdge(int e) const { return edgeFaces.degree(e) == 1; }
  bool isNonManifoldEdge(int e) const { return edgeFaces.degree(e) > 2; }
};

MeshTopology buildTopology(const TriangleMesh& mesh);

/// Faces sharing an edge with each face (non-manifold edges connect all their faces).
Adjacency faceFaceAdjacency(const MeshTopology& topology, int numFaces);

/// Closed loops of boundary edges, each as an ordered list of vertices. Edges of a
/// non-manifold boundary vertex are chained in the order met.
std::vector<std::vector<int>> boundaryLoops(const TriangleMesh& mesh, const MeshTopology& topology);

/// Number of edges shared by more than two faces, and of vertices whose faces do not form a
/// single fan (a "bow-tie").
struct ManifoldReport
{
  int nonManifoldEdges = 0;
  int nonManifoldVertices = 0;
  bool isManifold() const { return nonManifoldEdges == 0 && nonManifoldVertices == 0; }
};
ManifoldReport checkManifold(const TriangleMesh& mesh, const MeshTopology& topology);
} // namespace clothtrack
