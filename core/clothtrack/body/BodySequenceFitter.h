#pragma once
// The body fit's minimisation (Levenberg-Marquardt on poses and shape) over a sequence. Internal to
// the body fit (BodyFit.cpp).
#include "BodyFitTerms.h"
#include "TurnedPose.h"

#include <clothtrack/base/Error.h>
#include <clothtrack/mesh/PointIndex.h>

#include <Eigen/Cholesky>

#include <algorithm>
#include <optional>
#include <string>
#include <vector>

namespace clothtrack::bodyfit
{
/// How a limb restart's arms inside the torso are judged against the fit it would replace
/// (SequenceFitter::explainsBetter; the constants are SequenceFitter's).
struct ArmsRule
{
  /// A share of the arm samples inside the torso that no restart may exceed by more than
  /// kArmsCrossedShare, whatever the current fit's (refitTurnedRound: the backward fit's).
  double reference = std::numeric_limits<double>::infinity();
  /// A restart that takes the arms out of the chest (the current fit has at least
  /// kArmsThroughChest of the arm samples inside the torso, the restart kArmsOutShare fewer) is
  /// kept up to kArmsOutScoreRatio times the current score: on an unclothed frame, arms swung
  /// through the chest can explain forearms folded in front of it more closely than a fit of
  /// the folded forearms does (used in the final pass, BodyFit.cpp).
  bool letOut = false;
};

class SequenceFitter
{
public:
  SequenceFitter(const BodyModel& model, const BodyFitOptions& options)
      : options_(options), samples_(model, options.samples), restJoints_(model.joints),
        priorWeights_(jointPriorWeights(options)), reachTolerance_(options.reachTolerance)
  {
    for (int i = 0; i < samples_.numSamples(); ++i)
    {
      const int j = samples_.dominantJointOf(i);
      if (j == Pelvis || j == Spine1 || j == Spine2 || j == Spine3) torsoSamples_.push_back(i);
      if (j == LeftShoulder || j == LeftElbow || j == RightShoulder || j == RightElbow)
        armSamples_.push_back(i);
    }
  }

  BodySamples& samples() { return samples_; }

  /// Multiple of a limb's length within which a detected extremity may hang from its root.
  void setReachTolerance(double tolerance) { reachTolerance_ = tolerance; }

  /// Weight of the temporal prior on rotation parameter k: the root's and the legs' are lighter.
  double temporalWeight(int k) const
  {
    if (k < 3) return options_.rootTemporalWeight;
    const int joint = k / 3;
    const bool leg =
        joint == LeftHip || joint == RightHip || joint == LeftKnee || joint == RightKnee;
    return leg ? options_.legTemporalWeight : options_.temporalWeight;
  }

  /// Weight of the one-sided penalty on a knee bending backwards.
  double limitWeight() const { return 10.0 * options_.hingeStiffness * options_.posePriorWeight; }

  /// Residuals of `pose` (whose sample points and normals are p and normals).
  Assignments assign(const FrameSurface& frame, const BodyPose& pose, const Points& p,
                     const Points& normals, const BodyFitStage& stage, double gate) const
  {
    Assignments a;
    const int ns = samples_.numSamples();
    const double c2 = options_.robustScale * options_.robustScale;
    std::vector<Vec3> targets(ns), targetNormals(ns);
    std::vector<char> found(ns);
    frame.hints.resize(std::max<size_t>(frame.hints.size(), ns), -1);
    parallelFor(0, ns,
                [&](int i)
                {
                  found[i] = frame.closest(i, p.row(i).transpose(), stage.searchRadius, targets[i],
                                           targetNormals[i]);
                });
    for (int i = 0; i < ns; ++i)
    {
      if (!found[i]) continue;
      const Vec3& target = targets[i];
      const Vec3& normal = targetNormals[i];
      const Vec3 diff = p.row(i).transpose() - target;
      const double d2 = diff.squaredNorm();
      if (stage.nearestWeight > 0.0 && normals.row(i).dot(normal) > 0.0)
        a.planes.push_back({i, target, normal, stage.nearestWeight / ns * c2 / (c2 + d2), false});
      if (stage.insideWeight > 0.0 && normal.dot(diff) > 0.0)
        a.planes.push_back({i, target, normal, stage.insideWeight / ns, true});
    }
    if (stage.coverWeight > 0.0) cover(frame, p, normals, stage.coverWeight, a);
    if (stage.landmarkWeight > 0.0 && !frame.extremities.empty())
    {
      std::array<int, 5> match;
      matchExtremities(p, samples_, samples_.extremityRoots(pose), frame.extremities, gate,
                       options_.handGate, reachTolerance_, match);
      for (int label = 0; label < kNumExtremities; ++label)
        if (match[label] >= 0) ++a.matchedExtremities;
      for (int label = 0; label < kNumExtremities; ++label)
      {
        if (match[label] < 0) continue;
        const Vec3& target = frame.extremities[match[label]];
        int nearest = samples_.extremityPoint(label);
        for (int i : samples_.extremityRegion(label))
          if ((p.row(i).transpose() - target).squaredNorm() <
              (p.row(nearest).transpose() - target).squaredNorm())
            nearest = i;
        a.points.push_back({nearest, target, stage.landmarkWeight / a.matchedExtremities});
      }
    }
    return a;
  }

  /// Rows of E_c (BodyFitStage::coverWeight): each spread frame vertex pulls its nearest body
  /// sample, when their normals agree, towards the vertex's tangent plane, with Cauchy weights.
  /// What the body-to-frame rows leave out, the frame's far side, pulls here.
  void cover(const FrameSurface& frame, const Points& p, const Points& normals, double weight,
             Assignments& a) const
  {
    const int ns = samples_.numSamples();
    const PointIndex body(p.topRows(ns));
    const int m = static_cast<int>(frame.spread.size());
    std::vector<Neighbour> nearest(m);
    parallelFor(0, m,
                [&](int k) { nearest[k] = body.nearest(frame.mesh->vertex(frame.spread[k])); });
    const double c2 = options_.coverScale * options_.coverScale;
    for (int k = 0; k < m; ++k)
    {
      const int i = nearest[k].index;
      const Vec3 normal = frame.normals.row(frame.spread[k]).transpose();
      if (i < 0 || normals.row(i).dot(normal) <= 0.0 || normal.squaredNorm() < 0.5) continue;
      const double d2 = nearest[k].distance * nearest[k].distance;
      a.planes.push_back({i, frame.mesh->vertex(frame.spread[k]), normal.normalized(),
                          weight / m * c2 / (c2 + d2), false});
    }
  }

