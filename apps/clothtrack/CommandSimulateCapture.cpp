// clothtrack simulate-capture: turn a consistent-connectivity sequence (ground truth) into what a
// multi-view system delivers, frame by frame, with the per-vertex source map.
#include "Commands.h"
#include "Options.h"
#include "Progress.h"

#include "CaptureOutput.h"

#include "ctMeshConversion.h"
#include "ctPointCloudFile.h"

#include <clothtrack/cloud/DepthCapture.h>

#include <clothtrack/io/FrameList.h>
#include <clothtrack/io/MeshIO.h>

#include <vtkPolyData.h>

#include <cstdio>
#include <filesystem>
#include <limits>
#include <random>

namespace fs = std::filesystem;

namespace clothtrack::app
{
namespace
{
/// Options of the depth-camera rig (--point-cloud).
struct CloudCapture
{
  bool enabled = false;
  DepthRig rig;
  std::string format = "pcd";
  /// Where the rig stands: "sequence", the centre of the box holding every frame (a rig set up
  /// for the capture volume), or "first", the first frame's centre.
  std::string rigCentre = "sequence";
};

void addCloudOptions(po::options_description& options, CloudCapture& cloud)
{
  options.add_options()("point-cloud", po::bool_switch(&cloud.enabled),
                        "capture point clouds from depth cameras instead of meshes "
                        "(frames/frame_NNNN.pcd; the input is the ground truth)")(
      "cameras", po::value(&cloud.rig.cameras)->default_value(4),
      "point clouds: depth cameras on a circle around the subject")(
      "camera-distance", po::value(&cloud.rig.distance)->default_value(3.0),
      "point clouds: horizontal distance of the cameras from the subject, metres")(
      "outliers", po::value(&cloud.rig.outliers)->default_value(0.01),
      "point clouds: stray points added, as a share of the points seen")(
      "cloud-format", po::value(&cloud.format)->default_value("pcd"),
      "point clouds: pcd (binary_compressed), ply or xyz")(
      "rig-centre", po::value(&cloud.rigCentre)->default_value(cloud.rigCentre),
      "point clouds: the point the cameras look at: sequence (the centre of the box holding "
      "every frame, a rig set up for the capture volume) or first (the first frame's centre)");
}

void checkCloudOptions(const CloudCapture& cloud)
{
  if (!(cloud.rig.cameras >= 1 && cloud.rig.cameras <= 64))
    throw UsageError{"--cameras must be between 1 and 64"};
  if (!(cloud.rig.distance >= 0.5 && cloud.rig.distance <= 20))
    throw UsageError{"--camera-distance must be between 0.5 and 20 metres"};
  if (!(cloud.rig.outliers >= 0 && cloud.rig.outliers <= 1))
    throw UsageError{"--outliers must be in [0, 1]"};
  if (cloud.format != "pcd" && cloud.format != "ply" && cloud.format != "xyz")
    throw UsageError{"--cloud-format must be pcd, ply or xyz"};
  if (cloud.rigCentre != "sequence" && cloud.rigCentre != "first")
    throw UsageError{"--rig-centre must be sequence or first"};
}

/// The centre of the box holding every one of `frames`.
Vec3 sequenceCentre(const std::vector<std::string>& frames, const FrameConventions& conventions)
{
  Vec3 low = Vec3::Constant(std::numeric_limits<double>::infinity());
  Vec3 high = -low;
  Progress progress("rig", static_cast<int>(frames.size()));
  for (size_t k = 0; k < frames.size(); ++k)
  {
    const TriangleMesh truth = loadFrame(frames[k], conventions);
    low = low.cwiseMin(truth.V.colwise().minCoeff().transpose());
    high = high.cwiseMax(truth.V.colwise().maxCoeff().transpose());
    progress.step(static_cast<int>(k + 1));
  }
  progress.finish();
  return 0.5 * (low + high);
}

/// The cloud the rig sees of frame k, written as OUT/frames/frame_NNNN.<format>.
void captureCloudAndWrite(const std::string& output, long k, const TriangleMesh& truth,
                          const CloudCapture& cloud, unsigned seed)
{
  DepthRig rig = cloud.rig;
  rig.seed = seed * 7919u + static_cast<unsigned>(k);
  writePointCloudFile((fs::path(output) / "frames" / (frameStem(k) + "." + cloud.format)).string(),
                      captureDepth(truth, rig));
}
} // namespace

int runSimulateCapture(const Args& args)
{
  std::string input, output;
  SequenceOptions seq;
  CaptureOptions capture;
  double drop = 0.0;
  int seed = 1;
  po::options_description options("simulate-capture options");
  options.add_options()("input", po::value(&input)->required(),
                        "consistent-connectivity sequence (ground truth)")(
      "output,o", po::value(&output)->required(), "output folder: frames/ and source_map/")(
      "voxel", po::value(&capture.voxelSize)->default_value(0.015),
      "voxel size in metres (parts closer merge)")(
      "sheet-thickness", po::value(&capture.sheetThickness)->default_value(0.012),
      "thickness given to open surfaces (garments), metres")(
      "holes", po::value(&capture.holes)->default_value(0), "random holes per frame")(
      "hole-radius", po::value(&capture.holeRadius)->default_value(0.03),
      "hole radius, metres")("noise", po::value(&capture.noise)->default_value(0.0),
                             "standard deviation of normal noise, metres")(
      "drop", po::value(&drop)->default_value(0.0),
      "probability that a frame is dropped (missing frames)")(
      "seed", po::value(&seed)->default_value(1),
      "random seed (runs with the same seed are identical)")(
      "no-hull-fill", po::bool_switch(),
      "do not fill regions cameras cannot see into (inside a dress, enclosed gaps)");
  CloudCapture cloud;
  addCloudOptions(options, cloud);
  addSequenceOptions(options, seq);
  po::positional_options_description positional;
  positional.add("input", 1);
  po::variables_map values;
  if (!parseOptions(args, "clothtrack simulate-capture INPUT -o OUT [options]", options, positional,
                    values))
    return 0;
  resolveAutomatic(seq, input);
  const FrameConventions conventions = toConventions(seq);
  if (!(capture.voxelSize >= 0.002 && capture.voxelSize <= 0.2))
    throw UsageError{"--voxel must be between 0.002 and 0.2 metres"};
  capture.fillEnclosed = !values["no-hull-fill"].as<bool>();
  if (!(drop >= 0 && drop < 1)) throw UsageError{"--drop must be in [0, 1)"};
  checkCloudOptions(cloud);
  cloud.rig.noise = capture.noise;

  const std::vector<std::string> frames = listFrames(input);
  makeOutputFolders(output, {}, !cloud.enabled);
  if (cloud.enabled)
    cloud.rig.centre = sequenceCentre(
        cloud.rigCentre == "sequence" ? frames : std::vector<std::string>{frames.front()},
        conventions);
  std::mt19937 dropRng(static_cast<unsigned>(seed));
  std::uniform_real_distribution<double> uniform(0, 1);
  Progress progress("simulate-capture", static_cast<int>(frames.size()));
  int written = 0;
  for (size_t k = 0; k < frames.size(); ++k)
  {
    const bool dropped = uniform(dropRng) < drop;
    if (!dropped)
    {
      const TriangleMesh truth = loadFrame(frames[k], conventions);
      if (cloud.enabled)
        captureCloudAndWrite(output, static_cast<long>(k), truth, cloud,
                             static_cast<unsigned>(seed));
      else
        captureAndWrite(output, static_cast<long>(k), truth, capture, static_cast<unsigned>(seed));
      ++written;
    }
    progress.step(static_cast<int>(k + 1));
  }
  progress.finish();
  std::printf("wrote %d captured %s (%zu dropped) to %s/frames\n", written,
              cloud.enabled ? "point clouds" : "frames", frames.size() - written, output.c_str());
  return 0;
}
} // namespace clothtrack::app
