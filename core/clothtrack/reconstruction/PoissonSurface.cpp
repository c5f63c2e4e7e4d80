#include "PoissonSurface.h"

#include <clothtrack/base/Error.h>
#include <clothtrack/cloud/PclConversion.h>

#include <pcl/common/io.h>
#include <pcl/point_cloud.h>
#include <pcl/point_types.h>
#include <pcl/surface/poisson.h>

#include <omp.h>

#include <cstdio>
#include <cstring>
#include <unistd.h>

namespace clothtrack
{
namespace
{
/// Runs `work` with standard output going to a temporary file, and returns how many lines it
/// printed that start with `prefix`. PCL's Poisson prints one line per iso-surface edge it
/// could not pair, on standard output, where the app's own results go.
template <class Work> int countPrintedLines(const char* prefix, Work&& work)
{
  std::fflush(stdout);
  std::FILE* capture = std::tmpfile();
  const int saved = capture ? ::dup(STDOUT_FILENO) : -1;
  if (saved < 0 || ::dup2(::fileno(capture), STDOUT_FILENO) < 0)
  {
    if (capture) std::fclose(capture);
    if (saved >= 0) ::close(saved);
    work();
    return 0;
  }
  struct Restore
  {
    int saved;
    ~Restore()
    {
      std::fflush(stdout);
      ::dup2(saved, STDOUT_FILENO);
      ::close(saved);
    }
  };
  {
    Restore restore{saved};
    work();
  }
  std::rewind(capture);
  int count = 0;
  char line[512];
  while (std::fgets(line, sizeof(line), capture))
    count += std::strncmp(line, prefix, std::strlen(prefix)) == 0;
  std::fclose(capture);
  return count;
}
} // namespace

TriangleMesh poissonSurface(const PointCloud& cloud, const PoissonOptions& options,
                            int* unpairedEdges)
{
  if (!cloud.hasNormals()) throw Error("Poisson reconstruction needs oriented normals");
  auto points = pcl::make_shared<pcl::PointCloud<pcl::PointNormal>>();
  pcl::copyPointCloud(*toPcl(cloud), *points);
  pcl::Poisson<pcl::PointNormal> poisson;
  poisson.setDepth(options.depth);
  poisson.setSamplesPerNode(static_cast<float>(options.samplesPerNode));
  poisson.setManifold(true);
  poisson.setThreads(options.threads > 0 ? options.threads : omp_get_max_threads());
  poisson.setInputCloud(points);
  pcl::PointCloud<pcl::PointNormal> vertices;
  std::vector<pcl::Vertices> polygons;
  const int unpaired = countPrintedLines("Vertex pair not in list",
                                         [&] { poisson.reconstruct(vertices, polygons); });
  if (unpairedEdges) *unpairedEdges = unpaired;

  TriangleMesh mesh;
  mesh.V.resize(static_cast<long>(vertices.size()), 3);
  for (size_t i = 0; i < vertices.size(); ++i)
    mesh.V.row(static_cast<long>(i)) << vertices[i].x, vertices[i].y, vertices[i].z;
  std::vector<int> faces;
  for (const auto& polygon : polygons)
    for (size_t k = 1; k + 1 < polygon.vertices.size(); ++k)
      faces.insert(faces.end(),
                   {static_cast<int>(polygon.vertices[0]), static_cast<int>(polygon.vertices[k]),
                    static_cast<int>(polygon.vertices[k + 1])});
  mesh.F = Eigen::Map<const Triangles>(faces.data(), static_cast<long>(faces.size() / 3), 3);
  return mesh;
}
} // namespace clothtrack