  double regulariser(const Eigen::VectorXd& x, const Eigen::VectorXd* previous) const
  {
    double e = 0.0;
    for (int k = 3; k < NumJoints * 3; ++k) e += priorWeights_[k] * x[k] * x[k];
    for (int k : kHingeBends) e += limitWeight() * std::pow(std::min(0.0, x[k]), 2);
    if (previous)
      for (int k = 0; k < NumJoints * 3; ++k)
        e += temporalWeight(k) * std::pow(x[k] - (*previous)[k], 2);
    return e;
  }

  /// Damped Gauss-Newton on the pose with assignments refreshed every iteration.
  /// `rigid` moves the body as a whole only (root rotation and translation). `byTurns` moves the
  /// root by turns away from its current rotation (RootTurns), for tracking: a body that turns
  /// on from its neighbour's pose. Fits from fixed headings keep the axis-angle parameters, whose
  /// starts spread evenly over a full turn.
  double fitPose(const FrameSurface& frame, BodyPose& pose, const BodyPose* previous,
                 const std::vector<BodyFitStage>& stages, double gate, int* matched = nullptr,
                 bool rigid = false, bool byTurns = false)
  {
    auto active = [rigid](int c) { return !rigid || c < 3 || c >= NumJoints * 3; };
    Eigen::VectorXd x = toVector(pose);
    Eigen::VectorXd prev = previous ? toVector(*previous) : Eigen::VectorXd();
    const Eigen::VectorXd* prevPtr = previous ? &prev : nullptr;
    std::optional<RootTurns> turns;
    // With turns, x's root entries are the turn from the reference, and prev's the turn to the
    // previous root: the temporal prior then weighs the turn between the two frames.
    auto recentre = [&](const Vec3& root)
    {
      turns = RootTurns{axisAngleToMatrix(root)};
      x.head<3>().setZero();
      if (previous) prev.head<3>() = turns->turnTo(previous->rotations.row(Pelvis).transpose());
    };
    if (byTurns) recentre(x.head<3>());
    auto poseOf = [&turns](const Eigen::VectorXd& v)
    {
      BodyPose p = toPose(v);
      if (turns) p.rotations.row(Pelvis) = turns->rootAfter(v.head<3>()).transpose();
      return p;
    };
    double energy = 0.0;
    double lambda = 1e-3;
    std::vector<Points> columns(kPoseParameters);
    for (const BodyFitStage& stage : stages)
      for (int it = 0; it < stage.iterations; ++it)
      {
        Points normals;
        const BodyPose current = poseOf(x);
        const Points p = samples_.pose(current, &normals);
        const Assignments a = assign(frame, current, p, normals, stage, gate);
        if (matched) *matched = a.matchedExtremities;
        parallelFor(
            0, kPoseParameters,
            [&](int c)
            {
              if (!active(c))
              {
                columns[c] = Points::Zero(p.rows(), 3);
                return;
              }
              Eigen::VectorXd xs = x;
              xs[c] += kStep;
              columns[c] = (samples_.pose(poseOf(xs)) - p) / kStep;
            },
            8);
        Eigen::MatrixXd h = Eigen::MatrixXd::Zero(kPoseParameters, kPoseParameters);
        Eigen::VectorXd g = Eigen::VectorXd::Zero(kPoseParameters);
        a.accumulate(p, columns, h, g);
        for (int k = 0; k < NumJoints * 3; ++k)
        {
          if (k >= 3)
          {
            h(k, k) += priorWeights_[k];
            g[k] += priorWeights_[k] * x[k];
          }
          if (std::find(kHingeBends.begin(), kHingeBends.end(), k) != kHingeBends.end() &&
              x[k] < 0.0)
          {
            h(k, k) += limitWeight();
            g[k] += limitWeight() * x[k];
          }
          if (prevPtr)
          {
            h(k, k) += temporalWeight(k);
            g[k] += temporalWeight(k) * (x[k] - prev[k]);
          }
        }
        for (int k = 0; k < kPoseParameters; ++k)
          if (!active(k))
          {
            h.row(k).setZero();
            h.col(k).setZero();
            h(k, k) = 1.0;
            g[k] = 0.0;
          }
        energy = a.energy(p) + regulariser(x, prevPtr);
        for (int attempt = 0; attempt < 8; ++attempt)
        {
          Eigen::MatrixXd damped = h;
          damped.diagonal().array() += lambda * (h.diagonal().array() + 1e-9);
          const Eigen::VectorXd step = damped.ldlt().solve(-g);
          const Eigen::VectorXd candidate = x + step;
          const double e =
              a.energy(samples_.pose(poseOf(candidate))) + regulariser(candidate, prevPtr);
          if (std::isfinite(e) && e <= energy)
          {
            x = candidate;
            energy = e;
            if (turns) recentre(poseOf(x).rotations.row(Pelvis).transpose());
            lambda = std::max(1e-6, lambda / 3.0);
            break;
          }
          lambda *= 10.0;
        }
      }
    pose = poseOf(x);
    return energy;
  }

  /// How well a pose explains a frame, to compare fits from different starts: the mean
  /// squared distance of the body samples to the frame, each capped at the last stage's search
  /// radius (a sample with nothing near costs the cap, so a body off the frame cannot look
  /// good), plus the inside and extremity terms with the last stage's weights.
  double score(const FrameSurface& frame, const BodyPose& pose) const
  {
    Points normals;
    const Points p = samples_.pose(pose, &normals);
    BodyFitStage last = options_.stages.back();
    last.landmarkWeight = std::max(last.landmarkWeight, 0.05);
    const double cap = last.searchRadius * last.searchRadius;
    const int ns = samples_.numSamples();
    std::vector<double> cost(ns, cap);
    frame.hints.resize(std::max<size_t>(frame.hints.size(), ns), -1);
    parallelFor(0, ns,
                [&](int i)
                {
                  Vec3 target, normal;
                  if (!frame.closest(i, p.row(i).transpose(), last.searchRadius, target, normal))
                    return;
                  const Vec3 diff = p.row(i).transpose() - target;
                  const double outside = std::max(0.0, normal.dot(diff));
                  cost[i] =
                      std::min(diff.squaredNorm(), cap) + last.insideWeight * outside * outside;
                });
    double total = 0.0;
    for (double c : cost) total += c;
    last.nearestWeight = last.insideWeight = last.coverWeight = 0.0; // only the extremity rows
    const Assignments extremities = assign(frame, pose, p, normals, last, options_.extremityGate);
    return total / ns + extremities.energy(p);
  }

