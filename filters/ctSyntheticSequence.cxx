#include "ctSyntheticSequence.h"

#include <clothtrack/base/Error.h>
#include <clothtrack/body/Motion.h>
#include <clothtrack/mesh/Primitives.h>
#include <clothtrack/synth/ClothSimulator.h>

#include <cstdio>
#include <random>

namespace clothtrack
{
namespace
{
struct Preset
{
  const char* name;
  GarmentType garment;
  MotionType motion;
  double hemHeight;
  double flare;
};

const std::vector<Preset>& presets()
{
  static const std::vector<Preset> all = {
      {"dress-walk", GarmentType::Dress, MotionType::Walk, 0.30, 1.9},
      {"skirt-turn", GarmentType::Skirt, MotionType::Turn, 0.36, 2.3},
      {"trousers-squat", GarmentType::Trousers, MotionType::Squat, 0.0, 1.0},
      {"shirt-armraise", GarmentType::Shirt, MotionType::ArmRaise, 0.0, 1.0},
      {"dress-samba", GarmentType::Dress, MotionType::Dance, 0.22, 2.0},
      // The cases the body fit found hardest: a loop with a full turn and high knees in wide
      // trousers, quick half-turns, and arms folded against the body (limbs merge).
      {"trousers-walkloop", GarmentType::Trousers, MotionType::WalkLoop, 0.0, 1.5},
      {"shirt-halfturns", GarmentType::Shirt, MotionType::HalfTurns, 0.0, 1.0},
      {"shirt-crossedarms", GarmentType::Shirt, MotionType::CrossedArms, 0.0, 1.0},
  };
  return all;
}

const Preset* findPreset(const std::string& name)
{
  for (const auto& p : presets())
    if (name == p.name) return &p;
  return nullptr;
}
} // namespace

const std::vector<std::string>& syntheticPresets()
{
  static const std::vector<std::string> names = []
  {
    std::vector<std::string> n;
    for (const auto& p : presets()) n.push_back(p.name);
    return n;
  }();
  return names;
}

const std::vector<std::string>& syntheticMarkerNames()
{
  static const std::vector<std::string> names = {
      "forehead",   "left_shoulder", "right_shoulder", "left_elbow", "right_elbow",
      "left_wrist", "right_wrist",   "belly",          "left_knee",  "right_knee",
      "left_toe",   "right_toe",     "left_heel",      "right_heel"};
  return names;
}

double restHeight(const BodyModel& model, const Eigen::VectorXd& beta)
{
  Points vertices, joints;
  model.shape(beta, vertices, joints);
  return vertices.col(1).maxCoeff() - vertices.col(1).minCoeff();
}

namespace
{
/// Sets beta[0], the component that carries stature, so that the body is `stature` tall
/// (bisection: the height grows with beta[0]).
void setStature(const BodyModel& model, double stature, Eigen::VectorXd& beta)
{
  if (beta.size() == 0) throw Error("the body model has no shape space to set the stature");
  const double range = 4.0; // standard deviations
  Eigen::VectorXd low = beta, high = beta;
  low[0] = -range;
  high[0] = range;
  const double shortest = restHeight(model, low), tallest = restHeight(model, high);
  if (!(shortest < tallest) || stature < shortest || stature > tallest)
  {
    char text[160];
    std::snprintf(text, sizeof(text), "stature %.3f m is outside the body model's %.2f-%.2f m",
                  stature, std::min(shortest, tallest), std::max(shortest, tallest));
    throw Error(text);
  }
  for (int step = 0; step < 40; ++step)
  {
    beta[0] = 0.5 * (low[0] + high[0]);
    (restHeight(model, beta) < stature ? low : high)[0] = beta[0];
  }
}
} // namespace

void checkSyntheticOptions(const SyntheticOptions& options)
{
  if (!findPreset(options.preset))
  {
    std::string all;
    for (const auto& n : syntheticPresets()) all += (all.empty() ? "" : ", ") + n;
    throw Error("unknown preset '" + options.preset + "' (one of: " + all + ")");
  }
  if (options.frames < 1 || options.frames > 100000)
    throw Error("the number of frames must be between 1 and 100000");
  if (!(options.fps > 0)) throw Error("the frame rate must be positive");
}

Eigen::VectorXd generateSyntheticSequence(const BodyModel& model, const SyntheticOptions& options,
                                          const std::function<void(const SyntheticFrame&)>& sink)
{
  checkSyntheticOptions(options);
  const Preset* preset = findPreset(options.preset);

  std::mt19937 rng(options.seed);
  std::normal_distribution<double> normal(0.0, 1.0);
  Eigen::VectorXd beta = Eigen::VectorXd::Zero(model.numShapeComponents());
  for (int k = 0; k < std::min(6, static_cast<int>(beta.size())); ++k)
    beta[k] = std::clamp(options.shapeSpread * normal(rng), -2.0, 2.0);
  if (options.stature > 0) setStature(model, options.stature, beta);

  GarmentOptions garmentOptions;
  garmentOptions.type = preset->garment;
  garmentOptions.hemHeight = options.hemHeight > 0 ? options.hemHeight : preset->hemHeight;
  garmentOptions.flare = preset->flare;
  ClothSimulator cloth(model, beta, makeGarment(model, beta, garmentOptions));

  std::vector<int> markerVertices;
  for (const auto& name : syntheticMarkerNames())
  {
    const int index = model.landmarkIndex(name);
    if (index < 0) throw Error("the body model has no landmark '" + name + "' for the markers");
    markerVertices.push_back(model.landmarks[index].vertex);
  }

  for (int k = 0; k < options.frames; ++k)
  {
    SyntheticFrame frame;
    frame.index = k;
    frame.time = k / options.fps;
    frame.pose = model.grounded(beta, motionPose(preset->motion, frame.time));
    frame.body = model.posed(beta, frame.pose);
    if (k == 0)
      cloth.reset(frame.pose);
    else
      cloth.step(frame.pose, 1.0 / options.fps);
    const TriangleMesh garment{cloth.positions(), cloth.garment().rest.F};
    frame.clothed = concatenate(frame.body, garment);
    frame.garmentOffset = frame.body.numVertices();
    frame.markers.resize(static_cast<Eigen::Index>(markerVertices.size()), 3);
    for (size_t m = 0; m < markerVertices.size(); ++m)
      frame.markers.row(static_cast<Eigen::Index>(m)) = frame.body.V.row(markerVertices[m]);
    sink(frame);
  }
  return beta;
}
} // namespace clothtrack
