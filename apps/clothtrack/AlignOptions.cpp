#include "AlignOptions.h"
#include "ReconstructRun.h"

#include <clothtrack/body/SkinnedTemplate.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <sstream>

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

void addFitOptions(po::options_description& options, AlignSettings& s, std::string& stageSpec)
{
  TemplateFitOptions& fit = s.fit;
  options.add_options()("solver", po::value(&s.solver)->default_value(s.solver),
                        "template fit solver: exact or lbfgs")(
      "chains", po::value(&s.chains),
      "chains of the template fit (default 2, or the processes under mpirun if more): past two, "
      "each side of the template is split and each chain's key frame is fitted from the template")(
      "solver-tolerance", po::value(&fit.solverTolerance)->default_value(fit.solverTolerance),
      "exact solver: relative residual of each stage's last round")(
      "intermediate-tolerance",
      po::value(&fit.intermediateTolerance)->default_value(fit.intermediateTolerance),
      "exact solver: relative residual of the rounds before a stage's last")(
      "factor-backend", po::value(&s.factorBackend)->default_value(s.factorBackend),
      "exact solver: factorisation of the preconditioner, block (the library's own) or cholmod "
      "(SuiteSparse)")(
      "refactor-steps", po::value(&fit.refactorSteps)->default_value(fit.refactorSteps),
      "exact solver: renew a stage's factorisation after a frame that needed more conjugate-"
      "gradient steps per round than this (0: only when they fail)")(
      "nearest-reuse", po::value(&fit.nearestReuse)->default_value(fit.nearestReuse),
      "metres: a template vertex that moved less than this since its last closest-point search "
      "is projected onto the same triangle (0: search every round)")(
      "coverage-weight", po::value(&fit.coverageWeight)->default_value(fit.coverageWeight),
      "template fit: weight of the frame-to-template term (each frame vertex pulls its nearest "
      "template vertex), as a fraction of each stage's nearest-point weight (0: off)")(
      "stages", po::value(&stageSpec),
      "template fit weight stages wc,ws,wd,wt separated by '/' (default the paper's: "
      "1,400,0,0.1/1,200,10,0.1/0,100,10,0.1/0,50,10,0.1)")(
      "predict-radius",
      po::value(&s.prediction.predictRadius)->default_value(s.prediction.predictRadius),
      "each frame's fit starts from its neighbour's moved by the landmarks' locally rigid motion, "
      "weighted over this radius (m; 0: from the neighbour's fit as it is)")(
      "landmark-consensus",
      po::value(&s.prediction.landmarkConsensus)->default_value(s.prediction.landmarkConsensus),
      "start prediction: leave out landmark pairs that the locally rigid motion of their "
      "neighbours does not carry within this distance (m, random sample consensus; 0: keep all)")(
      "no-body-start", po::bool_switch(),
      "start each frame's fit from its neighbour's (moved as --predict-radius says) rather than "
      "from the template posed by the body fitted to the frame")(
      "no-start-stretch", po::bool_switch(),
      "start each frame from the template posed by its body as it is, rather than stretched "
      "along the up axis to the frame's lowest and highest points")(
      "correspondence-gate", po::value(&s.correspondenceGate)->default_value(s.correspondenceGate),
      "drop correspondences further than this from the template posed by the frame's body (m; "
      "0 keeps them all)")(
      "register-frames", po::bool_switch(&s.registerFrames),
      "body fit: start each frame from its predecessor's pose moved by the rigid motion between "
      "the two surfaces (generalized ICP)")(
      "stature-start", po::bool_switch(&s.statureStart),
      "body fit: start the shape's estimation at the stature the frames suggest rather than at "
      "the mean body (for people far from 1.7 m)")(
      "no-two-shapes", po::bool_switch(),
      "body fit: estimate the shape one way only, with the key frames' poses fixed (its pass 2 "
      "runs once, not under two shapes)")(
      "same-shape-tolerance", po::value(&s.sameShapeTolerance)->default_value(s.sameShapeTolerance),
      "body fit: two shapes whose rest-pose bodies lie this close at every vertex are one, and "
      "pass 2 runs under the first only (m; 0: always under both)")(
      "no-limb-restarts", po::bool_switch(),
      "body fit: do not start frames unrelated to their predecessor again with their limbs at "
      "rest, aimed at the extremities their fit leaves unpaired, or turned half round")(
      "split-body-fit", po::bool_switch(&s.splitBodyFit),
      "under mpirun: each process fits the body to its own segment of the sequence (faster; the "
      "result differs a little from one process's, which is otherwise kept bit for bit)")(
      "body-fit-overlap", po::value(&s.bodyFitOverlap)->default_value(s.bodyFitOverlap),
      "with --split-body-fit: frames of the neighbouring segments each process tracks first")(
      "no-retry", po::bool_switch(),
      "keep a frame's first fit even when it is clearly doubtful (by default such a frame is "
      "fitted again from other starts and the most confident fit kept)")(
      "no-correspondence", po::bool_switch(),
      "ablation: fit without the correspondence term Ec (with --predict-radius 0 --no-body-start: "
      "nearest points alone, a sequential non-rigid ICP)");
}

