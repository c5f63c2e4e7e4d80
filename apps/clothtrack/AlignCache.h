#pragma once
// Intermediate results of 'clothtrack align' kept under OUT/work, so that an interrupted run
// resumes where it stopped. Every file is written beside and renamed: a file that exists is
// complete. A file made for other inputs (other frame files) is not reused.
#include <clothtrack/PatchCorrespondence.h>
#include <clothtrack/TemplateFit.h>
#include <clothtrack/body/BodyFit.h>

#include <nlohmann/json.hpp>

#include <optional>
#include <string>
#include <vector>

namespace clothtrack::app
{
using FrameLandmarks = std::vector<OrientedSurfacePoint>;

/// Stage 1 output: the fitted body (shape, pose and status per frame), the landmarks of every
/// frame and how far its body is from the rest pose (NaN where the fit is poor or failed), with
/// the key of the inputs they came from.
struct BodyStage
{
  Eigen::VectorXd beta;
  std::vector<BodyPose> poses;
  std::vector<BodyFitStatus> status;
  std::vector<FrameLandmarks> landmarks;
  std::vector<double> restPoseDistance;
};
void writeBodyStage(const std::string& path, const nlohmann::json& key, const BodyStage& stage);
/// Empty when the file is missing, unreadable or was made with another key.
std::optional<BodyStage> readBodyStage(const std::string& path, const nlohmann::json& key);

/// OUT/body_fit.json: the model, beta and every frame's pose and status, in the layout of
/// 'clothtrack body-fit' (its per-frame figures apart), for the report and for users.
void writeBodyFitSummary(const std::string& path, const std::string& modelPath,
                         const std::vector<std::string>& files, const BodyStage& stage);

/// Stage 2 output for one frame: the template vertices' targets.
void writeTargets(const std::string& path, const std::string& frameFile,
                  const VertexTargets& targets);
/// Empty when missing, for another frame file or another template size.
std::optional<VertexTargets> readTargets(const std::string& path, const std::string& frameFile,
                                         int templateVertices);
} // namespace clothtrack::app
