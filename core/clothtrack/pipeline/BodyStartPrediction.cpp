#include "BodyStartPrediction.h"

#include <clothtrack/base/Error.h>

#include <cmath>
#include <memory>
#include <string>

namespace clothtrack
{
namespace
{
/// What bodyPosedTemplate needs of a body fit result: frames whose fit is not ok are not trusted.
FittedBodies fittedBodies(const BodyModel& model, const BodyFitResult& body, int templateFrame)
{
  FittedBodies bodies;
  for (const BodyFrameFit& f : body.frames)
  {
    bodies.skeletons.push_back(posedSkeleton(model, body.beta, f.pose));
    bodies.trusted.push_back(f.status == BodyFitStatus::Ok);
  }
  if (templateFrame >= 0 && templateFrame < static_cast<int>(body.frames.size()))
    bodies.templateBody = model.posed(body.beta, body.frames[templateFrame].pose).V;
  bodies.weights = model.weights;
  return bodies;
}
} // namespace

TemplatePosedByBody bodyPosedTemplate(const TriangleMesh& templateMesh, int templateFrame,
                                      FittedBodies bodies)
{
  const int n = static_cast<int>(bodies.skeletons.size());
  if (static_cast<int>(bodies.trusted.size()) != n)
    throw Error("body start: " + std::to_string(bodies.trusted.size()) + " fit flags for " +
                std::to_string(n) + " bodies");
  if (templateFrame < 0 || templateFrame >= n)
    throw Error("body start: the template frame " + std::to_string(templateFrame) +
                " has no fitted body");
  if (!bodies.trusted[templateFrame])
    return [](int) -> std::optional<Points> { return std::nullopt; };
  auto bound = std::make_shared<const SkinnedTemplate>(
      templateMesh, bodies.templateBody, bodies.weights, bodies.skeletons[templateFrame]);
  return [bound, skeletons = std::move(bodies.skeletons),
          trusted = std::move(bodies.trusted)](int k) -> std::optional<Points>
  {
    if (k < 0 || k >= static_cast<int>(skeletons.size()))
      throw Error("body start: frame " + std::to_string(k) + " has no fitted body");
    if (!trusted[k]) return std::nullopt;
    return bound->posed(skeletons[k]);
  };
}

TemplatePosedByBody bodyPosedTemplate(const BodyModel& model, const BodyFitResult& body,
                                      const TriangleMesh& templateMesh, int templateFrame)
{
  return bodyPosedTemplate(templateMesh, templateFrame, fittedBodies(model, body, templateFrame));
}

std::vector<bool> unplacedFrames(const BodyFitResult& body)
{
  std::vector<bool> unplaced;
  for (const BodyFrameFit& f : body.frames)
    unplaced.push_back(f.status != BodyFitStatus::Ok && !f.continuesPrevious);
  return unplaced;
}

void doubtFromBodies(SequenceQuality& quality, const BodyFitResult& body)
{
  if (body.frames.size() != quality.confidence.size() || quality.confidence.empty()) return;
  doubtUnplacedFrames(quality, unplacedFrames(body));
  std::vector<double> rivalRatios;
  for (const BodyFrameFit& f : body.frames) rivalRatios.push_back(f.rivalScoreRatio);
  doubtAmbiguousBodies(quality, rivalRatios);
}

std::optional<Points> bodyPosedStart(const TemplatePosedByBody& posed,
                                     const std::function<FramePtr(int)>& frames, int k)
{
  std::optional<Points> start = posed(k);
  if (start && frames)
    if (const FramePtr frame = frames(k)) stretchToFrameExtent(*start, *frame);
  return start;
}

StartPrediction bodyStartPrediction(TemplatePosedByBody posed, StartPrediction fallback,
                                    std::function<FramePtr(int)> frames)
{
  return [posed = std::move(posed), fallback = std::move(fallback),
          frames = std::move(frames)](int k, int from, const Points& fitOfFrom) -> Points
  {
    if (std::optional<Points> start = bodyPosedStart(posed, frames, k)) return std::move(*start);
    return fallback ? fallback(k, from, fitOfFrom) : fitOfFrom;
  };
}

std::function<VertexTargets(int, const VertexTargets&)>
targetsAgreeingWithBodyStart(TemplatePosedByBody posed, std::function<FramePtr(int)> frames,
                             double gate)
{
  if (!(gate >= 0)) throw Error("body start: the correspondence gate must be >= 0");
  if (!posed || gate == 0) return {};
  return [posed = std::move(posed), frames = std::move(frames),
          gate](int k, const VertexTargets& all) -> VertexTargets
  {
    const std::optional<Points> start = bodyPosedStart(posed, frames, k);
    if (!start || start->rows() != all.position.rows() ||
        static_cast<Eigen::Index>(all.matched.size()) != start->rows())
      return all; // no body to judge by, or a mismatch the fit itself names
    VertexTargets kept = all;
    for (Eigen::Index i = 0; i < start->rows(); ++i)
      if (kept.matched[i] && (kept.position.row(i) - start->row(i)).norm() > gate)
        kept.matched[i] = 0;
    return kept;
  };
}

void narrowTargetsToBodyStart(SequenceFitHooks& hooks, TemplatePosedByBody posed,
                              std::function<FramePtr(int)> frames, double gate)
{
  auto narrow = targetsAgreeingWithBodyStart(std::move(posed), std::move(frames), gate);
  if (!narrow || !hooks.targets) return;
  auto kept = std::make_shared<VertexTargets>();
  hooks.targets = [all = std::move(hooks.targets), narrow = std::move(narrow),
                   kept](int k) -> const VertexTargets*
  {
    const VertexTargets* targets = all(k);
    if (!targets) return nullptr;
    *kept = narrow(k, *targets);
    return kept.get();
  };
}

bool stretchToFrameExtent(Points& start, const TriangleMesh& frame, const Vec3& up)
{
  if (start.rows() == 0 || frame.V.rows() == 0) return false;
  const Eigen::VectorXd height = start * up, frameHeight = frame.V * up;
  const double low = height.minCoeff(), span = height.maxCoeff() - low;
  const double frameLow = frameHeight.minCoeff(), frameSpan = frameHeight.maxCoeff() - frameLow;
  if (!(span > 0) || !(std::abs(frameSpan / span - 1.0) <= kLargestExtentStretch)) return false;
  const Eigen::VectorXd shift =
      ((height.array() - low) * (frameSpan / span - 1.0) + (frameLow - low)).matrix();
  start += shift * up.transpose();
  return true;
}

StartPrediction bodyStartPrediction(const TriangleMesh& templateMesh, int templateFrame,
                                    FittedBodies bodies, StartPrediction fallback)
{
  const bool bound = templateFrame >= 0 &&
                     templateFrame < static_cast<int>(bodies.trusted.size()) &&
                     bodies.trusted[templateFrame];
  TemplatePosedByBody posed = bodyPosedTemplate(templateMesh, templateFrame, std::move(bodies));
  if (!bound) return fallback; // a body binding nothing changes no start
  return bodyStartPrediction(std::move(posed), std::move(fallback));
}

StartPrediction bodyStartPrediction(const BodyModel& model, const BodyFitResult& body,
                                    const TriangleMesh& templateMesh, int templateFrame,
                                    StartPrediction fallback)
{
  return bodyStartPrediction(templateMesh, templateFrame, fittedBodies(model, body, templateFrame),
                             std::move(fallback));
}
} // namespace clothtrack