void addCorrespondenceOptions(po::options_description& options, AlignSettings& s,
                              std::string& criterion)
{
  PatchCorrespondenceOptions& patches = s.patches;
  TemplateSelectionOptions& selection = s.selection;
  options.add_options()(
      "template-frame,template", po::value(&s.forcedTemplate)->default_value(-1),
      "template frame within the selected frames (-1: chosen automatically; also --template)")(
      "template-candidates", po::value(&s.templateCandidates)->default_value(0),
      "align under this many template frames, the next by pose after the chosen one, and keep "
      "the alignment that is both less stretched and closer to the frames (0: 3 on a "
      "collection of unrelated poses, 1 on a sequence)")(
      "template-criterion", po::value(&criterion)->default_value(criterion),
      "last template criterion after the topology: rest-pose (fitted body closest to the rest "
      "pose) or area-ratio (the paper's: most uniform mesh)")(
      "minimum-shell-area,min-shell-area",
      po::value(&selection.minimumShellArea)->default_value(selection.minimumShellArea),
      "template choice: components smaller than this (m^2) are not counted as body parts (also "
      "--min-shell-area)")(
      "persistence", po::value(&selection.persistence)->default_value(selection.persistence),
      "template choice: a split counts only if it lasts this many consecutive frames")(
      "epsilon", po::value(&patches.epsilon)->default_value(patches.epsilon),
      "near-isometry tolerance of the patches (m)")(
      "maximum-radius,max-radius",
      po::value(&patches.maximumRadius)->default_value(patches.maximumRadius),
      "patch radius tau_d (m; also --max-radius)")(
      "minimum-radius,min-radius",
      po::value(&patches.minimumRadius)->default_value(patches.minimumRadius),
      "smallest patch kept, tau_s (m; also --min-radius)")(
      "minimum-seed-consensus,seed-consensus",
      po::value(&patches.minimumSeedConsensus)->default_value(patches.minimumSeedConsensus),
      "share of the nearby landmarks whose geodesic distances a landmark pair must preserve to "
      "seed a patch (0: every pair seeds one; also --seed-consensus)");
}

