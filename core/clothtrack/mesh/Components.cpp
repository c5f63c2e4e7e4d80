#include "Components.h"

#include "TriangleMesh.h"

#include <algorithm>
#include <numeric>

namespace clothtrack
{
Components connectedComponents(const TriangleMesh& mesh, const MeshTopology& topology)
{
  const int nf = mesh.numFaces();
  std::vector<int> label(nf, -1);
  int count = 0;
  std::vector<int> stack;
  for (int seed = 0; seed < nf; ++seed)
  {
    if (label[seed] >= 0) continue;
    label[seed] = count;
    stack.push_back(seed);
    while (!stack.empty())
    {
      const int f = stack.back();
      stack.pop_back();
      for (int k = 0; k < 3; ++k)
      {
        const int e = topology.faceEdges[f][k];
        for (const int* g = topology.edgeFaces.begin(e); g != topology.edgeFaces.end(e); ++g)
          if (label[*g] < 0)
          {
            label[*g] = count;
            stack.push_back(*g);
          }
      }
    }
    ++count;
  }

  std::vector<ComponentInfo> info(count);
  const Eigen::VectorXd areas = faceAreas(mesh);
  for (int f = 0; f < nf; ++f)
  {
    info[label[f]].numFaces++;
    info[label[f]].area += areas[f];
  }
  // A vertex touching two components through a single point is counted in the first one
  // met: such pinched vertices are non-manifold and are reported by checkManifold.
  std::vector<int> vertexLabel(mesh.numVertices(), -1);
  for (int f = 0; f < nf; ++f)
    for (int k = 0; k < 3; ++k)
      if (vertexLabel[mesh.F(f, k)] < 0) vertexLabel[mesh.F(f, k)] = label[f];
  for (int v = 0; v < mesh.numVertices(); ++v)
    if (vertexLabel[v] >= 0) info[vertexLabel[v]].numVertices++;
  for (int e = 0; e < topology.numEdges(); ++e)
  {
    const int c = label[*topology.edgeFaces.begin(e)];
    info[c].numEdges++;
  }
  for (const auto& loop : boundaryLoops(mesh, topology))
    info[vertexLabel[loop.front()]].numBoundaries++;

  // Renumber by decreasing area.
  std::vector<int> order(count);
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(),
                   [&](int a, int b) { return info[a].area > info[b].area; });
  std::vector<int> rank(count);
  for (int i = 0; i < count; ++i) rank[order[i]] = i;

  Components result;
  result.info.resize(count);
  for (int i = 0; i < count; ++i) result.info[rank[i]] = info[i];
  result.faceLabel.resize(nf);
  for (int f = 0; f < nf; ++f) result.faceLabel[f] = rank[label[f]];
  result.vertexLabel.resize(mesh.numVertices());
  for (int v = 0; v < mesh.numVertices(); ++v)
    result.vertexLabel[v] = vertexLabel[v] < 0 ? -1 : rank[vertexLabel[v]];
  return result;
}

TriangleMesh extractComponent(const TriangleMesh& mesh, const Components& components, int component,
                              std::vector<int>* oldVertexIds)
{
  std::vector<int> newId(mesh.numVertices(), -1);
  std::vector<int> oldId;
  std::vector<int> keptFaces;
  for (int f = 0; f < mesh.numFaces(); ++f)
  {
    if (components.faceLabel[f] != component) continue;
    keptFaces.push_back(f);
    for (int k = 0; k < 3; ++k)
      if (newId[mesh.F(f, k)] < 0)
      {
        newId[mesh.F(f, k)] = static_cast<int>(oldId.size());
        oldId.push_back(mesh.F(f, k));
      }
  }
  TriangleMesh out;
  out.V.resize(static_cast<Eigen::Index>(oldId.size()), 3);
  for (size_t i = 0; i < oldId.size(); ++i)
    out.V.row(static_cast<Eigen::Index>(i)) = mesh.V.row(oldId[i]);
  out.F.resize(static_cast<Eigen::Index>(keptFaces.size()), 3);
  for (size_t i = 0; i < keptFaces.size(); ++i)
    for (int k = 0; k < 3; ++k)
      out.F(static_cast<Eigen::Index>(i), k) = newId[mesh.F(keptFaces[i], k)];
  if (oldVertexIds) *oldVertexIds = std::move(oldId);
  return out;
}
} // namespace clothtrack
