#include "Extremities.h"

#include <clothtrack/mesh/Components.h>
#include <clothtrack/mesh/Geodesic.h>
#include <clothtrack/mesh/MeshTopology.h>

#include <algorithm>
#include <numeric>

namespace clothtrack
{
int centralVertex(const TriangleMesh& mesh)
{
  if (mesh.numFaces() == 0) return -1;
  const MeshTopology topology = buildTopology(mesh);
  const Components components = connectedComponents(mesh, topology);
  const int largest = 0;
  const Eigen::VectorXd areas = faceAreas(mesh);
  Vec3 centroid = Vec3::Zero();
  double area = 0.0;
  for (int f = 0; f < mesh.numFaces(); ++f)
    if (components.faceLabel[f] == largest)
    {
      const Vec3 c =
          (mesh.vertex(mesh.F(f, 0)) + mesh.vertex(mesh.F(f, 1)) + mesh.vertex(mesh.F(f, 2))) / 3.0;
      centroid += areas[f] * c;
      area += areas[f];
    }
  if (area <= 0.0) return -1;
  centroid /= area;
  int best = -1;
  double bestDistance = std::numeric_limits<double>::infinity();
  for (int v = 0; v < mesh.numVertices(); ++v)
    if (components.vertexLabel[v] == largest)
    {
      const double d = (mesh.vertex(v) - centroid).squaredNorm();
      if (d < bestDistance) bestDistance = d, best = v;
    }
  return best;
}

std::vector<Extremity> geodesicExtremities(const TriangleMesh& mesh, double minPersistence)
{
  const int centre = centralVertex(mesh);
  if (centre < 0) return {};
  const WavefrontGeodesic geodesic(mesh, WavefrontGeodesic::Method::Dijkstra);
  const Eigen::VectorXd d = geodesic.distances({centre});
  const MeshTopology topology = buildTopology(mesh);

  // 0-dimensional persistence of the superlevel sets of d: sweep the vertices from the most
  // distant down; each vertex joins the regions of its already swept neighbours. When regions
  // meet, the one with the lower peak dies, its persistence being peak minus the current level.
  std::vector<int> order;
  for (int v = 0; v < mesh.numVertices(); ++v)
    if (d[v] != kUnreached) order.push_back(v);
  std::sort(order.begin(), order.end(), [&](int a, int b) { return d[a] > d[b]; });
  std::vector<int> parent(mesh.numVertices(), -1), peak(mesh.numVertices(), -1);
  auto root = [&](int v)
  {
    while (parent[v] != v) v = parent[v] = parent[parent[v]];
    return v;
  };
  std::vector<Extremity> found;
  for (int v : order)
  {
    parent[v] = v;
    peak[v] = v;
    for (const int* n = topology.vertexVertices.begin(v); n != topology.vertexVertices.end(v); ++n)
    {
      if (parent[*n] < 0) continue;
      int a = root(v), b = root(*n);
      if (a == b) continue;
      if (d[peak[a]] < d[peak[b]]) std::swap(a, b); // a keeps the higher peak
      const double persistence = d[peak[b]] - d[v];
      if (persistence >= minPersistence) found.push_back({peak[b], d[peak[b]], persistence});
      parent[b] = a;
    }
  }
  if (!order.empty())
    found.push_back(
        {peak[root(order.front())], d[order.front()], std::numeric_limits<double>::infinity()});
  std::sort(found.begin(), found.end(),
            [](const Extremity& a, const Extremity& b) { return a.distance > b.distance; });
  return found;
}
} // namespace clothtrack
