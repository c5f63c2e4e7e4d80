#pragma once
// Error at sparse markers (the protocol of Shehu et al. 2016, Figure 9): each marker is tied, at
// the template frame, to its nearest template vertex; its error in frame k is the distance
// between that vertex's aligned position and the marker's position in frame k.
#include "AlignmentError.h"
#include <clothtrack/mesh/TriangleMesh.h>

#include <string>
#include <vector>

namespace clothtrack
{
/// Marker trajectories: positions(k) is a markers x 3 matrix for frame k, NaN where a marker is
/// missing in that frame.
struct MarkerTrajectories
{
  std::vector<std::string> names;
  std::vector<Points> positions;
  int numFrames() const { return static_cast<int>(positions.size()); }
};

/// Reads `frame,time,marker,x,y,z` rows (a header line first; frames numbered from 0, as
/// `clothtrack synth` writes them). Throws Error naming the file and line of a bad row.
MarkerTrajectories readMarkersCsv(const std::string& path);

/// For each marker, the template vertex nearest to it at the template frame (-1 if the marker is
/// missing there).
std::vector<int> nearestTemplateVertices(const Points& templateVertices,
                                         const Points& markersAtTemplate);

/// frames x markers errors (metres; NaN where a marker is missing or has no vertex).
/// aligned[k] holds the template's vertices in frame k; markers.positions[k] the markers.
Eigen::MatrixXd markerErrors(const std::vector<Points>& aligned, const MarkerTrajectories& markers,
                             const std::vector<int>& vertices);

/// Statistics and cumulative curve of marker errors, the template frame left out.
SequenceErrors markerSequenceErrors(const Eigen::MatrixXd& errors, int templateFrame);
} // namespace clothtrack