  /// Distance from each of at most 1000 evenly spread frame vertices to the nearest body sample
  /// of `pose`: what of the frame the body leaves unexplained. Clothing keeps it at a few
  /// centimetres on a good fit; a limb fitted in the wrong place leaves tens there (its arm
  /// down inside the torso while the frame's is raised, which the body-to-frame terms of score()
  /// do not see).
  std::vector<double> frameToBody(const FrameSurface& frame, const BodyPose& pose) const
  {
    const PointIndex body(samples_.pose(pose).topRows(samples_.numSamples()));
    const int count = static_cast<int>(frame.spread.size());
    std::vector<double> distances(count);
    parallelFor(0, count,
                [&](int i)
                { distances[i] = body.nearest(frame.mesh->vertex(frame.spread[i])).distance; });
    return distances;
  }

  /// score() plus the frame-to-body side (squared distances capped as score() caps its own):
  /// to choose between fits of a frame that no neighbour vouches for.
  double twoSidedScore(const FrameSurface& frame, const BodyPose& pose) const
  {
    const double cap = options_.stages.back().searchRadius;
    double uncovered = 0.0;
    const std::vector<double> distances = frameToBody(frame, pose);
    for (double d : distances) uncovered += std::min(d * d, cap * cap);
    return score(frame, pose) + uncovered / std::max<size_t>(1, distances.size());
  }

  /// A short schedule that brings a start near the frame, to rank starts before the full one.
  static std::vector<BodyFitStage> quickStages()
  {
    return {{1.0, 0.1, 0.0, 4, 0.4}, {0.3, 1.0, 1.0, 4, 0.15}};
  }

  /// A pose briefly fitted, with its two-sided score.
  struct RankedPose
  {
    double score;
    BodyPose pose;
  };

  /// `starts` each briefly fitted (quickStages), those that explain the frame best
  /// (twoSidedScore) first.
  std::vector<RankedPose> rankedQuickFits(const FrameSurface& frame,
                                          const std::vector<BodyPose>& starts)
  {
    const std::vector<BodyFitStage> quick = quickStages();
    std::vector<RankedPose> ranked;
    for (BodyPose pose : starts)
    {
      fitPose(frame, pose, nullptr, quick, 2.0 * options_.extremityGate);
      ranked.push_back({twoSidedScore(frame, pose), pose});
    }
    std::stable_sort(ranked.begin(), ranked.end(),
                     [](const RankedPose& a, const RankedPose& b) { return a.score < b.score; });
    return ranked;
  }

  /// The largest distance between the same body sample in two poses (metres).
  double bodyApart(const BodyPose& a, const BodyPose& b) const
  {
    const int n = samples_.numSamples();
    return (samples_.pose(a).topRows(n) - samples_.pose(b).topRows(n)).rowwise().norm().maxCoeff();
  }

  /// Sets fit.rivalScoreRatio from `ranked` (rankedQuickFits): the first kRivalFits of them whose
  /// body lies more than kRivalDistance from the fit's somewhere are fitted fully, and the lowest
  /// score of those still that far from it, relative to the fit's, is the ratio. A rival is not
  /// adopted: the fit already kept the best start by the same score.
  void measureRivals(const FrameSurface& frame, const std::vector<RankedPose>& ranked,
                     BodyFrameFit& fit)
  {
    const double current = twoSidedScore(frame, fit.pose);
    double best = std::numeric_limits<double>::infinity();
    int tried = 0;
    for (const RankedPose& start : ranked)
    {
      if (tried == kRivalFits) break;
      if (!(bodyApart(start.pose, fit.pose) > kRivalDistance)) continue;
      ++tried;
      BodyPose rival = start.pose;
      fitPose(frame, rival, nullptr, options_.stages, options_.extremityGate);
      if (bodyApart(rival, fit.pose) > kRivalDistance)
        best = std::min(best, twoSidedScore(frame, rival));
    }
    if (current > 0) fit.rivalScoreRatio = std::min(fit.rivalScoreRatio, best / current);
  }

  /// A fit from one start, with its score.
  struct RankedFit
  {
    double score;
    BodyFrameFit fit;
  };

  /// `pose` with the whole body moved by `motion`: the root turned and the body shifted so that
  /// its samples land where `motion` carries them.
  BodyPose movedRigidly(const BodyPose& pose, const Eigen::Isometry3d& motion) const
  {
    const int n = samples_.numSamples();
    const Vec3 target = motion * Vec3(samples_.pose(pose).topRows(n).colwise().mean().transpose());
    BodyPose moved = pose;
    const Eigen::Matrix3d root = axisAngleToMatrix(pose.rotations.row(Pelvis).transpose());
    moved.rotations.row(Pelvis) = matrixToAxisAngle(motion.linear() * root).transpose();
    moved.translation += target - samples_.pose(moved).topRows(n).colwise().mean().transpose();
    return moved;
  }

  /// Tries every heading about the up axis, the body centred on the frame and moved rigidly;
  /// then fits fully from the best heading and from those a quarter, half and three quarters
  /// of a turn away (front and back are hard to tell apart under wide clothing: the limbs must
  /// settle before the feet and arms reveal the facing). Returns those fits, best score first.
  std::vector<RankedFit> initialFits(const FrameSurface& frame)
  {
    const int headings = std::max(1, options_.headings);
    const std::vector<BodyFitStage> quick = quickStages();
    std::vector<std::pair<double, BodyPose>> tried;
    for (int h = 0; h < headings; ++h)
    {
      BodyPose pose;
      pose.rotations.row(Pelvis) =
          (options_.up.normalized() * (2.0 * M_PI * h / headings)).transpose();
      const Points p = samples_.pose(pose);
      const Vec3 centre = p.topRows(samples_.numSamples()).colwise().mean().transpose();
      pose.translation = frame.centroid - centre;
      fitPose(frame, pose, nullptr, quick, 2.0 * options_.extremityGate, nullptr, true);
      tried.push_back({score(frame, pose), pose});
    }
    int best = 0;
    for (int h = 1; h < headings; ++h)
      if (tried[h].first < tried[best].first) best = h;
    // The best heading and the ones a quarter, half and three quarters of a turn from it.
    std::vector<int> candidates;
    for (int quarter = 0; quarter < 4; ++quarter)
    {
      const int h = (best + (quarter * headings + 2) / 4) % headings;
      if (std::find(candidates.begin(), candidates.end(), h) == candidates.end())
        candidates.push_back(h);
    }
    std::vector<RankedFit> fits;
    for (int h : candidates)
    {
      BodyFrameFit fit;
      fit.pose = tried[h].second;
      fit.energy = fitPose(frame, fit.pose, nullptr, options_.stages, options_.extremityGate,
                           &fit.extremitiesMatched);
      measure(frame, fit);
      fits.push_back({score(frame, fit.pose), fit});
    }
    std::sort(fits.begin(), fits.end(),
              [](const RankedFit& a, const RankedFit& b) { return a.score < b.score; });
    return fits;
  }

