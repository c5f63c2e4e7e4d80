// clothtrack body-fit: the body under the clothing of a sequence and its landmarks on every frame.
//   OUT/bodies.pvd + bodies/      fitted body per frame (the model's connectivity)
//   OUT/landmarks.pvd + landmarks/ oriented landmarks on each frame (Valid, Direction, ...)
//   OUT/body_fit.json             beta, pose and status per frame, landmarks found, timings
#include "BodyFitRun.h"
#include "Commands.h"
#include "Options.h"
#include "Progress.h"
#include "TextFile.h"

#include "ctBodyModelIO.h"
#include "ctLandmarkPolyData.h"
#include "ctMeshConversion.h"

#include <clothtrack/base/Error.h>
#include <clothtrack/base/Parallel.h>
#include <clothtrack/body/BodyFit.h>
#include <clothtrack/body/LandmarkTransfer.h>
#include <clothtrack/body/OrientedLandmarks.h>
#include <clothtrack/io/FrameList.h>
#include <clothtrack/mesh/InsideTest.h>
#include <clothtrack/pipeline/BodyStage.h>

#include <nlohmann/json.hpp>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <optional>

namespace fs = std::filesystem;

namespace clothtrack::app
{
namespace
{
struct BodyFitSettings
{
  std::string input, output, modelPath;
  SequenceOptions sequence;
  int threads = 0;
  bool skipBadFrames = false;
  BodyStageOptions stage;
};

/// The settings from the command line; nullopt after --help. Throws UsageError.
std::optional<BodyFitSettings> parseBodyFitSettings(const Args& args)
{
  BodyFitSettings s;
  BodyFitOptions& fit = s.stage.fit;
  LandmarkTransferOptions& transfer = s.stage.transfer;
  po::options_description options("body-fit options");
  options.add_options()("input", po::value(&s.input)->required(),
                        "folder, glob pattern, list file or mesh file")(
      "output,o", po::value(&s.output)->required(), "output folder")(
      "model", po::value(&s.modelPath), "body model file (default: the built-in model)")(
      "threads", po::value(&s.threads)->default_value(0),
      "threads (0: all cores)")("skip-bad-frames", po::bool_switch(&s.skipBadFrames),
                                "warn about unreadable frames and flag them instead of stopping")(
      "samples", po::value(&fit.samples)->default_value(fit.samples),
      "body vertices used by the dense terms")(
      "shape-frames", po::value(&fit.shapeFrames)->default_value(fit.shapeFrames),
      "key frames for the body shape")(
      "outside-tolerance",
      po::value(&transfer.outsideTolerance)->default_value(transfer.outsideTolerance),
      "landmark transfer tau_o (m)")(
      "inside-tolerance",
      po::value(&transfer.insideTolerance)->default_value(transfer.insideTolerance),
      "landmark transfer tau_i (m)")(
      "register-frames", po::bool_switch(&s.stage.registerFrames),
      "start each frame from its predecessor's pose moved by the rigid motion between the two "
      "surfaces (generalized ICP)")(
      "stature-start", po::bool_switch(&fit.statureStart),
      "start the shape's estimation at the stature the frames suggest rather than at the mean "
      "body (for people far from 1.7 m)")(
      "no-two-shapes", po::bool_switch(),
      "estimate the body shape one way only, with the key frames' poses fixed (pass 2 runs once, "
      "not under two shapes)")(
      "same-shape-tolerance",
      po::value(&fit.sameShapeTolerance)->default_value(fit.sameShapeTolerance),
      "two shapes whose rest-pose bodies lie this close at every vertex are one, and pass 2 "
      "runs under the first only (m; 0: always under both)")(
      "no-limb-restarts", po::bool_switch(),
      "do not start frames unrelated to their predecessor again with their limbs at rest, "
      "aimed at the extremities their fit leaves unpaired, swapped in pairs, or (on a "
      "collection, those explained worst) turned half round");
  addSequenceOptions(options, s.sequence);
  po::positional_options_description positional;
  positional.add("input", 1);
  po::variables_map values;
  if (!parseOptions(args, "clothtrack body-fit INPUT -o OUT [options]", options, positional,
                    values))
    return std::nullopt;
  fit.limbRestarts = !values["no-limb-restarts"].as<bool>();
  fit.twoShapes = !values["no-two-shapes"].as<bool>();
  if (s.threads < 0) throw UsageError{"--threads must be 0 or more"};
  if (fit.samples < 50) throw UsageError{"--samples must be at least 50"};
  if (fit.shapeFrames < 1) throw UsageError{"--shape-frames must be at least 1"};
  if (!(fit.sameShapeTolerance >= 0.0))
    throw UsageError{"--same-shape-tolerance must be 0 or more"};
  resolveAutomatic(s.sequence, s.input);
  return s;
}

/// The frames; with --skip-bad-frames an unreadable one is left out (nullptr) with a warning.
std::vector<const TriangleMesh*> readFrames(const BodyFitSettings& s,
                                            const std::vector<std::string>& files,
                                            std::vector<TriangleMesh>& meshes)
{
  const FrameConventions conventions = toConventions(s.sequence);
  meshes.assign(files.size(), {});
  std::vector<const TriangleMesh*> frames(files.size(), nullptr);
  Progress progress("reading", static_cast<int>(files.size()));
  for (size_t k = 0; k < files.size(); ++k)
  {
    try
    {
      std::vector<std::string> warnings;
      meshes[k] = loadFrame(files[k], conventions, &warnings);
      for (const auto& w : warnings) std::fprintf(stderr, "warning: %s\n", w.c_str());
      frames[k] = &meshes[k];
    }
    catch (const Error& e)
    {
      if (!s.skipBadFrames) throw;
      std::fprintf(stderr, "warning: %s (skipped)\n", e.what());
    }
    progress.step(static_cast<int>(k + 1));
  }
  progress.finish();
  return frames;
}

/// What the output says of the whole sequence.
struct BodyFitTotals
{
  int landmarksFound = 0, landmarks = 0;
  double insideSum = 0.0;
  nlohmann::json frames = nlohmann::json::array();
};

/// bodies.pvd, landmarks.pvd and each frame's record.
BodyFitTotals writeFrames(const BodyFitSettings& s, const BodyModel& model,
                          const std::vector<std::string>& files,
                          const std::vector<const TriangleMesh*>& frames,
                          const BodyStageResult& stage)
{
  const BodyFitResult& result = stage.body;
  const int n = static_cast<int>(files.size());
  // Bodies and the inside test, frames in parallel; then written in order.
  std::vector<TriangleMesh> bodies(n);
  std::vector<Points> bodyJoints(n);
  std::vector<double> insideFractions(n, 0.0);
  parallelFor(
      0, n,
      [&](int k)
      {
        const BodyFrameFit& f = result.frames[k];
        bodies[k] = model.posed(result.beta, f.pose, &bodyJoints[k]);
        if (frames[k] && f.status != BodyFitStatus::Failed)
          insideFractions[k] = fractionInside(SurfaceLocator(*frames[k]), bodies[k].V);
      },
      1);
  const std::string bodiesPvd = (fs::path(s.output) / "bodies.pvd").string();
  const std::string landmarksPvd = (fs::path(s.output) / "landmarks.pvd").string();
  std::vector<std::pair<double, std::string>> bodyEntries, landmarkEntries;
  BodyFitTotals totals;
  Progress progress("writing", n);
  for (int k = 0; k < n; ++k)
  {
    const BodyFrameFit& f = result.frames[k];
    vtkSmartPointer<vtkPolyData> bodyData = toPolyData(bodies[k]);
    addBodyModelArrays(model, bodyJoints[k], bodyData);
    const double time = static_cast<double>(k) / s.sequence.fps;
    bodyEntries.push_back({time, writeCollectionFrame(bodiesPvd, k, bodyData, false)});
    const std::vector<TransferredLandmark>& transferred = stage.transferred[k];
    vtkSmartPointer<vtkPolyData> landmarkData =
        transferredLandmarksToPolyData(stage.bodyLandmarks[k], transferred);
    addLandmarkIdentity(model, landmarkData);
    landmarkEntries.push_back({time, writeCollectionFrame(landmarksPvd, k, landmarkData, false)});
    int frameFound = 0;
    for (const auto& t : transferred) frameFound += t.valid;
    totals.landmarksFound += frameFound;
    totals.landmarks += static_cast<int>(stage.bodyLandmarks[k].size());
    totals.insideSum += insideFractions[k];
    if (f.status != BodyFitStatus::Ok)
      std::fprintf(stderr, "warning: %s: body fit %s%s%s\n", files[k].c_str(),
                   bodyFitStatusName(f.status), f.message.empty() ? "" : ": ", f.message.c_str());
    nlohmann::json extremities = nlohmann::json::array();
    for (const Vec3& e : f.extremities) extremities.push_back({e.x(), e.y(), e.z()});
    nlohmann::json record = bodyFrameJson(files[k], f);
    record.update({{"median_distance_m", f.medianDistance},
                   {"inside_fraction", insideFractions[k]},
                   {"samples_inside_within_2cm", f.insideFraction},
                   {"extremities_detected", f.extremitiesDetected},
                   {"extremities_matched", f.extremitiesMatched},
                   {"landmarks_found", frameFound},
                   {"extremities", extremities}});
    totals.frames.push_back(record);
    progress.step(k + 1);
  }
  progress.finish();
  writeCollection(bodiesPvd, bodyEntries);
  writeCollection(landmarksPvd, landmarkEntries);
  return totals;
}

double secondsSince(std::chrono::steady_clock::time_point start)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}
} // namespace