void addRunOptions(po::options_description& options, AlignSettings& s)
{
  options.add_options()("input", po::value(&s.input)->required(),
                        "folder, glob pattern, list file or mesh file")(
      "output,o", po::value(&s.output)->required(), "output folder")(
      "ground-truth", po::value(&s.truthInput),
      "ground-truth sequence (one connectivity, same frames as INPUT): adds the errors")(
      "frames", po::value(&s.frameSpec),
      "frames A:B of the input (A included, B not; either may be left out)")(
      "model", po::value(&s.modelPaths)->composing(),
      "body model file (default: the built-in model, also named 'builtin'); given more than once, "
      "the sequence is aligned under each model into OUT/models/, and the first model's alignment "
      "is kept unless another's is both less stretched and closer to the frames")(
      "threads", po::value(&s.threads)->default_value(0),
      "threads (0: all cores)")("skip-bad-frames", po::bool_switch(&s.skipBadFrames),
                                "leave out unreadable frames with a warning instead of stopping")(
      "no-report", po::bool_switch(&s.noReport), "skip the plots, renders and report.html")(
      "frame-memory", po::value(&s.frameMemoryMB)->default_value(s.frameMemoryMB),
      "MB of frames kept in memory between uses (input and ground truth each); the rest are read "
      "again from cleaned copies in the work folder, so memory does not grow with the length")(
      "maximum-truth-distance,truth-distance",
      po::value(&s.truth.maximumTruthDistance)->default_value(s.truth.maximumTruthDistance),
      "template vertices further than this from the ground truth have no error (m; also "
      "--truth-distance)")(
      "markers", po::value(&s.markersPath),
      "marker trajectories (CSV frame,time,marker,x,y,z, frames numbered as the input's): adds "
      "the error at each marker's nearest template vertex")(
      "work", po::value(&s.workDir),
      "folder for intermediate results (default OUT/work); runs on the same input with other fit "
      "options may share it and reuse its landmarks and correspondences");
}

void check(const AlignSettings& s)
{
  const TemplateFitOptions& fit = s.fit;
  const PatchCorrespondenceOptions& patches = s.patches;
  if (s.threads < 0) throw UsageError{"--threads must be 0 or more"};
  if (s.templateCandidates < 0) throw UsageError{"--template-candidates must be 0 or more"};
  if (s.modelPaths.size() > 1 && s.mode != AlignMode::Full)
    throw UsageError{"several --model values need the whole 'clothtrack align'"};
  for (const std::string& path : s.modelPaths)
    if (!path.empty() && !std::filesystem::is_regular_file(path))
      throw UsageError{path + ": no such body model file (--model; 'builtin' is the built-in one)"};
  if (s.bodyFitOverlap < 1) throw UsageError{"--body-fit-overlap must be 1 or more"};
  if (!(s.sameShapeTolerance >= 0)) throw UsageError{"--same-shape-tolerance must be 0 or more"};
  if (s.chains < 0 || s.chains == 1) throw UsageError{"--chains must be 2 or more"};
  if (!(s.frameMemoryMB >= 0)) throw UsageError{"--frame-memory must be 0 or more (MB)"};
  if (s.factorBackend != "block" && s.factorBackend != "cholmod")
    throw UsageError{"--factor-backend must be block or cholmod (got '" + s.factorBackend + "')"};
  if (!factorBackendAvailable(s.fit.factorBackend))
    throw UsageError{"--factor-backend cholmod: this build has no CHOLMOD (libsuitesparse-dev)"};
  if (s.solver != "exact" && s.solver != "lbfgs")
    throw UsageError{"--solver must be exact or lbfgs (got '" + s.solver + "')"};
  if (!(patches.epsilon > 0) || !(patches.minimumRadius >= 0) || !(patches.maximumRadius > 0))
    throw UsageError{
        "--epsilon and --maximum-radius must be positive, --minimum-radius at least 0"};
  if (!(patches.minimumSeedConsensus >= 0 && patches.minimumSeedConsensus <= 1))
    throw UsageError{"--minimum-seed-consensus must be between 0 and 1"};
  if (!(s.selection.minimumShellArea >= 0))
    throw UsageError{"--minimum-shell-area must be 0 or more"};
  if (s.selection.persistence < 1) throw UsageError{"--persistence must be at least 1"};
  if (!(s.truth.maximumTruthDistance > 0))
    throw UsageError{"--maximum-truth-distance must be positive"};
  if (!(s.prediction.predictRadius >= 0)) throw UsageError{"--predict-radius must be 0 or more"};
  if (!(s.correspondenceGate >= 0)) throw UsageError{"--correspondence-gate must be 0 or more (m)"};
  if (!(s.prediction.landmarkConsensus >= 0))
    throw UsageError{"--landmark-consensus must be 0 or more"};
  if (!(fit.solverTolerance > 0 && fit.solverTolerance < 1) ||
      !(fit.intermediateTolerance > 0 && fit.intermediateTolerance < 1))
    throw UsageError{"--solver-tolerance and --intermediate-tolerance must be in (0, 1)"};
  if (!(fit.refactorSteps >= 0) || !std::isfinite(fit.refactorSteps))
    throw UsageError{"--refactor-steps must be 0 or more"};
  if (!(fit.nearestReuse >= 0) || !std::isfinite(fit.nearestReuse))
    throw UsageError{"--nearest-reuse must be 0 or more"};
  if (!(fit.coverageWeight >= 0) || !std::isfinite(fit.coverageWeight))
    throw UsageError{"--coverage-weight must be 0 or more"};
}

