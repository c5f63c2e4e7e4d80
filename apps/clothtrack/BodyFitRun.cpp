#include "BodyFitRun.h"

#include "Progress.h"

#include "ctBodyModelIO.h"
#include "ctBuiltinBodyModel.h"

#include <clothtrack/base/Error.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <stdexcept>
#include <string>

namespace clothtrack::app
{
const BodyModel& bodyModel(const std::string& path, BodyModel& storage)
{
  if (path.empty()) return builtinBodyModel();
  storage = readBodyModel(path);
  return storage;
}

std::string bodyModelFingerprint(const std::string& path)
{
  if (path.empty()) return "builtin";
  std::ifstream in(path, std::ios::binary);
  if (!in) throw Error(path + ": cannot read the body model file");
  std::uint64_t hash = 14695981039346656037ull; // FNV-1a, 64 bits
  std::vector<char> buffer(1 << 16);
  while (in.read(buffer.data(), static_cast<std::streamsize>(buffer.size())) || in.gcount() > 0)
    for (std::streamsize i = 0; i < in.gcount(); ++i)
    {
      hash ^= static_cast<unsigned char>(buffer[static_cast<size_t>(i)]);
      hash *= 1099511628211ull;
    }
  char text[17];
  std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(hash));
  return text;
}

BodyFitResult fitBodiesWithProgress(const BodyModel& model,
                                    const std::vector<const TriangleMesh*>& frames,
                                    const BodyFitOptions& options)
{
  // The fit reports a fraction of its work (every frame twice, plus the shape): shown in frames.
  const int n = static_cast<int>(frames.size());
  Progress progress("body-fit", n);
  BodyFitResult result = fitBodySequence(model, frames, options,
                                         [&](double done)
                                         {
                                           progress.step(static_cast<int>(n * done));
                                           return true;
                                         });
  progress.finish();
  return result;
}

nlohmann::json bodyFrameJson(const std::string& file, const BodyFrameFit& fit)
{
  const BodyPose& pose = fit.pose;
  nlohmann::json rotations = nlohmann::json::array();
  for (int j = 0; j < NumJoints; ++j)
    rotations.push_back({pose.rotations(j, 0), pose.rotations(j, 1), pose.rotations(j, 2)});
  const double fromRest = fittedRestPoseDistance(fit.status, pose);
  return {
      {"file", file},
      {"status", bodyFitStatusName(fit.status)},
      {"message", fit.message},
      {"rotations", rotations},
      {"translation", {pose.translation.x(), pose.translation.y(), pose.translation.z()}},
      {"rest_pose_distance", std::isnan(fromRest) ? nlohmann::json() : nlohmann::json(fromRest)},
      {"frame_distance_m", fit.frameDistance},
      {"previous_gap_m", fit.previousGap},
      {"continues_previous", fit.continuesPrevious},
      {"rival_score_ratio", std::isfinite(fit.rivalScoreRatio) ? nlohmann::json(fit.rivalScoreRatio)
                                                               : nlohmann::json()}};
}

namespace
{
BodyFitStatus bodyFrameStatus(const nlohmann::json& record)
{
  const std::string name = record.at("status").get<std::string>();
  for (BodyFitStatus s : {BodyFitStatus::Ok, BodyFitStatus::Poor, BodyFitStatus::Failed})
    if (name == bodyFitStatusName(s)) return s;
  throw std::runtime_error("unknown body fit status '" + name + "'");
}

BodyPose bodyFramePose(const nlohmann::json& record)
{
  const auto& rotations = record.at("rotations");
  if (rotations.size() != NumJoints) throw std::runtime_error("another skeleton");
  BodyPose pose;
  for (int j = 0; j < NumJoints; ++j)
    for (int c = 0; c < 3; ++c) pose.rotations(j, c) = rotations.at(j).at(c).get<double>();
  for (int c = 0; c < 3; ++c) pose.translation[c] = record.at("translation").at(c).get<double>();
  return pose;
}
} // namespace

BodyFrameFit bodyFrameFit(const nlohmann::json& record)
{
  BodyFrameFit fit;
  fit.pose = bodyFramePose(record);
  fit.status = bodyFrameStatus(record);
  fit.message = record.value("message", std::string());
  fit.frameDistance = record.value("frame_distance_m", 0.0);
  fit.previousGap = record.value("previous_gap_m", 0.0);
  fit.continuesPrevious = record.value("continues_previous", true);
  const auto rival = record.find("rival_score_ratio");
  if (rival != record.end() && rival->is_number()) fit.rivalScoreRatio = rival->get<double>();
  return fit;
}

nlohmann::json coefficientsJson(const Eigen::VectorXd& beta)
{
  return std::vector<double>(beta.data(), beta.data() + beta.size());
}

Eigen::VectorXd coefficients(const nlohmann::json& values)
{
  const std::vector<double> beta = values.get<std::vector<double>>();
  return Eigen::Map<const Eigen::VectorXd>(beta.data(), static_cast<Eigen::Index>(beta.size()));
}

void warnAboutDiscontinuities(const BodyFitResult& body, const BodyFitOptions& options)
{
  std::vector<int> frames;
  for (size_t k = 0; k < body.frames.size(); ++k)
    if (!body.frames[k].continuesPrevious) frames.push_back(static_cast<int>(k));
  if (frames.empty()) return;
  std::string list;
  for (size_t i = 0; i < frames.size() && i < 8; ++i)
    list += (i ? ", " : "") + std::to_string(frames[i]);
  if (frames.size() > 8) list += ", ...";
  std::fprintf(stderr,
               "warning: %zu of %zu frames lie more than %.0f cm from the frame before them "
               "(%s): each was also fitted from the poses of earlier frames%s "
               "(body_fit.json: previous_gap_m)\n",
               frames.size(), body.frames.size(), 100.0 * options.neighbourGap, list.c_str(),
               options.limbRestarts ? ", and with its limbs started again" : "");
}

void warnAboutPoorFits(const BodyFitResult& body, const std::vector<std::string>& files)
{
  const int shown = 10;
  int poor = 0;
  for (size_t k = 0; k < body.frames.size(); ++k)
  {
    const BodyFrameFit& fit = body.frames[k];
    if (fit.status == BodyFitStatus::Ok) continue;
    if (++poor <= shown)
      std::fprintf(stderr,
                   "warning: %s: the body model does not fit this frame (%s): is it a person, "
                   "in the sequence's unit and up axis? Its landmarks and correspondences are "
                   "doubtful; check it, or leave it out (--frames)\n",
                   files[k].c_str(), fit.message.empty() ? "poor" : fit.message.c_str());
  }
  if (poor > shown)
    std::fprintf(stderr, "warning: %d more frames the body model does not fit (body_fit.json)\n",
                 poor - shown);
  if (2 * poor > static_cast<int>(body.frames.size()))
    std::fprintf(stderr,
                 "warning: the body model fits %d of %zu frames poorly: check --unit and --up "
                 "(or 'auto'), and that the frames show one person\n",
                 poor, body.frames.size());
}
} // namespace clothtrack::app
