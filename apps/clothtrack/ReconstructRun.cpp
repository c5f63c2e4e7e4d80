#include "ReconstructRun.h"
#include "CaptureOutput.h"
#include "Progress.h"
#include "TextFile.h"

#include "ctPointCloudFile.h"

#include <vtkPolyData.h>

#include <clothtrack/base/Error.h>
#include <clothtrack/reconstruction/SequenceCoverage.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>

namespace fs = std::filesystem;

namespace clothtrack::app
{
namespace
{
nlohmann::json reportJson(const std::string& cloud, const ReconstructionReport& r, double seconds)
{
  return {{"cloud", cloud},
          {"points", r.inputPoints},
          {"invalid_points", r.invalidPoints},
          {"outliers", r.cleaning.outliers},
          {"thinned_points", r.cleaning.output},
          {"given_normals", r.givenNormals},
          {"normal_uncertain_share", r.normals.uncertainShare},
          {"surface_variation", r.normals.medianSurfaceVariation},
          {"poisson_faces", r.poissonFaces},
          {"poisson_unpaired_edges", r.unpairedEdges},
          {"vertices", r.vertices},
          {"faces", r.faces},
          {"dropped_fan_faces", r.droppedFanFaces},
          {"repaired_vertices", r.repairedVertices},
          {"pieces", r.pieces},
          {"boundary_loops", r.boundaryLoops},
          {"genus", r.genus},
          {"area_m2", r.area},
          {"mean_point_distance_m", r.meanPointDistance},
          {"unexplained_share", r.unexplainedShare},
          {"doubts", r.doubts},
          {"seconds", seconds},
          {"seconds_per_step",
           {{"cleaning", r.cleaningSeconds},
            {"normals", r.normalSeconds},
            {"poisson", r.poissonSeconds},
            {"crop", r.cropSeconds}}}};
}

bool upToDate(const std::string& mesh, const std::string& cloud)
{
  std::error_code ec;
  return fs::exists(mesh, ec) && fs::last_write_time(mesh, ec) >= fs::last_write_time(cloud, ec);
}

/// Everything that decides a reconstructed mesh: meshes made with other options are redone.
nlohmann::json optionsKey(const ReconstructSettings& settings)
{
  const ReconstructionOptions& o = settings.options;
  return {{"cleaning",
           {o.cleaning.outlierNeighbours, o.cleaning.outlierDeviations, o.cleaning.voxelSize}},
          {"normals", {o.normals.neighbours, o.normals.orientationNeighbours}},
          {"poisson", {o.poisson.depth, o.poisson.samplesPerNode}},
          {"crop", {o.cropDistance, o.minimumPieceShare, o.minimumPoints}},
          {"conventions", {settings.conventions.unitScale, settings.conventions.upAxis}}};
}

/// The records of an earlier run into `folder` with the same options, by cloud file.
std::map<std::string, nlohmann::json> earlierRecords(const std::string& folder,
                                                     const nlohmann::json& key)
{
  std::map<std::string, nlohmann::json> records;
  std::ifstream in(fs::path(folder) / "reconstruction.json");
  const nlohmann::json earlier = nlohmann::json::parse(in, nullptr, false);
  if (earlier.is_discarded() || !earlier.contains("options") || earlier["options"] != key ||
      !earlier.contains("frames") || !earlier["frames"].is_array())
    return records;
  for (const auto& record : earlier["frames"])
    if (record.contains("cloud") && record["cloud"].is_string())
      records[record["cloud"].get<std::string>()] = record;
  return records;
}

/// Reconstructs one cloud into `mesh`; its record for reconstruction.json.
nlohmann::json reconstructOne(const std::string& cloud, const std::string& mesh,
                              const ReconstructSettings& settings)
{
  const auto start = std::chrono::steady_clock::now();
  ReconstructionReport report;
  const TriangleMesh surface = reconstructSurface(loadPointCloud(cloud, settings.conventions),
                                                  cloud, settings.options, &report);
  writeMeshFile(mesh, toPolyData(surface));
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  for (const std::string& doubt : report.doubts)
    std::fprintf(stderr, "\nwarning: %s: doubtful reconstruction: %s\n", cloud.c_str(),
                 doubt.c_str());
  return reportJson(cloud, report, seconds);
}

/// Frames whose surface is much smaller than the sequence's others (areaDoubts) get a
/// `sequence_doubts` entry and a warning; returns how many of them had no doubt before.
int doubtSmallFrames(nlohmann::json& frames)
{
  std::vector<double> areas;
  for (const nlohmann::json& f : frames) areas.push_back(f.value("area_m2", 0.0));
  const std::vector<std::string> doubts = areaDoubts(areas);
  int newlyDoubtful = 0;
  for (size_t k = 0; k < doubts.size(); ++k)
  {
    nlohmann::json& f = frames[k];
    f["sequence_doubts"] = nlohmann::json::array();
    if (doubts[k].empty()) continue;
    f["sequence_doubts"].push_back(doubts[k]);
    newlyDoubtful += f.value("doubts", nlohmann::json::array()).empty();
    std::fprintf(stderr, "warning: %s: doubtful reconstruction: %s\n",
                 f.value("cloud", std::string()).c_str(), doubts[k].c_str());
  }
  return newlyDoubtful;
}
} // namespace

void addReconstructionOptions(po::options_description& options, ReconstructionOptions& values)
{
  options.add_options()("cloud-voxel", po::value(&values.cleaning.voxelSize)->default_value(0.005),
                        "point clouds: voxel-grid thinning, metres (0 keeps every point)")(
      "cloud-outlier-neighbours", po::value(&values.cleaning.outlierNeighbours)->default_value(16),
      "point clouds: neighbours of the statistical outlier test (0: no test)")(
      "cloud-outlier-deviations", po::value(&values.cleaning.outlierDeviations)->default_value(2.0),
      "point clouds: a point whose neighbours lie this many deviations further than usual goes")(
      "poisson-depth", po::value(&values.poisson.depth)->default_value(7),
      "point clouds: Poisson octree depth (7: cells of about 1.5 cm for a person, about 11k "
      "vertices)")("crop", po::value(&values.cropDistance)->default_value(0.02),
                   "point clouds: surface further than this from every point is cut away, metres");
}

std::vector<std::string> reconstructSequence(const std::vector<std::string>& clouds,
                                             const std::string& folder,
                                             const ReconstructSettings& settings, long firstNumber)
{
  const ReconstructionOptions& o = settings.options;
  if (!(o.cleaning.voxelSize >= 0 && o.cleaning.voxelSize <= 0.1))
    throw UsageError{"--cloud-voxel must be between 0 and 0.1 metres"};
  if (!(o.poisson.depth >= 5 && o.poisson.depth <= 12))
    throw UsageError{"--poisson-depth must be between 5 and 12"};
  if (!(o.cropDistance > 0 && o.cropDistance <= 0.5))
    throw UsageError{"--crop must be in (0, 0.5] metres"};
  fs::create_directories(fs::path(folder) / "frames");
  const nlohmann::json key = optionsKey(settings);
  std::map<std::string, nlohmann::json> records = earlierRecords(folder, key);
  std::vector<std::string> meshes;
  nlohmann::json frames = nlohmann::json::array();
  int doubtful = 0, reused = 0;
  Progress progress("reconstruct", static_cast<int>(clouds.size()));
  for (size_t k = 0; k < clouds.size(); ++k)
  {
    const std::string mesh =
        (fs::path(folder) / "frames" / (frameStem(firstNumber + static_cast<long>(k)) + ".obj"))
            .string();
    nlohmann::json record;
    if (records.count(clouds[k]) && upToDate(mesh, clouds[k]))
    {
      record = records[clouds[k]];
      ++reused;
    }
    else
      try
      {
        record = reconstructOne(clouds[k], mesh, settings);
      }
      catch (const Error& e)
      {
        if (!settings.skipBadFrames) throw;
        std::fprintf(stderr, "\nwarning: %s (skipped)\n", e.what());
      }
    meshes.push_back(record.is_null() ? std::string() : mesh);
    if (!record.is_null())
    {
      doubtful += !record.value("doubts", nlohmann::json::array()).empty();
      frames.push_back(record);
    }
    progress.step(static_cast<int>(k + 1));
  }
  progress.finish();
  if (frames.empty()) throw Error(folder + ": no cloud of the sequence could be reconstructed");
  doubtful += doubtSmallFrames(frames);
  writeTextAtomically((fs::path(folder) / "reconstruction.json").string(),
                      nlohmann::json{{"options", key},
                                     {"frames", frames},
                                     {"doubtful_frames", doubtful},
                                     {"reused_frames", reused}}
                          .dump(1));
  return meshes;
}
} // namespace clothtrack::app