  /// The best-scoring initial fit, unless a fit facing the other way scores nearly as well and
  /// is more plausible. A body turned round can fit a loose garment about as closely, but only
  /// with its joints bent against their range: the mean body, 20 cm too tall for a 1.52 m man
  /// in wide trousers, fitted his first frame slightly closer facing backwards. The prior only
  /// breaks such ties: on its own it prefers a wrong pose nearer the rest pose to a true one
  /// that matches more extremities.
  BodyFrameFit initialFit(const FrameSurface& frame)
  {
    return mostPlausible(initialFits(frame)).fit;
  }

  /// initialFit's choice among initialFits' results.
  const RankedFit& mostPlausible(const std::vector<RankedFit>& fits) const
  {
    auto plausibility = [this](const RankedFit& r)
    { return r.score + regulariser(toVector(r.fit.pose), nullptr); };
    for (size_t k = 1; k < fits.size(); ++k)
      if (headingChange(fits[k].fit.pose, fits[0].fit.pose, options_.up) > 0.5 * M_PI)
        return fits[k].score <= options_.headingAmbiguity * fits[0].score &&
                       plausibility(fits[k]) < plausibility(fits[0])
                   ? fits[k]
                   : fits[0];
    return fits[0];
  }

  /// Statistics of a fitted pose: median distance and fraction of samples inside.
  void measure(const FrameSurface& frame, BodyFrameFit& fit) const
  {
    const Points p = samples_.pose(fit.pose);
    std::vector<double> distances;
    int inside = 0;
    frame.hints.resize(std::max<size_t>(frame.hints.size(), samples_.numSamples()), -1);
    for (int i = 0; i < samples_.numSamples(); ++i)
    {
      Vec3 target, normal;
      if (!frame.closest(i, p.row(i).transpose(), 10.0, target, normal))
      {
        distances.push_back(10.0);
        continue;
      }
      const Vec3 diff = p.row(i).transpose() - target;
      distances.push_back(diff.norm());
      inside += normal.dot(diff) <= options_.insideTolerance;
    }
    std::nth_element(distances.begin(), distances.begin() + distances.size() / 2, distances.end());
    fit.medianDistance = distances[distances.size() / 2];
    const std::vector<double> uncovered = frameToBody(frame, fit.pose);
    fit.frameDistance = 0.0;
    for (double d : uncovered) fit.frameDistance += d / std::max<size_t>(1, uncovered.size());
    fit.insideFraction = static_cast<double>(inside) / samples_.numSamples();
    const bool poor = fit.medianDistance > options_.poorDistance ||
                      fit.insideFraction < options_.poorInside || !std::isfinite(fit.energy);
    fit.status = poor ? BodyFitStatus::Poor : BodyFitStatus::Ok;
    fit.message = poor ? "body far from or outside the frame (median distance " +
                             std::to_string(fit.medianDistance) + " m, inside " +
                             std::to_string(fit.insideFraction) + ")"
                       : std::string();
  }

  /// One frame: from `init`, full schedule, the root moved by turns; a poor result is retried
  /// from every heading, and a retry is kept only when it explains the frame better by
  /// twoSidedScore. A frame that does not continue the one `init` comes from (`continuous`
  /// false: see BodyFitOptions::neighbourGap) may then face any way; with `everyHeading` it is
  /// retried from every heading even when its fit is ok. A body started from an unrelated
  /// pose can settle facing backwards, its limbs bent against their range into the frame's,
  /// and still lie close enough to the frame to pass for ok (5 of a random collection's 20
  /// frames).
  void fitFrame(const FrameSurface& frame, const BodyPose& init, const BodyPose* previous,
                const std::vector<BodyFitStage>& stages, BodyFrameFit& fit, bool continuous = true,
                bool everyHeading = false)
  {
    fit.pose = init;
    fit.energy = fitPose(frame, fit.pose, previous, stages, options_.extremityGate,
                         &fit.extremitiesMatched, /*rigid=*/false, /*byTurns=*/true);
    measure(frame, fit);
    if (fit.status == BodyFitStatus::Ok && (continuous || !everyHeading)) return;
    const auto retries = initialFits(frame);
    const RankedFit* retry = nullptr;
    if (!continuous)
      retry = &mostPlausible(retries);
    else
    {
      // A fresh start must face roughly the same way, leave no more of the frame unexplained
      // and be clearly better: a body turned the other way round can fit a wide garment almost
      // as well, a person cannot turn round between two frames, and a body with its arms down
      // inside a wide top sits inside the frame better than one reaching for the hands.
      for (const RankedFit& r : retries)
        if (r.fit.status == BodyFitStatus::Ok &&
            headingChange(r.fit.pose, init, options_.up) < 0.5 * M_PI &&
            r.fit.frameDistance <= fit.frameDistance)
        {
          retry = &r;
          break;
        }
    }
    const bool explainsMore =
        retry && twoSidedScore(frame, retry->fit.pose) < twoSidedScore(frame, fit.pose);
    const bool replace =
        explainsMore && (!continuous || retry->score < 0.5 * score(frame, fit.pose));
    if (replace) adopt(frame, retry->fit, fit);
  }

  /// `fit` takes the pose of `other`, a fit of the same frame from another start.
  void adopt(const FrameSurface& frame, const BodyFrameFit& other, BodyFrameFit& fit) const
  {
    fit.pose = other.pose;
    fit.energy = other.energy;
    fit.extremitiesMatched = other.extremitiesMatched;
    measure(frame, fit);
  }

