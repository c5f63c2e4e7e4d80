#pragma once
// Intermediate results of 'clothtrack align' kept under OUT/work, so that an interrupted run
// resumes where it stopped. Every file is written beside and renamed: a file that exists is
// complete. A file made for other inputs (other frame files) is not reused.
#include <clothtrack/PatchCorrespondence.h>
#include <clothtrack/TemplateFit.h>

#include <nlohmann/json.hpp>

#include <optional>
#include <string>
#include <vector>

namespace clothtrack::app
{
using FrameLandmarks = std::vector<OrientedSurfacePoint>;

/// Stage 1 output: the landmarks of every frame, with the key of the inputs they came from.
void writeLandmarks(const std::string& path, const nlohmann::json& key,
                    const std::vector<FrameLandmarks>& landmarks);
/// Empty when the file is missing, unreadable or was made with another key.
std::optional<std::vector<FrameLandmarks>> readLandmarks(const std::string& path,
                                                         const nlohmann::json& key);

/// Stage 2 output for one frame: the template vertices' targets.
void writeTargets(const std::string& path, const std::string& frameFile,
                  const VertexTargets& targets);
/// Empty when missing, for another frame file or another template size.
std::optional<VertexTargets> readTargets(const std::string& path, const std::string& frameFile,
                                         int templateVertices);
} // namespace clothtrack::app
