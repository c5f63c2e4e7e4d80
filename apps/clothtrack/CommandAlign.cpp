// clothtrack align: the whole pipeline on a folder of frames, through the core's stages.
//   OUT/aligned.pvd + aligned/   the template deformed through the sequence (one connectivity)
//   OUT/metrics.json             timings, memory and, with --ground-truth, the errors
//   OUT/work/                    intermediate results: a run that was stopped resumes from them
//   OUT/models/                  with several --model values, each model's run (AlignModels.h)
#include "AlignCache.h"
#include "AlignInput.h"
#include "AlignModels.h"
#include "AlignOptions.h"
#include "AlignTemplates.h"
#include "AlignedOutput.h"
#include "BackgroundWriter.h"
#include "BodyFitRun.h"
#include "Commands.h"
#include "ErrorMetrics.h"
#include "Progress.h"
#include "Ranks.h"
#include "ReconstructRun.h"
#include "Report.h"
#include "StoredLandmarks.h"
#include "TextFile.h"

#include "ctMeshConversion.h"
#include "ctPointCloudFile.h"

#include <clothtrack/base/Error.h>
#include <clothtrack/base/MemoryReuse.h>
#include <clothtrack/base/Parallel.h>
#include <clothtrack/eval/SequenceQuality.h>
#include <clothtrack/fit/MotionPrediction.h>
#include <clothtrack/fit/SequenceFit.h>
#include <clothtrack/io/FrameList.h>
#include <clothtrack/mesh/FrameConsistency.h>
#include <clothtrack/mesh/SubjectSize.h>
#include <clothtrack/pipeline/BodyStage.h>
#include <clothtrack/pipeline/BodyStartPrediction.h>
#include <clothtrack/pipeline/CorrespondenceStage.h>
#include <clothtrack/pipeline/FitJudge.h>
#include <clothtrack/pipeline/LandmarkConsensus.h>
#include <clothtrack/pipeline/TemplateStage.h>

#include <nlohmann/json.hpp>

#include <sys/resource.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <optional>
#include <thread>

namespace fs = std::filesystem;

