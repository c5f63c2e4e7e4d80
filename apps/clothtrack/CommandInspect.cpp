// clothtrack inspect: per-frame geometry and topology of a sequence, the facts that decide how
// hard it is to align (components, genus, holes, non-manifold parts).
#include "Commands.h"
#include "Options.h"
#include "Progress.h"

#include "ctMeshConversion.h"

#include <clothtrack/Components.h>
#include <clothtrack/FrameList.h>
#include <clothtrack/Laplacian.h>

#include <Eigen/Geometry>

#include <cstdio>
#include <filesystem>
#include <fstream>

namespace clothtrack::app
{
int runInspect(const Args& args)
{
  std::string input, csvPath;
  SequenceOptions seq;
  double minShellArea = 0.1;
  po::options_description options("inspect options");
  options.add_options()("input", po::value(&input)->required(),
                        "folder, glob pattern, list file or mesh file")(
      "min-shell-area", po::value(&minShellArea)->default_value(0.1),
      "components smaller than this (m^2) are not counted as body parts")(
      "csv", po::value(&csvPath), "also write the table as CSV to this file");
  addSequenceOptions(options, seq);
  po::positional_options_description positional;
  positional.add("input", 1);
  po::variables_map values;
  if (!parseOptions(args, "clothtrack inspect INPUT [options]", options, positional, values))
    return 0;
  const FrameConventions conventions = toConventions(seq);

  const std::vector<std::string> frames = listFrames(input);
  std::FILE* csv = nullptr;
  if (!csvPath.empty() && !(csv = std::fopen(csvPath.c_str(), "w")))
    throw UsageError{csvPath + ": cannot write file"};
  const char* header =
      "frame,file,vertices,faces,components,shells,genus_largest,boundaries_largest,"
      "area_m2,height_m,area_ratio,non_manifold_edges";
  if (csv) std::fprintf(csv, "%s\n", header);
  std::printf("%5s %-24s %8s %8s %5s %6s %5s %5s %8s %7s %10s %4s\n", "frame", "file", "verts",
              "faces", "comp", "shells", "genus", "holes", "area", "height", "area_ratio", "nme");
  Progress progress("inspect", static_cast<int>(frames.size()));
  for (size_t k = 0; k < frames.size(); ++k)
  {
    std::vector<std::string> warnings;
    const TriangleMesh mesh = loadFrame(frames[k], conventions, &warnings);
    for (const auto& w : warnings) std::fprintf(stderr, "warning: %s\n", w.c_str());
    const MeshTopology topology = buildTopology(mesh);
    const Components comps = connectedComponents(mesh, topology);
    const ManifoldReport manifold = checkManifold(mesh, topology);
    int shells = 0;
    for (const auto& c : comps.info) shells += c.area >= minShellArea ? 1 : 0;
    // Area ratio of the largest component: max / min mixed Voronoi vertex area.
    const TriangleMesh largest = extractComponent(mesh, comps, 0);
    const Eigen::VectorXd areas = mixedVoronoiAreas(largest);
    const double ratio = areas.minCoeff() > 0 ? areas.maxCoeff() / areas.minCoeff() : INFINITY;
    const double height = mesh.V.col(1).maxCoeff() - mesh.V.col(1).minCoeff();
    const auto& big = comps.info[0];
    const std::string name = std::filesystem::path(frames[k]).filename().string();
    std::printf("%5zu %-24.24s %8d %8d %5d %6d %5d %5d %8.4f %7.3f %10.1f %4d\n", k, name.c_str(),
                mesh.numVertices(), mesh.numFaces(), comps.count(), shells, big.genus(),
                big.numBoundaries, surfaceArea(mesh), height, ratio, manifold.nonManifoldEdges);
    if (csv)
      std::fprintf(csv, "%zu,%s,%d,%d,%d,%d,%d,%d,%.6f,%.6f,%.4f,%d\n", k, name.c_str(),
                   mesh.numVertices(), mesh.numFaces(), comps.count(), shells, big.genus(),
                   big.numBoundaries, surfaceArea(mesh), height, ratio, manifold.nonManifoldEdges);
    progress.step(static_cast<int>(k + 1));
  }
  progress.finish();
  if (csv && std::fclose(csv) != 0) throw UsageError{csvPath + ": write error"};
  return 0;
}
} // namespace clothtrack::app
