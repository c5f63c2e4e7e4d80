#include "ManifoldRepair.h"

#include "MeshTopology.h"

#include <algorithm>
#include <vector>

namespace clothtrack
{
namespace
{
int removeExtraEdgeFaces(TriangleMesh& mesh, const MeshTopology& topo)
{
  std::vector<char> removed(mesh.numFaces(), 0);
  int count = 0;
  for (int e = 0; e < topo.numEdges(); ++e)
  {
    // Keep the first two faces still present on the edge.
    int kept = 0;
    for (const int* f = topo.edgeFaces.begin(e); f != topo.edgeFaces.end(e); ++f)
    {
      if (removed[*f]) continue;
      if (kept < 2)
        ++kept;
      else
      {
        removed[*f] = 1;
        ++count;
      }
    }
  }
  if (count == 0) return 0;
  Triangles faces(mesh.numFaces() - count, 3);
  int row = 0;
  for (int f = 0; f < mesh.numFaces(); ++f)
    if (!removed[f]) faces.row(row++) = mesh.F.row(f);
  mesh.F = faces;
  return count;
}

int splitBowTies(TriangleMesh& mesh, const MeshTopology& topo)
{
  std::vector<Vec3> extra;
  int splits = 0;
  std::vector<int> labels, stack; // reused from vertex to vertex
  for (int v = 0; v < mesh.numVertices(); ++v)
  {
    int fans = 0;
    // Label the faces around v by fan (faces connected through edges that contain v).
    labels.assign(topo.vertexFaces.degree(v), -1);
    const int* faces = topo.vertexFaces.begin(v);
    for (int s = 0; s < topo.vertexFaces.degree(v); ++s)
    {
      if (labels[s] >= 0) continue;
      stack.assign(1, s);
      labels[s] = fans;
      while (!stack.empty())
      {
        const int a = stack.back();
        stack.pop_back();
        for (int b = 0; b < topo.vertexFaces.degree(v); ++b)
        {
          if (labels[b] >= 0) continue;
          // Faces a and b share an edge through v when they share another vertex.
          int shared = 0;
          for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j)
              shared += mesh.F(faces[a], i) == mesh.F(faces[b], j) && mesh.F(faces[a], i) != v;
          if (shared > 0)
          {
            labels[b] = fans;
            stack.push_back(b);
          }
        }
      }
      ++fans;
    }
    // Every fan after the first gets its own copy of the vertex.
    for (int s = 0; s < topo.vertexFaces.degree(v); ++s)
    {
      if (labels[s] == 0) continue;
      const int copy = mesh.numVertices() + static_cast<int>(extra.size()) + labels[s] - 1;
      for (int c = 0; c < 3; ++c)
        if (mesh.F(faces[s], c) == v) mesh.F(faces[s], c) = copy;
    }
    for (int f = 1; f < fans; ++f) extra.push_back(mesh.vertex(v));
    splits += std::max(0, fans - 1); // an unused vertex has no fan
  }
  if (!extra.empty())
  {
    Points V(mesh.numVertices() + static_cast<int>(extra.size()), 3);
    V.topRows(mesh.numVertices()) = mesh.V;
    for (size_t i = 0; i < extra.size(); ++i)
      V.row(mesh.numVertices() + static_cast<int>(i)) = extra[i].transpose();
    mesh.V = V;
  }
  return splits;
}
} // namespace

ManifoldRepairReport makeManifold(TriangleMesh& mesh)
{
  ManifoldRepairReport report;
  // One topology serves both steps unless the first removed faces.
  const MeshTopology topo = buildTopology(mesh);
  report.removedFaces = removeExtraEdgeFaces(mesh, topo);
  report.splitVertices = splitBowTies(mesh, report.removedFaces > 0 ? buildTopology(mesh) : topo);
  return report;
}
} // namespace clothtrack
