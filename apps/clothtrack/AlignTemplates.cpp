#include "AlignTemplates.h"

#include "AlignModels.h"
#include "MetricsFile.h"
#include "Ranks.h"
#include "Report.h"
#include "TextFile.h"

#include <clothtrack/eval/ModelChoice.h>
#include <clothtrack/selection/TemplateSelection.h>

#include <nlohmann/json.hpp>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace fs = std::filesystem;

namespace clothtrack::app
{
namespace
{
/// The further template frames to align under: the next frames by pose after the one chosen,
/// on a collection of poses (or whenever more than one candidate is asked for).
std::vector<int> furtherTemplates(const AlignSettings& settings, const fs::path& out,
                                  const nlohmann::json& metrics)
{
  int count = settings.templateCandidates;
  if (count == 0)
  {
    std::ifstream file(out / "body_fit.json");
    const nlohmann::json body = nlohmann::json::parse(file, nullptr, false);
    std::vector<bool> continues;
    if (body.is_object())
      for (const nlohmann::json& frame : body.value("per_frame", nlohmann::json::array()))
        continues.push_back(frame.value("continues_previous", true));
    count = defaultTemplateCandidates(continues);
  }
  std::vector<int> further;
  const int chosen = metrics.value("template_frame", -1);
  for (int k : metrics.value("template_frames_by_pose", std::vector<int>()))
    if (k != chosen && static_cast<int>(further.size()) + 1 < count) further.push_back(k);
  return further;
}

fs::path candidateFolder(const AlignSettings& s, int frame)
{
  return fs::path(s.output) / "templates" / ("frame_" + std::to_string(frame));
}

/// The candidate's own work folder, holding the first alignment's body fit (its landmarks.jsonl)
/// so that only the correspondences and the fit are made again.
std::string candidateWork(const AlignSettings& s, int frame)
{
  const fs::path first = s.workDir.empty() ? fs::path(s.output) / "work" : fs::path(s.workDir);
  const fs::path work =
      s.workDir.empty() ? candidateFolder(s, frame) / "work"
                        : fs::path(s.workDir) / "templates" / ("frame_" + std::to_string(frame));
  fs::create_directories(work);
  fs::copy_file(first / "landmarks.jsonl", work / "landmarks.jsonl",
                fs::copy_options::overwrite_existing);
  return work.string();
}

nlohmann::json choiceSummary(const AlignSettings& s, const std::vector<nlohmann::json>& metrics,
                             const std::vector<AlignmentFigures>& figures, int kept)
{
  nlohmann::json candidates = nlohmann::json::array();
  for (size_t i = 0; i < metrics.size(); ++i)
  {
    const int frame = metrics[i]["template_frame"].get<int>();
    nlohmann::json entry = alignmentEntry(
        metrics[i], figures[i],
        static_cast<int>(i) == kept ? std::string(".")
                                    : fs::relative(candidateFolder(s, frame), s.output).string());
    entry["template_frame"] = frame;
    candidates.push_back(entry);
  }
  return {{"criterion", templateChoiceCriterion()},
          {"kept", kept},
          {"kept_template_frame", candidates[kept]["template_frame"]},
          {"candidates", candidates}};
}

void printChoice(const nlohmann::json& choice)
{
  std::printf("\nkept the alignment under template frame %d:\n",
              choice["kept_template_frame"].get<int>());
  for (const nlohmann::json& c : choice["candidates"])
    printAlignmentEntry("template frame " + std::to_string(c["template_frame"].get<int>()), c);
}
} // namespace

int alignChoosingTemplate(const AlignSettings& settings,
                          const std::function<int(const AlignSettings&)>& alignOnce)
{
  if (settings.forcedTemplate >= 0 || settings.templateCandidates == 1 ||
      settings.mode != AlignMode::Full || ranks::count() > 1)
    return alignOnce(settings);
  AlignSettings first = settings;
  first.noReport = true;
  if (const int code = alignOnce(first); code != 0) return code;
  const fs::path out(settings.output);
  std::vector<nlohmann::json> metrics = {readMetrics(out / "metrics.json")};
  const std::vector<int> further = furtherTemplates(settings, out, metrics[0]);
  for (size_t i = 0; i < further.size(); ++i)
  {
    AlignSettings one = settings;
    one.forcedTemplate = further[i];
    one.output = candidateFolder(settings, further[i]).string();
    one.workDir = candidateWork(settings, further[i]);
    one.noReport = true;
    std::printf("\ntemplate candidate %zu of %zu: frame %d\n", i + 2, further.size() + 1,
                further[i]);
    std::fflush(stdout);
    if (const int code = alignOnce(one); code != 0) return code;
    metrics.push_back(readMetrics(fs::path(one.output) / "metrics.json"));
  }
  if (!further.empty())
  {
    std::vector<AlignmentFigures> figures;
    for (const nlohmann::json& m : metrics) figures.push_back(alignmentFigures(m));
    const int kept = preferredAlignment(figures);
    if (kept > 0)
    {
      // The first alignment, made in OUT, gives way to the kept one and takes its folder.
      const fs::path firstFolder =
          candidateFolder(settings, metrics[0]["template_frame"].get<int>());
      fs::create_directories(firstFolder);
      keepAlignment(out, firstFolder);
      writeTextAtomically((firstFolder / "metrics.json").string(), metrics[0].dump(2) + "\n");
      keepAlignment(candidateFolder(settings, further[kept - 1]), out);
    }
    nlohmann::json result = metrics[kept];
    result["template_choice"] = choiceSummary(settings, metrics, figures, kept);
    result["template_criterion"] = "alignment-figures";
    result["template_frames_by_pose"] = metrics[0]["template_frames_by_pose"];
    // The run's cost is every candidate's (the later ones reuse the first one's body fit).
    double seconds = 0;
    for (const nlohmann::json& m : metrics) seconds += m.value("seconds_total", 0.0);
    result["seconds_total"] = seconds;
    if (const int frames = result.value("frames", 0); frames > 0)
      result["seconds_per_frame"] = seconds / frames;
    printChoice(result["template_choice"]);
    writeKeptAlignment(settings, result);
  }
  else if (!settings.noReport)
  {
    writeReport(settings.output);
    std::printf("report: %s\n", (out / "report.html").c_str());
  }
  return 0;
}
} // namespace clothtrack::app
