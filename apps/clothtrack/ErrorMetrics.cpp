#include "ErrorMetrics.h"

#include "Commands.h"

#include <algorithm>
#include <cmath>
#include <filesystem>

namespace clothtrack::app
{
std::vector<TriangleMesh> loadGroundTruth(const std::vector<std::string>& files,
                                          const FrameConventions& conventions)
{
  std::vector<TriangleMesh> truth;
  for (const std::string& file : files)
  {
    truth.push_back(loadFrame(file, conventions));
    checkTruthConnectivity(file, truth.back(), truth.front().numFaces());
  }
  return truth;
}

void checkTruthConnectivity(const std::string& file, const TriangleMesh& truth, int firstFaces)
{
  if (truth.numFaces() != firstFaces)
    throw UsageError{file + ": the ground truth must keep one connectivity (" +
                     std::to_string(truth.numFaces()) + " triangles; " +
                     std::to_string(firstFaces) + " in the first frame)"};
}

void addVertexErrorMetrics(nlohmann::json& metrics, const std::vector<Eigen::VectorXd>& errors,
                           int templateFrame, const std::string& truthInput, int verticesWithTruth)
{
  const SequenceErrors summary = sequenceErrors(errors, templateFrame);
  std::vector<double> perFrameMean, perFrameMedian, perFrameP90, perFrameMax, perFrameWithin10;
  for (const ErrorStatistics& s : summary.perFrame)
  {
    perFrameMean.push_back(s.mean);
    perFrameMedian.push_back(s.median);
    perFrameP90.push_back(s.p90);
    perFrameMax.push_back(s.max);
    perFrameWithin10.push_back(s.within10cm);
  }
  const ErrorStatistics& all = summary.pooled;
  metrics["ground_truth"] = truthInput;
  metrics["vertices_with_ground_truth"] = verticesWithTruth;
  metrics["mean_vertex_error_m"] = all.mean;
  metrics["median_vertex_error_m"] = all.median;
  metrics["p90_vertex_error_m"] = all.p90;
  metrics["max_vertex_error_m"] = all.max;
  metrics["within_5cm"] = all.within5cm;
  metrics["within_10cm"] = all.within10cm;
  metrics["worst_frame"] = summary.worstFrame;
  metrics["worst_frame_mean_error_m"] = perFrameMean[summary.worstFrame];
  metrics["drift_m_per_frame"] = summary.driftPerFrame;
  metrics["per_frame_mean_error_m"] = perFrameMean;
  metrics["per_frame_median_error_m"] = perFrameMedian;
  metrics["per_frame_p90_error_m"] = perFrameP90;
  metrics["per_frame_max_error_m"] = perFrameMax;
  metrics["per_frame_within_10cm"] = perFrameWithin10;
  metrics["cumulative_error"] = {{"threshold_m", summary.thresholds},
                                 {"fraction", summary.fractions}};
}

void addMarkerMetrics(nlohmann::json& metrics, const std::vector<Points>& aligned,
                      const MarkerTrajectories& markers, int templateFrame,
                      const std::string& markersPath)
{
  const int n = static_cast<int>(aligned.size());
  const std::vector<int> vertices =
      nearestTemplateVertices(aligned[templateFrame], markers.positions[templateFrame]);
  const Eigen::MatrixXd errors = markerErrors(aligned, markers, vertices);
  const SequenceErrors summary = markerSequenceErrors(errors, templateFrame);
  nlohmann::json perMarker = nlohmann::json::object();
  for (size_t i = 0; i < markers.names.size(); ++i)
  {
    std::vector<double> column;
    for (int k = 0; k < n; ++k)
      if (k != templateFrame && std::isfinite(errors(k, i))) column.push_back(errors(k, i));
    if (!column.empty()) perMarker[markers.names[i]] = errorStatistics(column).mean;
  }
  std::vector<double> perFrame;
  for (const ErrorStatistics& s : summary.perFrame) perFrame.push_back(s.mean);
  metrics["markers"] = std::filesystem::absolute(markersPath).string();
  metrics["marker_mean_error_m"] = summary.pooled.mean;
  metrics["marker_median_error_m"] = summary.pooled.median;
  metrics["marker_max_error_m"] = summary.pooled.max;
  metrics["marker_within_5cm"] = summary.pooled.within5cm;
  metrics["marker_within_10cm"] = summary.pooled.within10cm;
  metrics["per_marker_mean_error_m"] = perMarker;
  metrics["per_frame_marker_error_m"] = perFrame;
  metrics["marker_cumulative_error"] = {{"threshold_m", summary.thresholds},
                                        {"fraction", summary.fractions}};
}

MarkerTrajectories selectedMarkers(const std::string& path, const std::vector<int>& frameNumbers)
{
  const MarkerTrajectories all = readMarkersCsv(path);
  const int needed =
      frameNumbers.empty() ? 0 : *std::max_element(frameNumbers.begin(), frameNumbers.end()) + 1;
  if (all.numFrames() < needed)
    throw UsageError{path + ": markers for " + std::to_string(all.numFrames()) +
                     " frames, the input has " + std::to_string(needed)};
  MarkerTrajectories selected{all.names, {}};
  for (int k : frameNumbers) selected.positions.push_back(all.positions[k]);
  return selected;
}
} // namespace clothtrack::app
