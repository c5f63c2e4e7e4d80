#include "BodyStartPrediction.h"

#include <clothtrack/base/Error.h>

#include <memory>
#include <string>

namespace clothtrack
{
StartPrediction bodyStartPrediction(const TriangleMesh& templateMesh, int templateFrame,
                                    FittedBodies bodies, StartPrediction fallback)
{
  const int n = static_cast<int>(bodies.skeletons.size());
  if (static_cast<int>(bodies.trusted.size()) != n)
    throw Error("body start: " + std::to_string(bodies.trusted.size()) + " fit flags for " +
                std::to_string(n) + " bodies");
  if (templateFrame < 0 || templateFrame >= n)
    throw Error("body start: the template frame " + std::to_string(templateFrame) +
                " has no fitted body");
  // A doubtful body at the template frame would bind the template wrongly everywhere.
  if (!bodies.trusted[templateFrame]) return fallback;
  auto bound = std::make_shared<const SkinnedTemplate>(
      templateMesh, bodies.templateBody, bodies.weights, bodies.skeletons[templateFrame]);
  return [bound, skeletons = std::move(bodies.skeletons), trusted = std::move(bodies.trusted),
          fallback = std::move(fallback)](int k, int from, const Points& fitOfFrom) -> Points
  {
    if (k < 0 || k >= static_cast<int>(skeletons.size()))
      throw Error("body start: frame " + std::to_string(k) + " has no fitted body");
    if (trusted[k]) return bound->posed(skeletons[k]);
    return fallback ? fallback(k, from, fitOfFrom) : fitOfFrom;
  };
}

StartPrediction bodyStartPrediction(const BodyModel& model, const BodyFitResult& body,
                                    const TriangleMesh& templateMesh, int templateFrame,
                                    StartPrediction fallback)
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
  return bodyStartPrediction(templateMesh, templateFrame, std::move(bodies), std::move(fallback));
}
} // namespace clothtrack
