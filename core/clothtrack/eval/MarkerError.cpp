#include "MarkerError.h"

#include <clothtrack/base/Error.h>

#include <cmath>
#include <fstream>
#include <limits>
#include <map>
#include <sstream>

namespace clothtrack
{
MarkerTrajectories readMarkersCsv(const std::string& path)
{
  std::ifstream in(path);
  if (!in) throw Error(path + ": cannot open the marker file");
  std::string line;
  if (!std::getline(in, line)) throw Error(path + ": empty marker file");
  struct Row
  {
    int frame;
    std::string name;
    Vec3 p;
  };
  std::vector<Row> rows;
  std::map<std::string, int> index;
  MarkerTrajectories markers;
  int lineNumber = 1, frames = 0;
  while (std::getline(in, line))
  {
    ++lineNumber;
    if (line.empty() || line == "\r") continue;
    std::stringstream fields(line);
    std::string frame, time, name, x, y, z;
    Row row{};
    try
    {
      if (!std::getline(fields, frame, ',') || !std::getline(fields, time, ',') ||
          !std::getline(fields, name, ',') || !std::getline(fields, x, ',') ||
          !std::getline(fields, y, ',') || !std::getline(fields, z))
        throw std::invalid_argument("fields");
      size_t used = 0;
      row.frame = std::stoi(frame, &used);
      if (used != frame.size() || row.frame < 0) throw std::invalid_argument("frame");
      row.p = Vec3(std::stod(x), std::stod(y), std::stod(z));
    }
    catch (const std::exception&)
    {
      throw Error(path + ":" + std::to_string(lineNumber) +
                  ": expected frame,time,marker,x,y,z (got '" + line + "')");
    }
    if (!row.p.allFinite())
      throw Error(path + ":" + std::to_string(lineNumber) + ": marker position is not finite");
    row.name = name;
    if (!index.count(name))
    {
      index[name] = static_cast<int>(markers.names.size());
      markers.names.push_back(name);
    }
    frames = std::max(frames, row.frame + 1);
    rows.push_back(row);
  }
  if (rows.empty()) throw Error(path + ": no marker rows");
  const int m = static_cast<int>(markers.names.size());
  markers.positions.assign(frames,
                           Points::Constant(m, 3, std::numeric_limits<double>::quiet_NaN()));
  for (const Row& row : rows) markers.positions[row.frame].row(index[row.name]) = row.p.transpose();
  return markers;
}

std::vector<int> nearestTemplateVertices(const Points& templateVertices,
                                         const Points& markersAtTemplate)
{
  std::vector<int> vertices(markersAtTemplate.rows(), -1);
  for (Eigen::Index m = 0; m < markersAtTemplate.rows(); ++m)
  {
    if (!markersAtTemplate.row(m).allFinite() || templateVertices.rows() == 0) continue;
    Eigen::Index best = 0;
    (templateVertices.rowwise() - markersAtTemplate.row(m)).rowwise().squaredNorm().minCoeff(&best);
    vertices[m] = static_cast<int>(best);
  }
  return vertices;
}

Eigen::MatrixXd markerErrors(const std::vector<Points>& aligned, const MarkerTrajectories& markers,
                             const std::vector<int>& vertices)
{
  if (static_cast<int>(aligned.size()) != markers.numFrames())
    throw Error("marker error: " + std::to_string(markers.numFrames()) + " marker frames for " +
                std::to_string(aligned.size()) + " aligned frames");
  const int m = static_cast<int>(vertices.size());
  Eigen::MatrixXd errors =
      Eigen::MatrixXd::Constant(aligned.size(), m, std::numeric_limits<double>::quiet_NaN());
  for (size_t k = 0; k < aligned.size(); ++k)
    for (int i = 0; i < m; ++i)
      if (vertices[i] >= 0 && markers.positions[k].row(i).allFinite())
        errors(k, i) = (aligned[k].row(vertices[i]) - markers.positions[k].row(i)).norm();
  return errors;
}

SequenceErrors markerSequenceErrors(const Eigen::MatrixXd& errors, int templateFrame)
{
  std::vector<Eigen::VectorXd> perFrame(errors.rows());
  for (Eigen::Index k = 0; k < errors.rows(); ++k) perFrame[k] = errors.row(k).transpose();
  return sequenceErrors(perFrame, templateFrame);
}
} // namespace clothtrack
