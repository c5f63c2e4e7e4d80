#include "MeshTopology.h"

#include <algorithm>
#include <cstdint>
#include <numeric>

namespace clothtrack
{
namespace
{
Adjacency buildCsr(int size, const std::vector<std::pair<int, int>>& pairs)
{
  Adjacency adj;
  adj.offsets.assign(size + 1, 0);
  for (const auto& p : pairs) ++adj.offsets[p.first + 1];
  std::partial_sum(adj.offsets.begin(), adj.offsets.end(), adj.offsets.begin());
  adj.items.resize(pairs.size());
  std::vector<int> cursor(adj.offsets.begin(), adj.offsets.end() - 1);
  for (const auto& p : pairs) adj.items[cursor[p.first]++] = p.second;
  return adj;
}
} // namespace

MeshTopology buildTopology(const TriangleMesh& mesh)
{
  MeshTopology topo;
  const int nf = mesh.numFaces();
  const int nv = mesh.numVertices();

  // Sort half-edges by their undirected key; equal keys form one edge.
  struct HalfEdge
  {
    std::uint64_t key;
    int face;
    int side;
  };
  std::vector<HalfEdge> half(3 * static_cast<size_t>(nf));
  for (int f = 0; f < nf; ++f)
    for (int k = 0; k < 3; ++k)
    {
      int a = mesh.F(f, k), b = mesh.F(f, (k + 1) % 3);
      if (a > b) std::swap(a, b);
      half[3 * f + k] = {(static_cast<std::uint64_t>(a) << 32) | static_cast<std::uint32_t>(b), f,
                         k};
    }
  std::sort(half.begin(), half.end(),
            [](const HalfEdge& x, const HalfEdge& y)
            { return x.key != y.key ? x.key < y.key : x.face < y.face; });

  topo.faceEdges.assign(nf, {-1, -1, -1});
  std::vector<std::pair<int, int>> edgeFacePairs;
  edgeFacePairs.reserve(half.size());
  for (size_t i = 0; i < half.size(); ++i)
  {
    if (i == 0 || half[i].key != half[i - 1].key)
      topo.edges.push_back(
          {static_cast<int>(half[i].key >> 32), static_cast<int>(half[i].key & 0xffffffffu)});
    const int e = static_cast<int>(topo.edges.size()) - 1;
    topo.faceEdges[half[i].face][half[i].side] = e;
    edgeFacePairs.emplace_back(e, half[i].face);
  }
  topo.edgeFaces = buildCsr(topo.numEdges(), edgeFacePairs);

  std::vector<std::pair<int, int>> vv;
  vv.reserve(2 * topo.edges.size());
  for (const auto& e : topo.edges)
  {
    vv.emplace_back(e[0], e[1]);
    vv.emplace_back(e[1], e[0]);
  }
  topo.vertexVertices = buildCsr(nv, vv);

  std::vector<std::pair<int, int>> vf;
  vf.reserve(3 * static_cast<size_t>(nf));
  for (int f = 0; f < nf; ++f)
    for (int k = 0; k < 3; ++k) vf.emplace_back(mesh.F(f, k), f);
  topo.vertexFaces = buildCsr(nv, vf);
  return topo;
}

Adjacency faceFaceAdjacency(const MeshTopology& topology, int numFaces)
{
  std::vector<std::pair<int, int>> pairs;
  for (int e = 0; e < topology.numEdges(); ++e)
    for (const int* a = topology.edgeFaces.begin(e); a != topology.edgeFaces.end(e); ++a)
      for (const int* b = topology.edgeFaces.begin(e); b != topology.edgeFaces.end(e); ++b)
        if (a != b) pairs.emplace_back(*a, *b);
  return buildCsr(numFaces, pairs);
}

std::vector<std::vector<int>> boundaryLoops(const TriangleMesh& mesh, const MeshTopology& topology)
{
  // Orient each boundary edge like its face so that loops are walked consistently.
  std::vector<std::pair<int, int>> next; // from -> to
  for (int f = 0; f < mesh.numFaces(); ++f)
    for (int k = 0; k < 3; ++k)
      if (topology.isBoundaryEdge(topology.faceEdges[f][k]))
        next.emplace_back(mesh.F(f, k), mesh.F(f, (k + 1) % 3));
  const Adjacency outgoing = buildCsr(mesh.numVertices(), next);
  std::vector<int> used(outgoing.items.size(), 0);

  std::vector<std::vector<int>> loops;
  for (int start = 0; start < mesh.numVertices(); ++start)
    for (int slot = outgoing.offsets[start]; slot < outgoing.offsets[start + 1]; ++slot)
    {
      if (used[slot]) continue;
      std::vector<int> loop{start};
      used[slot] = 1;
      int v = outgoing.items[slot];
      while (v != start)
      {
        loop.push_back(v);
        int chosen = -1;
        for (int s = outgoing.offsets[v]; s < outgoing.offsets[v + 1]; ++s)
          if (!used[s])
          {
            chosen = s;
            break;
          }
        if (chosen < 0) break; // open chain: only possible with inconsistent orientation
        used[chosen] = 1;
        v = outgoing.items[chosen];
      }
      loops.push_back(std::move(loop));
    }
  return loops;
}

ManifoldReport checkManifold(const TriangleMesh& mesh, const MeshTopology& topology)
{
  ManifoldReport report;
  for (int e = 0; e < topology.numEdges(); ++e)
    if (topology.isNonManifoldEdge(e)) ++report.nonManifoldEdges;

  // A manifold vertex has its incident faces connected through edges that contain it.
  std::vector<int> label(mesh.numFaces(), -1);
  for (int v = 0; v < mesh.numVertices(); ++v)
  {
    const int deg = topology.vertexFaces.degree(v);
    if (deg <= 1) continue;
    const int* faces = topology.vertexFaces.begin(v);
    std::vector<int> stack{faces[0]};
    label[faces[0]] = v;
    int reached = 1;
    while (!stack.empty())
    {
      const int f = stack.back();
      stack.pop_back();
      for (int k = 0; k < 3; ++k)
      {
        const int e = topology.faceEdges[f][k];
        const auto& ed = topology.edges[e];
        if (ed[0] != v && ed[1] != v) continue;
        for (const int* g = topology.edgeFaces.begin(e); g != topology.edgeFaces.end(e); ++g)
          if (label[*g] != v)
          {
            label[*g] = v;
            ++reached;
            stack.push_back(*g);
          }
      }
    }
    if (reached != deg) ++report.nonManifoldVertices;
  }
  return report;
}
} // namespace clothtrack