const char* usageOf(AlignMode mode)
{
  switch (mode)
  {
  case AlignMode::CorrespondOnly:
    return "clothtrack correspond INPUT -o OUT [--work DIR] [options] (stages 1 and 2 into the "
           "work folder, for 'clothtrack fit')";
  case AlignMode::FitOnly:
    return "clothtrack fit INPUT -o OUT [--work DIR] [options] (stage 3 from the work folder "
           "that 'clothtrack correspond' filled)";
  default:
    return "clothtrack align INPUT -o OUT [--ground-truth GT] [options]";
  }
}
} // namespace

bool AlignSettings::needLandmarks() const
{
  return fit.useCorrespondence || prediction.predictRadius > 0 || startFromBody ||
         (forcedTemplate < 0 && selection.templateCriterion == TemplateCriterion::RestPose);
}

nlohmann::json AlignSettings::fitKey() const
{
  return {{"solver", solver},
          {"tolerances", {fit.solverTolerance, fit.intermediateTolerance}},
          {"refactor_steps", fit.refactorSteps},
          {"factor_backend", factorBackend},
          {"nearest_reuse", fit.nearestReuse},
          {"coverage_weight", fit.coverageWeight},
          {"truth_distance", truth.maximumTruthDistance},
          {"predict_radius", prediction.predictRadius},
          {"landmark_consensus", prediction.landmarkConsensus},
          {"body_start", startFromBody},
          {"start_stretch", stretchStart},
          {"correspondence_gate", correspondenceGate},
          {"skinning_revision", kSkinnedTemplateRevision},
          {"use_correspondence", fit.useCorrespondence},
          {"retry_doubtful", retryDoubtful},
          {"chains", chains},
          {"stages", stagesJson(fit.stages)}};
}

std::optional<AlignSettings> parseAlignSettings(const Args& args, AlignMode mode)
{
  AlignSettings s;
  s.mode = mode;
  std::string criterion = "rest-pose", stageSpec;
  po::options_description options("align options");
  addRunOptions(options, s);
  addCorrespondenceOptions(options, s, criterion);
  addFitOptions(options, s, stageSpec);
  addReconstructionOptions(options, s.reconstruction);
  addSequenceOptions(options, s.sequence);
  po::positional_options_description positional;
  positional.add("input", 1);
  po::variables_map values;
  if (!parseOptions(args, usageOf(mode), options, positional, values)) return std::nullopt;
  s.fit.solver = s.solver == "exact" ? FitSolver::Exact : FitSolver::LBFGS;
  s.fit.factorBackend =
      s.factorBackend == "cholmod" ? FactorBackend::Cholmod : FactorBackend::Block;
  if (!stageSpec.empty()) s.fit.stages = parseStages(stageSpec);
  s.fit.useCorrespondence = !values["no-correspondence"].as<bool>();
  s.retryDoubtful = !values["no-retry"].as<bool>();
  s.startFromBody = !values["no-body-start"].as<bool>();
  s.stretchStart = !values["no-start-stretch"].as<bool>();
  s.limbRestarts = !values["no-limb-restarts"].as<bool>();
  s.twoShapes = !values["no-two-shapes"].as<bool>();
  s.selection.templateCriterion = parseTemplateCriterion(criterion);
  for (std::string& path : s.modelPaths)
    if (path == kBuiltinModelName) path.clear();
  if (s.modelPaths.size() == 1) s.modelPath = s.modelPaths.front();
  check(s);
  resolveAutomatic(s.sequence, s.input);
  return s;
}
} // namespace clothtrack::app