  /// A second start for the final pass: a neighbouring frame's final pose (the predecessor going
  /// forward, the successor going back), with the temporal prior towards it; kept if it explains
  /// the frame better by twoSidedScore than `fit` and, with `coverAsMuch`, leaves no more of it
  /// unexplained. Going back, a limb drawn in towards the torso lowered the score while the
  /// frame's own limb went uncovered (pjump's frames 205-214: frame distance 8.3 to 9.2 cm, the
  /// alignment 7 to 15 cm). The same guard going forward changes which track the later frames
  /// follow: on pjump, for the worse (4.99 to 6.17 cm).
  void refitFromNeighbour(const FrameSurface& frame, const BodyPose& neighbour,
                          const std::vector<BodyFitStage>& stages, BodyFrameFit& fit,
                          bool coverAsMuch)
  {
    BodyFrameFit other;
    other.pose = neighbour;
    other.energy = fitPose(frame, other.pose, &neighbour, stages, options_.extremityGate,
                           &other.extremitiesMatched, /*rigid=*/false, /*byTurns=*/true);
    measure(frame, other);
    if ((!coverAsMuch || other.frameDistance <= fit.frameDistance) &&
        twoSidedScore(frame, other.pose) < twoSidedScore(frame, fit.pose))
    {
      // Measured already: taken with its measures rather than measured again.
      fit.pose = other.pose;
      fit.energy = other.energy;
      fit.extremitiesMatched = other.extremitiesMatched;
      fit.medianDistance = other.medianDistance;
      fit.insideFraction = other.insideFraction;
      fit.frameDistance = other.frameDistance;
      fit.status = other.status;
      fit.message = other.message;
    }
  }

  /// A frame that no neighbour vouches for, started again from the poses of frames already
  /// fitted (a collection of poses repeats some): each moved onto the frame and briefly fitted,
  /// the best by twoSidedScore fitted fully, and kept if it explains the frame better than `fit`.
  void refitFromPoses(const FrameSurface& frame, const std::vector<BodyPose>& poses,
                      BodyFrameFit& fit)
  {
    std::vector<BodyPose> starts;
    for (const BodyPose& seen : poses)
    {
      BodyPose pose = seen;
      const Points p = samples_.pose(pose);
      pose.translation +=
          frame.centroid - p.topRows(samples_.numSamples()).colwise().mean().transpose();
      starts.push_back(pose);
    }
    if (!starts.empty()) refitFrom(frame, rankedQuickFits(frame, starts).front().pose, fit);
  }

  /// The fit started again from the joints of other fits (the poses the other frames of a
  /// collection settled on), each under the fit's own root: its place and heading kept, every
  /// other joint as the peer holds it. The limb restarts change one limb or pair at a time, and
  /// the upper-body start takes every joint above the pelvis to rest; a torso twisted while an arm
  /// is raised needs both changed at once, and a peer may hold them so (collection seed 13's
  /// frame 9, BENCHMARKS.md). Each start briefly fitted, the best by twoSidedScore fitted fully
  /// and kept if it explains the frame better (explainsBetter); the starts that settled elsewhere
  /// then measure how ambiguous the frame is (measureRivals).
  void refitFromPeerJoints(const FrameSurface& frame, const std::vector<BodyPose>& peers,
                           BodyFrameFit& fit)
  {
    std::vector<BodyPose> starts;
    for (const BodyPose& peer : peers)
    {
      BodyPose pose = peer;
      pose.rotations.row(Pelvis) = fit.pose.rotations.row(Pelvis);
      pose.translation = fit.pose.translation;
      starts.push_back(pose);
    }
    if (starts.empty()) return;
    const std::vector<RankedPose> ranked = rankedQuickFits(frame, starts);
    refitFrom(frame, ranked.front().pose, fit);
    measureRivals(frame, ranked, fit);
  }

  /// The body turned half round, fitted fully from two starts and its limbs started again
  /// (refitLimbs) after each; each kept when it explains the frame better (explainsBetter).
  /// The every-heading search ranks headings before the limbs have settled, and its best can
  /// face backwards with the knees straight and the elbows bent the other way into the frame's
  /// limbs; only with its limbs restarted does the body facing the right way explain the frame
  /// better (before that, worse on every frame measured). The first start turns the body about
  /// the up axis through its centre with its limbs at rest; the second turns it in place
  /// (turnedInPlace), each limb where its opposite lay: on thirteen random collections it
  /// turned four bodies round that the first start left facing backwards or fitted worse.
  void refitTurnedRound(const FrameSurface& frame, BodyFrameFit& fit)
  {
    const BodyPose kept = fit.pose;
    const int n = samples_.numSamples();
    const Vec3 centre = samples_.pose(kept).topRows(n).colwise().mean().transpose();
    const Eigen::Isometry3d halfTurn = Eigen::Translation3d(centre) *
                                       Eigen::AngleAxisd(M_PI, options_.up.normalized()) *
                                       Eigen::Translation3d(-centre);
    BodyPose atRest = movedRigidly(kept, halfTurn);
    const Eigen::RowVector3d root = atRest.rotations.row(Pelvis);
    atRest.rotations.setZero();
    atRest.rotations.row(Pelvis) = root;
    for (const BodyPose& start : {atRest, turnedInPlace(kept, restJoints_)})
    {
      BodyFrameFit turned;
      turned.pose = start;
      turned.energy = fitPose(frame, turned.pose, nullptr, options_.stages, options_.extremityGate,
                              &turned.extremitiesMatched);
      // Its limb restarts keep to the arms of the fit it would replace: each may push the arms
      // a little further into the torso than the one before, together past what adopting it
      // allows (collection seed 12's frame 18: 0.019, then 0.102 of them, against none).
      ArmsRule arms;
      arms.reference = armsInsideTorso(fit.pose);
      refitLimbs(frame, turned, arms);
      if (explainsBetter(frame, turned.pose, fit.pose)) adopt(frame, turned, fit);
    }
  }

  /// A frame that no neighbour vouches for, started again from its own fit with each limb (each
  /// arm, both arms, each leg) put back in the rest pose, then with each limb aimed at a
  /// detected extremity that the fit leaves unpaired; each start is fitted fully without a
  /// temporal prior and kept if it explains the frame better by twoSidedScore. Extremities are
  /// paired by proximity, so a fit whose arms crossed to the other side's hands keeps them
  /// crossed, and a leg kicked out lies beyond the pairing gate of a foot hanging down.
  /// `arms`: how a restart's arms inside the torso are judged (explainsBetter).
  void refitLimbs(const FrameSurface& frame, BodyFrameFit& fit, const ArmsRule& arms = {})
  {
    refitWithLimbsAtRest(frame, fit, arms);
    refitWithLimbsAimed(frame, fit, arms);
    refitWithPairsSwapped(frame, fit, arms);
  }

