#pragma once
// The body fit as the commands run it: the model from a file or the built-in one, and the fit
// of a whole sequence with a progress line.
#include <clothtrack/body/BodyFit.h>

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace clothtrack::app
{
/// The model read from `path` into `storage`, or the built-in model when `path` is empty.
const BodyModel& bodyModel(const std::string& path, BodyModel& storage);

/// fitBodySequence with a "body-fit" progress line counted in frames.
BodyFitResult fitBodiesWithProgress(const BodyModel& model,
                                    const std::vector<const TriangleMesh*>& frames,
                                    const BodyFitOptions& options = {});

/// One frame of a body_fit.json ('clothtrack body-fit', 'clothtrack align'): file, status name,
/// joint rotations, translation and rest_pose_distance (null unless the fit is ok).
nlohmann::json bodyFrameJson(const std::string& file, BodyFitStatus status, const BodyPose& pose);
/// The status and pose of such a record; throws std::exception when it is not one.
BodyFitStatus bodyFrameStatus(const nlohmann::json& record);
BodyPose bodyFramePose(const nlohmann::json& record);
} // namespace clothtrack::app
