#pragma once
// Stage 1 (Shehu et al. 2016, section 4.1): the body fitted under the clothing of every frame,
// and its oriented anatomical landmarks carried onto each frame's surface. A frame whose body fit
// failed gets no landmark: its pose is only the neighbour's.
#include <clothtrack/base/Progress.h>
#include <clothtrack/body/BodyFit.h>
#include <clothtrack/body/LandmarkTransfer.h>

#include <vector>

namespace clothtrack
{
struct BodyStageOptions
{
  BodyFitOptions fit;
  LandmarkTransferOptions transfer;
};

/// The landmarks found on one frame, as patch seeds (id: the model's landmark index).
using FrameLandmarks = std::vector<OrientedSurfacePoint>;

struct BodyStageResult
{
  BodyFitResult body;
  /// Per frame, the model's oriented landmarks on the fitted body, in the model's order.
  std::vector<std::vector<OrientedPoint>> bodyLandmarks;
  /// Per frame, each of them carried onto the frame (invalid where not found).
  std::vector<std::vector<TransferredLandmark>> transferred;
  /// Per frame, the valid ones as surface points: the input of stages 2 and 3.
  std::vector<FrameLandmarks> landmarks;
};

/// Fits the body to every frame (null frames are flagged failed) and transfers its landmarks.
/// The body fit takes 95 % of the reported progress. Throws Error when no frame can be fitted or
/// when cancelled.
BodyStageResult fitBodyAndLandmarks(const BodyModel& model,
                                    const std::vector<const TriangleMesh*>& frames,
                                    const BodyStageOptions& options = {},
                                    const StageProgress& progress = {});

/// Each frame's fittedRestPoseDistance, the template criterion: NaN unless its body fit is ok
/// and explains its frame nearly as well as the sequence's median fit does (frameDistance at
/// most `explainedRatio` times the median of the ok fits). The template frame's body binds the
/// template for every frame; a body that fell towards the rest pose, leaving a raised limb
/// unexplained, looked like the best template.
std::vector<double> restPoseDistances(const BodyFitResult& body, double explainedRatio = 1.3);
} // namespace clothtrack
