#include "BodyFitRun.h"

#include "Progress.h"

#include "ctBodyModelIO.h"
#include "ctBuiltinBodyModel.h"

#include <cmath>
#include <stdexcept>

namespace clothtrack::app
{
const BodyModel& bodyModel(const std::string& path, BodyModel& storage)
{
  if (path.empty()) return builtinBodyModel();
  storage = readBodyModel(path);
  return storage;
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

nlohmann::json bodyFrameJson(const std::string& file, BodyFitStatus status, const BodyPose& pose)
{
  nlohmann::json rotations = nlohmann::json::array();
  for (int j = 0; j < NumJoints; ++j)
    rotations.push_back({pose.rotations(j, 0), pose.rotations(j, 1), pose.rotations(j, 2)});
  const double fromRest = fittedRestPoseDistance(status, pose);
  return {
      {"file", file},
      {"status", bodyFitStatusName(status)},
      {"rotations", rotations},
      {"translation", {pose.translation.x(), pose.translation.y(), pose.translation.z()}},
      {"rest_pose_distance", std::isnan(fromRest) ? nlohmann::json() : nlohmann::json(fromRest)}};
}

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
} // namespace clothtrack::app
