// clothtrack simulate-capture: turn a consistent-connectivity sequence (ground truth) into what a
// multi-view system delivers, frame by frame, with the per-vertex source map.
#include "Commands.h"
#include "Options.h"
#include "Progress.h"

#include "CaptureOutput.h"

#include "ctMeshConversion.h"

#include <clothtrack/io/FrameList.h>
#include <clothtrack/io/MeshIO.h>

#include <vtkPolyData.h>

#include <cstdio>
#include <filesystem>
#include <random>

namespace fs = std::filesystem;

namespace clothtrack::app
{
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

  const std::vector<std::string> frames = listFrames(input);
  makeOutputFolders(output);
  std::mt19937 dropRng(static_cast<unsigned>(seed));
  std::uniform_real_distribution<double> uniform(0, 1);
  Progress progress("simulate-capture", static_cast<int>(frames.size()));
  int written = 0;
  for (size_t k = 0; k < frames.size(); ++k)
  {
    const bool dropped = uniform(dropRng) < drop;
    if (!dropped)
    {
      captureAndWrite(output, static_cast<long>(k), loadFrame(frames[k], conventions), capture,
                      static_cast<unsigned>(seed));
      ++written;
    }
    progress.step(static_cast<int>(k + 1));
  }
  progress.finish();
  std::printf("wrote %d captured frames (%zu dropped) to %s/frames\n", written,
              frames.size() - written, output.c_str());
  return 0;
}
} // namespace clothtrack::app
