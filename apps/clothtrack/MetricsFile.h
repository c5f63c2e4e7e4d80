#pragma once
// Reading an output folder's metrics.json (written by 'clothtrack align').
#include <nlohmann/json.hpp>

#include <filesystem>

namespace clothtrack::app
{
/// The parsed file; UsageError naming it when it is missing or not JSON.
nlohmann::json readMetrics(const std::filesystem::path& path);
} // namespace clothtrack::app
