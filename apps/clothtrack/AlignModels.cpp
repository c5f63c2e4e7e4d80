#include "AlignModels.h"

#include "MetricsFile.h"
#include "Ranks.h"
#include "Report.h"
#include "TextFile.h"

#include <clothtrack/eval/ModelChoice.h>

#include <nlohmann/json.hpp>

#include <cstdio>
#include <filesystem>
#include <limits>
#include <string>

namespace fs = std::filesystem;

namespace clothtrack::app
{
namespace
{
/// A per-frame array of metrics.json, a frame without a value (null) as NaN.
std::vector<double> perFrame(const nlohmann::json& metrics, const char* key)
{
  std::vector<double> values;
  for (const nlohmann::json& value : metrics.value(key, nlohmann::json::array()))
    values.push_back(value.is_number() ? value.get<double>()
                                       : std::numeric_limits<double>::quiet_NaN());
  return values;
}

} // namespace

AlignmentFigures alignmentFigures(const nlohmann::json& metrics)
{
  return {meanOverFrames(perFrame(metrics, "per_frame_stretch")),
          meanOverFrames(perFrame(metrics, "per_frame_surface_distance_m"))};
}

void keepAlignment(const fs::path& from, const fs::path& out)
{
  for (const char* name : {"aligned", "aligned.pvd", "body_fit.json", "run.json"})
  {
    fs::remove_all(out / name);
    if (fs::exists(from / name)) fs::rename(from / name, out / name);
  }
}

nlohmann::json alignmentEntry(const nlohmann::json& metrics, const AlignmentFigures& figures,
                              const std::string& folder)
{
  nlohmann::json entry = {
      {"folder", folder},
      {"mean_stretch", figures.stretch},
      {"mean_surface_distance_m", figures.surfaceDistance},
      {"doubtful_frames", metrics.value("doubtful_frames", nlohmann::json::array()).size()}};
  for (const char* key : {"seconds_total", "mean_vertex_error_m", "within_10cm"})
    if (metrics.contains(key)) entry[key] = metrics[key];
  return entry;
}

void writeKeptAlignment(const AlignSettings& settings, const nlohmann::json& metrics)
{
  const fs::path out(settings.output);
  writeTextAtomically((out / "metrics.json").string(), metrics.dump(2) + "\n");
  std::printf("wrote %s and %s\n", (out / "aligned.pvd").c_str(), (out / "metrics.json").c_str());
  if (!settings.noReport)
  {
    writeReport(settings.output);
    std::printf("report: %s\n", (out / "report.html").c_str());
  }
}

void printAlignmentEntry(const std::string& label, const nlohmann::json& entry)
{
  std::printf("  %-24s mean stretch %.4f, surface distance %.2f mm", label.c_str(),
              entry["mean_stretch"].get<double>(),
              1000 * entry["mean_surface_distance_m"].get<double>());
  if (entry.contains("mean_vertex_error_m"))
    std::printf(", mean vertex error %.2f cm, %.2f %% within 10 cm",
                100 * entry["mean_vertex_error_m"].get<double>(),
                100 * entry["within_10cm"].get<double>());
  std::printf(" (%s)\n", entry["folder"].get<std::string>().c_str());
}

namespace
{
/// The model as the user named it (the built-in one by its name), and as a folder name.
std::string modelLabel(const std::string& path)
{
  return path.empty() ? kBuiltinModelName : path;
}

std::string modelName(const std::string& path)
{
  return path.empty() ? kBuiltinModelName : fs::path(path).stem().string();
}

/// Each model's own output folder: OUT/models/<i>_<name>.
fs::path modelFolder(const AlignSettings& s, size_t i)
{
  return fs::path(s.output) / "models" / (std::to_string(i) + "_" + modelName(s.modelPaths[i]));
}

nlohmann::json choiceSummary(const AlignSettings& s, const std::vector<nlohmann::json>& metrics,
                             const std::vector<AlignmentFigures>& figures, int kept)
{
  nlohmann::json models = nlohmann::json::array();
  for (size_t i = 0; i < metrics.size(); ++i)
  {
    nlohmann::json entry =
        alignmentEntry(metrics[i], figures[i], fs::relative(modelFolder(s, i), s.output).string());
    entry["model"] = modelLabel(s.modelPaths[i]);
    models.push_back(entry);
  }
  return {{"criterion", modelChoiceCriterion()}, {"kept", kept}, {"models", models}};
}

void printChoice(const nlohmann::json& choice)
{
  const int kept = choice["kept"].get<int>();
  std::printf("\nkept the alignment under model %s:\n",
              choice["models"][kept]["model"].get<std::string>().c_str());
  for (const nlohmann::json& m : choice["models"])
    printAlignmentEntry(m["model"].get<std::string>(), m);
}
} // namespace

int alignUnderEachModel(const AlignSettings& settings,
                        const std::function<int(const AlignSettings&)>& alignOnce)
{
  const size_t count = settings.modelPaths.size();
  for (size_t i = 0; i < count; ++i)
  {
    AlignSettings one = settings;
    one.modelPath = settings.modelPaths[i];
    one.modelPaths = {one.modelPath};
    one.output = modelFolder(settings, i).string();
    if (!settings.workDir.empty())
      one.workDir = (fs::path(settings.workDir) / modelFolder(settings, i).filename()).string();
    one.noReport = true;
    if (ranks::leader())
    {
      std::printf("model %zu of %zu: %s\n", i + 1, count, modelLabel(one.modelPath).c_str());
      std::fflush(stdout);
    }
    if (const int code = alignOnce(one); code != 0) return code;
  }
  if (!ranks::leader()) return 0;
  std::vector<nlohmann::json> metrics;
  std::vector<AlignmentFigures> figures;
  for (size_t i = 0; i < count; ++i)
  {
    metrics.push_back(readMetrics(modelFolder(settings, i) / "metrics.json"));
    figures.push_back(alignmentFigures(metrics.back()));
  }
  const int kept = preferredAlignment(figures);
  const fs::path out(settings.output);
  keepAlignment(modelFolder(settings, kept), out);
  nlohmann::json result = metrics[kept];
  result["model"] = modelLabel(settings.modelPaths[kept]);
  result["model_choice"] = choiceSummary(settings, metrics, figures, kept);
  printChoice(result["model_choice"]);
  writeKeptAlignment(settings, result);
  return 0;
}
} // namespace clothtrack::app
