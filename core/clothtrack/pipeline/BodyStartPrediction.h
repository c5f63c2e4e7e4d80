#pragma once
// The start of each frame's template fit from the body fitted to it (body/SkinnedTemplate.h):
// the template posed by the frame's body. Frames whose body fit is not trusted start as the
// fallback says (the landmark prediction, or the neighbour's fit).
#include <clothtrack/body/BodyFit.h>
#include <clothtrack/body/SkinnedTemplate.h>
#include <clothtrack/eval/FrameConfidence.h>
#include <clothtrack/eval/SequenceQuality.h>
#include <clothtrack/fit/SequenceFit.h>

#include <functional>
#include <optional>
#include <vector>

namespace clothtrack
{
/// What a fitted sequence of bodies gives the start: one skeleton and one trusted flag per frame,
/// and the posed vertices and skinning weights of the template frame's body.
struct FittedBodies
{
  std::vector<PosedSkeleton> skeletons;
  std::vector<bool> trusted;
  Points templateBody;
  Eigen::MatrixXd weights;
};

/// The template bound to the template frame's body and posed by frame k's; nullopt for frames
/// whose body is not trusted, and for every frame when the template frame's body is not (a
/// doubtful body there would bind the template wrongly everywhere). Safe to call from several
/// threads at once. The same also judges a fit (eval/FrameConfidence.h, body distance).
TemplatePosedByBody bodyPosedTemplate(const TriangleMesh& templateMesh, int templateFrame,
                                      FittedBodies bodies);

/// The same from a body fit result and its model (the command line): frames whose fit is not
/// ok are not trusted.
TemplatePosedByBody bodyPosedTemplate(const BodyModel& model, const BodyFitResult& body,
                                      const TriangleMesh& templateMesh, int templateFrame);

/// Frames nothing places (eval/SequenceQuality.h, doubtUnplacedFrames): their body fit is not
/// ok, so they have no body start, and they do not continue their predecessor
/// (BodyFrameFit::continuesPrevious), so the fallback carries an unrelated frame's fit to them.
std::vector<bool> unplacedFrames(const BodyFitResult& body);

/// The doubts a frame's body fit raises whatever the frame measures (eval/SequenceQuality.h):
/// unplacedFrames (doubtUnplacedFrames), and a body that another pose explains almost as well
/// (BodyFrameFit::rivalScoreRatio, doubtAmbiguousBodies). Does nothing unless `body` has one fit
/// per measured frame (a run without a body fit has none).
void doubtFromBodies(SequenceQuality& quality, const BodyFitResult& body);

/// The start of frame k: the template posed by frame k's body. Frames without one start from
/// `fallback` (which may be empty: the neighbour's fit as it is). With `frames`, each posed
/// template is first stretched to its frame's extent (stretchToFrameExtent).
StartPrediction bodyStartPrediction(TemplatePosedByBody posed, StartPrediction fallback,
                                    std::function<FramePtr(int)> frames = {});

/// The start bodyStartPrediction gives frame k when its body is trusted: the template posed by
/// the frame's body, stretched to the frame's extent when `frames` is given; nullopt otherwise.
std::optional<Points> bodyPosedStart(const TemplatePosedByBody& posed,
                                     const std::function<FramePtr(int)>& frames, int k);

/// Default gate of targetsAgreeingWithBodyStart (metres; BENCHMARKS.md, "Robustness:
/// correspondences the body contradicts").
inline constexpr double kDefaultCorrespondenceGate = 0.05;

/// Correspondences the frame's body contradicts. For a frame the body starts (bodyPosedStart), a
/// template vertex's target further than `gate` from where that start puts the vertex is
/// dropped; the other frames' targets pass as they are. The patches are seeded by landmarks
/// carried from the same bodies, but a patch that grows along a boot shaft or across a limb
/// pulls a whole region the wrong way, and the fit's nearest points cannot see a slide along the
/// surface (pjump: the first stage slid the shins 9 cm down the boots, docs/template-fit.md).
/// An empty function when there is nothing to narrow (no bodies, or a gate of 0). Throws Error
/// for a negative gate.
std::function<VertexTargets(int k, const VertexTargets& all)>
targetsAgreeingWithBodyStart(TemplatePosedByBody posed, std::function<FramePtr(int)> frames,
                             double gate);

/// Narrows `hooks.targets` by targetsAgreeingWithBodyStart, for every fit of the frame (a retry
/// from another start with all of them kept fits pjump worse, docs/template-fit.md). The new
/// hook keeps one buffer, as the hooks' contract allows (one call at a time, copied at once).
void narrowTargetsToBodyStart(SequenceFitHooks& hooks, TemplatePosedByBody posed,
                              std::function<FramePtr(int)> frames, double gate);

/// Largest relative change of height stretchToFrameExtent makes; beyond it the start is left as
/// it is (a frame missing its feet, or a stray fragment of the floor, is not a body that slid).
inline constexpr double kLargestExtentStretch = 0.2;

/// Moves and scales `start` along `up` (a unit vector) so that its lowest and highest points
/// meet the frame's. The template lies on the template frame; where the body fitted to another
/// frame stands higher or lower in it than the template frame's body did (feet that end inside
/// boots, and hang lower in one frame than in the next), the posed template is carried up or
/// down the surface with it, and the fit, whose data terms cannot see a slide along the
/// surface, keeps it (pjump: 4.26 to 4.06 cm, docs/template-fit.md). Returns false, the start
/// unchanged, where the height would change by more than kLargestExtentStretch.
bool stretchToFrameExtent(Points& start, const TriangleMesh& frame, const Vec3& up = Vec3::UnitY());

/// bodyStartPrediction(bodyPosedTemplate(templateMesh, templateFrame, bodies), fallback); when
/// the template frame's body is not trusted, `fallback` itself is returned.
StartPrediction bodyStartPrediction(const TriangleMesh& templateMesh, int templateFrame,
                                    FittedBodies bodies, StartPrediction fallback);

/// The same from a body fit result and its model (the command line): frames whose fit is not
/// ok are not trusted.
StartPrediction bodyStartPrediction(const BodyModel& model, const BodyFitResult& body,
                                    const TriangleMesh& templateMesh, int templateFrame,
                                    StartPrediction fallback);
} // namespace clothtrack
