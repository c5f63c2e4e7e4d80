// clothtrack reconstruct: a sequence of point clouds (depth cameras, multi-view stereo, LiDAR)
// made into one mesh per frame, the input 'align' takes.
#include "Commands.h"
#include "Options.h"
#include "ReconstructRun.h"

#include "ctPointCloudFile.h"

#include <clothtrack/io/FrameList.h>

#include <algorithm>
#include <cstdio>

namespace clothtrack::app
{
int runReconstruct(const Args& args)
{
  std::string input, output;
  SequenceOptions seq;
  ReconstructSettings settings;
  po::options_description options("reconstruct options");
  options.add_options()("input", po::value(&input)->required(),
                        "point-cloud sequence: folder, glob or list of .pcd .ply .xyz files")(
      "output,o", po::value(&output)->required(),
      "output folder: frames/frame_NNNN.obj and reconstruction.json")(
      "skip-bad-frames", po::bool_switch(&settings.skipBadFrames),
      "leave out a cloud that cannot be reconstructed, with a warning, instead of stopping");
  addReconstructionOptions(options, settings.options);
  addSequenceOptions(options, seq);
  po::positional_options_description positional;
  positional.add("input", 1);
  po::variables_map values;
  if (!parseOptions(args, "clothtrack reconstruct CLOUDS -o OUT [options]", options, positional,
                    values))
    return 0;
  resolveAutomatic(seq, input);
  settings.conventions = toConventions(seq);
  const std::vector<std::string> clouds = listFrames(input);
  for (const auto& cloud : clouds)
    if (!isPointCloudFile(cloud))
      throw UsageError{cloud + ": not a point cloud (a mesh with faces needs no reconstruction)"};
  const auto meshes = reconstructSequence(clouds, output, settings);
  const long written =
      std::count_if(meshes.begin(), meshes.end(), [](const std::string& m) { return !m.empty(); });
  std::printf("wrote %ld reconstructed frames to %s/frames\n", written, output.c_str());
  return 0;
}
} // namespace clothtrack::app
