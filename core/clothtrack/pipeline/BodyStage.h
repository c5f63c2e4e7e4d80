#pragma once
// Stage 1 (Shehu et al. 2016, section 4.1): the body fitted under the clothing of every frame,
// and its oriented anatomical landmarks carried onto each frame's surface. A frame whose body fit
// failed gets no landmark: its pose is only the neighbour's.
#include <clothtrack/base/Progress.h>
#include <clothtrack/body/BodyFit.h>
#include <clothtrack/body/LandmarkTransfer.h>
#include <clothtrack/cloud/RigidRegistration.h>

#include <Eigen/Geometry>

#include <functional>
#include <optional>
#include <vector>

namespace clothtrack
{
struct BodyStageOptions
{
  BodyFitOptions fit;
  LandmarkTransferOptions transfer;
  /// Each frame's body fit starts from its predecessor's pose moved by the rigid motion between
  /// the two surfaces (generalized ICP, cloud/RigidRegistration.h; BodyFitOptions::frameMotion),
  /// where it converged and carries at least minimumRegistrationOverlap of the surface onto the
  /// next. Off by default: on the development sequences it changed the mean error by 0.05 cm at
  /// most, either way (BENCHMARKS.md, "PCL in the pipeline").
  bool registerFrames = false;
  RigidRegistrationOptions registration;
  double minimumRegistrationOverlap = 0.5;
  /// False: BodyStageResult::bodyLandmarks and transferred stay empty and only the seeds
  /// (`landmarks`) are kept, a third of the memory per frame.
  bool keepBodyLandmarks = true;
};

/// BodyFitOptions::frameMotion by generalized ICP: nullopt where the registration did not
/// converge or leaves more than 1 - minimumOverlap of the moved surface unexplained.
FrameMotion rigidFrameMotion(const RigidRegistrationOptions& options, double minimumOverlap);

/// The landmarks found on one frame, as patch seeds (id: the model's landmark index).
using FrameLandmarks = std::vector<OrientedSurfacePoint>;

struct BodyStageResult
{
  BodyFitResult body;
  /// Per frame, the model's oriented landmarks on the fitted body, in the model's order (empty
  /// unless BodyStageOptions::keepBodyLandmarks).
  std::vector<std::vector<OrientedPoint>> bodyLandmarks;
  /// Per frame, each of them carried onto the frame (invalid where not found; empty unless
  /// keepBodyLandmarks).
  std::vector<std::vector<TransferredLandmark>> transferred;
  /// Per frame, the valid ones as surface points: the input of stages 2 and 3.
  std::vector<FrameLandmarks> landmarks;
};

/// Fits the body to every frame (null frames are flagged failed) and transfers its landmarks.
/// With a shared body fit (BodyFitOptions::sharing) and keepBodyLandmarks off, each process
/// transfers the landmarks of its part of the frames and receives the others'.
/// The body fit takes 95 % of the reported progress. Throws Error when no frame can be fitted or
/// when cancelled.
BodyStageResult fitBodyAndLandmarks(const BodyModel& model,
                                    const std::vector<const TriangleMesh*>& frames,
                                    const BodyStageOptions& options = {},
                                    const StageProgress& progress = {});
/// The same over frames read when needed (mesh/FrameSource.h).
BodyStageResult fitBodyAndLandmarks(const BodyModel& model, const FrameSource& frames,
                                    const BodyStageOptions& options = {},
                                    const StageProgress& progress = {});

/// Each frame's fittedRestPoseDistance, the template criterion: NaN unless its body fit is ok
/// and explains its frame nearly as well as the sequence's median fit does (frameDistance at
/// most `explainedRatio` times the median of the ok fits). The template frame's body binds the
/// template for every frame; a body that fell towards the rest pose, leaving a raised limb
/// unexplained, looked like the best template. The distances are then confirmedByNeighbours.
std::vector<double> restPoseDistances(const BodyFitResult& body, double explainedRatio = 1.3);

/// Each finite distance in `own` raised to the largest finite one of the neighbours that the
/// frame is tracked with (its predecessor if it continues it, its successor if that continues
/// it). A pose holds for a moment, not a single frame: a one-frame dip towards the rest pose
/// between two bent neighbours is more often a wrong fit than a true pose (pjump's frame 23 at
/// 6.6 rad between 8.5 and 7.0, a template 9 cm off). Frames of a collection of unrelated poses
/// continue nothing and keep their own distance.
std::vector<double> confirmedByNeighbours(const std::vector<BodyFrameFit>& fits,
                                          const std::vector<double>& own);
} // namespace clothtrack
