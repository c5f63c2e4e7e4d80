#pragma once
// 'clothtrack align --model A --model B ...': the whole alignment under each body model, and one
// kept by its ground-truth-free figures (eval/ModelChoice.h: the first, unless another is both
// less stretched and closer to the frames).
//   OUT/models/<i>_<name>/   each model's alignment (its own work folder, metrics.json)
//   OUT/aligned.pvd, aligned/, body_fit.json, run.json   moved from the kept model's folder
//   OUT/metrics.json         the kept model's, with "model" and "model_choice" added
#include "AlignOptions.h"

#include <clothtrack/eval/ModelChoice.h>

#include <nlohmann/json.hpp>

#include <filesystem>
#include <functional>
#include <string>

namespace clothtrack::app
{
/// The ground-truth-free figures of an alignment's metrics.json (mean stretch and surface
/// distance over its frames).
AlignmentFigures alignmentFigures(const nlohmann::json& metrics);

/// Moves a kept alignment's results (aligned frames, body fit, run description) from `from` up
/// into `out`, replacing earlier ones.
void keepAlignment(const std::filesystem::path& from, const std::filesystem::path& out);

/// One alignment of a choice as metrics.json lists it: its folder (relative to OUT), figures,
/// count of doubtful frames, and its time and errors where measured.
nlohmann::json alignmentEntry(const nlohmann::json& metrics, const AlignmentFigures& figures,
                              const std::string& folder);

/// Writes the kept alignment's `metrics` to OUT/metrics.json, then the report unless
/// settings.noReport.
void writeKeptAlignment(const AlignSettings& settings, const nlohmann::json& metrics);

/// One line of a choice as align prints it: the label, the figures, the errors and the folder.
void printAlignmentEntry(const std::string& label, const nlohmann::json& entry);

/// Runs alignOnce under each of settings.modelPaths, then keeps one; returns the exit code.
int alignUnderEachModel(const AlignSettings& settings,
                        const std::function<int(const AlignSettings&)>& alignOnce);
} // namespace clothtrack::app
