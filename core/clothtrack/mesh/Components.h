#pragma once
// Connected components (through shared edges) of a triangle mesh and their topology.
#include "MeshTopology.h"

#include <vector>

namespace clothtrack
{
struct ComponentInfo
{
  int numVertices = 0;
  int numEdges = 0;
  int numFaces = 0;
  int numBoundaries = 0;
  double area = 0.0;
  /// V - E + F.
  int eulerCharacteristic() const { return numVertices - numEdges + numFaces; }
  /// Genus of an orientable surface: chi = 2 - 2g - b.
  int genus() const { return (2 - eulerCharacteristic() - numBoundaries) / 2; }
};

struct Components
{
  /// Component of each face; faces sharing an edge share a component.
  std::vector<int> faceLabel;
  /// Component of each vertex, -1 for a vertex used by no face.
  std::vector<int> vertexLabel;
  /// Sorted by decreasing area: component 0 is the largest.
  std::vector<ComponentInfo> info;

  int count() const { return static_cast<int>(info.size()); }
};

Components connectedComponents(const TriangleMesh& mesh, const MeshTopology& topology);

/// Keep only the faces of one component; vertices are renumbered. oldVertexIds (optional)
/// receives the original index of each kept vertex.
TriangleMesh extractComponent(const TriangleMesh& mesh, const Components& components, int component,
                              std::vector<int>* oldVertexIds = nullptr);
} // namespace clothtrack