int runBodyFit(const Args& args)
{
  const std::optional<BodyFitSettings> settings = parseBodyFitSettings(args);
  if (!settings) return 0;
  const BodyFitSettings& s = *settings;
  setThreadCount(s.threads);
  const auto start = std::chrono::steady_clock::now();
  const std::vector<std::string> files = listFrames(s.input);
  std::vector<TriangleMesh> meshes;
  const std::vector<const TriangleMesh*> frames = readFrames(s, files, meshes);
  const double readSeconds = secondsSince(start);

  if (s.modelPath.empty()) std::fprintf(stderr, "building the built-in body model...\n");
  BodyModel ownModel;
  const BodyModel& model = bodyModel(s.modelPath, ownModel);
  const auto fitStart = std::chrono::steady_clock::now();
  const int n = static_cast<int>(files.size());
  BodyStageResult stage;
  {
    Progress fitProgress("body-fit", n);
    stage = fitBodyAndLandmarks(model, frames, s.stage,
                                [&](double done)
                                {
                                  fitProgress.step(static_cast<int>(n * done));
                                  return true;
                                });
    fitProgress.finish();
  }
  const BodyFitResult& result = stage.body;
  const double fitSeconds = secondsSince(fitStart);
  warnAboutDiscontinuities(result, s.stage.fit);
  warnAboutPoorFits(result, files);

  fs::create_directories(s.output);
  const BodyFitTotals totals = writeFrames(s, model, files, frames, stage);
  const double foundFraction =
      totals.landmarks ? static_cast<double>(totals.landmarksFound) / totals.landmarks : 0.0;
  const double insideFraction = n ? totals.insideSum / n : 0.0;
  nlohmann::json summary = {{"frames", n},
                            {"beta", coefficientsJson(result.beta)},
                            {"moved_shape", result.movedShape},
                            {"other_beta", coefficientsJson(result.otherBeta)},
                            {"shape_gap_m", result.shapeGap},
                            {"landmarks_found_fraction", foundFraction},
                            {"body_inside_fraction", insideFraction},
                            {"seconds_total", secondsSince(start)},
                            {"seconds_read", readSeconds},
                            {"seconds_fit", fitSeconds},
                            {"seconds_per_frame", n ? fitSeconds / n : 0.0},
                            {"threads", threadCount()},
                            {"per_frame", totals.frames}};
  writeTextAtomically((fs::path(s.output) / "body_fit.json").string(), summary.dump(2) + "\n");
  int ok = 0;
  for (const auto& f : result.frames) ok += f.status == BodyFitStatus::Ok;
  std::printf("fitted %d frames in %.1f s (%.2f s/frame): %d ok; landmarks found %.1f %%, body "
              "vertices inside the frame %.1f %%; wrote %s\n",
              n, fitSeconds, n ? fitSeconds / n : 0.0, ok, 100.0 * foundFraction,
              100.0 * insideFraction, s.output.c_str());
  return 0;
}
} // namespace clothtrack::app
