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

/// What the work folder's results are keyed on for the model at `path`: "builtin" when empty,
/// else a hash of the file's bytes, so that a model file rewritten in place is not taken for the
/// one the stored body fits were made with. Throws Error when the file cannot be read.
std::string bodyModelFingerprint(const std::string& path);

/// fitBodySequence with a "body-fit" progress line counted in frames.
BodyFitResult fitBodiesWithProgress(const BodyModel& model,
                                    const std::vector<const TriangleMesh*>& frames,
                                    const BodyFitOptions& options = {});

/// One frame of a body_fit.json ('clothtrack body-fit', 'clothtrack align'): file, status name,
/// joint rotations, translation, rest_pose_distance (null unless the fit is ok),
/// frame_distance_m, previous_gap_m and continues_previous.
nlohmann::json bodyFrameJson(const std::string& file, const BodyFrameFit& fit);
/// The fit such a record describes (status, pose, message and the figures above, where
/// present); throws std::exception when it is not one.
BodyFrameFit bodyFrameFit(const nlohmann::json& record);
/// Shape coefficients as a JSON array, and back (throws std::exception when not an array).
nlohmann::json coefficientsJson(const Eigen::VectorXd& beta);
Eigen::VectorXd coefficients(const nlohmann::json& values);
/// Warns when frames do not continue the frame before them (BodyFitOptions::neighbourGap): a
/// cut, a gap in the capture, or a collection of unrelated poses; says how they were fitted.
void warnAboutDiscontinuities(const BodyFitResult& body, const BodyFitOptions& options);
/// Warns about each frame the body model does not fit (status poor or failed), naming its file
/// and why: a frame that is not a person, or a person the model cannot follow there. Its
/// landmarks, and so its correspondences, are doubtful.
void warnAboutPoorFits(const BodyFitResult& body, const std::vector<std::string>& files);
} // namespace clothtrack::app