  /// The fit started again with its spine, neck, head, clavicles and arms in the rest pose
  /// (pelvis and legs kept), fitted fully and kept if it explains the frame better. A torso
  /// twisted the wrong way can hold the arms on the other side's arms, each arm restart alone then
  /// settling worse (collection seed 8's frame 6: restarts 0.0038-0.0127 against 0.0029, this start
  /// 0.0017, the wrists 76 and 65 cm from the truth's to 4 and 3 cm).
  void refitWithUpperBodyAtRest(const FrameSurface& frame, BodyFrameFit& fit,
                                const ArmsRule& arms = {})
  {
    BodyPose start = fit.pose;
    for (Joint j : {Spine1, Spine2, Spine3, Neck, Head, LeftClavicle, LeftShoulder, LeftElbow,
                    LeftWrist, RightClavicle, RightShoulder, RightElbow, RightWrist})
      start.rotations.row(j).setZero();
    refitFrom(frame, start, fit, arms);
  }

  /// Both legs started across the frame's two lowest detections that are not paired with the
  /// head or a hand: the pelvis moved to stand between them (standAcross) and each leg aimed at
  /// one (both ways round), kept when it explains the frame better. A fit with both legs in one
  /// of the frame's legs leaves the other empty, and a single leg aimed from a pelvis standing
  /// off it crosses the gap between the frame's legs and is drawn back (BENCHMARKS.md).
  void refitWithLegsAcross(const FrameSurface& frame, BodyFrameFit& fit)
  {
    const std::array<int, kNumExtremities> match = pairedExtremities(frame, fit.pose);
    const int head = match[0], leftHand = match[kLimbs[0].extremity],
              rightHand = match[kLimbs[1].extremity];
    std::vector<int> feet;
    for (int d = 0; d < static_cast<int>(frame.extremities.size()); ++d)
      if (d != head && d != leftHand && d != rightHand) feet.push_back(d);
    if (feet.size() < 2) return;
    // Frames are read Y up.
    std::sort(feet.begin(), feet.end(),
              [&](int a, int b) { return frame.extremities[a].y() < frame.extremities[b].y(); });
    const Vec3 a = frame.extremities[feet[0]];
    const Vec3 b = frame.extremities[feet[1]];
    for (int swapped = 0; swapped < 2; ++swapped)
    {
      const Vec3& left = swapped ? b : a;
      const Vec3& right = swapped ? a : b;
      BodyPose start = fit.pose;
      const std::array<Aim, 2> aims = {Aim{kLimbs[2].root, kLimbs[2].extremity, left},
                                       Aim{kLimbs[3].root, kLimbs[3].extremity, right}};
      if (!standAcross(start, aims)) continue;
      if (aimLimb(kLimbs[2], left, start, kAcrossHipExtension) &&
          aimLimb(kLimbs[3], right, start, kAcrossHipExtension))
        refitFrom(frame, start, fit);
    }
  }

  /// Share of the arm samples (upper arms and forearms) lying more than kInsideTorso below the
  /// surface at their nearest torso sample: arms that cross through the chest to the other
  /// side's hands. An unclothed frame is explained about as closely by them as by arms that do
  /// not cross, so the two-sided score alone cannot refuse them.
  double armsInsideTorso(const BodyPose& pose) const
  {
    const std::vector<int>& torso = torsoSamples_;
    const std::vector<int>& arms = armSamples_;
    if (torso.empty() || arms.empty()) return 0.0;
    Points normals;
    const Points p = samples_.pose(pose, &normals);
    Points torsoPoints(torso.size(), 3);
    for (size_t t = 0; t < torso.size(); ++t) torsoPoints.row(t) = p.row(torso[t]);
    const PointIndex index(torsoPoints);
    int inside = 0;
    for (int i : arms)
    {
      const int t = torso[index.nearest(p.row(i).transpose()).index];
      if ((p.row(i) - p.row(t)).dot(normals.row(t)) < -kInsideTorso) ++inside;
    }
    return static_cast<double>(inside) / arms.size();
  }

  /// Gauss-Newton steps on beta with the key frames' joint rotations fixed, and their
  /// translations too unless `moveTranslations` (BodyFitOptions::twoShapes).
  void fitShape(const std::vector<const FrameSurface*>& frames, std::vector<BodyPose>& poses,
                int iterations, bool moveTranslations)
  {
    const int k = std::min(options_.shapeComponents, samples_.numComponents());
    if (k <= 0 || frames.empty()) return;
    const int n = k + (moveTranslations ? 3 * static_cast<int>(frames.size()) : 0);
    BodyFitStage stage = options_.stages.back();
    stage.coverWeight = options_.shapeCoverWeight;
    double lambda = 1e-3;
    for (int it = 0; it < iterations; ++it)
    {
      Eigen::MatrixXd h = Eigen::MatrixXd::Zero(n, n);
      Eigen::VectorXd g = Eigen::VectorXd::Zero(n);
      std::vector<Assignments> assignments;
      for (size_t f = 0; f < frames.size(); ++f)
        assignments.push_back(accumulateShapeFrame(*frames[f], poses[f], stage, k,
                                                   1.0 / frames.size(), static_cast<int>(f), h, g));
      const Eigen::VectorXd beta = samples_.beta();
      const std::vector<BodyPose> start = poses;
      auto apply = [&](const Eigen::VectorXd& x)
      {
        Eigen::VectorXd b = beta;
        b.head(k) += x.head(k);
        samples_.setShape(b);
        for (size_t f = 0; k + 3 * f + 3 <= static_cast<size_t>(n); ++f)
          poses[f].translation = start[f].translation + x.segment<3>(k + 3 * f);
        return b;
      };
      auto energyOf = [&](const Eigen::VectorXd& x)
      {
        const Eigen::VectorXd b = apply(x);
        double e = options_.shapePriorWeight * b.head(k).squaredNorm();
        for (size_t f = 0; f < frames.size(); ++f)
          e += assignments[f].energy(samples_.pose(poses[f]));
        return e;
      };
      h.diagonal().head(k).array() += options_.shapePriorWeight;
      g.head(k) += options_.shapePriorWeight * beta.head(k);
      const double energy = energyOf(Eigen::VectorXd::Zero(n));
      bool accepted = false;
      for (int attempt = 0; attempt < 8 && !accepted; ++attempt)
      {
        Eigen::MatrixXd damped = h;
        damped.diagonal().array() += lambda * (h.diagonal().array() + 1e-12);
        const Eigen::VectorXd step = damped.ldlt().solve(-g);
        const double e = energyOf(step);
        if (std::isfinite(e) && e <= energy)
        {
          accepted = true;
          lambda = std::max(1e-6, lambda / 3.0);
        }
        else
          lambda *= 10.0;
      }
      if (!accepted)
      {
        apply(Eigen::VectorXd::Zero(n));
        break;
      }
    }
  }

private:
  /// One key frame's part of a shape step: its assignments (weighted by `weight`), and J^T W J,
  /// J^T W r added to `h`, `g` over beta's first k components and, when `h` has room for them,
  /// the frame's translation (parameters k + 3 f .. k + 3 f + 2). Without them, accumulated as
  /// when the translations never moved, to the same bits.
  Assignments accumulateShapeFrame(const FrameSurface& frame, const BodyPose& pose,
                                   const BodyFitStage& stage, int k, double weight, int f,
                                   Eigen::MatrixXd& h, Eigen::VectorXd& g)
  {
    Points normals;
    const Points p = samples_.pose(pose, &normals);
    Assignments a = assign(frame, pose, p, normals, stage, options_.extremityGate);
    for (auto& r : a.planes) r.weight *= weight;
    for (auto& r : a.points) r.weight *= weight;
    const bool moves = h.rows() > k;
    std::vector<Points> columns(k + (moves ? 3 : 0));
    parallelFor(
        0, k, [&](int c) { columns[c] = (samples_.poseWithShapeStep(pose, c, kStep) - p) / kStep; },
        4);
    if (!moves)
    {
      a.accumulate(p, columns, h, g);
      return a;
    }
    for (int d = 0; d < 3; ++d)
      columns[k + d] = Points::Zero(p.rows(), 3), columns[k + d].col(d).setOnes();
    const int m = k + 3;
    Eigen::MatrixXd hf = Eigen::MatrixXd::Zero(m, m);
    Eigen::VectorXd gf = Eigen::VectorXd::Zero(m);
    a.accumulate(p, columns, hf, gf);
    h.topLeftCorner(k, k) += hf.topLeftCorner(k, k);
    g.head(k) += gf.head(k);
    const int t = k + 3 * f;
    h.block(0, t, k, 3) += hf.topRightCorner(k, 3);
    h.block(t, 0, 3, k) += hf.bottomLeftCorner(3, k);
    h.block<3, 3>(t, t) += hf.bottomRightCorner<3, 3>();
    g.segment<3>(t) += gf.tail<3>();
    return a;
  }

