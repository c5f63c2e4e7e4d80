// clothtrack select-template: the template frame of a sequence and every frame's criteria
// (also the per-frame topology report of 'clothtrack inspect').
#include "BodyFitRun.h"
#include "Commands.h"
#include "Options.h"
#include "Progress.h"

#include "ctMeshConversion.h"

#include <clothtrack/body/BodyFit.h>
#include <clothtrack/io/FrameList.h>
#include <clothtrack/pipeline/BodyStage.h>
#include <clothtrack/selection/TemplateSelection.h>

#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>

namespace clothtrack::app
{
namespace
{
/// Each frame's distance from the rest pose (NaN unless its body fit is ok), fitting the body.
std::vector<double> fitRestPoseDistances(const std::vector<TriangleMesh>& meshes,
                                         const std::string& modelPath)
{
  BodyModel ownModel;
  const BodyModel& model = bodyModel(modelPath, ownModel);
  std::vector<const TriangleMesh*> pointers;
  for (const auto& m : meshes) pointers.push_back(&m);
  return restPoseDistances(fitBodiesWithProgress(model, pointers));
}

/// The same from the body_fit.json of 'clothtrack body-fit', which must list the same frames.
std::vector<double> readRestPoseDistances(const std::string& path,
                                          const std::vector<std::string>& frames)
{
  std::ifstream in(path);
  if (!in) throw UsageError{path + ": cannot read file"};
  try
  {
    const nlohmann::json j = nlohmann::json::parse(in);
    const auto& perFrame = j.at("per_frame");
    if (perFrame.size() != frames.size())
      throw UsageError{path + ": " + std::to_string(perFrame.size()) + " frames, the input has " +
                       std::to_string(frames.size())};
    BodyFitResult body;
    for (const auto& f : perFrame) body.frames.push_back(bodyFrameFit(f));
    return restPoseDistances(body);
  }
  catch (const std::exception& e)
  {
    throw UsageError{path + ": not a body_fit.json with each frame's pose (" + e.what() + ")"};
  }
}

/// Each frame's criteria, as read.
struct FrameTableRows
{
  const std::vector<FrameTopology>& criteria;
  const std::vector<int>& vertices;
  const std::vector<int>& faces;
};

/// The table on stdout and, with a path, as CSV; with `chosen`, the choice's columns too.
void printFrameTable(const std::vector<std::string>& frames, const FrameTableRows& rows,
                     const TemplateSelection* chosen, const std::vector<double>& restPose,
                     const std::string& csvPath)
{
  std::FILE* csv = nullptr;
  if (!csvPath.empty() && !(csv = std::fopen(csvPath.c_str(), "w")))
    throw UsageError{csvPath + ": cannot write file"};
  if (csv)
    std::fprintf(csv,
                 "frame,file,vertices,faces,components,shells,genus_largest,boundaries_largest,"
                 "area_largest_m2,"
                 "area_ratio,non_manifold_edges%s\n",
                 chosen ? ",persistent_shells,rest_pose_distance,candidate,chosen" : "");
  std::printf("%5s %-24s %8s %8s %5s %6s %5s %5s %8s %10s %4s%s\n", "frame", "file", "verts",
              "faces", "comp", "shells", "genus", "holes", "area", "area_ratio", "nme",
              chosen ? "  persist  rest_pose cand" : "");
  for (size_t k = 0; k < frames.size(); ++k)
  {
    const FrameTopology& t = rows.criteria[k];
    const std::string file = std::filesystem::path(frames[k]).filename().string();
    std::printf("%5zu %-24.24s %8d %8d %5d %6d %5d %5d %8.4f %10.1f %4d", k, file.c_str(),
                rows.vertices[k], rows.faces[k], t.components, t.shells, t.genus, t.boundaries,
                t.area, t.areaRatio, t.nonManifoldEdges);
    if (chosen)
      std::printf("  %7d %10.3f %4s%s", chosen->persistentShells[k],
                  restPose.empty() ? NAN : restPose[k], chosen->candidate[k] ? "yes" : "",
                  static_cast<int>(k) == chosen->chosen ? "  <- template" : "");
    std::printf("\n");
    if (csv)
    {
      std::fprintf(csv, "%zu,%s,%d,%d,%d,%d,%d,%d,%.6f,%.4f,%d", k, file.c_str(), rows.vertices[k],
                   rows.faces[k], t.components, t.shells, t.genus, t.boundaries, t.area,
                   t.areaRatio, t.nonManifoldEdges);
      if (chosen)
        std::fprintf(csv, ",%d,%.6f,%d,%d", chosen->persistentShells[k],
                     restPose.empty() ? NAN : restPose[k], chosen->candidate[k],
                     static_cast<int>(k) == chosen->chosen);
      std::fprintf(csv, "\n");
    }
  }
  if (csv && std::fclose(csv) != 0) throw UsageError{csvPath + ": write error"};
}

int runFrameTable(const Args& args, bool choose)
{
  std::string input, csvPath;
  SequenceOptions seq;
  TemplateSelectionOptions selection;
  int forced = -1;
  std::string criterionName = "rest-pose", modelPath, bodyFitPath;
  const char* name = choose ? "select-template" : "inspect";
  po::options_description options(std::string(name) + " options");
  options.add_options()("input", po::value(&input)->required(),
                        "folder, glob pattern, list file or mesh file")(
      "minimum-shell-area,min-shell-area",
      po::value(&selection.minimumShellArea)->default_value(selection.minimumShellArea),
      "components smaller than this (m^2) are not counted as body parts (also --min-shell-area)")(
      "csv", po::value(&csvPath), "also write the table as CSV to this file");
  if (choose)
    options.add_options()("persistence",
                          po::value(&selection.persistence)->default_value(selection.persistence),
                          "a split counts only if it lasts this many consecutive frames")(
        "template-frame,template", po::value(&forced)->default_value(-1),
        "use this frame (-1: choose automatically; also --template)")(
        "template-criterion", po::value(&criterionName)->default_value(criterionName),
        "last criterion after the topology: rest-pose (fitted body closest to the rest pose; "
        "fits the body unless --body-fit is given) or area-ratio (the paper's)")(
        "body-fit", po::value(&bodyFitPath),
        "body_fit.json written by 'clothtrack body-fit' for these frames: its poses are used "
        "instead of fitting the body again")("model", po::value(&modelPath),
                                             "body model file (default: the built-in model)");
  addSequenceOptions(options, seq);
  po::positional_options_description positional;
  positional.add("input", 1);
  po::variables_map values;
  if (!parseOptions(args, std::string("clothtrack ") + name + " INPUT [options]", options,
                    positional, values))
    return 0;
  resolveAutomatic(seq, input);
  const FrameConventions conventions = toConventions(seq);
  if (selection.persistence < 1) throw UsageError{"--persistence must be at least 1"};
  if (choose) selection.templateCriterion = parseTemplateCriterion(criterionName);
  const bool byPose =
      choose && forced < 0 && selection.templateCriterion == TemplateCriterion::RestPose;

  const std::vector<std::string> frames = listFrames(input);
  if (forced >= static_cast<int>(frames.size()))
    throw UsageError{"--template " + std::to_string(forced) +
                     " is out of range: " + std::to_string(frames.size()) + " frames"};
  std::vector<FrameTopology> criteria;
  std::vector<int> vertices, faces;
  std::vector<TriangleMesh> meshes; // kept only for the body fit
  Progress progress(name, static_cast<int>(frames.size()));
  for (size_t k = 0; k < frames.size(); ++k)
  {
    std::vector<std::string> warnings;
    TriangleMesh mesh = loadFrame(frames[k], conventions, &warnings);
    for (const auto& w : warnings) std::fprintf(stderr, "warning: %s\n", w.c_str());
    criteria.push_back(frameTopology(mesh, selection.minimumShellArea));
    vertices.push_back(mesh.numVertices());
    faces.push_back(mesh.numFaces());
    if (byPose && bodyFitPath.empty()) meshes.push_back(std::move(mesh));
    progress.step(static_cast<int>(k + 1));
  }
  progress.finish();
  std::vector<double> restPose;
  if (byPose)
    restPose = bodyFitPath.empty() ? fitRestPoseDistances(meshes, modelPath)
                                   : readRestPoseDistances(bodyFitPath, frames);
  TemplateSelection chosen;
  if (choose)
  {
    chosen = selectTemplate(criteria, selection, restPose);
    if (forced >= 0) chosen.chosen = forced;
  }

  printFrameTable(frames, {criteria, vertices, faces}, choose ? &chosen : nullptr, restPose,
                  csvPath);
  if (choose)
    std::printf("template frame: %d (%s), %s%s\n", chosen.chosen,
                std::filesystem::path(frames[chosen.chosen]).filename().string().c_str(),
                forced >= 0 ? "set by --template" : "chosen by ",
                forced >= 0 ? "" : templateCriterionName(chosen.decidedBy));
  return 0;
}
} // namespace

int runInspect(const Args& args)
{
  return runFrameTable(args, false);
}
int runSelectTemplate(const Args& args)
{
  return runFrameTable(args, true);
}
} // namespace clothtrack::app
