#ifndef ctSyntheticSequence_h
#define ctSyntheticSequence_h
// Synthetic clothed motion with ground truth: the body model in a motion, wearing a simulated
// garment. Presets pair a garment and a motion. C++ only (not wrapped).
#include "ctFiltersModule.h"

#include <clothtrack/body/BodyModel.h>

#include <functional>
#include <string>
#include <vector>

namespace clothtrack
{
struct SyntheticOptions
{
  std::string preset = "dress-walk";
  int frames = 40;
  double fps = 25.0;
  unsigned seed = 7;
  /// Spread of the random body shape (beta ~ N(0, shapeSpread^2) on the first components).
  double shapeSpread = 0.7;
  /// Hem height as a fraction of stature (dress, skirt); <= 0 keeps the preset's.
  double hemHeight = 0.0;
  /// Height of the body in rest pose, metres: > 0 sets the first shape component so that the
  /// random body has this height (people far from the mean); <= 0 keeps the random height.
  double stature = 0.0;
};

struct SyntheticFrame
{
  int index = 0;
  double time = 0.0;
  BodyPose pose;
  TriangleMesh body;    ///< posed body alone
  TriangleMesh clothed; ///< ground truth: body then garment vertices, same connectivity every frame
  int garmentOffset = 0; ///< first garment vertex in `clothed`
  Points markers;        ///< the 14 marker positions (see syntheticMarkerNames())
};

/// dress-walk, skirt-turn, trousers-squat, shirt-armraise, dress-samba, trousers-walkloop,
/// shirt-halfturns, shirt-crossedarms.
CTFILTERS_EXPORT const std::vector<std::string>& syntheticPresets();
/// forehead, shoulders, elbows, wrists, belly, knees, feet (toes), heels.
CTFILTERS_EXPORT const std::vector<std::string>& syntheticMarkerNames();

/// Height of the body of shape beta in rest pose (extent along y, the model's up axis), metres.
CTFILTERS_EXPORT double restHeight(const BodyModel& model, const Eigen::VectorXd& beta);

/// Throws Error on an unknown preset or bad options; cheap, so front ends check before they build
/// the body model.
CTFILTERS_EXPORT void checkSyntheticOptions(const SyntheticOptions& options);

/// Runs the simulation frame by frame; `sink` receives each frame in order (memory stays flat).
/// Returns the shape beta used. Throws Error on an unknown preset or bad options.
CTFILTERS_EXPORT Eigen::VectorXd
generateSyntheticSequence(const BodyModel& model, const SyntheticOptions& options,
                          const std::function<void(const SyntheticFrame&)>& sink);
} // namespace clothtrack

#endif
