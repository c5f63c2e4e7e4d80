// clothtrack synth: a synthetic clothed capture with ground truth, from the built-in body model.
//   OUT/frames/frame_NNNN.obj        what a capture delivers (independently re-meshed)
//   OUT/ground_truth/frame_NNNN.obj  the clothed surface, same connectivity in every frame
//   OUT/source_map/frame_NNNN.vtp    captured frame + the ground-truth point of each vertex
//   OUT/body.json                    beta, pose per frame, garment vertex offset, options
//   OUT/markers.csv                  14 marker trajectories
#include "CaptureOutput.h"
#include "Commands.h"
#include "Options.h"
#include "Progress.h"
#include "TextFile.h"

#include "ctBuiltinBodyModel.h"
#include "ctCaptureSimulation.h"
#include "ctMeshConversion.h"
#include "ctSyntheticSequence.h"

#include <clothtrack/io/MeshIO.h>

#include <vtkPolyData.h>

#include <cstdio>
#include <filesystem>

namespace fs = std::filesystem;

namespace clothtrack::app
{
int runSynth(const Args& args)
{
  std::string output, presets;
  for (const auto& p : syntheticPresets()) presets += (presets.empty() ? "" : ", ") + p;
  SyntheticOptions synth;
  CaptureOptions capture;
  int seed = 7;
  po::options_description options("synth options");
  options.add_options()("output,o", po::value(&output)->required(), "output folder")(
      "preset", po::value(&synth.preset)->default_value("dress-walk"),
      ("garment and motion: " + presets).c_str())(
      "frames", po::value(&synth.frames)->default_value(40),
      "number of frames")("fps", po::value(&synth.fps)->default_value(25.0), "frames per second")(
      "seed", po::value(&seed)->default_value(7), "random seed (body shape, capture noise)")(
      "hem", po::value(&synth.hemHeight)->default_value(0.0),
      "hem height / stature for dresses and skirts (0: preset)")(
      "stature", po::value(&synth.stature)->default_value(0.0),
      "height of the body in metres, e.g. 1.95 (0: random around the mean)")(
      "voxel", po::value(&capture.voxelSize)->default_value(0.015), "capture voxel size, metres")(
      "holes", po::value(&capture.holes)->default_value(0),
      "random holes per captured frame")("noise", po::value(&capture.noise)->default_value(0.0),
                                         "capture noise along normals, metres")(
      "no-hull-fill", po::bool_switch(),
      "do not fill regions cameras cannot see into (inside a dress, enclosed gaps)");
  po::positional_options_description positional;
  po::variables_map values;
  if (!parseOptions(args, "clothtrack synth -o OUT [--preset NAME] [options]", options, positional,
                    values))
    return 0;
  if (!(capture.voxelSize >= 0.002 && capture.voxelSize <= 0.2))
    throw UsageError{"--voxel must be between 0.002 and 0.2 metres"};
  capture.fillEnclosed = !values["no-hull-fill"].as<bool>();
  synth.seed = static_cast<unsigned>(seed);
  checkSyntheticOptions(synth);
  makeOutputFolders(output, {"ground_truth"});

  std::fprintf(stderr, "building the built-in body model...\n");
  const BodyModel& model = builtinBodyModel();
  Progress progress("synth", synth.frames);
  std::string poses, markers = "frame,time,marker,x,y,z\n";
  int garmentOffset = 0;
  const Eigen::VectorXd beta = generateSyntheticSequence(
      model, synth,
      [&](const SyntheticFrame& frame)
      {
        const std::string name = frameStem(frame.index);
        writeMeshFile((fs::path(output) / "ground_truth" / (name + ".obj")).string(),
                      toPolyData(frame.clothed));
        captureAndWrite(output, frame.index, frame.clothed, capture, synth.seed);

        char buffer[160];
        poses += poses.empty() ? "" : ",\n";
        poses += "    {\"time\": " + std::to_string(frame.time) + ", \"rotations\": [";
        for (int j = 0; j < NumJoints; ++j)
        {
          std::snprintf(buffer, sizeof(buffer), "%s[%.9g, %.9g, %.9g]", j ? ", " : "",
                        frame.pose.rotations(j, 0), frame.pose.rotations(j, 1),
                        frame.pose.rotations(j, 2));
          poses += buffer;
        }
        std::snprintf(buffer, sizeof(buffer), "], \"translation\": [%.9g, %.9g, %.9g]}",
                      frame.pose.translation.x(), frame.pose.translation.y(),
                      frame.pose.translation.z());
        poses += buffer;
        for (Eigen::Index m = 0; m < frame.markers.rows(); ++m)
        {
          std::snprintf(buffer, sizeof(buffer), "%d,%.6f,%s,%.6f,%.6f,%.6f\n", frame.index,
                        frame.time, syntheticMarkerNames()[m].c_str(), frame.markers(m, 0),
                        frame.markers(m, 1), frame.markers(m, 2));
          markers += buffer;
        }
        garmentOffset = frame.garmentOffset;
        progress.step(frame.index + 1);
      });
  progress.finish();

  std::string betaText;
  for (Eigen::Index k = 0; k < beta.size(); ++k)
    betaText += (k ? ", " : "") + std::to_string(beta[k]);
  std::string joints;
  for (int j = 0; j < NumJoints; ++j)
    joints += std::string(j ? ", " : "") + "\"" + jointNames()[j] + "\"";
  writeTextAtomically((fs::path(output) / "body.json").string(),
                      "{\n  \"preset\": \"" + synth.preset + "\",\n  \"seed\": " +
                          std::to_string(seed) + ",\n  \"fps\": " + std::to_string(synth.fps) +
                          ",\n  \"frames\": " + std::to_string(synth.frames) +
                          ",\n  \"stature_m\": " + std::to_string(restHeight(model, beta)) +
                          ",\n  \"voxel_size_m\": " + std::to_string(capture.voxelSize) +
                          ",\n  \"garment_first_vertex\": " + std::to_string(garmentOffset) +
                          ",\n  \"beta\": [" + betaText + "],\n  \"joints\": [" + joints +
                          "],\n  \"poses\": [\n" + poses + "\n  ]\n}\n");
  writeTextAtomically((fs::path(output) / "markers.csv").string(), markers);
  std::printf("wrote %d frames of '%s' to %s (frames/, ground_truth/, source_map/, body.json, "
              "markers.csv)\n",
              synth.frames, synth.preset.c_str(), output.c_str());
  return 0;
}
} // namespace clothtrack::app
