#pragma once
// Evaluation shared by 'align' and 'eval': the ground-truth frames and the error entries of
// metrics.json.
#include "ctMeshConversion.h"

#include <clothtrack/eval/AlignmentError.h>
#include <clothtrack/eval/MarkerError.h>

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace clothtrack::app
{
/// Reads the ground-truth frames `files` (one connectivity for all: UsageError naming the file
/// that breaks it).
std::vector<TriangleMesh> loadGroundTruth(const std::vector<std::string>& files,
                                          const FrameConventions& conventions);

/// UsageError naming `file` when this ground-truth frame breaks the connectivity of the first
/// (`firstFaces` triangles).
void checkTruthConnectivity(const std::string& file, const TriangleMesh& truth, int firstFaces);

/// Vertex errors against a ground truth (one vector per frame): mean_vertex_error_m, within_10cm,
/// per_frame_* lists, cumulative_error, ...
void addVertexErrorMetrics(nlohmann::json& metrics, const std::vector<Eigen::VectorXd>& errors,
                           int templateFrame, const std::string& truthInput, int verticesWithTruth);

/// Marker errors: marker_mean_error_m, per_marker_mean_error_m, marker_cumulative_error, ...
/// `aligned` holds the template's vertices in every frame; markers their positions.
void addMarkerMetrics(nlohmann::json& metrics, const std::vector<Points>& aligned,
                      const MarkerTrajectories& markers, int templateFrame,
                      const std::string& markersPath);

/// Markers of the frames `frameNumbers` (indices in the full input) from `path`; UsageError when
/// the file has too few frames.
MarkerTrajectories selectedMarkers(const std::string& path, const std::vector<int>& frameNumbers);
} // namespace clothtrack::app
