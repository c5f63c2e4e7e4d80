#include "BodyFit.h"

#include "BodySequenceFitter.h"
#include "Extremities.h"

#include <clothtrack/base/Bytes.h>
#include <clothtrack/base/Error.h>
#include <clothtrack/base/Parallel.h>
#include <clothtrack/mesh/Geodesic.h>
#include <clothtrack/mesh/SubjectSize.h>
#include <clothtrack/mesh/SurfaceGap.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <limits>
#include <memory>
#include <optional>
#include <utility>

namespace clothtrack
{
namespace
{
/// The value at index size / 2 once sorted (the upper of the two middle ones); `values` non-empty.
double upperMedian(std::vector<double> values)
{
  std::nth_element(values.begin(), values.begin() + values.size() / 2, values.end());
  return values[values.size() / 2];
}
} // namespace

std::optional<double> medianFrameDistance(const std::vector<BodyFrameFit>& fits, size_t minimumFits)
{
  std::vector<double> distances;
  for (const BodyFrameFit& f : fits)
    if (f.status == BodyFitStatus::Ok) distances.push_back(f.frameDistance);
  if (distances.empty() || distances.size() < minimumFits) return std::nullopt;
  return upperMedian(std::move(distances));
}

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

namespace
{
/// The frames' surfaces, built when first needed and released after use. A frame's detected
/// extremities are kept, so that building its surface again does not detect them again.
class FrameSurfaces
{
public:
  FrameSurfaces(const FrameSource& frames, double persistence)
      : frames_(frames), persistence_(persistence), meshes_(frames.count()),
        surfaces_(frames.count()), detected_(frames.count())
  {
  }

  const FrameSurface& get(int i)
  {
    if (!surfaces_[i])
    {
      meshes_[i] = frames_.frame(i); // the surface refers to it: held as long
      surfaces_[i] = std::make_unique<FrameSurface>(*meshes_[i], persistence_,
                                                    detected_[i] ? &*detected_[i] : nullptr);
      detected_[i] = surfaces_[i]->extremities;
    }
    return *surfaces_[i];
  }

  void release(int i)
  {
    surfaces_[i].reset();
    meshes_[i].reset();
  }

private:
  const FrameSource& frames_;
  double persistence_;
  std::vector<FramePtr> meshes_;
  std::vector<std::unique_ptr<FrameSurface>> surfaces_;
  std::vector<std::optional<std::vector<Vec3>>> detected_; ///< empty until first detected
};

/// Progress over the fit's units of work (a frame of a pass, a key frame of a shape round, a
/// restart of the end steps). The end steps' work is known only once the passes are done, so the
/// plan can be redrawn: progress then goes on from where it stands, never back.
class FitProgress
{
public:
  FitProgress(const StageProgress& progress, double units) : progress_(progress), units_(units) {}

  void advance(double amount)
  {
    done_ += amount;
    if (progress_ && !progress_(fraction())) throw Error("body fit: cancelled");
  }

  /// Reports the fit done (the end steps may have found nothing to restart).
  void finish()
  {
    start_ = 1.0;
    advance(0.0);
  }

  /// The rest of the fit is `units` units of work: the rest of the progress is spread over them.
  void replan(double units)
  {
    start_ = fraction();
    units_ = units;
    done_ = 0.0;
  }

private:
  double fraction() const
  {
    return units_ > 0.0 ? start_ + (1.0 - start_) * std::min(1.0, done_ / units_) : start_;
  }