namespace clothtrack::app
{
namespace
{
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

/// Everything a run shares between its stages.
struct Run
{
  AlignSettings settings;
  Input input;
  fs::path out, work;
  nlohmann::json stageSeconds, stagePeakMemory, landmarkKey, correspondenceKey;
  BodyStage body;
  StoredLandmarks landmarks; ///< each frame's, read from the body stage's file when needed
  int templateFrame = -1;
  std::string templateDecidedBy = "given";
  /// The frames the rest-pose criterion would choose in turn (templateFramesByPose); empty when
  /// the template was given or chosen otherwise.
  std::vector<int> templateFramesByPose;
  /// The template posed by each frame's fitted body: fit starts, and their judge. Empty when
  /// the body was not fitted.
  TemplatePosedByBody posedByBody;
  std::vector<FrameFit> fits;
  std::vector<Eigen::VectorXd> errors;
  int verticesWithTruth = 0;
  int reusedCorrespondences = 0; ///< frames whose correspondences an earlier run left
  int reusedLandmarks = 0;       ///< frames whose body fit and landmarks an earlier run left
  FramePtr templateHeld;         ///< the template frame, held for the whole run
  const TriangleMesh& templateMesh() const { return *templateHeld; }
};

/// Removes the partial files (NAME.part, renamed to NAME once complete) that a run killed while
/// writing left in `folders`, and says how many: the next write would replace them anyway, but
/// until then they look like results.
void removeLeftoverParts(const std::vector<fs::path>& folders)
{
  int removed = 0;
  for (const fs::path& folder : folders)
  {
    std::error_code ec;
    for (auto it = fs::recursive_directory_iterator(folder, ec);
         !ec && it != fs::recursive_directory_iterator(); it.increment(ec))
    {
      // Another process's frame copies, which it may be writing now: it clears its own.
      if (it->is_directory(ec) && it->path().filename().string().rfind("rank_", 0) == 0)
        it.disable_recursion_pending();
      else if (it->is_regular_file(ec) && it->path().extension() == ".part" &&
               fs::remove(it->path(), ec))
        ++removed;
    }
  }
  if (removed > 0)
    std::fprintf(stderr, "removed %d partial files left by an interrupted run\n", removed);
}

/// Every body-fit and transfer option, so that landmarks of other options (an older release's
/// defaults) are not reused.
nlohmann::json bodyStageKey(const BodyStageOptions& o)
{
  const BodyFitOptions& f = o.fit;
  nlohmann::json stages = nlohmann::json::array();
  for (const BodyFitStage& st : f.stages)
    stages.push_back({st.landmarkWeight, st.nearestWeight, st.insideWeight, st.iterations,
                      st.searchRadius, st.coverWeight});
  return {{"revision", kBodyFitRevision},
          {"stages", stages},
          {"weights",
           {f.temporalWeight, f.rootTemporalWeight, f.legTemporalWeight, f.posePriorWeight,
            f.hingeStiffness, f.shapePriorWeight}},
          {"shape",
           {f.shapeComponents, f.shapeFrames, f.shapeRounds, f.statureStart, f.twoShapes,
            f.sameShapeTolerance}},
          {"samples", f.samples},
          {"robust_scale", f.robustScale},
          {"cover", {f.shapeCoverWeight, f.coverScale}},
          {"extremities",
           {f.extremityPersistence, f.extremityGate, f.handGate, f.reachTolerance,
            f.shapeReachTolerance}},
          {"headings", {f.headings, f.headingAmbiguity}},
          {"leg_raise", f.legRaiseStart},
          {"limb_restarts", f.limbRestarts},
          {"judge", {f.poorDistance, f.insideTolerance, f.poorInside}},
          {"continuity", {f.neighbourGap, f.unexplainedRatio, f.unexplainedMargin}},
          {"transfer", {o.transfer.outsideTolerance, o.transfer.insideTolerance}},
          {"register_frames",
           {o.registerFrames, o.registration.voxelSize, o.registration.maximumDistance,
            o.registration.maximumIterations, o.minimumRegistrationOverlap}}};
}

/// Under mpirun, each process's segment of the body fit (--split-body-fit).
BodyFitSharing bodyFitSharing(const AlignSettings& s)
{
  BodyFitSharing sharing;
  if (ranks::count() == 1 || !s.splitBodyFit) return sharing;
  sharing.part = ranks::rank();
  sharing.parts = ranks::count();
  sharing.overlap = s.bodyFitOverlap;
  sharing.allGather = ranks::gatherBytes;
  return sharing;
}

/// Stage 1, or its result from the work folder. `together`: every process fits its segment.
void runBodyStage(Run& run, bool together)
{
  const AlignSettings& s = run.settings;
  const int n = run.input.count();
  const fs::path cache = run.work / "landmarks.jsonl";
  BodyStageOptions options;
  options.registerFrames = s.registerFrames;
  options.fit.statureStart = s.statureStart;
  options.fit.limbRestarts = s.limbRestarts;
  options.fit.twoShapes = s.twoShapes;
  options.fit.sameShapeTolerance = s.sameShapeTolerance;
  options.keepBodyLandmarks = false; // only the seeds are used: a long sequence stays small
  run.landmarkKey = {{"files", run.input.files},
                     {"model", s.modelPath},
                     {"model_content", bodyModelFingerprint(s.modelPath)},
                     {"up", s.sequence.up},
                     {"unit", s.sequence.unit},
                     {"scale", s.sequence.scale},
                     {"body_fit", bodyStageKey(options)}};
  if (together)
  {
    // Segments tracked apart are fitted a little differently from one whole track.
    options.fit.sharing = bodyFitSharing(s);
    const BodyFitSharing& sharing = options.fit.sharing;
    run.landmarkKey["shared"] = {sharing.parts, sharing.overlap, sharing.minimumSegment};
  }
  run.body = {};
  run.landmarks = StoredLandmarks(n);
  if (!s.needLandmarks())
  {
    std::fprintf(stderr, "body fit: skipped (no correspondence term, no start prediction, "
                         "template not chosen by pose)\n");
    return;
  }
  auto cached = readBodyStage(cache.string(), run.landmarkKey);
  if (together) ranks::barrier(); // every process has looked before the first writes
  if (cached && static_cast<int>(cached->lineOffsets.size()) == n &&
      static_cast<int>(cached->body.frames.size()) == n)
  {
    run.body = std::move(*cached);
    run.landmarks = StoredLandmarks(cache.string(), run.body.lineOffsets, run.body.landmarkCounts);
    run.reusedLandmarks = n;
    std::fprintf(stderr, "body fit: landmarks of %d frames reused from %s\n", n, cache.c_str());
  }
  else
  {
    // Without these landmarks the work folder has no correspondences either: say so before the
    // long fit, not after it.
    if (s.mode == AlignMode::FitOnly && s.fit.useCorrespondence)
      throw UsageError{cache.string() +
                       ": no body fit for these frames and options (run 'clothtrack correspond' "
                       "with the same input, options and work folder first)"};
    BodyModel ownModel;
    const BodyModel& model = bodyModel(s.modelPath, ownModel);
    Progress progress("body-fit", n);
    BodyStageResult result = fitBodyAndLandmarks(model, *run.input.frames, options,
                                                 [&](double done)
                                                 {
                                                   progress.step(static_cast<int>(n * done));
                                                   return true;
                                                 });
    progress.finish();
    run.body.body = std::move(result.body);
    run.body.landmarks = std::move(result.landmarks);
    if (ranks::leader())
    {
      writeBodyStage(cache.string(), run.landmarkKey, run.input.files, run.body);
      run.landmarks =
          StoredLandmarks(cache.string(), run.body.lineOffsets, run.body.landmarkCounts);
    }
    else
      run.landmarks = StoredLandmarks(std::move(run.body.landmarks));
    run.body.landmarks = {}; // read again from the file when needed
  }
  if (!ranks::leader()) return; // the leader writes and warns for all
  writeBodyFitJson((run.out / "body_fit.json").string(), s.modelPath, run.input.files, run.body);
  warnAboutDiscontinuities(run.body.body, options.fit);
  warnAboutPoorFits(run.body.body, run.input.files);
  for (int k = 0; k < n; ++k)
    if (run.landmarks.count(k) == 0)
      std::fprintf(stderr,
                   "warning: %s: no landmark found; the frame is fitted to its surface "
                   "alone\n",
                   run.input.files[k].c_str());
}

/// A template set by --template names one of the frames read; checked before the body fit.
void checkForcedTemplate(const Run& run)
{
  const int j = run.settings.forcedTemplate;
  if (j >= run.input.count())
    throw UsageError{"--template " + std::to_string(j) +
                     " is out of range: " + std::to_string(run.input.count()) + " frames"};
}

/// Stage 2a.
void runTemplateStage(Run& run)
{
  const AlignSettings& s = run.settings;
  run.templateFrame = s.forcedTemplate; // in range (checkForcedTemplate)
  if (run.templateFrame < 0)
  {
    const std::vector<double> distances = restPoseDistances(run.body.body);
    const TemplateSelection chosen = chooseTemplateFrame(*run.input.frames, s.selection, distances);
    run.templateFrame = chosen.chosen;
    run.templateDecidedBy = templateCriterionName(chosen.decidedBy);
    if (chosen.decidedBy == TemplateCriterion::RestPose)
      run.templateFramesByPose = templateFramesByPose(chosen, distances);
  }
  const int j = run.templateFrame;
  run.templateHeld = run.input.frame(j);
  if (!ranks::leader()) return;
  std::fprintf(stderr, "template: frame %d (%s), %d vertices, %s%s\n", j,
               fs::path(run.input.files[j]).filename().c_str(), run.templateMesh().numVertices(),
               s.forcedTemplate >= 0 ? "set by --template" : "chosen by ",
               s.forcedTemplate >= 0 ? "" : run.templateDecidedBy.c_str());
}

std::string frameFileName(int frameNumber)
{
  char name[32];
  std::snprintf(name, sizeof(name), "frame_%04d.bin", frameNumber);
  return name;
}

fs::path targetPath(const Run& run, int k)
{
  return run.work / "correspondence" / frameFileName(run.input.frameNumber[k]);
}

/// Correspondences depend on the landmarks, the template and the patch options; the aligned
/// frames on those and on the fit options. Results made with other ones are removed.
void startKeys(Run& run)
{
  const PatchCorrespondenceOptions& p = run.settings.patches;
  run.correspondenceKey = {{"landmarks", run.landmarkKey},
                           {"template", run.templateFrame},
                           {"patches", {p.epsilon, p.minimumRadius, p.maximumRadius}},
                           {"seed_consensus", p.minimumSeedConsensus}};
  const fs::path folder = run.work / "correspondence";
  if (!ranks::leader()) return; // the others wait until the leader has cleared the way
  if (!sameKey(folder / "key.json", run.correspondenceKey))
  {
    fs::remove_all(folder);
    fs::create_directories(folder);
    writeTextAtomically((folder / "key.json").string(), run.correspondenceKey.dump(2) + "\n");
  }
  nlohmann::json key = run.settings.fitKey();
  key["correspondence"] = run.correspondenceKey;
  key["ground_truth"] = run.input.truthFiles;
  const fs::path path = run.out / "run.json";
  if (sameKey(path, key)) return;
  if (fs::exists(run.out / "aligned"))
    std::fprintf(stderr,
                 "new run: earlier results in %s were made with other inputs or options and are "
                 "replaced\n",
                 run.settings.output.c_str());
  fs::remove_all(run.out / "aligned");
  fs::remove_all(run.out / "fit_state");
  writeTextAtomically(path.string(), key.dump(2) + "\n");
}

/// Stage 2b for every frame still to fit whose correspondences the work folder lacks; with
/// several processes, each takes every count()-th frame.
void runCorrespondenceStage(Run& run, const AlignedOutput& output)
{
  const AlignSettings& s = run.settings;
  const PatchCorrespondenceOptions& p = s.patches;
  const fs::path folder = run.work / "correspondence";
  if (!s.fit.useCorrespondence) return;
  const int nv = run.templateMesh().numVertices();
  std::vector<int> missing;
  for (int k = ranks::rank(); k < run.input.count(); k += ranks::count())
    if (k != run.templateFrame && !fs::exists(output.framePath(run.input.frameNumber[k])))
    {
      if (readTargets(targetPath(run, k).string(), run.input.files[k], nv))
        ++run.reusedCorrespondences;
      else
        missing.push_back(k);
    }
  if (run.reusedCorrespondences > 0)
    std::fprintf(stderr, "correspond: correspondences of %d frames reused from %s\n",
                 run.reusedCorrespondences, folder.c_str());
  if (missing.empty()) return;
  if (s.mode == AlignMode::FitOnly)
    throw UsageError{folder.string() + ": no correspondences for " +
                     std::to_string(missing.size()) +
                     " frames with this template and these options (run 'clothtrack "
                     "correspond' with the same input, options and work folder first)"};
  run.landmarks.keep(run.templateFrame);
  const TemplatePatches patches(run.templateMesh(), run.landmarks[run.templateFrame], p);
  const int count = static_cast<int>(missing.size());
  Progress progress("correspond", count);
  correspondFrames(
      patches, run.templateFrame, missing, [&](int k) { return run.input.frame(k); },
      [&](int k) -> const FrameLandmarks& { return run.landmarks[k]; },
      [&](int k, FrameCorrespondence&& c)
      {
        writeTargets(targetPath(run, k).string(), run.input.files[k], vertexTargets(c));
        run.landmarks.release(k);
      },
      [&](double done)
      {
        progress.step(static_cast<int>(count * done + 0.5));
        return true;
      });
  progress.finish();
}

/// Where align keeps the template fit's solver state after frame k while the fit runs.
std::string solverStatePath(const Run& run, int k)
{
  return (run.out / "fit_state" / frameFileName(run.input.frameNumber[k])).string();
}

/// Hooks that keep the template fit's solver state after each frame (TemplateFitterState), so
/// that a stopped run resumes exactly. Frame k's state is on disk before its aligned frame (both
/// go through `writer`, in order), and the state before it is removed after that frame (the
/// `fitted` hook): whichever frame a stopped run wrote last, the state that follows it is there.
void keepSolverStates(const Run& run, BackgroundWriter& writer, SequenceFitHooks& hooks)
{
  fs::create_directories(run.out / "fit_state");
  hooks.resumedState = [&run](int k)
  {
    std::optional<TemplateFitterState> state =
        readFitterState(solverStatePath(run, k), run.templateMesh().numVertices());
    if (!state)
      std::fprintf(stderr,
                   "warning: the solver state after frame %d (%s) was not kept: the frames fitted "
                   "after it may differ from an uninterrupted run within the solver's tolerance\n",
                   k, run.input.files[k].c_str());
    return state;
  };
  hooks.fitterState = [&run, &writer](int k, const TemplateFitterState& state)
  { writer.submit([path = solverStatePath(run, k), state]() { writeFitterState(path, state); }); };
}

/// The chains of the template fit: as set, else two (the paper's), or one per process when more
/// processes share the run.
int chainCount(const AlignSettings& s)
{
  return s.chains > 0 ? s.chains : std::max(2, ranks::count());
}

/// The chains this process fits: chain c on process c mod count(); one process fits them all.
std::vector<int> ownChains(const AlignSettings& s)
{
  std::vector<int> own;
  for (int c = ranks::rank(); c < chainCount(s); c += ranks::count()) own.push_back(c);
  return own;
}

/// Whether this process fitted frame k (the template frame goes with chain 0).
bool fitsFrame(const Run& run, int k)
{
  const int j = run.templateFrame;
  const std::vector<FitChain> chains =
      sequenceChains(run.input.count(), j, chainCount(run.settings));
  for (int c : ownChains(run.settings))
  {
    if (c == 0 && k == j) return true;
    if (c >= static_cast<int>(chains.size())) continue;
    if (chains[c].contains(k)) return true;
  }
  return false;
}

/// The frame whose fit frame k starts from: the one before it in its chain, or the template
/// frame for a chain's first frame; -1 for the template frame itself.
int chainPredecessor(const Run& run, int k)
{
  const int j = run.templateFrame;
  if (k == j) return -1;
  for (const FitChain& chain : sequenceChains(run.input.count(), j, chainCount(run.settings)))
    if (chain.contains(k)) return k == chain.first ? j : k - chain.direction;
  return -1;
}

/// With several processes: the seconds of every frame, whether it was resumed and the surface
/// distance its fit measured (each process knows its own frames'), and on the leader the other
/// processes' fits read back from
/// OUT/aligned with the errors that their processes wrote there (measured again by `errorsOf`
/// when a ground truth is given but a frame lacks them), as its own would be after the fit.
void shareFits(Run& run, const AlignedOutput& output,
               const std::function<void(int, const Points&)>& errorsOf)
{
  if (ranks::count() == 1) return;
  const int n = run.input.count();
  std::vector<double> shared(3 * n + 1, 0.0);
  for (int k = 0; k < n; ++k)
    if (fitsFrame(run, k))
    {
      shared[3 * k] = run.fits[k].seconds;
      shared[3 * k + 1] = run.fits[k].resumed;
      shared[3 * k + 2] = fittedSurfaceDistance(run.fits[k]);
    }
  shared[3 * n] = run.reusedCorrespondences;
  ranks::sum(shared);
  run.reusedCorrespondences = static_cast<int>(shared[3 * n]);
  for (int k = 0; k < n; ++k)
    if (!fitsFrame(run, k)) run.fits[k].meanSurfaceDistance = shared[3 * k + 2];
  if (!ranks::leader()) return;
  for (int k = 0; k < n; ++k)
  {
    if (fitsFrame(run, k)) continue;
    Eigen::VectorXd errors;
    std::optional<FrameFit> fit = output.earlier(run.input.frameNumber[k], &errors);
    if (!fit)
      throw Error(output.framePath(run.input.frameNumber[k]).string() +
                  ": another process did not leave this frame");
    if (run.verticesWithTruth > 0 && errors.size() > 0)
      run.errors[k] = std::move(errors);
    else
      errorsOf(k, fit->positions);
    fit->meanSurfaceDistance = shared[3 * k + 2];
    fit->positions = Points();
    fit->used = {};
    fit->surfaceDistance = Eigen::VectorXd();
    fit->seconds = shared[3 * k];
    fit->resumed = shared[3 * k + 1] > 0;
    run.fits[k] = std::move(*fit);
  }
}

/// What the fit reads: frames, correspondences (into `targets`, one frame at a time), starts
/// and the judge of each fit.
void addInputHooks(Run& run, SequenceFitHooks& hooks, VertexTargets& targets)
{
  // The hooks outlive this function: they hold pointers to the run, not references to locals.
  const AlignSettings& s = run.settings;
  const int n = run.input.count(), j = run.templateFrame;
  Run* r = &run;
  hooks.frame = [r](int k) { return r->input.frame(k); };
  hooks.keepFits = false; // written as they come; evaluate reads them back
  if (s.fit.useCorrespondence)
    hooks.targets = [r, out = &targets](int k) -> const VertexTargets*
    {
      const Input& in = r->input;
      std::optional<VertexTargets> read =
          readTargets(targetPath(*r, k).string(), in.files[k], r->templateMesh().numVertices());
      if (!read)
        throw Error("the correspondences of " + in.files[k] + " vanished from " +
                    (r->work / "correspondence").string() + " during the run");
      *out = std::move(*read);
      return out;
    };
  if (s.prediction.predictRadius > 0)
    hooks.start = landmarkStartPrediction(
        [r](int k) { return r->input.frame(k); },
        [r](int k) -> const FrameLandmarks& { return r->landmarks[k]; }, s.prediction);
  if (static_cast<int>(run.body.body.frames.size()) == n)
  {
    BodyModel ownModel;
    run.posedByBody =
        bodyPosedTemplate(bodyModel(s.modelPath, ownModel), run.body.body, run.templateMesh(), j);
  }
  if (s.startFromBody && run.posedByBody)
  {
    const std::function<FramePtr(int)> frames =
        s.stretchStart ? std::function<FramePtr(int)>([r](int k) { return r->input.frame(k); })
                       : nullptr;
    hooks.start = bodyStartPrediction(run.posedByBody, std::move(hooks.start), frames);
    narrowTargetsToBodyStart(hooks, run.posedByBody, frames, s.correspondenceGate);
  }
  if (s.retryDoubtful) judgeFits(hooks, run.templateMesh(), {}, run.posedByBody);
}

/// Stage 3: both chains through the core, each frame written as soon as it is fitted.
void runFitStage(Run& run, const AlignedOutput& output)
{
  const AlignSettings& s = run.settings;
  const Input& in = run.input;
  const int n = in.count(), j = run.templateFrame;
  std::optional<TruthAnchors> anchors;
  if (in.truth)
    anchors =
        anchorToTruth(run.templateMesh().V, *in.truth->frame(j), s.truth.maximumTruthDistance);
  run.verticesWithTruth = anchors ? anchors->count() : 0;
  run.errors.assign(n, Eigen::VectorXd());
  auto errorsOf = [&](int k, const Points& positions)
  {
    run.errors[k] =
        anchors ? vertexErrors(positions, *in.truth->frame(k), *anchors) : Eigen::VectorXd();
  };

  VertexTargets targets;
  SequenceFitHooks hooks;
  addInputHooks(run, hooks, targets);
  hooks.resumed = [&](int k)
  {
    std::optional<FrameFit> earlier = output.earlier(in.frameNumber[k]);
    if (earlier) errorsOf(k, earlier->positions);
    return earlier;
  };
  BackgroundWriter writer; // finishes before what its tasks refer to goes
  keepSolverStates(run, writer, hooks);
  hooks.fitted = [&](int k, const FrameFit& fit)
  {
    // Every few frames, what the frames before them left in the allocator's heaps goes back.
    if (k % 16 == 0) releaseFreedMemory();
    errorsOf(k, fit.positions);
    // Once frame k is written, the state and landmarks of the frame its chain fitted before it
    // are no longer needed (the template frame's stay: every chain starts from it).
    const int previous = chainPredecessor(run, k);
    const std::string used = previous >= 0 && previous != j ? solverStatePath(run, previous) : "";
    if (previous != j) run.landmarks.release(previous);
    // The writer gets copies: the chain moves on to the next frame at once.
    writer.submit(
        [&output, number = in.frameNumber[k], fit, errors = run.errors[k], used]()
        {
          output.write(number, fit, errors);
          std::error_code ignored;
          if (!used.empty()) fs::remove(used, ignored);
        });
  };
  Progress progress("align", n);
  hooks.progress = [&](double done)
  {
    progress.step(static_cast<int>(n * done + 0.5));
    return true;
  };
  hooks.chainCount = chainCount(s);
  hooks.fitChains = ownChains(s);
  run.fits = hooks.fitChains.empty() ? std::vector<FrameFit>(n)
                                     : fitTemplateSequence(run.templateMesh(), j, n, hooks, s.fit);
  writer.finish();
  ranks::barrier(); // every process has written its frames
  progress.finish();
  shareFits(run, output, errorsOf);
  if (!ranks::leader()) return;
  fs::remove_all(run.out / "fit_state"); // every frame is written: no fit continues from these
  output.writeCollection(in.frameNumber, s.sequence.fps);
}

/// The frames fitted again because their first fit was doubtful, and what was kept.
void addRetryMetrics(nlohmann::json& metrics, const std::vector<FrameFit>& fits)
{
  std::vector<int> attempts;
  nlohmann::json retried = nlohmann::json::array();
  for (int k = 0; k < static_cast<int>(fits.size()); ++k)
  {
    const FrameFit& f = fits[k];
    attempts.push_back(f.attempts);
    if (f.attempts > 1)
      retried.push_back({{"frame", k},
                         {"attempts", f.attempts},
                         {"kept", f.recovery.empty() ? "the first fit" : f.recovery},
                         {"severity", f.doubt}});
  }
  metrics["per_frame_fit_attempts"] = attempts;
  metrics["retried_frames"] = retried;
}

/// Each frame's confidence; every doubtful frame is listed with its doubt and warned about.
void addConfidenceMetrics(nlohmann::json& metrics, const SequenceQuality& quality,
                          const std::vector<std::string>& files)
{
  std::vector<double> confidence, stretch, folded;
  nlohmann::json bodyDistance = nlohmann::json::array(), extentGap = nlohmann::json::array();
  for (const FrameConfidence& c : quality.confidence)
  {
    confidence.push_back(c.confidence);
    stretch.push_back(c.stretch);
    folded.push_back(c.folded);
    bodyDistance.push_back(c.bodyDistance >= 0 ? nlohmann::json(c.bodyDistance) : nullptr);
    extentGap.push_back(c.extentGap >= 0 ? nlohmann::json(c.extentGap) : nullptr);
  }
  metrics["per_frame_confidence"] = confidence;
  metrics["per_frame_stretch"] = stretch;
  metrics["per_frame_folded"] = folded;
  metrics["per_frame_body_distance_m"] = bodyDistance;
  metrics["per_frame_extent_gap_m"] = extentGap;
  nlohmann::json doubtful = nlohmann::json::array();
  for (int k : quality.doubtfulFrames)
    doubtful.push_back({{"frame", k}, {"file", files[k]}, {"doubt", quality.confidence[k].doubt}});
  metrics["doubtful_frames"] = doubtful;
  const int shown = 10;
  for (int i = 0; i < static_cast<int>(quality.doubtfulFrames.size()) && i < shown; ++i)
  {
    const int k = quality.doubtfulFrames[i];
    std::fprintf(stderr, "warning: frame %d (%s) is doubtful: %s\n", k, files[k].c_str(),
                 quality.confidence[k].doubt.c_str());
  }
  if (quality.doubtfulFrames.size() > static_cast<size_t>(shown))
    std::fprintf(stderr, "warning: %zu more doubtful frames (metrics.json: doubtful_frames)\n",
                 quality.doubtfulFrames.size() - shown);
}

/// Frame k's fitted vertices: the fit keeps only the template frame's (SequenceFitHooks::keepFits),
/// the others are read back from OUT/aligned.
Points alignedPositions(const Run& run, const AlignedOutput& output, int k)
{
  if (run.fits[k].positions.rows() > 0) return run.fits[k].positions;
  std::optional<FrameFit> fit = output.earlier(run.input.frameNumber[k]);
  if (!fit)
    throw Error(output.framePath(run.input.frameNumber[k]).string() +
                ": the aligned frame vanished or was damaged during the run");
  return std::move(fit->positions);
}

/// How well the aligned frames follow the input without a ground truth. With several processes
/// each measures its part of the sequence and the leader joins the parts, as one process would
/// have measured them; the others get nothing.
SequenceQuality measureQuality(const Run& run, const AlignedOutput& output)
{
  const int n = run.input.count();
  const auto [from, to] = rangePart(n, ranks::rank(), ranks::count());
  std::vector<double> known(n, -1.0);
  for (int k = from; k < to; ++k) known[k] = fittedSurfaceDistance(run.fits[k]);
  SequenceQuality part =
      sequenceQualityOfFrames([&](int k) { return alignedPositions(run, output, k); },
                              run.templateMesh().F, *run.input.frames, known, run.templateFrame,
                              FitJudgeOptions().limits, run.posedByBody, from, to);
  SequenceQuality quality;
  if (ranks::count() == 1)
  {
    summarise(part);
    quality = std::move(part);
  }
  else
  {
    const std::vector<std::string> parts =
        ranks::gatherBytes(encodeSequenceQuality(part, from, to));
    if (!ranks::leader()) return SequenceQuality();
    quality = joinSequenceQuality(parts, n);
  }
  // Frames whose start came from an unrelated frame's fit are doubtful whatever they measure,
  // and so are those whose body another pose explains almost as well.
  doubtFromBodies(quality, run.body.body);
  return quality;
}

/// metrics.json: inputs, template, errors (with a ground truth), quality without one, timings.
nlohmann::json evaluate(const Run& run, const AlignedOutput& output, const SequenceQuality& quality)
{
  const AlignSettings& s = run.settings;
  const Input& in = run.input;
  const int n = in.count(), j = run.templateFrame;
  nlohmann::json metrics;
  metrics["input"] = s.input;
  metrics["clothtrack_version"] = CLOTHTRACK_VERSION; // which release made these results
  metrics["frames"] = n;
  metrics["template_frame"] = j;
  metrics["template_criterion"] = run.templateDecidedBy;
  if (!run.templateFramesByPose.empty())
    metrics["template_frames_by_pose"] = run.templateFramesByPose;
  metrics["template_file"] = in.files[j];
  metrics["template_vertices"] = run.templateMesh().numVertices();
  metrics["frame_numbers"] = in.frameNumber;
  metrics["files"] = in.files;
  metrics["unit"] = s.sequence.unit;
  metrics["up"] = s.sequence.up;
  metrics["unit_scale"] = toConventions(s.sequence).unitScale;
  int resumed = 0;
  for (const FrameFit& f : run.fits) resumed += f.resumed;
  metrics["resumed_frames"] = resumed;
  metrics["reused_correspondence_frames"] = run.reusedCorrespondences;
  metrics["reused_landmark_frames"] = run.reusedLandmarks;
  metrics["register_frames"] = s.registerFrames;
  nlohmann::json jumps = nlohmann::json::array();
  for (const FrameJump& jump : in.jumps)
    jumps.push_back({{"frame", jump.frame},
                     {"file", in.files[jump.frame]},
                     {"size_ratio", jump.sizeRatio},
                     {"shift_m", jump.shift},
                     {"problem", jump.problem}});
  metrics["jumping_frames"] = jumps;
  metrics["threads"] = threadCount();
  metrics["solver"] = s.solver;
  metrics["predict_radius_m"] = s.prediction.predictRadius;
  metrics["landmark_consensus_m"] = s.prediction.landmarkConsensus;
  std::vector<double> landmarkCounts;
  for (int k = 0; k < run.landmarks.frames(); ++k)
    landmarkCounts.push_back(static_cast<double>(run.landmarks.count(k)));
  metrics["landmarks_per_frame"] = landmarkCounts;
  if (in.truth) addVertexErrorMetrics(metrics, run.errors, j, s.truthInput, run.verticesWithTruth);
  if (in.markers)
  {
    std::vector<Points> positions;
    for (int k = 0; k < n; ++k) positions.push_back(alignedPositions(run, output, k));
    addMarkerMetrics(metrics, positions, *in.markers, j, s.markersPath);
  }
  // Without ground truth too: how well the result covers each frame, and how smoothly it moves.
  metrics["per_frame_surface_distance_m"] = quality.surfaceDistance;
  metrics["per_frame_coverage_distance_m"] = quality.coverageDistance;
  metrics["mean_surface_distance_m"] = quality.meanSurfaceDistance;
  metrics["mean_coverage_distance_m"] = quality.meanCoverageDistance;
  metrics["mean_jitter_m"] = quality.meanJitter;
  addConfidenceMetrics(metrics, quality, in.files);
  addRetryMetrics(metrics, run.fits);
  return metrics;
}

void addTimings(nlohmann::json& metrics, const Run& run, double total)
{
  const int n = run.input.count();
  int fitted = 0;
  double fittedSeconds = 0;
  for (int k = 0; k < n; ++k)
    if (!run.fits[k].resumed && k != run.templateFrame)
      ++fitted, fittedSeconds += run.fits[k].seconds;
  metrics["seconds_total"] = total;
  metrics["seconds_per_frame"] = total / n;
  metrics["seconds_per_fitted_frame"] = fitted ? fittedSeconds / fitted : 0.0;
  metrics["stage_seconds"] = run.stageSeconds;
  metrics["peak_rss_mb"] = peakMemoryMB();
  metrics["stage_peak_rss_mb"] = run.stagePeakMemory;
  // Streaming: how often frames were read after the first time, and whether from the work folder.
  metrics["frame_memory_mb"] = run.settings.frameMemoryMB;
  metrics["frames_kept_on_disk"] = run.input.spilled;
  metrics["frame_reads"] = run.input.frames->loads();
}

void printSummary(const Run& run, const nlohmann::json& metrics, double total)
{
  const int n = run.input.count();
  const int resumed = metrics["resumed_frames"].get<int>();
  std::printf("aligned %d frames (template frame %d) in %.1f s (%.2f s/frame%s)", n,
              run.templateFrame, total, total / n,
              resumed ? (", " + std::to_string(resumed) + " resumed").c_str() : "");
  if (metrics.contains("mean_vertex_error_m"))
    std::printf("; mean vertex error %.2f cm, %.2f %% within 10 cm",
                100 * metrics["mean_vertex_error_m"].get<double>(),
                100 * metrics["within_10cm"].get<double>());
  if (metrics.contains("marker_mean_error_m"))
    std::printf("; markers %.2f cm", 100 * metrics["marker_mean_error_m"].get<double>());
  std::printf("\nwrote %s and %s\n", (run.out / "aligned.pvd").c_str(),
              (run.out / "metrics.json").c_str());
  std::fflush(stdout);
}

/// The cleaned frames a long run kept in the work folder (AlignInput.h): a next run reads its
/// input again anyway.
void removeFrameCopies(const Run& run)
{
  std::error_code ignored;
  const fs::path copies =
      ranks::leader() ? run.work : run.work / ("rank_" + std::to_string(ranks::rank()));
  fs::remove_all(copies / "frames", ignored);
  fs::remove_all(copies / "truth", ignored);
  if (!ranks::leader()) fs::remove(copies, ignored); // once empty
}

/// Runs `stage` and records its wall time under `name`.
template <class Stage> void timed(Run& run, const char* name, const Stage& stage)
{
  const auto start = Clock::now();
  stage();
  releaseFreedMemory();
  run.stageSeconds[name] = since(start);
  run.stagePeakMemory[name] = peakMemoryMB(); // where the peak was reached
}

/// Reading and stage 1. With several processes every process reads the frames at once, but
/// point clouds are first reconstructed by the leader alone. A sequence long enough to share is
/// then fitted by every process, each its segment; a shorter one by the leader alone, which keeps
/// the body fit in the work folder for the others to take from there.
void readAndFitBodies(Run& run)
{
  const bool leader = ranks::leader();
  const bool leaderReadsFirst = ranks::count() > 1 && inputHasPointClouds(run.settings);
  if (!leader && leaderReadsFirst) ranks::barrier();
  // Each process keeps its own copies of frames that do not fit in memory, and clears what an
  // interrupted run left among them; the leader clears the rest.
  const fs::path copies = leader ? run.work : run.work / ("rank_" + std::to_string(ranks::rank()));
  if (!leader) removeLeftoverParts({copies});
  timed(run, "read", [&] { run.input = readInput(run.settings, copies); });
  checkForcedTemplate(run);
  fs::create_directories(run.work);
  fs::create_directories(run.out);
  if (leader) removeLeftoverParts({run.out, run.work});
  const bool together = bodyFitSharing(run.settings).splits(run.input.count());
  if (!leader && !leaderReadsFirst) ranks::barrier();
  if (together && leader) ranks::barrier();
  timed(run, "body_fit", [&] { runBodyStage(run, together); });
  if (!together && leader) ranks::barrier();
}

/// The stages' seconds of every process, in metrics.json when several shared the run.
void addRankTimings(nlohmann::json& metrics, const Run& run)
{
  const char* stages[] = {"read", "body_fit", "select_template", "correspond", "fit", "evaluate"};
  std::vector<double> own;
  for (const char* stage : stages) own.push_back(run.stageSeconds.value(stage, 0.0));
  const std::vector<double> all = ranks::gather(own);
  metrics["ranks"] = ranks::count();
  nlohmann::json perRank = nlohmann::json::array();
  for (size_t r = 0; r * own.size() < all.size(); ++r)
  {
    nlohmann::json seconds;
    for (size_t i = 0; i < own.size(); ++i) seconds[stages[i]] = all[r * own.size() + i];
    perRank.push_back(seconds);
  }
  metrics["rank_stage_seconds"] = perRank;
}

int alignOnce(const AlignSettings& settings, AlignMode mode)
{
  Run run;
  run.settings = settings;
  const AlignSettings& s = run.settings;
  // Processes on one machine share its cores.
  const int cores = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  setThreadCount(s.threads > 0 || ranks::count() == 1 ? s.threads
                                                      : std::max(1, cores / ranks::count()));
  const auto start = Clock::now();
  run.out = s.output;
  run.work = s.workDir.empty() ? run.out / "work" : fs::path(s.workDir);
  readAndFitBodies(run);
  timed(run, "select_template", [&] { runTemplateStage(run); });
  const AlignedOutput output(run.out, run.templateMesh());
  startKeys(run);
  ranks::barrier(); // the leader has removed results of other options
  timed(run, "correspond", [&] { runCorrespondenceStage(run, output); });
  ranks::barrier(); // every frame's correspondences are in the work folder
  if (mode == AlignMode::CorrespondOnly)
  {
    removeFrameCopies(run);
    if (!ranks::leader()) return 0;
    std::printf("landmarks and correspondences of %d frames (template frame %d) in %s; "
                "'clothtrack fit' with the same input and work folder fits the template\n",
                run.input.count(), run.templateFrame, run.work.c_str());
    return 0;
  }
  timed(run, "fit", [&] { runFitStage(run, output); });
  nlohmann::json metrics;
  timed(run, "evaluate",
        [&]
        {
          const SequenceQuality quality = measureQuality(run, output);
          if (ranks::leader()) metrics.update(evaluate(run, output, quality));
        });
  addRankTimings(metrics, run);
  if (!ranks::leader())
  {
    removeFrameCopies(run);
    return 0;
  }
  removeFrameCopies(run);
  const double total = since(start);
  addTimings(metrics, run, total);
  writeTextAtomically((run.out / "metrics.json").string(), metrics.dump(2) + "\n");
  printSummary(run, metrics, total);
  if (!s.noReport)
  {
    writeReport(s.output);
    std::printf("report: %s\n", (run.out / "report.html").c_str());
  }
  return 0;
}

int alignCommand(const Args& args, AlignMode mode)
{
  std::optional<AlignSettings> settings = parseAlignSettings(args, mode);
  if (!settings) return 0;
  const auto alignUnderItsTemplates = [mode](const AlignSettings& one)
  {
    return alignChoosingTemplate(one,
                                 [mode](const AlignSettings& t) { return alignOnce(t, mode); });
  };
  if (settings->modelPaths.size() > 1)
    return alignUnderEachModel(*settings, alignUnderItsTemplates);
  return alignUnderItsTemplates(*settings);
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
