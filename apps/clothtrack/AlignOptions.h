#pragma once
// The options of 'clothtrack align', 'correspond' and 'fit': their parsing and checks. Every
// default is the core's own (the options structs of the stages).
#include "Commands.h"
#include "Options.h"

#include <clothtrack/correspondence/PatchCorrespondence.h>
#include <clothtrack/eval/AlignmentError.h>
#include <clothtrack/fit/MotionPrediction.h>
#include <clothtrack/fit/TemplateFit.h>
#include <clothtrack/pipeline/BodyStartPrediction.h>
#include <clothtrack/reconstruction/SurfaceReconstruction.h>
#include <clothtrack/selection/TemplateSelection.h>

#include <nlohmann/json.hpp>

#include <optional>
#include <string>
#include <vector>

namespace clothtrack::app
{
/// What a run does: everything ('align'), stages 1 and 2 into the work folder ('correspond'), or
/// stage 3 and the evaluation from a work folder that 'correspond' filled ('fit').
enum class AlignMode
{
  Full,
  CorrespondOnly,
  FitOnly
};

/// The --model value that names the built-in body model.
inline constexpr const char* kBuiltinModelName = "builtin";

struct AlignSettings
{
  AlignMode mode = AlignMode::Full;
  std::string input, output, truthInput, frameSpec, modelPath, markersPath, workDir;
  /// Several --model values: the sequence is aligned under each, and one alignment is kept by its
  /// ground-truth-free figures (AlignModels.h). "builtin" names the built-in model. One value is
  /// modelPath.
  std::vector<std::string> modelPaths;
  std::string solver = "exact";
  std::string factorBackend = factorBackendName(FactorBackend::Block);
  SequenceOptions sequence;
  int threads = 0;
  /// Chains of the template fit (sequenceChains); 0: two, or one per process under mpirun.
  int chains = 0;
  int forcedTemplate = -1; ///< -1: chosen automatically
  /// Template frames aligned under, one alignment kept (AlignTemplates.h); 0: three on a
  /// collection of poses, one on a sequence.
  int templateCandidates = 0;
  TemplateSelectionOptions selection;
  TruthAnchorOptions truth;
  StartPredictionOptions prediction;
  TemplateFitOptions fit;
  PatchCorrespondenceOptions patches;
  /// Point-cloud input is reconstructed into meshes first (OUT/reconstructed).
  ReconstructionOptions reconstruction;
  /// Each frame's fit starts from the template posed by the body fitted to the frame
  /// (pipeline/BodyStartPrediction.h); frames with a doubtful body fit start from the landmark
  /// prediction.
  bool startFromBody = true;
  /// The template posed by a frame's body is first stretched to the frame's height
  /// (stretchToFrameExtent in pipeline/BodyStartPrediction.h).
  bool stretchStart = true;
  /// Correspondences further than this from the body's start are dropped (metres; 0 keeps them
  /// all; targetsAgreeingWithBodyStart in pipeline/BodyStartPrediction.h).
  double correspondenceGate = kDefaultCorrespondenceGate;
  /// A frame whose fit is clearly doubtful is fitted again from other starts (FitJudge.h).
  bool retryDoubtful = true;
  /// Body fit: each frame starts from its predecessor's pose moved by the rigid motion between
  /// the two surfaces (BodyStageOptions::registerFrames).
  bool registerFrames = false;
  /// Body fit: the shape's estimation starts at the stature the frames suggest
  /// (BodyFitOptions::statureStart).
  bool statureStart = false;
  /// Body fit: frames unrelated to their predecessor are also started with their limbs at rest,
  /// aimed at unpaired extremities and swapped in pairs (BodyFitOptions::limbRestarts).
  bool limbRestarts = true;
  /// Body fit: the shape estimated two ways, the better kept (BodyFitOptions::
  /// twoShapes); off with --no-two-shapes.
  bool twoShapes = true;
  /// Body fit: two shapes this close at rest are one (BodyFitOptions::sameShapeTolerance, m).
  double sameShapeTolerance = BodyFitOptions{}.sameShapeTolerance;
  /// Under mpirun, each process fits the body to a segment of the sequence, tracking
  /// bodyFitOverlap frames of its neighbours' segments first (BodyFitSharing). Off: the first
  /// process fits the whole sequence, and the result is one process's bit for bit.
  bool splitBodyFit = false;
  int bodyFitOverlap = 8;
  bool skipBadFrames = false;
  bool noReport = false;
  /// Megabytes of frames (input and ground truth each) kept in memory between their uses; past
  /// it, frames are read again from cleaned copies in the work folder. Peak memory then no
  /// longer grows with the sequence's length.
  double frameMemoryMB = 64;

  /// The body fit gives the landmarks (correspondences, start prediction) and the poses that
  /// choose the template; when none of these is wanted, it is skipped.
  bool needLandmarks() const;
  /// The options that decide the aligned frames (run.json): results made with others are redone.
  nlohmann::json fitKey() const;
};

/// The settings from the command line; nullopt after --help. Throws UsageError.
std::optional<AlignSettings> parseAlignSettings(const Args& args, AlignMode mode);
} // namespace clothtrack::app
