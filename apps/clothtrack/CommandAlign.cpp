// clothtrack align: the whole pipeline on a folder of frames.
//   OUT/aligned.pvd + aligned/   the template deformed through the sequence (one connectivity)
//   OUT/metrics.json             timings, memory and, with --ground-truth, the errors
//   OUT/work/                    intermediate results: a run that was stopped resumes from them
#include "AlignCache.h"
#include "BackgroundWriter.h"
#include "BodyFitRun.h"
#include "Commands.h"
#include "ErrorMetrics.h"
#include "Options.h"
#include "Progress.h"
#include "Report.h"
#include "TextFile.h"

#include "ctBodyModelIO.h"
#include "ctMeshConversion.h"

#include <clothtrack/AlignmentError.h>
#include <clothtrack/Error.h>
#include <clothtrack/FrameList.h>
#include <clothtrack/LandmarkTransfer.h>
#include <clothtrack/MarkerError.h>
#include <clothtrack/MotionPrediction.h>
#include <clothtrack/Parallel.h>
#include <clothtrack/SurfaceLocator.h>
#include <clothtrack/TemplateSelection.h>
#include <clothtrack/body/BodyFit.h>
#include <clothtrack/body/OrientedLandmarks.h>

#include <vtkDoubleArray.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkUnsignedCharArray.h>

#include <nlohmann/json.hpp>

#include <sys/resource.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <mutex>
#include <optional>
#include <sstream>
#include <thread>

namespace fs = std::filesystem;