  /// A limb: the extremity label it ends in (BodyFitPose.h), its root joint and the joints
  /// below the root (an arm has two: its wrist is listed twice).
  struct Limb
  {
    int extremity;
    Joint root;
    std::array<Joint, 3> below;
  };
  static constexpr std::array<Limb, 4> kLimbs = {
      {{1, LeftShoulder, {LeftElbow, LeftWrist, LeftWrist}},
       {2, RightShoulder, {RightElbow, RightWrist, RightWrist}},
       {3, LeftHip, {LeftKnee, LeftAnkle, LeftToe}},
       {4, RightHip, {RightKnee, RightAnkle, RightToe}}}};

  /// `start` fitted fully without a temporal prior; replaces `fit` if it explains the frame
  /// better (explainsBetter).
  void refitFrom(const FrameSurface& frame, const BodyPose& start, BodyFrameFit& fit,
                 const ArmsRule& arms = {})
  {
    BodyFrameFit other;
    other.pose = start;
    other.energy = fitPose(frame, other.pose, nullptr, options_.stages, options_.extremityGate,
                           &other.extremitiesMatched);
    if (explainsBetter(frame, other.pose, fit.pose, arms)) adopt(frame, other, fit);
  }

  /// A restart's fit replaces the current one when its two-sided score is lower, unless its arms
  /// go through the torso where the current ones do not (kArmsCrossedShare more of their
  /// samples inside it than in `current` or than `arms.reference`, whichever is fewer). With
  /// `arms.letOut`, a candidate that takes arms out of the chest may score up to
  /// kArmsOutScoreRatio times the current fit (ArmsRule).
  bool explainsBetter(const FrameSurface& frame, const BodyPose& candidate, const BodyPose& current,
                      const ArmsRule& arms = {}) const
  {
    const double currentArms = armsInsideTorso(current), candidateArms = armsInsideTorso(candidate);
    if (candidateArms - std::min(currentArms, arms.reference) > kArmsCrossedShare) return false;
    const bool armsComeOut = arms.letOut && currentArms >= kArmsThroughChest &&
                             currentArms - candidateArms >= kArmsOutShare;
    return twoSidedScore(frame, candidate) <
           (armsComeOut ? kArmsOutScoreRatio : 1.0) * twoSidedScore(frame, current);
  }

  void refitWithLimbsAtRest(const FrameSurface& frame, BodyFrameFit& fit, const ArmsRule& arms)
  {
    // Each arm with its clavicle, both arms together (crossed arms swap both), each leg.
    const std::array<std::vector<int>, 5> groups = {{{0}, {1}, {0, 1}, {2}, {3}}};
    for (const std::vector<int>& group : groups)
    {
      BodyPose start = fit.pose;
      for (int l : group)
      {
        const Limb& limb = kLimbs[l];
        start.rotations.row(limb.root).setZero();
        for (Joint j : limb.below) start.rotations.row(j).setZero();
        if (l < 2) start.rotations.row(jointParents()[limb.root]).setZero(); // the clavicle
      }
      refitFrom(frame, start, fit, arms);
    }
  }

  void refitWithLimbsAimed(const FrameSurface& frame, BodyFrameFit& fit, const ArmsRule& arms)
  {
    const std::array<int, kNumExtremities> match = pairedExtremities(frame, fit.pose);
    for (size_t d = 0; d < frame.extremities.size(); ++d)
    {
      if (std::find(match.begin(), match.end(), static_cast<int>(d)) != match.end()) continue;
      for (const Limb& limb : kLimbs)
      {
        BodyPose start = fit.pose;
        if (aimLimb(limb, frame.extremities[d], start)) refitFrom(frame, start, fit, arms);
      }
    }
  }

  /// Both arms, then both legs, aimed each at the extremity its partner is paired with: a pair
  /// that crossed through the body to the other side's hands or feet stays paired by proximity,
  /// so neither limb is free for the aimed restarts.
  void refitWithPairsSwapped(const FrameSurface& frame, BodyFrameFit& fit, const ArmsRule& arms)
  {
    for (int first : {0, 2})
    {
      const std::array<int, kNumExtremities> match = pairedExtremities(frame, fit.pose);
      const Limb& a = kLimbs[first];
      const Limb& b = kLimbs[first + 1];
      if (match[a.extremity] < 0 || match[b.extremity] < 0) continue;
      BodyPose start = fit.pose;
      if (aimLimb(a, frame.extremities[match[b.extremity]], start) &&
          aimLimb(b, frame.extremities[match[a.extremity]], start))
        refitFrom(frame, start, fit, arms);
    }
  }

