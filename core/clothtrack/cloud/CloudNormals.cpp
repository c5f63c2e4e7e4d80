#include "CloudNormals.h"
#include "PclConversion.h"

#include <pcl/features/normal_3d_omp.h>
#include <pcl/kdtree/kdtree_flann.h>
#include <pcl/search/kdtree.h>

#include <queue>

namespace clothtrack
{
namespace
{
/// The k nearest neighbours of every point (without itself).
std::vector<std::vector<int>> neighbourGraph(const pcl::PointCloud<pcl::PointXYZ>::Ptr& points,
                                             int k)
{
  pcl::KdTreeFLANN<pcl::PointXYZ> tree;
  tree.setInputCloud(points);
  const int n = static_cast<int>(points->size());
  std::vector<std::vector<int>> graph(n);
#pragma omp parallel for schedule(static)
  for (int i = 0; i < n; ++i)
  {
    pcl::Indices found;
    std::vector<float> distances;
    tree.nearestKSearch((*points)[i], k + 1, found, distances);
    for (const auto j : found)
      if (j != i) graph[i].push_back(j);
  }
  // Symmetric, so that the tree can reach a point from either side.
  for (int i = 0; i < n; ++i)
    for (const int j : std::vector<int>(graph[i]))
      if (std::find(graph[j].begin(), graph[j].end(), i) == graph[j].end()) graph[j].push_back(i);
  return graph;
}

/// Prim's algorithm over 1 - |ni . nj| from `seed`, flipping each reached normal to agree with
/// the one it is reached from. Returns the number of uncertain steps.
int propagateFrom(int seed, const std::vector<std::vector<int>>& graph, Points& normals,
                  std::vector<bool>& done)
{
  using Entry = std::tuple<double, int, int>; // cost, point, reached from
  std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> queue;
  queue.emplace(0.0, seed, -1);
  int uncertain = 0;
  while (!queue.empty())
  {
    const auto [cost, i, from] = queue.top();
    queue.pop();
    if (done[i]) continue;
    done[i] = true;
    if (from >= 0)
    {
      const double agreement = normals.row(i).dot(normals.row(from));
      if (agreement < 0) normals.row(i) *= -1;
      if (std::abs(agreement) < 0.5) ++uncertain;
    }
    for (const int j : graph[i])
      if (!done[j]) queue.emplace(1.0 - std::abs(normals.row(i).dot(normals.row(j))), j, i);
  }
  return uncertain;
}
} // namespace

void estimateNormals(PointCloud& cloud, const NormalOptions& options, NormalReport* report)
{
  const int n = cloud.size();
  auto points = toPclXYZ(cloud.P);
  pcl::NormalEstimationOMP<pcl::PointXYZ, pcl::Normal> estimation;
  estimation.setInputCloud(points);
  estimation.setSearchMethod(pcl::make_shared<pcl::search::KdTree<pcl::PointXYZ>>());
  estimation.setKSearch(std::min(options.neighbours, std::max(3, n - 1)));
  pcl::PointCloud<pcl::Normal> normals;
  estimation.compute(normals);
  cloud.N.resize(n, 3);
  std::vector<float> variation;
  variation.reserve(n);
  for (int i = 0; i < n; ++i)
  {
    const auto& m = normals[i];
    if (std::isfinite(m.curvature)) variation.push_back(m.curvature);
    if (std::isfinite(m.normal_x) && std::isfinite(m.normal_y) && std::isfinite(m.normal_z))
      cloud.N.row(i) << m.normal_x, m.normal_y, m.normal_z;
    else
      cloud.N.row(i) << 0, 1, 0;
  }

  const auto graph = neighbourGraph(points, std::min(options.orientationNeighbours, n - 1));
  const Vec3 centroid = cloud.P.colwise().mean().transpose();
  std::vector<bool> done(n, false);
  int uncertain = 0, trees = 0;
  // Seeds from the top down: the topmost point of each part faces up (the top of the head).
  std::vector<int> order(n);
  for (int i = 0; i < n; ++i) order[i] = i;
  std::sort(order.begin(), order.end(),
            [&](int a, int b) { return cloud.P(a, 1) > cloud.P(b, 1); });
  for (const int seed : order)
  {
    if (done[seed]) continue;
    ++trees;
    // A part's topmost point faces up; one that is no higher than the centre (a stray cluster)
    // faces away from the centre of the cloud.
    const Vec3 away = cloud.P.row(seed).transpose() - centroid;
    const Vec3 outward = trees == 1 ? Vec3::UnitY() : away;
    if (cloud.N.row(seed).dot(outward) < 0) cloud.N.row(seed) *= -1;
    uncertain += propagateFrom(seed, graph, cloud.N, done);
  }
  if (report)
  {
    if (!variation.empty())
    {
      std::nth_element(variation.begin(), variation.begin() + variation.size() / 2,
                       variation.end());
      report->medianSurfaceVariation = variation[variation.size() / 2];
    }
    report->uncertainShare = n > 1 ? static_cast<double>(uncertain) / (n - 1) : 0.0;
    report->trees = trees;
  }
}
} // namespace clothtrack