namespace clothtrack::app
{
namespace
{
/// --stages: "wc,ws,wd,wt/wc,ws,wd,wt/...", every weight a finite number >= 0.
std::vector<FitStage> parseStages(const std::string& spec)
{
  std::vector<FitStage> stages;
  std::stringstream all(spec);
  for (std::string item; std::getline(all, item, '/');)
  {
    double w[4];
    char tail = 0;
    if (std::sscanf(item.c_str(), "%lf,%lf,%lf,%lf%c", &w[0], &w[1], &w[2], &w[3], &tail) != 4 ||
        !std::all_of(w, w + 4, [](double x) { return std::isfinite(x) && x >= 0; }))
      throw UsageError{"--stages: '" + item +
                       "' is not four weights wc,ws,wd,wt (numbers, 0 or more)"};
    stages.push_back({w[0], w[1], w[2], w[3]});
  }
  if (stages.empty()) throw UsageError{"--stages: no stage"};
  return stages;
}

nlohmann::json stagesJson(const std::vector<FitStage>& stages)
{
  nlohmann::json out = nlohmann::json::array();
  for (const FitStage& s : stages)
    out.push_back({s.correspondence, s.smoothness, s.nearest, s.temporal});
  return out;
}

using Clock = std::chrono::steady_clock;

double since(Clock::time_point start)
{
  return std::chrono::duration<double>(Clock::now() - start).count();
}

double peakMemoryMB()
{
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return usage.ru_maxrss / 1024.0; // kilobytes on Linux
}

/// "A:B" (either end may be empty) -> [begin, end) of `count` frames.
std::pair<int, int> frameRange(const std::string& spec, int count)
{
  if (spec.empty()) return {0, count};
  const auto colon = spec.find(':');
  if (colon == std::string::npos) throw UsageError{"--frames must be A:B (got '" + spec + "')"};
  auto number = [&](const std::string& text, int fallback)
  {
    if (text.empty()) return fallback;
    size_t used = 0;
    int value = 0;
    try
    {
      value = std::stoi(text, &used);
    }
    catch (const std::exception&)
    {
      used = 0;
    }
    if (used != text.size() || value < 0)
      throw UsageError{"--frames must be A:B with frame numbers >= 0 (got '" + spec + "')"};
    return value;
  };
  const int begin = number(spec.substr(0, colon), 0);
  const int end = std::min(count, number(spec.substr(colon + 1), count));
  if (begin >= end)
    throw UsageError{"--frames " + spec + " selects no frame of the " + std::to_string(count)};
  return {begin, end};
}

void addArray(vtkPolyData* mesh, const char* name, const Eigen::Ref<const Eigen::MatrixXd>& values)
{
  vtkNew<vtkDoubleArray> array;
  array->SetName(name);
  array->SetNumberOfComponents(static_cast<int>(values.cols()));
  array->SetNumberOfTuples(values.rows());
  for (Eigen::Index i = 0; i < values.rows(); ++i)
    for (Eigen::Index c = 0; c < values.cols(); ++c) array->SetTypedComponent(i, c, values(i, c));
  mesh->GetPointData()->AddArray(array);
}

/// Whether the JSON file at `path` holds `key`.
bool sameKey(const fs::path& path, const nlohmann::json& key)
{
  std::ifstream in(path);
  if (!in) return false;
  try
  {
    return nlohmann::json::parse(in) == key;
  }
  catch (const nlohmann::json::exception&)
  {
    return false;
  }
}

/// Distance from each point to the surface behind `locator`.
Eigen::VectorXd distances(const Points& points, const SurfaceLocator& locator)
{
  Eigen::VectorXd d(points.rows());
  for (Eigen::Index i = 0; i < points.rows(); ++i)
    d[i] = locator.closestPoint(points.row(i).transpose()).distance;
  return d;
}
/// What a run does: everything ('align'), stages 1 and 2 into the work folder ('correspond'), or
/// stage 3 and the evaluation from a work folder that 'correspond' filled ('fit').
enum class AlignMode
{
  Full,
  CorrespondOnly,
  FitOnly
};

int alignCommand(const Args& args, AlignMode mode)
{
  std::string input, output, truthInput, frameSpec, modelPath, markersPath, workDir,
      solver = "exact";
  SequenceOptions seq;
  int threads = 0, forcedTemplate = -1;
  std::string templateCriterion = "rest-pose", stageSpec;
  double truthDistance = 0.03;
  double predictRadius = 0.3;
  TemplateFitOptions fit;
  PatchCorrespondenceOptions patches;
  po::options_description options("align options");
  options.add_options()("input", po::value(&input)->required(),
                        "folder, glob pattern, list file or mesh file")(
      "output,o", po::value(&output)->required(), "output folder")(
      "ground-truth", po::value(&truthInput),
      "ground-truth sequence (one connectivity, same frames as INPUT): adds the errors")(
      "frames", po::value(&frameSpec),
      "frames A:B of the input (A included, B not; either may "
      "be left out)")("template", po::value(&forcedTemplate)->default_value(-1),
                      "template frame within the selected frames (-1: chosen automatically)")(
      "template-criterion", po::value(&templateCriterion)->default_value(templateCriterion),
      "last template criterion after the topology: rest-pose (fitted body closest to the rest "
      "pose) or area-ratio (the paper's: most uniform mesh)")(
      "model", po::value(&modelPath), "body model file (default: the built-in model)")(
      "threads", po::value(&threads)->default_value(0),
      "threads (0: all cores)")("skip-bad-frames", po::bool_switch(),
                                "leave out unreadable frames with a warning instead of stopping")(
      "no-report", po::bool_switch(), "skip the plots, renders and report.html")(
      "solver", po::value(&solver)->default_value(solver), "template fit solver: exact or lbfgs")(
      "solver-tolerance", po::value(&fit.solverTolerance)->default_value(fit.solverTolerance),
      "exact solver: relative residual of each stage's last round")(
      "intermediate-tolerance",
      po::value(&fit.intermediateTolerance)->default_value(fit.intermediateTolerance),
      "exact solver: relative residual of the rounds before a stage's last")(
      "refactor-steps", po::value(&fit.refactorSteps)->default_value(fit.refactorSteps),
      "exact solver: renew a stage's factorisation after a frame that needed more conjugate-"
      "gradient steps per round than this (0: only when they fail)")(
      "nearest-reuse", po::value(&fit.nearestReuse)->default_value(fit.nearestReuse),
      "metres: a template vertex that moved less than this since its last closest-point search "
      "is projected onto the same triangle (0: search every round)")(
      "stages", po::value(&stageSpec),
      "template fit weight stages wc,ws,wd,wt separated by '/' (default the paper's: "
      "1,400,0,0.1/1,200,10,0.1/0,100,10,0.1/0,50,10,0.1)")(
      "epsilon", po::value(&patches.epsilon)->default_value(patches.epsilon),
      "near-isometry tolerance of the patches (m)")(
      "max-radius", po::value(&patches.maxRadius)->default_value(patches.maxRadius),
      "patch radius tau_d (m)")("min-radius",
                                po::value(&patches.minRadius)->default_value(patches.minRadius),
                                "smallest patch kept, tau_s (m)")(
      "seed-consensus", po::value(&patches.minConsensus)->default_value(patches.minConsensus),
      "share of the nearby landmarks whose geodesic distances a landmark pair must preserve to "
      "seed a patch (0: every pair seeds one)")(
      "predict-radius", po::value(&predictRadius)->default_value(predictRadius),
      "each frame's fit starts from its neighbour's moved by the landmarks' locally rigid motion, "
      "weighted over this radius (m; 0: from the neighbour's fit as it is)")(
      "truth-distance", po::value(&truthDistance)->default_value(truthDistance),
      "template vertices further than this from the ground truth have no error (m)")(
      "markers", po::value(&markersPath),
      "marker trajectories (CSV frame,time,marker,x,y,z, frames numbered as the input's): adds "
      "the error at each marker's nearest template vertex")(
      "work", po::value(&workDir),
      "folder for intermediate results (default OUT/work); runs on the same input with other fit "
      "options may share it and reuse its landmarks and correspondences")(
      "no-correspondence", po::bool_switch(),
      "ablation: fit without the correspondence term Ec (with --predict-radius 0: nearest "
      "points alone, a sequential non-rigid ICP)");
  addSequenceOptions(options, seq);
  po::positional_options_description positional;
  positional.add("input", 1);
  po::variables_map values;
  const char* usage =
      mode == AlignMode::CorrespondOnly
          ? "clothtrack correspond INPUT -o OUT [--work DIR] [options] (stages 1 and 2 into the "
            "work folder, for 'clothtrack fit')"
      : mode == AlignMode::FitOnly
          ? "clothtrack fit INPUT -o OUT [--work DIR] [options] (stage 3 from the work folder "
            "that 'clothtrack correspond' filled)"
          : "clothtrack align INPUT -o OUT [--ground-truth GT] [options]";
  if (!parseOptions(args, usage, options, positional, values)) return 0;
  const FrameConventions conventions = toConventions(seq);
  if (threads < 0) throw UsageError{"--threads must be 0 or more"};
  if (solver != "exact" && solver != "lbfgs")
    throw UsageError{"--solver must be exact or lbfgs (got '" + solver + "')"};
  fit.solver = solver == "exact" ? FitSolver::Exact : FitSolver::LBFGS;
  if (!stageSpec.empty()) fit.stages = parseStages(stageSpec);
  if (!(patches.epsilon > 0) || !(patches.minRadius >= 0) || !(patches.maxRadius > 0))
    throw UsageError{"--epsilon and --max-radius must be positive, --min-radius at least 0"};
  if (!(patches.minConsensus >= 0 && patches.minConsensus <= 1))
    throw UsageError{"--seed-consensus must be between 0 and 1"};
  if (!(truthDistance > 0)) throw UsageError{"--truth-distance must be positive"};
  if (!(predictRadius >= 0)) throw UsageError{"--predict-radius must be 0 or more"};
  if (!(fit.solverTolerance > 0 && fit.solverTolerance < 1) ||
      !(fit.intermediateTolerance > 0 && fit.intermediateTolerance < 1))
    throw UsageError{"--solver-tolerance and --intermediate-tolerance must be in (0, 1)"};
  if (!(fit.refactorSteps >= 0) || !std::isfinite(fit.refactorSteps))
    throw UsageError{"--refactor-steps must be 0 or more"};
  if (!(fit.nearestReuse >= 0) || !std::isfinite(fit.nearestReuse))
    throw UsageError{"--nearest-reuse must be 0 or more"};
  const TemplateCriterion criterion = parseTemplateCriterion(templateCriterion);
  setThreadCount(threads);
  const bool skipBad = values["skip-bad-frames"].as<bool>();
  fit.useCorrespondence = !values["no-correspondence"].as<bool>();
  // The body fit gives the landmarks (correspondences, start prediction) and the poses that
  // choose the template; when none of these is wanted, it is skipped.
  const bool needLandmarks = fit.useCorrespondence || predictRadius > 0 ||
                             (forcedTemplate < 0 && criterion == TemplateCriterion::RestPose);
  const auto start = Clock::now();
  nlohmann::json stageSeconds;

  // Frames, and the ground truth beside them.
  auto t0 = Clock::now();
  const std::vector<std::string> allFiles = listFrames(input);
  const auto [begin, end] = frameRange(frameSpec, static_cast<int>(allFiles.size()));
  std::vector<std::string> allTruth;
  if (!truthInput.empty())
  {
    allTruth = listFrames(truthInput);
    if (allTruth.size() != allFiles.size())
      throw UsageError{truthInput + ": " + std::to_string(allTruth.size()) +
                       " ground-truth frames for " + std::to_string(allFiles.size()) +
                       " input frames"};
  }
  std::vector<std::string> files, truthFiles;
  std::vector<int> frameNumber; // index in the full input list
  std::vector<TriangleMesh> frames;
  {
    Progress progress("reading", end - begin);
    for (int k = begin; k < end; ++k)
    {
      try
      {
        std::vector<std::string> warnings;
        TriangleMesh mesh = loadFrame(allFiles[k], conventions, &warnings);
        for (const auto& w : warnings) std::fprintf(stderr, "warning: %s\n", w.c_str());
        frames.push_back(std::move(mesh));
        files.push_back(fs::absolute(allFiles[k]).string());
        frameNumber.push_back(k);
        if (!allTruth.empty()) truthFiles.push_back(allTruth[k]);
      }
      catch (const Error& e)
      {
        if (!skipBad) throw;
        std::fprintf(stderr, "warning: %s (frame left out)\n", e.what());
      }
      progress.step(k - begin + 1);
    }
    progress.finish();
  }
  const int n = static_cast<int>(frames.size());
  // Frames missing from a numbered sequence make the motion jump there: say so.
  for (int k = 1; k < n; ++k)
  {
    const long before = frameNumberFromName(files[k - 1]), after = frameNumberFromName(files[k]);
    if (before >= 0 && after > before + 1)
      std::fprintf(stderr, "warning: frames %ld to %ld are missing between %s and %s\n", before + 1,
                   after - 1, fs::path(files[k - 1]).filename().c_str(),
                   fs::path(files[k]).filename().c_str());
  }
  if (n < 2) throw UsageError{input + ": at least two readable frames are needed"};
  const std::vector<TriangleMesh> truth = loadGroundTruth(truthFiles, conventions);
  stageSeconds["read"] = since(t0);

  // Markers are read now, so that a bad file stops the run before the long stages.
  std::optional<MarkerTrajectories> markers;
  if (!markersPath.empty()) markers = selectedMarkers(markersPath, frameNumber);

  const fs::path out(output);
  const fs::path work = workDir.empty() ? out / "work" : fs::path(workDir);
  fs::create_directories(work);
  fs::create_directories(out);

  // Stage 1: body under the clothing, landmarks on every frame.
  t0 = Clock::now();
  const nlohmann::json landmarkKey = {
      {"files", files}, {"model", modelPath}, {"up", seq.up}, {"unit", seq.unit}};
  BodyStage body;
  body.landmarks.resize(n);
  std::vector<FrameLandmarks>& landmarks = body.landmarks;
  if (!needLandmarks)
    std::fprintf(stderr, "body fit: skipped (no correspondence term, no start prediction, "
                         "template not chosen by pose)\n");
  else if (auto cached = readBodyStage((work / "landmarks.json").string(), landmarkKey);
           cached && static_cast<int>(cached->landmarks.size()) == n &&
           static_cast<int>(cached->poses.size()) == n)
  {
    body = std::move(*cached);
    std::fprintf(stderr, "body fit: landmarks of %d frames reused from %s\n", n,
                 (work / "landmarks.json").c_str());
  }
  else
  {
    BodyModel ownModel;
    const BodyModel& model = bodyModel(modelPath, ownModel);
    std::vector<const TriangleMesh*> pointers;
    for (const auto& f : frames) pointers.push_back(&f);
    const BodyFitResult fitted = fitBodiesWithProgress(model, pointers);
    body.beta = fitted.beta;
    for (const BodyFrameFit& f : fitted.frames)
    {
      body.poses.push_back(f.pose);
      body.status.push_back(f.status);
    }
    parallelFor(
        0, n,
        [&](int k)
        {
          const TriangleMesh posed = model.posed(fitted.beta, fitted.frames[k].pose);
          const SurfaceLocator locator(frames[k]);
          landmarks[k] =
              landmarkSeeds(transferLandmarks(orientedLandmarks(model, posed), frames[k], locator));
        },
        1);
    writeBodyStage((work / "landmarks.json").string(), landmarkKey,
                   bodyFitJson(modelPath, files, body), body);
  }
  if (needLandmarks)
    writeTextAtomically((out / "body_fit.json").string(),
                        bodyFitJson(modelPath, files, body).dump(1) + "\n");
  for (int k = 0; k < n; ++k)
    if (landmarks[k].empty())
      std::fprintf(stderr,
                   "warning: %s: no landmark found; the frame is fitted to its surface "
                   "alone\n",
                   files[k].c_str());
  stageSeconds["body_fit"] = since(t0);

  // Stage 2a: the template frame.
  t0 = Clock::now();
  int j = forcedTemplate;
  std::string templateDecidedBy = "given";
  if (j >= n)
    throw UsageError{"--template " + std::to_string(j) + " is out of range: " + std::to_string(n) +
                     " frames"};
  if (j < 0)
  {
    std::vector<FrameTopology> topology(n);
    parallelFor(
        0, n, [&](int k) { topology[k] = frameTopology(frames[k], 0.1); }, 1);
    TemplateSelectionOptions selection;
    selection.criterion = criterion;
    const TemplateSelection chosen = selectTemplate(topology, selection, restPoseDistances(body));
    j = chosen.chosen;
    templateDecidedBy = templateCriterionName(chosen.decidedBy);
  }
  const TriangleMesh& templ = frames[j];
  std::fprintf(stderr, "template: frame %d (%s), %d vertices, %s%s\n", j,
               fs::path(files[j]).filename().c_str(), templ.numVertices(),
               forcedTemplate >= 0 ? "set by --template" : "chosen by ",
               forcedTemplate >= 0 ? "" : templateDecidedBy.c_str());
  stageSeconds["select_template"] = since(t0);

  // Correspondences depend on the landmarks, the template and the patch options; the aligned
  // frames on those and on the fit options. Results made with other ones are not reused.
  const nlohmann::json correspondenceKey = {
      {"landmarks", landmarkKey},
      {"template", j},
      {"patches", {patches.epsilon, patches.minRadius, patches.maxRadius}},
      {"seed_consensus", patches.minConsensus}};
  const fs::path correspondenceDir = work / "correspondence";
  if (!sameKey(correspondenceDir / "key.json", correspondenceKey))
  {
    fs::remove_all(correspondenceDir);
    fs::create_directories(correspondenceDir);
    writeTextAtomically((correspondenceDir / "key.json").string(),
                        correspondenceKey.dump(2) + "\n");
  }
  const nlohmann::json runKey = {{"correspondence", correspondenceKey},
                                 {"ground_truth", truthFiles},
                                 {"solver", solver},
                                 {"tolerances", {fit.solverTolerance, fit.intermediateTolerance}},
                                 {"refactor_steps", fit.refactorSteps},
                                 {"nearest_reuse", fit.nearestReuse},
                                 {"truth_distance", truthDistance},
                                 {"predict_radius", predictRadius},
                                 {"use_correspondence", fit.useCorrespondence},
                                 {"stages", stagesJson(fit.stages)}};
  const fs::path runKeyPath = out / "run.json";
  if (!sameKey(runKeyPath, runKey))
  {
    if (fs::exists(out / "aligned"))
      std::fprintf(stderr,
                   "new run: earlier results in %s were made with other inputs or "
                   "options and are replaced\n",
                   output.c_str());
    fs::remove_all(out / "aligned");
    writeTextAtomically(runKeyPath.string(), runKey.dump(2) + "\n");
  }

  std::optional<TruthAnchors> anchors;
  if (!truth.empty()) anchors = anchorToTruth(templ.V, truth[j], truthDistance);

  // Stages 2b and 3: correspondence and fit, frame by frame in the paper's order: the template
  // frame j, then j-1 down to 0 and j+1 up to n-1. The two chains are independent, so they run
  // side by side, each with its own fitter (a fitter keeps per-chain factorisations).
  const TemplateFitter backwardFitter(templ, fit), forwardFitter(templ, fit);
  const std::string alignedPvd = (out / "aligned.pvd").string();
  std::vector<Points> aligned(n);
  std::vector<Eigen::VectorXd> errors(n);
  std::vector<double> frameSeconds(n, 0.0);
  std::vector<double> toSurface(n, -1.0); // mean distance to the frame; -1: not known yet
  std::atomic<int> resumed{0}, done{0};
  std::mutex progressMutex;
  std::unique_ptr<Progress> alignProgress; // started with the chains
  auto alignedPath = [&](int k)
  {
    char name[32];
    std::snprintf(name, sizeof(name), "aligned_%04d.vtp", frameNumber[k]);
    return out / "aligned" / name;
  };
  auto targetPath = [&](int k)
  {
    char name[32];
    std::snprintf(name, sizeof(name), "frame_%04d.bin", frameNumber[k]);
    return (correspondenceDir / name).string();
  };
  // Declared after everything its tasks refer to, so that it finishes before they go.
  BackgroundWriter writer;
  auto alignFrame = [&](int k, const TemplateFitter& fitter)
  {
    if (fs::exists(alignedPath(k)))
    {
      const TriangleMesh finished = readMeshFile(alignedPath(k).string());
      if (finished.numVertices() == templ.numVertices() && finished.V.allFinite())
      {
        aligned[k] = finished.V;
        ++resumed;
      }
    }
    Eigen::Matrix<unsigned char, Eigen::Dynamic, 1> used =
        Eigen::Matrix<unsigned char, Eigen::Dynamic, 1>::Zero(templ.numVertices());
    Eigen::VectorXd surfaceDistance = Eigen::VectorXd::Zero(templ.numVertices());
    const bool fitNow = aligned[k].rows() == 0; // not resumed from an earlier run
    if (fitNow)
    {
      const auto frameStart = Clock::now();
      if (k == j)
        aligned[k] = templ.V;
      else
      {
        std::optional<VertexTargets> targets;
        if (fit.useCorrespondence)
        {
          targets = readTargets(targetPath(k), files[k], templ.numVertices());
          if (!targets)
            throw Error("the correspondences of " + files[k] + " vanished from " +
                        correspondenceDir.string() + " during the run");
        }
        const int previous = k < j ? k + 1 : k - 1;
        Points start = aligned[previous];
        if (predictRadius > 0)
        {
          std::vector<Vec3> before, after;
          pairLandmarks(frames[previous], landmarks[previous], frames[k], landmarks[k], before,
                        after);
          start = predictMotion(start, before, after, predictRadius);
        }
        const FrameFit result = fitter.fit(start, frames[k], targets ? &*targets : nullptr);
        aligned[k] = result.positions;
        for (int i = 0; i < templ.numVertices(); ++i) used[i] = result.used[i];
        surfaceDistance = result.surfaceDistance;
      }
      toSurface[k] = surfaceDistance.mean(); // zero for the template on its own frame
      frameSeconds[k] = since(frameStart);
    }
    if (anchors) errors[k] = vertexErrors(aligned[k], truth[k], *anchors);
    if (fitNow)
      // The writer gets copies: the chain moves on to the next frame at once.
      writer.submit(
          [&templ, &alignedPvd, number = frameNumber[k], positions = aligned[k], error = errors[k],
           surfaceDistance, used]()
          {
            vtkSmartPointer<vtkPolyData> mesh = toPolyData(TriangleMesh{positions, templ.F});
            addArray(mesh, "Displacement", positions - templ.V);
            addArray(mesh, "SurfaceDistance", surfaceDistance);
            vtkNew<vtkUnsignedCharArray> usedArray;
            usedArray->SetName("CorrespondenceUsed");
            usedArray->SetNumberOfTuples(templ.numVertices());
            for (int i = 0; i < templ.numVertices(); ++i) usedArray->SetValue(i, used[i]);
            mesh->GetPointData()->AddArray(usedArray);
            if (error.size() > 0) addArray(mesh, "Error", error);
            writeCollectionFrame(alignedPvd, number, mesh, false);
          });
    const std::lock_guard<std::mutex> lock(progressMutex);
    alignProgress->step(++done);
  };
  // Stage 2b first, for every frame still to fit, all cores (frames are independent): the chains
  // then only read them.
  t0 = Clock::now();
  if (fit.useCorrespondence)
  {
    std::vector<int> missing;
    for (int k = 0; k < n; ++k)
      if (k != j && !fs::exists(alignedPath(k)) &&
          !readTargets(targetPath(k), files[k], templ.numVertices()))
        missing.push_back(k);
    if (!missing.empty() && mode == AlignMode::FitOnly)
      throw UsageError{correspondenceDir.string() + ": no correspondences for " +
                       std::to_string(missing.size()) +
                       " frames with this template and these options (run 'clothtrack "
                       "correspond' with the same input, options and work folder first)"};
    if (!missing.empty())
    {
      const TemplatePatches templatePatches(templ, landmarks[j], patches);
      Progress correspondProgress("correspond", static_cast<int>(missing.size()));
      std::atomic<int> corresponded{0};
      parallelFor(
          0, static_cast<int>(missing.size()),
          [&](int m)
          {
            const int k = missing[m];
            writeTargets(targetPath(k), files[k],
                         vertexTargets(templatePatches.correspond(frames[k], landmarks[k])));
            const std::lock_guard<std::mutex> lock(progressMutex);
            correspondProgress.step(++corresponded);
          },
          1);
      correspondProgress.finish();
    }
  }
  stageSeconds["correspond"] = since(t0);
  if (mode == AlignMode::CorrespondOnly)
  {
    std::printf("landmarks and correspondences of %d frames (template frame %d) in %s; "
                "'clothtrack fit' with the same input and work folder fits the template\n",
                n, j, work.c_str());
    return 0;
  }

  t0 = Clock::now();
  alignProgress = std::make_unique<Progress>("align", n);
  alignFrame(j, forwardFitter);
  {
    std::exception_ptr backwardError;
    auto backward = [&]()
    {
      try
      {
        for (int k = j - 1; k >= 0; --k) alignFrame(k, backwardFitter);
      }
      catch (...)
      {
        backwardError = std::current_exception();
      }
    };
    std::thread backwardThread;
    if (threadCount() > 1)
      backwardThread = std::thread(backward);
    else
      backward();
    for (int k = j + 1; k < n; ++k)
    {
      try
      {
        alignFrame(k, forwardFitter);
      }
      catch (...)
      {
        if (backwardThread.joinable()) backwardThread.join();
        throw;
      }
    }
    if (backwardThread.joinable()) backwardThread.join();
    if (backwardError) std::rethrow_exception(backwardError);
  }
  writer.finish();
  alignProgress->finish();
  std::vector<std::pair<double, std::string>> entries;
  for (int k = 0; k < n; ++k)
  {
    char name[48];
    std::snprintf(name, sizeof(name), "aligned/aligned_%04d.vtp", frameNumber[k]);
    entries.push_back({frameNumber[k] / seq.fps, name});
  }
  writeCollection(alignedPvd, entries);
  stageSeconds["fit"] = since(t0);

  // Evaluation.
  t0 = Clock::now();
  nlohmann::json metrics;
  metrics["input"] = input;
  metrics["frames"] = n;
  metrics["template_frame"] = j;
  metrics["template_criterion"] = templateDecidedBy;
  metrics["template_file"] = files[j];
  metrics["template_vertices"] = templ.numVertices();
  metrics["frame_numbers"] = frameNumber;
  metrics["files"] = files;
  metrics["unit"] = seq.unit;
  metrics["up"] = seq.up;
  metrics["resumed_frames"] = resumed.load();
  metrics["threads"] = threadCount();
  metrics["solver"] = solver;
  metrics["predict_radius_m"] = predictRadius;
  std::vector<double> landmarkCounts;
  for (const auto& l : landmarks) landmarkCounts.push_back(static_cast<double>(l.size()));
  metrics["landmarks_per_frame"] = landmarkCounts;
  if (anchors) addVertexErrorMetrics(metrics, errors, j, truthInput, anchors->count());
  if (markers) addMarkerMetrics(metrics, aligned, *markers, j, markersPath);
  // Without ground truth too: how well the result covers each frame, and how smoothly it moves.
  std::vector<double> coverage(n), jitter;
  parallelFor(
      0, n,
      [&](int k)
      {
        if (toSurface[k] < 0) // resumed: the fit's own distances are not at hand
          toSurface[k] = distances(aligned[k], SurfaceLocator(frames[k])).mean();
        const TriangleMesh alignedMesh{aligned[k], templ.F};
        const SurfaceLocator alignedLocator(alignedMesh);
        coverage[k] = distances(frames[k].V, alignedLocator).mean();
      },
      1);
  for (int k = 1; k + 1 < n; ++k)
    jitter.push_back((aligned[k + 1] - 2 * aligned[k] + aligned[k - 1]).rowwise().norm().mean());
  metrics["per_frame_surface_distance_m"] = toSurface;
  metrics["per_frame_coverage_distance_m"] = coverage;
  double meanSurface = 0, meanCoverage = 0, meanJitter = 0;
  for (int k = 0; k < n; ++k) meanSurface += toSurface[k] / n, meanCoverage += coverage[k] / n;
  for (double x : jitter) meanJitter += x / jitter.size();
  metrics["mean_surface_distance_m"] = meanSurface;
  metrics["mean_coverage_distance_m"] = meanCoverage;
  metrics["mean_jitter_m"] = meanJitter;
  stageSeconds["evaluate"] = since(t0);

  const double total = since(start);
  int computed = 0;
  double computedSeconds = 0;
  for (int k = 0; k < n; ++k)
    if (frameSeconds[k] > 0) ++computed, computedSeconds += frameSeconds[k];
  metrics["seconds_total"] = total;
  metrics["seconds_per_frame"] = total / n;
  metrics["seconds_per_fitted_frame"] = computed ? computedSeconds / computed : 0.0;
  metrics["stage_seconds"] = stageSeconds;
  metrics["peak_rss_mb"] = peakMemoryMB();
  writeTextAtomically((out / "metrics.json").string(), metrics.dump(2) + "\n");

  std::printf("aligned %d frames (template frame %d) in %.1f s (%.2f s/frame%s)", n, j, total,
              total / n,
              resumed ? (", " + std::to_string(resumed.load()) + " resumed").c_str() : "");
  if (anchors)
    std::printf("; mean vertex error %.2f cm, %.2f %% within 10 cm",
                100 * metrics["mean_vertex_error_m"].get<double>(),
                100 * metrics["within_10cm"].get<double>());
  if (markers) std::printf("; markers %.2f cm", 100 * metrics["marker_mean_error_m"].get<double>());
  std::printf("\nwrote %s and %s\n", alignedPvd.c_str(), (out / "metrics.json").c_str());
  std::fflush(stdout);
  if (!values["no-report"].as<bool>())
  {
    writeReport(output);
    std::printf("report: %s\n", (out / "report.html").c_str());
  }
  return 0;
}
} // namespace

int runAlign(const Args& args)
{
  return alignCommand(args, AlignMode::Full);
}

int runCorrespond(const Args& args)
{
  return alignCommand(args, AlignMode::CorrespondOnly);
}

int runFit(const Args& args)
{
  return alignCommand(args, AlignMode::FitOnly);
}
} // namespace clothtrack::app
