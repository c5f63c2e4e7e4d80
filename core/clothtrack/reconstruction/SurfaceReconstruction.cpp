#include "SurfaceReconstruction.h"

#include <clothtrack/base/Error.h>
#include <clothtrack/io/PointCloudIO.h>
#include <clothtrack/mesh/Components.h>
#include <clothtrack/mesh/MeshValidation.h>
#include <clothtrack/mesh/PointIndex.h>
#include <clothtrack/mesh/SurfaceLocator.h>

#include <algorithm>
#include <chrono>
#include <cstdio>

namespace clothtrack
{
namespace
{
/// The faces whose `keep` flag is set, with the vertices they use renumbered.
TriangleMesh keepFaces(const TriangleMesh& mesh, const std::vector<bool>& keep)
{
  std::vector<int> newIndex(mesh.numVertices(), -1);
  std::vector<int> faces;
  int used = 0;
  for (int f = 0; f < mesh.numFaces(); ++f)
  {
    if (!keep[f]) continue;
    for (int k = 0; k < 3; ++k)
    {
      int& index = newIndex[mesh.F(f, k)];
      if (index < 0) index = used++;
      faces.push_back(index);
    }
  }
  TriangleMesh out;
  out.V.resize(used, 3);
  for (int v = 0; v < mesh.numVertices(); ++v)
    if (newIndex[v] >= 0) out.V.row(newIndex[v]) = mesh.V.row(v);
  out.F = Eigen::Map<const Triangles>(faces.data(), static_cast<long>(faces.size() / 3), 3);
  return out;
}

/// Faces of the smaller fans at each bow-tie vertex (a vertex whose faces form several fans, as
/// the crop leaves where it cuts across a thin part). Splitting such a vertex would put two
/// vertices at one place, which every reader merges again; the small fans are dropped instead.
/// Returns the number of faces dropped.
int dropSmallFans(TriangleMesh& mesh)
{
  int dropped = 0;
  for (int round = 0; round < 5; ++round)
  {
    const MeshTopology topology = buildTopology(mesh);
    std::vector<bool> keep(mesh.numFaces(), true);
    bool changed = false;
    for (int v = 0; v < mesh.numVertices(); ++v)
    {
      const std::vector<int> faces(topology.vertexFaces.begin(v), topology.vertexFaces.end(v));
      if (faces.size() < 2) continue;
      // Fans: faces around v joined when they share a second vertex (an edge through v).
      std::vector<int> fan(faces.size(), -1);
      int fans = 0;
      for (size_t seed = 0; seed < faces.size(); ++seed)
      {
        if (fan[seed] >= 0) continue;
        std::vector<size_t> stack = {seed};
        fan[seed] = fans;
        while (!stack.empty())
        {
          const size_t a = stack.back();
          stack.pop_back();
          for (size_t b = 0; b < faces.size(); ++b)
          {
            if (fan[b] >= 0) continue;
            int shared = 0;
            for (int i = 0; i < 3; ++i)
              for (int j = 0; j < 3; ++j) shared += mesh.F(faces[a], i) == mesh.F(faces[b], j);
            if (shared >= 2)
            {
              fan[b] = fans;
              stack.push_back(b);
            }
          }
        }
        ++fans;
      }
      if (fans < 2) continue;
      std::vector<int> size(fans, 0);
      for (const int f : fan) ++size[f];
      const int largest =
          static_cast<int>(std::max_element(size.begin(), size.end()) - size.begin());
      for (size_t i = 0; i < faces.size(); ++i)
        if (fan[i] != largest && keep[faces[i]])
        {
          keep[faces[i]] = false;
          ++dropped;
          changed = true;
        }
    }
    if (!changed) break;
    mesh = keepFaces(mesh, keep);
  }
  return dropped;
}

/// Seconds since `start`, and `start` moved to now.
double lap(std::chrono::steady_clock::time_point& start)
{
  const auto now = std::chrono::steady_clock::now();
  const double seconds = std::chrono::duration<double>(now - start).count();
  start = now;
  return seconds;
}

std::string percent(double share)
{
  char text[32];
  std::snprintf(text, sizeof(text), "%.1f %%", 100 * share);
  return text;
}

/// Topology and fit of the result, and the doubts they raise.
void describeResult(const TriangleMesh& mesh, const Points& cleaned, ReconstructionReport& report)
{
  report.vertices = mesh.numVertices();
  report.area = surfaceArea(mesh);
  report.faces = mesh.numFaces();
  const MeshTopology topology = buildTopology(mesh);
  const Components components = connectedComponents(mesh, topology);
  report.pieces = components.count();
  report.boundaryLoops = static_cast<int>(boundaryLoops(mesh, topology).size());
  report.genus = components.count() > 0 ? components.info[0].genus() : 0;
  const SurfaceLocator surface(mesh);
  const long stride = std::max<long>(1, cleaned.rows() / 20000);
  long far = 0, counted = 0;
  double sum = 0;
  for (long i = 0; i < cleaned.rows(); i += stride, ++counted)
  {
    const SurfacePoint closest = surface.closestPoint(cleaned.row(i).transpose());
    const double distance = closest.face >= 0 ? closest.distance : 1.0;
    sum += distance;
    far += distance > 0.01;
  }
  report.meanPointDistance = counted ? sum / counted : 0.0;
  report.unexplainedShare = counted ? static_cast<double>(far) / counted : 1.0;
  if (report.unexplainedShare > 0.05)
    report.doubts.push_back(percent(report.unexplainedShare) +
                            " of the points lie more than 1 cm from the surface");
  // Legs seen below a skirt are pieces of their own (nothing is seen inside it), and so can be
  // the skirt, cut from the waist where it meets the body in a crease; a result whose largest
  // piece is less than 30 % of it is in fragments.
  if (report.pieces > 1 && components.info[0].numFaces < 0.3 * report.faces)
    report.doubts.push_back(
        "the surface is in " + std::to_string(report.pieces) + " pieces, the largest holding " +
        percent(static_cast<double>(components.info[0].numFaces) / report.faces) + " of it");
  if (report.normals.uncertainShare > 0.05)
    report.doubts.push_back("normals turn sharply between neighbours for " +
                            percent(report.normals.uncertainShare) +
                            " of the points (parts closer than the point spacing?)");
}
} // namespace

TriangleMesh cropToPoints(const TriangleMesh& mesh, const Points& points, double distance,
                          double minimumPieceShare)
{
  const PointIndex index(points);
  std::vector<bool> near(mesh.numVertices());
#pragma omp parallel for schedule(static)
  for (int v = 0; v < mesh.numVertices(); ++v)
    near[v] = index.nearest(mesh.vertex(v)).distance <= distance;
  std::vector<bool> keep(mesh.numFaces());
  for (int f = 0; f < mesh.numFaces(); ++f)
    keep[f] = near[mesh.F(f, 0)] && near[mesh.F(f, 1)] && near[mesh.F(f, 2)];
  TriangleMesh cropped = keepFaces(mesh, keep);
  if (cropped.numFaces() == 0) return cropped;
  const MeshTopology topology = buildTopology(cropped);
  const Components components = connectedComponents(cropped, topology);
  std::vector<bool> large(cropped.numFaces());
  for (int f = 0; f < cropped.numFaces(); ++f)
    large[f] =
        components.info[components.faceLabel[f]].numFaces >= minimumPieceShare * cropped.numFaces();
  return keepFaces(cropped, large);
}

TriangleMesh reconstructSurface(const PointCloud& input, const std::string& name,
                                const ReconstructionOptions& options, ReconstructionReport* out,
                                const StageProgress& progress)
{
  auto done = [&](double share)
  {
    if (progress && !progress(share)) throw Error(name + ": reconstruction cancelled");
  };
  ReconstructionReport report;
  auto clock = std::chrono::steady_clock::now();
  PointCloud cloud = input;
  report.inputPoints = input.size();
  report.invalidPoints = dropInvalidPoints(cloud, name, options.minimumPoints);
  cloud = cleanCloud(cloud, options.cleaning, &report.cleaning);
  if (cloud.size() < options.minimumPoints)
    throw Error(name + ": only " + std::to_string(cloud.size()) + " of the " +
                std::to_string(report.inputPoints) +
                " points are left after outlier removal and thinning, too few for a surface");
  report.cleaningSeconds = lap(clock);
  done(0.15);
  report.givenNormals = cloud.hasNormals();
  PointCloud oriented = cloud;
  estimateNormals(oriented, options.normals, &report.normals);
  if (report.givenNormals) oriented.N = cloud.N;
  // A surface's neighbourhoods are flat (variation near 0); points filling a volume give 1/3.
  if (report.normals.medianSurfaceVariation > 0.15)
    throw Error(name + ": the points do not lie on a surface (median surface variation " +
                std::to_string(report.normals.medianSurfaceVariation) +
                ", a surface gives under 0.05): is this a capture of a person, or noise?");
  report.normalSeconds = lap(clock);
  done(0.35);
  const TriangleMesh closed = poissonSurface(oriented, options.poisson, &report.unpairedEdges);
  report.poissonVertices = closed.numVertices();
  report.poissonFaces = closed.numFaces();
  report.poissonSeconds = lap(clock);
  done(0.9);
  TriangleMesh mesh =
      cropToPoints(closed, cloud.P, options.cropDistance, options.minimumPieceShare);
  if (mesh.numFaces() == 0)
    throw Error(name + ": the reconstructed surface lies nowhere near the points");
  // The crop can leave two fans of faces on one vertex (a bow tie) and slivers; repaired here
  // rather than warned about on every frame the pipeline reads.
  report.droppedFanFaces = dropSmallFans(mesh);
  const CleaningReport repairs = validateAndClean(mesh, name);
  report.repairedVertices = repairs.bowTieVerticesSplit + repairs.mergedVertices;
  describeResult(mesh, cloud.P, report);
  report.cropSeconds = lap(clock);
  done(1.0);
  if (out) *out = report;
  return mesh;
}
} // namespace clothtrack