  const StageProgress& progress_;
  double start_ = 0.0;
  double units_;
  double done_ = 0.0;
};

/// A restart of the end steps (turned round, started from other poses or with the legs across)
/// in units of a pass's frame: on a collection of 20 unrelated poses (random seed 11) five such
/// restarts took 4.6 s, 0.28 s a unit of its passes.
constexpr double kRestartUnits = 3.0;

/// Peers whose joints restartFromPeers tries on each unrelated frame, and that step's work per
/// frame in units of a pass's frame (a brief fit from each peer, then one full fit): on collection
/// seed 13 it took 11.8 s for 20 frames, about two units each.
constexpr size_t kMostPeers = 24;
constexpr double kPeerRestartUnits = 2.0;

/// Indices of the frames that can be fitted at all; the others are marked failed.
std::vector<int> usableFrames(const FrameSource& frames, std::vector<BodyFrameFit>& fits)
{
  std::vector<int> usable;
  for (int i = 0; i < frames.count(); ++i)
  {
    const std::string problem = frameProblem(frames.frame(i).get());
    if (problem.empty())
      usable.push_back(i);
    else
    {
      fits[i].status = BodyFitStatus::Failed;
      fits[i].message = problem;
    }
  }
  if (usable.empty()) throw Error("body fit: no frame can be fitted (all empty or corrupt)");
  return usable;
}

/// The poses of the ok fits among the usable frames before frame `end`, at most 24 spread
/// evenly over them (all of them when `end` is not usable).
std::vector<BodyPose> okPoses(const std::vector<int>& usable, int end,
                              const std::vector<BodyFrameFit>& fits)
{
  std::vector<int> ok;
  for (int i : usable)
  {
    if (i == end) break;
    if (fits[i].status == BodyFitStatus::Ok) ok.push_back(i);
  }
  const size_t count = std::min<size_t>(ok.size(), 24);
  std::vector<BodyPose> poses;
  for (size_t k = 0; k < count; ++k) poses.push_back(fits[ok[k * ok.size() / count]].pose);
  return poses;
}

/// The start of a frame that continues `from`: the predecessor's pose, moved by the rigid
/// motion between the two surfaces when BodyFitOptions::frameMotion gives one.
BodyPose predictedPose(const SequenceFitter& fitter, const BodyFitOptions& options,
                       const TriangleMesh& from, const TriangleMesh& to, const BodyPose& previous)
{
  if (!options.frameMotion) return previous;
  const std::optional<Eigen::Isometry3d> motion = options.frameMotion(from, to);
  return motion ? fitter.movedRigidly(previous, *motion) : previous;
}

/// Pass 1: the mean shape, each frame from its neighbour's pose, the first from the most
/// plausible heading. A frame far from its predecessor is not tied to it by the temporal prior,
/// and is also started from the poses of the frames fitted before it (refitFromPoses).
void firstPass(SequenceFitter& fitter, FrameSurfaces& surfaces, const std::vector<int>& usable,
               const BodyFitOptions& options, std::vector<BodyFrameFit>& fits,
               FitProgress& progress)
{
  const BodyFrameFit start = fitter.initialFit(surfaces.get(usable.front()));
  int last = -1;
  for (int i : usable)
  {
    const FrameSurface& s = surfaces.get(i);
    BodyFrameFit& fit = fits[i];
    if (last >= 0)
    {
      const FrameSurface& before = surfaces.get(last);
      const double gap = meanSurfaceGap(*before.mesh, *before.locator, *s.mesh, *s.locator);
      const bool continuous = gap <= options.neighbourGap;
      const BodyPose init =
          continuous ? predictedPose(fitter, options, *before.mesh, *s.mesh, fits[last].pose)
                     : fits[last].pose;
      surfaces.release(last);
      fitter.fitFrame(s, init, continuous ? &init : nullptr, options.stages, fit, continuous,
                      /*everyHeading=*/true);
      if (!continuous)
      {
        fitter.refitFromPoses(s, okPoses(usable, i, fits), fit);
        if (options.limbRestarts) fitter.refitLimbs(s, fit);
      }
      fit.previousGap = gap;
      fit.continuesPrevious = continuous;
    }
    else
      fit = start;
    fit.extremities = s.extremities;
    fit.extremitiesDetected = static_cast<int>(s.extremities.size());
    last = i;
    progress.advance(1.0);
  }
  surfaces.release(last);
}

/// Height (extent along Y) of a set of points.
double heightOf(const Points& points)
{
  return points.col(1).maxCoeff() - points.col(1).minCoeff();
}

/// The shape of least norm whose rest pose is `ratio` times the mean body's height, that height
/// kept within a person's (SubjectSize.h); heights are near linear in beta: one finite
/// difference per component.
Eigen::VectorXd scaledShape(const BodyModel& model, Eigen::Index components, double ratio)
{
  const Eigen::VectorXd mean = Eigen::VectorXd::Zero(components);
  Points vertices, joints;
  model.shape(mean, vertices, joints);
  const double meanHeight = heightOf(vertices);
  const double target = std::clamp(ratio * meanHeight, kSmallestPerson, kTallestPerson);
  Eigen::VectorXd gradient(components);
  for (Eigen::Index c = 0; c < components; ++c)
  {
    Eigen::VectorXd unit = mean;
    unit[c] = 1.0;
    model.shape(unit, vertices, joints);
    gradient[c] = heightOf(vertices) - meanHeight;
  }
  if (gradient.squaredNorm() < 1e-12) return mean;
  return gradient * ((target - meanHeight) / gradient.squaredNorm());
}

/// The median over the key frames of the frame's height over its fitted body's; 1 when none.
double statureRatio(const BodyModel& model, const Eigen::VectorXd& beta,
                    const std::vector<const FrameSurface*>& frames,
                    const std::vector<BodyPose>& poses)
{
  std::vector<double> ratios;
  for (size_t k = 0; k < frames.size(); ++k)
  {
    const double body = heightOf(model.posed(beta, poses[k]).V);
    if (body > 0) ratios.push_back(heightOf(frames[k]->mesh->V) / body);
  }
  return ratios.empty() ? 1.0 : upperMedian(std::move(ratios));
}

/// Key frames for the shape, spread over the sequence, well-fitted ones first.
std::vector<int> shapeKeyFrames(const std::vector<int>& usable, const BodyFitOptions& options,
                                const std::vector<BodyFrameFit>& fits)
{
  std::vector<int> candidates;
  for (int i : usable)
    if (fits[i].status == BodyFitStatus::Ok) candidates.push_back(i);
  if (candidates.empty()) candidates = usable;
  const int numKeys = std::min<int>(std::max(1, options.shapeFrames), candidates.size());
  std::vector<int> keys;
  for (int k = 0; k < numKeys; ++k)
    keys.push_back(candidates[(2 * k + 1) * candidates.size() / (2 * numKeys)]);
  return keys;
}

/// The last stage with E_c, as the shape's steps have it, for the key frames' poses: a shape
/// grown towards the frame while its poses stay as the thinner body left them takes up their
/// errors (a leg too long in a squat).
std::vector<BodyFitStage> keyPoseStages(const BodyFitOptions& options)
{
  std::vector<BodyFitStage> stages(options.stages.end() - 1, options.stages.end());
  stages.back().coverWeight = options.shapeCoverWeight;
  return stages;
}

/// Beta alternating with the key frames' poses, from the fitter's current shape and `keyPoses`.
Eigen::VectorXd estimateShape(SequenceFitter& fitter,
                              const std::vector<const FrameSurface*>& keySurfaces,
                              std::vector<BodyPose> keyPoses, bool moveTranslations,
                              const BodyFitOptions& options, FitProgress& progress)
{
  const std::vector<BodyFitStage> refine = keyPoseStages(options);
  for (int round = 0; round < options.shapeRounds; ++round)
  {
    fitter.fitShape(keySurfaces, keyPoses, 4, moveTranslations);
    for (size_t k = 0; k < keySurfaces.size(); ++k)
    {
      fitter.fitPose(*keySurfaces[k], keyPoses[k], nullptr, refine, options.extremityGate);
      progress.advance(1.0);
    }
  }
  return fitter.samples().beta();
}

/// Beta on key frames spread over the sequence, alternating with their poses: with the poses
/// fixed, and with BodyFitOptions::twoShapes also with their translations moving.
std::vector<Eigen::VectorXd> fitShapes(const BodyModel& model, SequenceFitter& fitter,
                                       FrameSurfaces& surfaces, const std::vector<int>& usable,
                                       const BodyFitOptions& options,
                                       const std::vector<BodyFrameFit>& fits, FitProgress& progress)
{
  const std::vector<int> keys = shapeKeyFrames(usable, options, fits);
  std::vector<const FrameSurface*> keySurfaces;
  std::vector<BodyPose> keyPoses;
  for (int i : keys)
  {
    keySurfaces.push_back(&surfaces.get(i));
    keyPoses.push_back(fits[i].pose);
  }
  if (options.statureStart)
  {
    const std::vector<BodyFitStage> refine = keyPoseStages(options);
    const Eigen::VectorXd& beta = fitter.samples().beta();
    const double ratio = statureRatio(model, beta, keySurfaces, keyPoses);
    fitter.samples().setShape(scaledShape(model, beta.size(), ratio));
    for (size_t k = 0; k < keys.size(); ++k)
      fitter.fitPose(*keySurfaces[k], keyPoses[k], nullptr, refine, options.extremityGate);
  }
  const Eigen::VectorXd start = fitter.samples().beta();
  std::vector<Eigen::VectorXd> shapes{
      estimateShape(fitter, keySurfaces, keyPoses, false, options, progress)};
  if (options.twoShapes)
  {
    fitter.samples().setShape(start);
    shapes.push_back(estimateShape(fitter, keySurfaces, keyPoses, true, options, progress));
  }
  for (int i : keys) surfaces.release(i);
  return shapes;
}

/// Third and fourth starts for the final pass: `fit` with one leg raised (hip flexed, knee
/// folded), fitted with the temporal prior towards that start, each kept if it explains the frame
/// better both ways. A track from the predecessor falls behind a knee raised fast under wide
/// trousers, where the straight leg still lies inside the cloth.
void tryRaisedLegs(SequenceFitter& fitter, const FrameSurface& frame,
                   const std::vector<BodyFitStage>& stages, double raise, BodyFrameFit& fit)
{
  if (raise <= 0.0) return;
  for (const auto& [hip, knee] : {std::pair{LeftHip, LeftKnee}, std::pair{RightHip, RightKnee}})
  {
    BodyPose raised = fit.pose;
    raised.rotations(hip, 0) -= raise; // hip flexion is a negative rotation about X
    raised.rotations(knee, 0) += 1.5 * raise;
    fitter.refitFromNeighbour(frame, raised, stages, fit, /*coverAsMuch=*/false);
  }
}

/// The units planned for restarting the poor fits of the frames `own`: one restart at least, so
/// that the progress does not reach its end before the restarts run.
double poorFitRestartUnits(const std::vector<int>& own, const std::vector<BodyFrameFit>& fits)
{
  const auto poor = std::count_if(own.begin(), own.end(),
                                  [&](int i) { return fits[i].status == BodyFitStatus::Poor; });
  return kRestartUnits * static_cast<double>(std::max<decltype(poor)>(1, poor));
}

/// Whether usable frame k was fitted as an unrelated pose: it does not continue its predecessor,
/// or it is the first and its successor does not continue it (then it is as unrelated as the
/// frames of a collection).
bool unrelatedFrame(const std::vector<int>& usable, size_t k, const std::vector<BodyFrameFit>& fits)
{
  if (!fits[usable[k]].continuesPrevious) return true;
  return k == 0 && k + 1 < usable.size() && !fits[usable[k + 1]].continuesPrevious;
}

/// The usable frames fitted as unrelated poses (unrelatedFrame).
std::vector<int> unrelatedFrames(const std::vector<int>& usable,
                                 const std::vector<BodyFrameFit>& fits)
{
  std::vector<int> unrelated;
  for (size_t k = 0; k < usable.size(); ++k)
    if (unrelatedFrame(usable, k, fits)) unrelated.push_back(usable[k]);
  return unrelated;
}

/// Those of `frames` that are among `own`, in the order of `frames`.
std::vector<int> ownedFrames(const std::vector<int>& frames, const std::vector<int>& own)
{
  std::vector<int> owned;
  for (int i : frames)
    if (std::find(own.begin(), own.end(), i) != own.end()) owned.push_back(i);
  return owned;
}

/// The fits of unrelated frames (of `own`) that explain their frame worst, turned half round
/// (SequenceFitter::refitTurnedRound): those whose two-sided score exceeds
/// BodyFitOptions::turnRoundRatio times the median of the unrelated frames'. A body left facing
/// backwards explains its frame worse than the others explain theirs: on four random collections
/// the five such frames had the highest or second highest score of their collection, 1.4 to 2 times
/// its median.
void turnRoundWorstUnrelated(SequenceFitter& fitter, FrameSurfaces& surfaces,
                             const std::vector<int>& usable, const std::vector<int>& own,
                             const BodyFitOptions& options, std::vector<BodyFrameFit>& fits,
                             FitProgress& progress)
{
  const std::vector<int> unrelated = ownedFrames(unrelatedFrames(usable, fits), own);
  std::vector<double> scores;
  for (int i : unrelated)
  {
    scores.push_back(fitter.twoSidedScore(surfaces.get(i), fits[i].pose));
    surfaces.release(i);
  }
  if (unrelated.size() < 3) return;
  const double limit = options.turnRoundRatio * upperMedian(scores);
  const auto turned =
      std::count_if(scores.begin(), scores.end(), [&](double score) { return score > limit; });
  // The peers' restarts (restartFromPeers) follow, on the same frames.
  progress.replan(kRestartUnits * static_cast<double>(turned) +
                  kPeerRestartUnits * static_cast<double>(unrelated.size()) +
                  poorFitRestartUnits(own, fits));
  for (size_t u = 0; u < unrelated.size(); ++u)
  {
    if (!(scores[u] > limit)) continue;
    fitter.refitTurnedRound(surfaces.get(unrelated[u]), fits[unrelated[u]]);
    surfaces.release(unrelated[u]);
    progress.advance(kRestartUnits);
  }
}

/// Every unrelated frame of `own` started again from the joints of the other unrelated frames'
/// fits (SequenceFitter::refitFromPeerJoints), up to kMostPeers of them spread over the
/// sequence. Only where at least three frames are unrelated (a collection of poses); a sequence
/// whose frames continue each other has none.
void restartFromPeers(SequenceFitter& fitter, FrameSurfaces& surfaces,
                      const std::vector<int>& usable, const std::vector<int>& own,
                      std::vector<BodyFrameFit>& fits, FitProgress& progress)
{
  const std::vector<int> unrelated = unrelatedFrames(usable, fits);
  if (unrelated.size() < 3) return;
  const std::vector<int> mine = ownedFrames(unrelated, own);
  progress.replan(kPeerRestartUnits * static_cast<double>(mine.size()) +
                  poorFitRestartUnits(own, fits));
  // The peers as they were before any is restarted, so that the order does not matter.
  std::vector<BodyPose> poses;
  for (int i : unrelated) poses.push_back(fits[i].pose);
  for (int i : mine)
  {
    std::vector<BodyPose> peers;
    const size_t others = unrelated.size() - 1, count = std::min(others, kMostPeers);
    for (size_t m = 0; m < count; ++m)
    {
      size_t u = m * others / count;
      if (unrelated[u] >= i) ++u; // skip the frame itself
      peers.push_back(poses[u]);
    }
    fitter.refitFromPeerJoints(surfaces.get(i), peers, fits[i]);
    surfaces.release(i);
    progress.advance(kPeerRestartUnits);
  }
}

/// Pass 2: the final shape, each frame from its pass-1 pose, smooth in time where it continues
/// its predecessor. The poses are already close: the last stage suffices. Where the frame
/// continues its predecessor, that frame's final pose is a second start: a first-pass track that
/// drifted with the mean shape (its heading 10 degrees off for the rest of pjump) is
/// pulled back by the final shape's own track.
void finalPass(SequenceFitter& fitter, FrameSurfaces& surfaces, const std::vector<int>& usable,
               const BodyFitOptions& options, std::vector<BodyFrameFit>& fits,
               FitProgress& progress)
{
  const std::vector<BodyFitStage> finalStages(options.stages.end() - 1, options.stages.end());
  // Only here, under the final shape: arms let out in the first pass move the shape, and with
  // it the template frame (BENCHMARKS.md, "Tried, not kept: arms let out of the torso at a
  // higher score").
  ArmsRule armsLetOut;
  armsLetOut.letOut = true;
  const BodyPose* previous = nullptr;
  for (size_t k = 0; k < usable.size(); ++k)
  {
    const int i = usable[k];
    BodyFrameFit& fit = fits[i];
    const BodyPose init = fit.pose;
    fitter.fitFrame(surfaces.get(i), init, fit.continuesPrevious ? previous : nullptr, finalStages,
                    fit, fit.continuesPrevious, /*everyHeading=*/true);
    if (previous && fit.continuesPrevious)
      fitter.refitFromNeighbour(surfaces.get(i), *previous, finalStages, fit,
                                /*coverAsMuch=*/false);
    tryRaisedLegs(fitter, surfaces.get(i), finalStages, options.legRaiseStart, fit);
    if (options.limbRestarts && unrelatedFrame(usable, k, fits))
    {
      fitter.refitLimbs(surfaces.get(i), fit, armsLetOut);
      fitter.refitWithUpperBodyAtRest(surfaces.get(i), fit, armsLetOut);
    }
    if (fit.status == BodyFitStatus::Poor && fit.message.empty()) fit.message = "poor fit";
    previous = &fit.pose;
    surfaces.release(i);
    progress.advance(1.0);
  }
}

/// Pass 2 backwards: each frame that its successor continues is also started from the
/// successor's final pose, and the fit that explains the frame better is kept. A forward track
/// that fell behind a fast motion (a squat's deepest frames) is caught from the other side.
void backwardPass(SequenceFitter& fitter, FrameSurfaces& surfaces, const std::vector<int>& usable,
                  const BodyFitOptions& options, std::vector<BodyFrameFit>& fits,
                  FitProgress& progress)
{
  const std::vector<BodyFitStage> finalStages(options.stages.end() - 1, options.stages.end());
  for (size_t k = usable.size(); k-- > 0;)
  {
    const int i = usable[k];
    if (k + 1 < usable.size() && fits[usable[k + 1]].continuesPrevious)
      fitter.refitFromNeighbour(surfaces.get(i), fits[usable[k + 1]].pose, finalStages, fits[i],
                                /*coverAsMuch=*/true);
    surfaces.release(i);
    progress.advance(1.0);
  }
}

/// The frame distance above which an ok fit is poor: the sequence's median raised by
/// BodyFitOptions::unexplainedRatio and unexplainedMargin; infinite with fewer than 3 ok fits.
double unexplainedLimit(const BodyFitOptions& options, const std::vector<BodyFrameFit>& fits)
{
  const std::optional<double> median = medianFrameDistance(fits, 3);
  if (!median) return std::numeric_limits<double>::infinity();
  return std::max(options.unexplainedRatio * *median, *median + options.unexplainedMargin);
}

/// An ok fit whose frame distance exceeds `limit` becomes poor: its body leaves a limb of the
/// frame unexplained.
void flagIfUnexplained(double limit, BodyFrameFit& fit)
{
  if (fit.status != BodyFitStatus::Ok || !(fit.frameDistance > limit)) return;
  fit.status = BodyFitStatus::Poor;
  char message[160];
  std::snprintf(message, sizeof message,
                "the body leaves part of the frame unexplained (frame to body %.1f cm, limit "
                "%.1f cm)",
                100.0 * fit.frameDistance, 100.0 * limit);
  fit.message = message;
}

/// Poor fits started again from the poses of the sequence's ok fits (at most 24, spread over
/// it): a fit that went wrong where its neighbours did not, or a pose that a collection repeats.
/// Those still poor are started again with their legs across the frame's two lowest detections
/// (a fit with both legs in one of the frame's). Of the frames `own` only.
void recoverPoorFits(SequenceFitter& fitter, FrameSurfaces& surfaces,
                     const std::vector<int>& usable, const std::vector<int>& own, double limit,
                     std::vector<BodyFrameFit>& fits, FitProgress& progress)
{
  const std::vector<BodyPose> poses = okPoses(usable, -1, fits);
  progress.replan(poorFitRestartUnits(own, fits));
  for (int i : own)
  {
    if (fits[i].status != BodyFitStatus::Poor) continue;
    fitter.refitFromPoses(surfaces.get(i), poses, fits[i]);
    flagIfUnexplained(limit, fits[i]);
    if (fits[i].status == BodyFitStatus::Poor)
    {
      fitter.refitWithLegsAcross(surfaces.get(i), fits[i]);
      flagIfUnexplained(limit, fits[i]);
    }
    surfaces.release(i);
    progress.advance(kRestartUnits);
  }
}

/// A process's share of the usable frames (BodyFitSharing): the frames it owns, and those its
/// forward and backward passes track through to reach them.
struct Segment
{
  std::vector<int> own;
  std::vector<int> forward;  ///< `overlap` frames before its own, then its own
  std::vector<int> backward; ///< its own, then `overlap` frames after them
};

Segment segmentOf(const std::vector<int>& usable, const BodyFitSharing& sharing)
{
  const int m = static_cast<int>(usable.size());
  if (!sharing.splits(m)) return {usable, usable, usable};
  const auto [begin, end] = rangePart(m, sharing.part, sharing.parts);
  const int overlap = std::max(1, sharing.overlap);
  auto frames = [&](int from, int to) {
    return std::vector<int>(usable.begin() + std::max(0, from), usable.begin() + std::min(m, to));
  };
  return {frames(begin, end), frames(begin - overlap, end), frames(begin, end + overlap)};
}

/// Every process's fits of its own frames, brought to every process.
void shareFits(const BodyFitSharing& sharing, const std::vector<int>& own,
               std::vector<BodyFrameFit>& fits)
{
  for (const std::string& bytes : sharing.allGather(encodeFrameFits(fits, own)))
    decodeFrameFits(bytes, fits);
}

/// The first process's shapes, on every process: each estimated them from the same fits, and
/// the poses of all must be fitted under the same shapes whatever the arithmetic of their
/// machines.
void shareShapes(const BodyFitSharing& sharing, std::vector<Eigen::VectorXd>& shapes)
{
  ByteWriter own;
  if (sharing.part == 0)
    for (const Eigen::VectorXd& beta : shapes)
      for (double b : beta) own.put(b);
  const std::string first = sharing.allGather(own.take()).at(0);
  ByteReader read(first, "shared body shapes");
  for (Eigen::VectorXd& beta : shapes)
    for (double& b : beta) b = read.get<double>();
  read.expectEnd();
}

/// The largest distance between the rest-pose vertices of shapes `a` and `b`.
double restShapeGap(const BodyModel& model, const Eigen::VectorXd& a, const Eigen::VectorXd& b)
{
  Points first, second, joints;
  model.shape(a, first, joints);
  model.shape(b, second, joints);
  return (first - second).rowwise().norm().maxCoeff();
}

/// Drops the second of two `shapes` when they are one body (BodyFitOptions::sameShapeTolerance),
/// keeping it as the result's other shape; returns whether it was dropped. Every process of a
/// shared fit holds the same shapes, so all drop it or none.
bool dropSameShape(const BodyModel& model, const BodyFitOptions& options,
                   std::vector<Eigen::VectorXd>& shapes, BodyFitResult& result)
{
  if (shapes.size() < 2) return false;
  result.shapeGap = restShapeGap(model, shapes[0], shapes[1]);
  if (!(result.shapeGap < options.sameShapeTolerance)) return false;
  result.otherBeta = shapes[1];
  shapes.resize(1);
  return true;
}

/// The median frame distance of the frames that could be fitted.
double typicalFrameDistance(const std::vector<BodyFrameFit>& fits)
{
  std::vector<double> distances;
  for (const BodyFrameFit& f : fits)
    if (f.status != BodyFitStatus::Failed) distances.push_back(f.frameDistance);
  return distances.empty() ? 0.0 : upperMedian(std::move(distances));
}

/// Pass 2 forwards and backwards under each of `shapes`; the sequence keeps the shape under
/// which its median frame distance is lower (BodyFitOptions::twoShapes), and the fitter is left
/// with it. Each frame choosing its own shape explains it better still, but the later stages
/// then meet bodies of two statures: on pjump the alignment lost 0.1 cm that way, in the very
/// frames that changed shape (BENCHMARKS.md).
void finalPasses(SequenceFitter& fitter, FrameSurfaces& surfaces, const Segment& segment,
                 const BodyFitOptions& options, const std::vector<Eigen::VectorXd>& shapes,
                 const std::function<void(std::vector<BodyFrameFit>&)>& share,
                 BodyFitResult& result, FitProgress& progress)
{
  const std::vector<BodyFrameFit> firstPass = result.frames;
  double best = std::numeric_limits<double>::infinity();
  size_t kept = 0;
  for (size_t s = 0; s < shapes.size(); ++s)
  {
    std::vector<BodyFrameFit> fits = firstPass;
    fitter.samples().setShape(shapes[s]);
    finalPass(fitter, surfaces, segment.forward, options, fits, progress);
    share(fits);
    backwardPass(fitter, surfaces, segment.backward, options, fits, progress);
    share(fits);
    const double distance = typicalFrameDistance(fits);
    if (!(distance < best)) continue;
    best = distance;
    kept = s;
    result.frames = std::move(fits);
  }
  result.beta = shapes[kept];
  result.movedShape = kept > 0;
  if (shapes.size() > 1) result.otherBeta = shapes[1 - kept];
  fitter.samples().setShape(result.beta);
}
} // namespace

BodyFitResult fitBodySequence(const BodyModel& model,
                              const std::vector<const TriangleMesh*>& frames,
                              const BodyFitOptions& options, const StageProgress& progress)
{
  return fitBodySequence(model, FramesInMemory(frames), options, progress);
}

BodyFitResult fitBodySequence(const BodyModel& model, const FrameSource& frames,
                              const BodyFitOptions& options, const StageProgress& progress)
{
  if (model.numVertices() == 0) throw Error("body fit: the body model is empty");
  if (options.stages.empty()) throw Error("body fit: no stage in the weight schedule");
  const int n = frames.count();
  BodyFitResult result;
  result.frames.resize(n);
  const std::vector<int> usable = usableFrames(frames, result.frames);
  // Shared among processes, each tracks its own segment; the fits are exchanged after each pass.
  const BodyFitSharing& sharing = options.sharing;
  const bool shared = sharing.splits(static_cast<int>(usable.size()));
  if (shared && !sharing.allGather) throw Error("body fit: shared, but with no exchange");
  const Segment segment = segmentOf(usable, sharing);
  auto share = [&](std::vector<BodyFrameFit>& fits)
  {
    if (shared) shareFits(sharing, segment.own, fits);
  };
  const int shapes = options.twoShapes ? 2 : 1;
  const double laterPasses = shapes * (segment.forward.size() + segment.backward.size() +
                                       options.shapeRounds * std::max(1, options.shapeFrames));
  FitProgress fitProgress(progress, segment.forward.size() + laterPasses);
  FrameSurfaces surfaces(frames, options.extremityPersistence);
  SequenceFitter fitter(model, options);

  fitter.setReachTolerance(options.shapeReachTolerance);
  firstPass(fitter, surfaces, segment.forward, options, result.frames, fitProgress);
  share(result.frames);
  // The first pass's poor fits foretell the end steps' restarts.
  fitProgress.replan(laterPasses + poorFitRestartUnits(segment.own, result.frames));
  std::vector<Eigen::VectorXd> betas =
      fitShapes(model, fitter, surfaces, usable, options, result.frames, fitProgress);
  if (shared) shareShapes(sharing, betas);
  fitter.setReachTolerance(options.reachTolerance);
  if (dropSameShape(model, options, betas, result))
    fitProgress.advance(segment.forward.size() + segment.backward.size());
  finalPasses(fitter, surfaces, segment, options, betas, share, result, fitProgress);
  if (options.limbRestarts)
  {
    turnRoundWorstUnrelated(fitter, surfaces, usable, segment.own, options, result.frames,
                            fitProgress);
    share(result.frames);
    restartFromPeers(fitter, surfaces, usable, segment.own, result.frames, fitProgress);
    share(result.frames);
  }
  const double limit = unexplainedLimit(options, result.frames);
  for (BodyFrameFit& fit : result.frames) flagIfUnexplained(limit, fit);
  recoverPoorFits(fitter, surfaces, usable, segment.own, limit, result.frames, fitProgress);
  share(result.frames);
  fitProgress.finish();

  // Frames that could not be fitted take their nearest fitted neighbour's pose.
  for (int i = 0; i < n; ++i)
  {
    if (result.frames[i].status != BodyFitStatus::Failed) continue;
    int nearest = usable.front();
    for (int j : usable)
      if (std::abs(j - i) < std::abs(nearest - i)) nearest = j;
    result.frames[i].pose = result.frames[nearest].pose;
  }
  return result;
}
} // namespace clothtrack
