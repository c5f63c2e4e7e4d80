#include "BodyFit.h"

#include "BodySequenceFitter.h"
#include "Extremities.h"

#include <clothtrack/base/Error.h>
#include <clothtrack/base/Parallel.h>
#include <clothtrack/mesh/Geodesic.h>

#include <algorithm>
#include <array>
#include <limits>

namespace clothtrack
{
double fittedRestPoseDistance(BodyFitStatus status, const BodyPose& pose)
{
  return status == BodyFitStatus::Ok ? restPoseDistance(pose)
                                     : std::numeric_limits<double>::quiet_NaN();
}

const char* bodyFitStatusName(BodyFitStatus status)
{
  switch (status)
  {
  case BodyFitStatus::Ok:
    return "ok";
  case BodyFitStatus::Poor:
    return "poor";
  case BodyFitStatus::Failed:
    return "failed";
  }
  return "unknown";
}

using namespace bodyfit;

std::vector<int> bodyExtremityVertices(const BodyModel& model)
{
  const std::array<std::vector<int>, kNumExtremities> groups = {
      {{Head}, {LeftWrist}, {RightWrist}, {LeftToe, LeftAnkle}, {RightToe, RightAnkle}}};
  const int centre = centralVertex(model.mesh);
  if (centre < 0) throw Error("body model: empty mesh");
  const WavefrontGeodesic geodesic(model.mesh, WavefrontGeodesic::Method::Dijkstra);
  const Eigen::VectorXd d = geodesic.distances({centre});
  std::vector<int> out;
  for (const auto& group : groups)
  {
    int best = -1;
    for (int v = 0; v < model.numVertices(); ++v)
    {
      const int j = dominantJoint(model, v);
      if (std::find(group.begin(), group.end(), j) == group.end() || d[v] == kUnreached) continue;
      if (best < 0 || d[v] > d[best]) best = v;
    }
    if (best < 0) throw Error("body model: no vertex is skinned to an end of a limb or the head");
    out.push_back(best);
  }
  return out;
}

BodyFitResult fitBodySequence(const BodyModel& model,
                              const std::vector<const TriangleMesh*>& frames,
                              const BodyFitOptions& options, const StageProgress& progress)
{
  if (model.numVertices() == 0) throw Error("body fit: the body model is empty");
  if (options.stages.empty()) throw Error("body fit: no stage in the weight schedule");
  const int n = static_cast<int>(frames.size());
  BodyFitResult result;
  result.frames.resize(n);
  SequenceFitter fitter(model, options);
  fitter.setReachTolerance(options.shapeReachTolerance);
  double done = 0.0;
  const double total = 2.0 * n + options.shapeRounds * std::max(1, options.shapeFrames);
  auto advance = [&](double amount)
  {
    done += amount;
    if (progress && !progress(std::min(1.0, done / total))) throw Error("body fit: cancelled");
  };

  // Frames that can be fitted at all.
  std::vector<std::unique_ptr<FrameSurface>> surfaces(n);
  std::vector<int> usable;
  for (int i = 0; i < n; ++i)
  {
    const std::string problem = frameProblem(frames[i]);
    if (!problem.empty())
    {
      result.frames[i].status = BodyFitStatus::Failed;
      result.frames[i].message = problem;
      continue;
    }
    usable.push_back(i);
  }
  if (usable.empty()) throw Error("body fit: no frame can be fitted (all empty or corrupt)");
  auto surface = [&](int i) -> const FrameSurface&
  {
    if (!surfaces[i])
      surfaces[i] = std::make_unique<FrameSurface>(*frames[i], options.extremityPersistence,
                                                   result.frames[i].extremitiesDetected >= 0 &&
                                                           !result.frames[i].extremities.empty()
                                                       ? &result.frames[i].extremities
                                                       : nullptr);
    return *surfaces[i];
  };
  auto release = [&](int i) { surfaces[i].reset(); };

  // Pass 1: mean shape, each frame from its neighbour.
  const BodyPose* previous = nullptr;
  for (int i : usable)
  {
    const FrameSurface& s = surface(i);
    BodyFrameFit& fit = result.frames[i];
    fit.extremities = s.extremities;
    fit.extremitiesDetected = static_cast<int>(s.extremities.size());
    if (previous)
      fitter.fitFrame(s, *previous, previous, options.stages, fit);
    else
    {
      const BodyFrameFit first = fitter.initialFit(s);
      fit.pose = first.pose;
      fit.energy = first.energy;
      fit.extremitiesMatched = first.extremitiesMatched;
      fit.status = first.status;
      fit.message = first.message;
      fit.medianDistance = first.medianDistance;
      fit.insideFraction = first.insideFraction;
    }
    previous = &fit.pose;
    release(i);
    advance(1.0);
  }

  // Shape on key frames spread over the sequence, preferring well-fitted ones.
  std::vector<int> candidates;
  for (int i : usable)
    if (result.frames[i].status == BodyFitStatus::Ok) candidates.push_back(i);
  if (candidates.empty()) candidates = usable;
  const int numKeys = std::min<int>(std::max(1, options.shapeFrames), candidates.size());
  std::vector<int> keys;
  for (int k = 0; k < numKeys; ++k)
    keys.push_back(candidates[(2 * k + 1) * candidates.size() / (2 * numKeys)]);
  std::vector<const FrameSurface*> keySurfaces;
  std::vector<BodyPose> keyPoses;
  for (int i : keys)
  {
    keySurfaces.push_back(&surface(i));
    keyPoses.push_back(result.frames[i].pose);
  }
  const std::vector<BodyFitStage> refine(options.stages.end() - 1, options.stages.end());
  for (int round = 0; round < options.shapeRounds; ++round)
  {
    fitter.fitShape(keySurfaces, keyPoses, 4);
    for (size_t k = 0; k < keys.size(); ++k)
    {
      fitter.fitPose(*keySurfaces[k], keyPoses[k], nullptr, refine, options.extremityGate);
      advance(1.0);
    }
  }
  for (int i : keys) release(i);
  result.beta = fitter.samples().beta();
  fitter.setReachTolerance(options.reachTolerance);

  // Pass 2: final shape, each frame from its pass-1 pose, smooth in time.
  // The poses are already close: the last stage suffices.
  const std::vector<BodyFitStage> finalStages(options.stages.end() - 1, options.stages.end());
  previous = nullptr;
  for (int i : usable)
  {
    const FrameSurface& s = surface(i);
    BodyFrameFit& fit = result.frames[i];
    fitter.fitFrame(s, fit.pose, previous, finalStages, fit);
    if (fit.status == BodyFitStatus::Poor && fit.message.empty()) fit.message = "poor fit";
    previous = &fit.pose;
    release(i);
    advance(1.0);
  }

  // Frames that could not be fitted take their nearest fitted neighbour's pose.
  for (int i = 0; i < n; ++i)
  {
    if (result.frames[i].status != BodyFitStatus::Failed) continue;
    int nearest = -1;
    for (int j : usable)
      if (nearest < 0 || std::abs(j - i) < std::abs(nearest - i)) nearest = j;
    result.frames[i].pose = result.frames[nearest].pose;
  }
  return result;
}
} // namespace clothtrack
