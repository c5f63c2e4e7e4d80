// clothtrack eval: the errors of an aligned sequence already on disk (the output folder of
// 'align') against a ground truth and/or markers, without aligning again. Adds the error entries
// to OUT/metrics.json and the Error array to every aligned frame.
#include "Commands.h"
#include "ErrorMetrics.h"
#include "MetricsFile.h"
#include "Options.h"
#include "TextFile.h"

#include "ctMeshConversion.h"

#include <clothtrack/base/Error.h>
#include <clothtrack/eval/AlignmentError.h>
#include <clothtrack/io/FrameList.h>

#include <vtkDoubleArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

#include <nlohmann/json.hpp>

#include <cstdio>
#include <filesystem>
#include <fstream>

namespace fs = std::filesystem;

namespace clothtrack::app
{
namespace
{
vtkSmartPointer<vtkPolyData> readAligned(const fs::path& path)
{
  if (!fs::exists(path)) throw UsageError{path.string() + ": aligned frame missing"};
  vtkSmartPointer<vtkPolyData> data;
  try
  {
    data = readVTPFile(path.string());
  }
  catch (const Error& e)
  {
    throw UsageError{e.what()};
  }
  if (data->GetNumberOfPoints() == 0)
    throw UsageError{path.string() + ": unreadable or empty aligned frame"};
  return data;
}
/// Each aligned frame's vertex errors against the ground truth: the Error array of
/// aligned.pvd's frames and the error figures of metrics.json.
void addGroundTruthErrors(nlohmann::json& metrics, const fs::path& out,
                          const std::vector<int>& frameNumbers, int j,
                          std::vector<vtkSmartPointer<vtkPolyData>>& frames,
                          const std::vector<Points>& aligned, const std::string& truthInput,
                          double truthDistance, const FrameConventions& conventions)
{
  const int n = static_cast<int>(frameNumbers.size());
  const std::vector<std::string> files = listFrames(truthInput);
  std::vector<std::string> selected;
  for (int k : frameNumbers)
  {
    if (k >= static_cast<int>(files.size()))
      throw UsageError{truthInput + ": " + std::to_string(files.size()) +
                       " ground-truth frames, the aligned sequence needs frame " +
                       std::to_string(k)};
    selected.push_back(files[k]);
  }
  const std::vector<TriangleMesh> truth = loadGroundTruth(selected, conventions);
  const TruthAnchors anchors = anchorToTruth(aligned[j], truth[j], truthDistance);
  std::vector<Eigen::VectorXd> errors(n);
  for (int k = 0; k < n; ++k)
  {
    errors[k] = vertexErrors(aligned[k], truth[k], anchors);
    vtkNew<vtkDoubleArray> array;
    array->SetName("Error");
    array->SetNumberOfTuples(errors[k].size());
    for (Eigen::Index i = 0; i < errors[k].size(); ++i) array->SetValue(i, errors[k][i]);
    frames[k]->GetPointData()->AddArray(array); // replaces an Error array already there
    writeCollectionFrame((out / "aligned.pvd").string(), frameNumbers[k], frames[k], false);
  }
  addVertexErrorMetrics(metrics, errors, j, truthInput, anchors.count());
}
} // namespace

int runEval(const Args& args)
{
  std::string folder, truthInput, markersPath;
  double truthDistance = TruthAnchorOptions{}.maximumTruthDistance;
  po::options_description options("eval options");
  options.add_options()("folder", po::value(&folder)->required(),
                        "output folder of 'clothtrack align' (metrics.json, aligned/)")(
      "ground-truth", po::value(&truthInput),
      "ground-truth sequence (one connectivity, the same frames as the aligned input)")(
      "markers", po::value(&markersPath), "marker trajectories (CSV frame,time,marker,x,y,z)")(
      "maximum-truth-distance,truth-distance",
      po::value(&truthDistance)->default_value(truthDistance),
      "template vertices further than this from the ground truth have no error (m; also "
      "--truth-distance)");
  po::positional_options_description positional;
  positional.add("folder", 1);
  po::variables_map values;
  if (!parseOptions(args, "clothtrack eval OUT [--ground-truth GT] [--markers CSV]", options,
                    positional, values))
    return 0;
  if (truthInput.empty() && markersPath.empty())
    throw UsageError{"eval needs --ground-truth, --markers or both"};
  if (!(truthDistance > 0)) throw UsageError{"--maximum-truth-distance must be positive"};

  const fs::path out(folder);
  nlohmann::json metrics = readMetrics(out / "metrics.json");
  std::vector<int> frameNumbers;
  int j = -1;
  SequenceOptions seq;
  try
  {
    frameNumbers = metrics.at("frame_numbers").get<std::vector<int>>();
    j = metrics.at("template_frame").get<int>();
    seq.unit = metrics.at("unit").get<std::string>();
    seq.up = metrics.at("up").get<std::string>();
    // A --scale run: its metres per file unit replace the unit (older runs have no such key).
    if (metrics.contains("unit_scale") && metrics.at("unit_scale").get<double>() != 1.0)
      seq = {"m", seq.up, metrics.at("unit_scale").get<double>(), seq.fps};
  }
  catch (const nlohmann::json::exception&)
  {
    throw UsageError{(out / "metrics.json").string() +
                     ": lacks frame_numbers, template_frame, unit or up (not written by align?)"};
  }
  const int n = static_cast<int>(frameNumbers.size());
  if (n < 2 || j < 0 || j >= n)
    throw UsageError{(out / "metrics.json").string() + ": inconsistent frames or template frame"};

  std::vector<vtkSmartPointer<vtkPolyData>> frames;
  std::vector<Points> aligned;
  for (int k : frameNumbers)
  {
    char name[48];
    std::snprintf(name, sizeof(name), "aligned/aligned_%04d.vtp", k);
    frames.push_back(readAligned(out / name));
    aligned.push_back(toTriangleMesh(frames.back(), (out / name).string()).V);
    if (aligned.back().rows() != aligned.front().rows())
      throw UsageError{(out / name).string() + ": not the template's vertex count"};
  }

  if (!truthInput.empty())
    addGroundTruthErrors(metrics, out, frameNumbers, j, frames, aligned, truthInput, truthDistance,
                         toConventions(seq));
  if (!markersPath.empty())
    addMarkerMetrics(metrics, aligned, selectedMarkers(markersPath, frameNumbers), j, markersPath);
  writeTextAtomically((out / "metrics.json").string(), metrics.dump(2) + "\n");

  std::printf("evaluated %d frames (template frame %d)", n, j);
  if (metrics.contains("mean_vertex_error_m") && !truthInput.empty())
    std::printf("; mean vertex error %.2f cm, %.2f %% within 10 cm",
                100 * metrics["mean_vertex_error_m"].get<double>(),
                100 * metrics["within_10cm"].get<double>());
  if (!markersPath.empty())
    std::printf("; markers %.2f cm", 100 * metrics["marker_mean_error_m"].get<double>());
  std::printf("\nupdated %s\n", (out / "metrics.json").c_str());
  return 0;
}
} // namespace clothtrack::app
