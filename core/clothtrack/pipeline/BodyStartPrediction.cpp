#include "BodyStartPrediction.h"

#include <clothtrack/base/Error.h>

#include <string>

namespace clothtrack
{
StartPrediction bodyStartPrediction(std::shared_ptr<const SkinnedTemplate> bound,
                                    std::vector<PosedSkeleton> skeletons, std::vector<bool> trusted,
                                    StartPrediction fallback)
{
  if (!bound) throw Error("body start: no template bound to the body");
  if (trusted.size() != skeletons.size())
    throw Error("body start: " + std::to_string(trusted.size()) + " fit flags for " +
                std::to_string(skeletons.size()) + " bodies");
  return [bound = std::move(bound), skeletons = std::move(skeletons), trusted = std::move(trusted),
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
  const int n = static_cast<int>(body.frames.size());
  if (templateFrame < 0 || templateFrame >= n)
    throw Error("body start: the template frame " + std::to_string(templateFrame) +
                " has no fitted body");
  // A doubtful body at the template frame would bind the template wrongly everywhere.
  if (body.frames[templateFrame].status != BodyFitStatus::Ok) return fallback;
  std::vector<PosedSkeleton> skeletons;
  std::vector<bool> trusted;
  for (const BodyFrameFit& f : body.frames)
  {
    skeletons.push_back(posedSkeleton(model, body.beta, f.pose));
    trusted.push_back(f.status == BodyFitStatus::Ok);
  }
  const BodyPose& pose = body.frames[templateFrame].pose;
  auto bound = std::make_shared<SkinnedTemplate>(templateMesh, model.posed(body.beta, pose).V,
                                                 model.weights, skeletons[templateFrame]);
  return bodyStartPrediction(std::move(bound), std::move(skeletons), std::move(trusted),
                             std::move(fallback));
}
} // namespace clothtrack
