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

namespace fs = std::filesystem;

namespace clothtrack::app
{
int runBodyFit(const Args& args)
{
  std::string input, output, modelPath;
  SequenceOptions seq;
  int threads = 0;
  BodyFitOptions fit;
  LandmarkTransferOptions transfer;
  po::options_description options("body-fit options");
  options.add_options()("input", po::value(&input)->required(),
                        "folder, glob pattern, list file or mesh file")(
      "output,o", po::value(&output)->required(), "output folder")(
      "model", po::value(&modelPath), "body model file (default: the built-in model)")(
      "threads", po::value(&threads)->default_value(0),
      "threads (0: all cores)")("skip-bad-frames", po::bool_switch(),
                                "warn about unreadable frames and flag them instead of stopping")(
      "samples", po::value(&fit.samples)->default_value(fit.samples),
      "body vertices used by the dense terms")(
      "shape-frames", po::value(&fit.shapeFrames)->default_value(fit.shapeFrames),
      "key frames for the body shape")("outside-tolerance",
                                       po::value(&transfer.outsideTolerance)->default_value(0.05),
                                       "landmark transfer tau_o (m)")(
      "inside-tolerance", po::value(&transfer.insideTolerance)->default_value(0.2),
      "landmark transfer tau_i (m)");
  addSequenceOptions(options, seq);
  po::positional_options_description positional;
  positional.add("input", 1);
  po::variables_map values;
  if (!parseOptions(args, "clothtrack body-fit INPUT -o OUT [options]", options, positional,
                    values))
    return 0;
  const FrameConventions conventions = toConventions(seq);
  if (threads < 0) throw UsageError{"--threads must be 0 or more"};
  if (fit.samples < 50) throw UsageError{"--samples must be at least 50"};
  if (fit.shapeFrames < 1) throw UsageError{"--shape-frames must be at least 1"};
  setThreadCount(threads);
  const bool skipBad = values["skip-bad-frames"].as<bool>();

  const auto start = std::chrono::steady_clock::now();
  const std::vector<std::string> files = listFrames(input);
  std::vector<TriangleMesh> meshes(files.size());
  std::vector<const TriangleMesh*> frames(files.size(), nullptr);
  {
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
        if (!skipBad) throw;
        std::fprintf(stderr, "warning: %s (skipped)\n", e.what());
      }
      progress.step(static_cast<int>(k + 1));
    }
    progress.finish();
  }
  const double readSeconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  if (modelPath.empty()) std::fprintf(stderr, "building the built-in body model...\n");
  BodyModel ownModel;
  const BodyModel& model = bodyModel(modelPath, ownModel);

  const auto fitStart = std::chrono::steady_clock::now();
  const int n = static_cast<int>(files.size());
  BodyStageResult stage;
  {
    Progress fitProgress("body-fit", n);
    stage = fitBodyAndLandmarks(model, frames, {fit, transfer},
                                [&](double done)
                                {
                                  fitProgress.step(static_cast<int>(n * done));
                                  return true;
                                });
    fitProgress.finish();
  }
  const BodyFitResult& result = stage.body;
  const double fitSeconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - fitStart).count();

  fs::create_directories(output);
  const std::string bodiesPvd = (fs::path(output) / "bodies.pvd").string();
  const std::string landmarksPvd = (fs::path(output) / "landmarks.pvd").string();
  std::vector<std::pair<double, std::string>> bodyEntries, landmarkEntries;
  nlohmann::json frameRecords = nlohmann::json::array();
  int found = 0, total = 0;
  double insideSum = 0.0;
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
  Progress progress("writing", n);
  for (int k = 0; k < n; ++k)
  {
    const BodyFrameFit& f = result.frames[k];
    const TriangleMesh& body = bodies[k];
    const Points& joints = bodyJoints[k];
    vtkSmartPointer<vtkPolyData> bodyData = toPolyData(body);
    addBodyModelArrays(model, joints, bodyData);
    const double time = static_cast<double>(k) / seq.fps;
    bodyEntries.push_back({time, writeCollectionFrame(bodiesPvd, k, bodyData, false)});

    const std::vector<OrientedPoint>& points = stage.bodyLandmarks[k];
    const std::vector<TransferredLandmark>& transferred = stage.transferred[k];
    const double inside = insideFractions[k];
    vtkSmartPointer<vtkPolyData> landmarkData = transferredLandmarksToPolyData(points, transferred);
    addLandmarkIdentity(model, landmarkData);
    landmarkEntries.push_back({time, writeCollectionFrame(landmarksPvd, k, landmarkData, false)});
    int frameFound = 0;
    for (const auto& t : transferred) frameFound += t.valid;
    found += frameFound;
    total += static_cast<int>(points.size());
    insideSum += inside;
    if (f.status != BodyFitStatus::Ok)
      std::fprintf(stderr, "warning: %s: body fit %s%s%s\n", files[k].c_str(),
                   bodyFitStatusName(f.status), f.message.empty() ? "" : ": ", f.message.c_str());

    nlohmann::json extremities = nlohmann::json::array();
    for (const Vec3& e : f.extremities) extremities.push_back({e.x(), e.y(), e.z()});
    nlohmann::json record = bodyFrameJson(files[k], f.status, f.pose);
    record.update({{"message", f.message},
                   {"median_distance_m", f.medianDistance},
                   {"inside_fraction", inside},
                   {"samples_inside_within_2cm", f.insideFraction},
                   {"extremities_detected", f.extremitiesDetected},
                   {"extremities_matched", f.extremitiesMatched},
                   {"landmarks_found", frameFound},
                   {"extremities", extremities}});
    frameRecords.push_back(record);
    progress.step(k + 1);
  }
  progress.finish();
  writeCollection(bodiesPvd, bodyEntries);
  writeCollection(landmarksPvd, landmarkEntries);

  nlohmann::json summary = {
      {"frames", n},
      {"beta", std::vector<double>(result.beta.data(), result.beta.data() + result.beta.size())},
      {"landmarks_found_fraction", total ? static_cast<double>(found) / total : 0.0},
      {"body_inside_fraction", n ? insideSum / n : 0.0},
      {"seconds_total",
       std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count()},
      {"seconds_read", readSeconds},
      {"seconds_fit", fitSeconds},
      {"seconds_per_frame", n ? fitSeconds / n : 0.0},
      {"threads", threadCount()},
      {"per_frame", frameRecords}};
  writeTextAtomically((fs::path(output) / "body_fit.json").string(), summary.dump(2) + "\n");
  int ok = 0;
  for (const auto& f : result.frames) ok += f.status == BodyFitStatus::Ok;
  std::printf("fitted %d frames in %.1f s (%.2f s/frame): %d ok; landmarks found %.1f %%, body "
              "vertices inside the frame %.1f %%; wrote %s\n",
              n, fitSeconds, n ? fitSeconds / n : 0.0, ok, total ? 100.0 * found / total : 0.0,
              n ? 100.0 * insideSum / n : 0.0, output.c_str());
  return 0;
}
} // namespace clothtrack::app
