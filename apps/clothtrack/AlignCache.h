#pragma once
// Intermediate results of 'clothtrack align' kept under OUT/work, so that an interrupted run
// resumes where it stopped. Every file is written beside and renamed: a file that exists is
// complete. A file made for other inputs (other frame files) is not reused.
#include <clothtrack/correspondence/PatchCorrespondence.h>
#include <clothtrack/fit/TemplateFit.h>
#include <clothtrack/pipeline/BodyStage.h>

#include <nlohmann/json.hpp>

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace clothtrack::app
{
/// What the work folder keeps of stage 1: the fitted body (shape; pose and status per frame, the
/// rest of each frame's record is not kept) and the landmarks of every frame. The frames are
/// empty when the body fit was skipped.
struct BodyStage
{
  BodyFitResult body;
  /// Per frame, its landmarks as the body fit found them; empty when read back from the work
  /// folder (StoredLandmarks reads them there when needed).
  std::vector<FrameLandmarks> landmarks;
  /// Per frame, where its line starts in the work folder's file and how many landmarks it holds.
  std::vector<std::int64_t> lineOffsets;
  std::vector<int> landmarkCounts;
};

/// Writes the fitted body in the layout of the body_fit.json of 'clothtrack body-fit' (its
/// per-frame figures apart): model, beta, and per frame the file, status, pose and
/// rest_pose_distance. OUT/body_fit.json, for the report and for users. Written frame by frame:
/// no document of the whole sequence is built.
void writeBodyFitJson(const std::string& path, const std::string& modelPath,
                      const std::vector<std::string>& files, const BodyStage& stage);

/// The body stage with the key of the inputs it came from, as JSON lines: the key and the shape
/// first, then one line per frame (its body fit and landmarks), written and read a frame at a
/// time.
/// Fills the stage's lineOffsets and landmarkCounts.
void writeBodyStage(const std::string& path, const nlohmann::json& key,
                    const std::vector<std::string>& files, BodyStage& stage);
/// Empty when the file is missing, unreadable or was made with another key. The landmarks stay
/// in the file: lineOffsets and landmarkCounts say where.
std::optional<BodyStage> readBodyStage(const std::string& path, const nlohmann::json& key);

/// Stage 2 output for one frame: the template vertices' targets.
void writeTargets(const std::string& path, const std::string& frameFile,
                  const VertexTargets& targets);
/// Empty when missing, for another frame file or another template size.
std::optional<VertexTargets> readTargets(const std::string& path, const std::string& frameFile,
                                         int templateVertices);
/// The template fit's solver state after one frame (TemplateFitterState): a run stopped after
/// that frame continues from it exactly as it would have without the stop.
void writeFitterState(const std::string& path, const TemplateFitterState& state);
/// Empty when missing, truncated or made for another template size.
std::optional<TemplateFitterState> readFitterState(const std::string& path, int templateVertices);
} // namespace clothtrack::app