  /// The frame's detected extremity paired with each of the body's in `pose` (-1: none), as
  /// the fit pairs them (BodyFitOptions::extremityGate).
  std::array<int, kNumExtremities> pairedExtremities(const FrameSurface& frame,
                                                     const BodyPose& pose) const
  {
    std::array<int, kNumExtremities> match;
    matchExtremities(samples_.pose(pose), samples_, samples_.extremityRoots(pose),
                     frame.extremities, options_.extremityGate, options_.handGate, reachTolerance_,
                     match);
    return match;
  }

  /// A limb's root (a hip) and extremity, and the point the extremity is aimed at.
  struct Aim
  {
    Joint root;
    int extremity;
    Vec3 target;
  };

  /// Moves `pose` to stand as high as it can over the segment between the aims' targets with
  /// each target within its limb's length of the limb's root (the pelvis moved along the feet's
  /// segment, then up or down); false when no point of it has both within reach. A body left
  /// with both legs in a kicked leg stands too high and too far forward for its other foot.
  bool standAcross(BodyPose& pose, const std::array<Aim, 2>& aims) const
  {
    const std::vector<Eigen::Matrix4d> world = samples_.jointTransforms(pose);
    const Vec3 pelvis = world[Pelvis].topRightCorner<3, 1>();
    Vec3 along = aims[1].target - aims[0].target;
    along.y() = 0.0;
    Vec3 bestShift = Vec3::Zero();
    double bestRise = -std::numeric_limits<double>::infinity();
    constexpr int kSteps = 20;
    for (int step = 0; step <= kSteps; ++step)
    {
      Vec3 shift = aims[0].target + along * (static_cast<double>(step) / kSteps) - pelvis;
      shift.y() = 0.0;
      double rise = std::numeric_limits<double>::infinity();
      for (const Aim& aim : aims)
      {
        const Vec3 root = world[aim.root].topRightCorner<3, 1>() + shift;
        const double length = samples_.reach()[aim.extremity];
        // Frames are read Y up.
        const double across = std::hypot(root.x() - aim.target.x(), root.z() - aim.target.z());
        rise = across < length
                   ? std::min(rise, aim.target.y() + std::sqrt(length * length - across * across) -
                                        root.y())
                   : -std::numeric_limits<double>::infinity();
      }
      if (!(rise > bestRise)) continue;
      bestRise = rise;
      bestShift = shift + Vec3(0.0, rise, 0.0);
    }
    if (!std::isfinite(bestRise)) return false;
    pose.translation += bestShift;
    return true;
  }

  /// Straightens `limb` below its root and turns the root so that the limb points at
  /// `target`; false when the target is out of the limb's reach.
  bool aimLimb(const Limb& limb, const Vec3& target, BodyPose& pose,
               double largestHipExtension = kLargestHipExtension) const
  {
    for (Joint j : limb.below) pose.rotations.row(j).setZero();
    const std::vector<Eigen::Matrix4d> world = samples_.jointTransforms(pose);
    const Vec3 origin = world[limb.root].topRightCorner<3, 1>();
    if ((target - origin).norm() > kAimReach * samples_.reach()[limb.extremity] + 0.03)
      return false;
    const Vec3 tip = samples_.pose(pose).row(samples_.extremityPoint(limb.extremity)).transpose();
    // The root's world rotation is its parent's times its own: turn = P R' (P R)^-1.
    const Eigen::Matrix3d turn =
        Eigen::Quaterniond::FromTwoVectors(tip - origin, target - origin).toRotationMatrix();
    const Eigen::Matrix3d parent = world[jointParents()[limb.root]].topLeftCorner<3, 3>();
    const Eigen::Matrix3d own = axisAngleToMatrix(pose.rotations.row(limb.root).transpose());
    pose.rotations.row(limb.root) =
        matrixToAxisAngle(parent.transpose() * turn * parent * own).transpose();
    // A leg aimed backwards lets a body facing the wrong way reach a foot kicked forward.
    return limb.extremity < 3 || pose.rotations(limb.root, 0) <= largestHipExtension;
  }
  /// Depth (m) below the torso's surface from which an arm sample counts as inside it.
  static constexpr double kInsideTorso = 0.02;
  /// Change in the share of arm samples inside the torso that tells crossed arms from others.
  static constexpr double kArmsCrossedShare = 0.1;
  /// ArmsRule::letOut: the share of arm samples inside the torso from which arms go through the
  /// chest (fits of poses that are right reach 0.25), the fewer a restart must have, and the
  /// score it may then reach against the current fit's.
  static constexpr double kArmsThroughChest = 0.3;
  static constexpr double kArmsOutShare = 0.2;
  static constexpr double kArmsOutScoreRatio = 1.25;
  /// measureRivals: how far apart (metres, the farthest body sample) two fits must lie to be
  /// two readings of the frame, and how many rival starts are fitted fully.
  static constexpr double kRivalDistance = 0.3;
  static constexpr int kRivalFits = 2;
  /// Hip extension (radians, a positive rotation about X) beyond which a leg is not aimed.
  static constexpr double kLargestHipExtension = 0.6;
  /// The same when both legs are aimed across the frame's feet, each at its own: the leg
  /// standing behind a kick extends further (up to 0.71 radians on the kicks of random
  /// collection 11, from a pelvis tilted by the fit that left both legs in the kicked one).
  static constexpr double kAcrossHipExtension = 1.2;
  /// A limb is aimed only at a detection within this multiple of its length (plus 3 cm, as
  /// matchExtremities allows) from its root.
  static constexpr double kAimReach = 1.2;

  const BodyFitOptions& options_;
  BodySamples samples_;
  Points restJoints_;            ///< the mean shape's joints at rest: the body's own axes
  Eigen::VectorXd priorWeights_; ///< per rotation parameter
  std::vector<int> torsoSamples_, armSamples_; ///< by their dominant joints (armsInsideTorso)
  double reachTolerance_;
};

inline std::string frameProblem(const TriangleMesh* frame)
{
  if (!frame || frame->numFaces() == 0) return "empty frame";
  if (!frame->V.allFinite()) return "frame has non-finite coordinates";
  if (frame->F.minCoeff() < 0 || frame->F.maxCoeff() >= frame->numVertices())
    return "frame has out-of-range vertex indices";
  return {};
}

} // namespace clothtrack::bodyfit
