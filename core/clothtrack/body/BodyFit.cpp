#include "BodyFit.h"

#include "../Error.h"
#include "../Extremities.h"
#include "../Geodesic.h"
#include "../Parallel.h"
#include "../SurfaceLocator.h"

#include <Eigen/Cholesky>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <memory>

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

namespace
{
constexpr int kNumExtremities = 5;
/// The joint each extremity hangs from: it cannot be further from it than in the rest pose.
constexpr std::array<int, kNumExtremities> kExtremityRoots = {Neck, LeftShoulder, RightShoulder,
                                                              LeftHip, RightHip};
constexpr int kPoseParameters = NumJoints * 3 + 3;
constexpr double kStep = 1e-5; // finite-difference step (radians, metres, beta units)

int dominantJoint(const BodyModel& model, int vertex)
{
  Eigen::Index j;
  model.weights.row(vertex).maxCoeff(&j);
  return static_cast<int>(j);
}

/// Prior weight of each rotation parameter (x, y, z about the rest-pose axes; y is the twist
/// of a limb pointing down). Joints get the stiffness of their anatomy: knees are hinges, hips
/// bend forward far but barely twist; spine joints, clavicles, ankles and toes move little. Without
/// that, legs inside wide trousers or a dress are free to cross, twist or splay, which fits the
/// cloth as well as straight legs but is lost a few frames later.
Eigen::VectorXd jointPriorWeights(const BodyFitOptions& options)
{
  Eigen::VectorXd w = Eigen::VectorXd::Constant(kPoseParameters, options.posePriorWeight);
  auto stiffen = [&](int joint, double x, double y, double z)
  {
    w[3 * joint] *= x;
    w[3 * joint + 1] *= y;
    w[3 * joint + 2] *= z;
  };
  const double hinge = options.hingeStiffness;
  for (int hip : {LeftHip, RightHip}) stiffen(hip, 1.0, 0.1 * hinge, 0.03 * hinge);
  for (int knee : {LeftKnee, RightKnee}) stiffen(knee, 1.0, hinge, hinge);
  for (int ankle : {LeftAnkle, RightAnkle}) stiffen(ankle, 1.0, 0.1 * hinge, 0.1 * hinge);
  for (int toe : {LeftToe, RightToe}) stiffen(toe, 0.1 * hinge, 0.1 * hinge, 0.1 * hinge);
  // Each spine joint bends a little; a large bend there trades against the pelvis tilting
  // (under wide trousers a forward-tilted pelvis with a back-bent spine fits a squat too).
  for (int spine : {Spine1, Spine2, Spine3}) stiffen(spine, 0.1 * hinge, 0.1 * hinge, 0.1 * hinge);
  for (int clavicle : {LeftClavicle, RightClavicle})
    stiffen(clavicle, 0.1 * hinge, 0.1 * hinge, 0.1 * hinge);
  for (int wrist : {LeftWrist, RightWrist})
    stiffen(wrist, 0.03 * hinge, 0.03 * hinge, 0.03 * hinge);
  w.head<3>().setZero(); // the root turns freely
  w.tail<3>().setZero(); // translation
  return w;
}

/// Rotation parameters of the knees' bend, which is never negative (no knee bends backwards).
constexpr std::array<int, 2> kHingeBends = {3 * LeftKnee, 3 * RightKnee};

/// Angle (0 to pi) between the directions two poses face, seen along `up`.
double headingChange(const BodyPose& a, const BodyPose& b, const Vec3& up)
{
  const Vec3 u = up.normalized();
  auto facing = [&u](const BodyPose& pose)
  {
    const Vec3 f = axisAngleToMatrix(pose.rotations.row(Pelvis).transpose()) * Vec3::UnitZ();
    return Vec3(f - f.dot(u) * u);
  };
  const Vec3 fa = facing(a), fb = facing(b);
  return std::atan2(fa.cross(fb).norm(), fa.dot(fb));
}

Eigen::VectorXd toVector(const BodyPose& pose)
{
  Eigen::VectorXd x(kPoseParameters);
  for (int j = 0; j < NumJoints; ++j) x.segment<3>(3 * j) = pose.rotations.row(j).transpose();
  x.tail<3>() = pose.translation;
  return x;
}

BodyPose toPose(const Eigen::VectorXd& x)
{
  BodyPose pose;
  for (int j = 0; j < NumJoints; ++j) pose.rotations.row(j) = x.segment<3>(3 * j).transpose();
  pose.translation = x.tail<3>();
  return pose;
}

/// The body points the energy looks at (samples, then the extremity vertices), in rest pose for
/// the current shape, with sparse skinning weights.
class BodySamples
{
public:
  BodySamples(const BodyModel& model, int numSamples) : model_(model)
  {
    const int n = model.numVertices();
    const int stride = std::max(1, n / std::max(1, numSamples));
    for (int v = 0; v < n; v += stride) vertices_.push_back(v);
    numSamples_ = static_cast<int>(vertices_.size());
    for (int v : bodyExtremityVertices(model)) vertices_.push_back(v);
    // A detected foot tip may be the heel or the toe (a trouser hem or a dress changes which
    // is further), so a foot is matched by its nearest point on the whole foot.
    const std::array<std::vector<int>, kNumExtremities> regionJoints = {
        {{}, {}, {}, {LeftToe, LeftAnkle}, {RightToe, RightAnkle}}};
    for (int label = 0; label < kNumExtremities; ++label)
    {
      regions_[label] = {extremityPoint(label)};
      for (int i = 0; i < numSamples_; ++i)
      {
        const int j = dominantJoint(model, vertices_[i]);
        const auto& group = regionJoints[label];
        if (std::find(group.begin(), group.end(), j) != group.end()) regions_[label].push_back(i);
      }
    }
    weights_.resize(vertices_.size());
    for (size_t i = 0; i < vertices_.size(); ++i)
      for (int j = 0; j < NumJoints; ++j)
        if (model.weights(vertices_[i], j) > 1e-4)
          weights_[i].push_back({j, model.weights(vertices_[i], j)});
    const int k = model.numShapeComponents();
    basis_.resize(3 * vertices_.size(), k);
    for (size_t i = 0; i < vertices_.size(); ++i)
      basis_.middleRows(3 * i, 3) = model.vertexBasis.middleRows(3 * vertices_[i], 3);
    setShape(Eigen::VectorXd::Zero(k));
  }

  int numSamples() const { return numSamples_; }
  int numPoints() const { return static_cast<int>(vertices_.size()); }
  int extremityPoint(int label) const { return numSamples_ + label; }
  /// Points that may stand for an extremity: its tip, and for a foot the whole foot.
  const std::vector<int>& extremityRegion(int label) const { return regions_[label]; }
  const Eigen::VectorXd& beta() const { return beta_; }
  int numComponents() const { return static_cast<int>(basis_.cols()); }

  void setShape(const Eigen::VectorXd& beta)
  {
    beta_ = Eigen::VectorXd::Zero(basis_.cols());
    const Eigen::Index k = std::min(beta.size(), beta_.size());
    beta_.head(k) = beta.head(k);
    Points all;
    model_.shape(beta_, all, joints_);
    rest_.resize(numPoints(), 3);
    for (int i = 0; i < numPoints(); ++i) rest_.row(i) = all.row(vertices_[i]);
    for (int label = 0; label < kNumExtremities; ++label)
      reach_[label] =
          (rest_.row(extremityPoint(label)) - joints_.row(kExtremityRoots[label])).norm();
    TriangleMesh shaped{all, model_.mesh.F};
    const Points normals = vertexNormals(shaped);
    restNormals_.resize(numPoints(), 3);
    for (int i = 0; i < numPoints(); ++i) restNormals_.row(i) = normals.row(vertices_[i]);
  }

  /// Posed points (and normals) of the current shape.
  Points pose(const BodyPose& pose, Points* normals = nullptr) const
  {
    return skin(rest_, joints_, pose, normals);
  }

  /// Rest-pose distance from each extremity to the joint it hangs from.
  const std::array<double, kNumExtremities>& reach() const { return reach_; }

  /// Posed positions of the joints the extremities hang from.
  std::array<Vec3, kNumExtremities> extremityRoots(const BodyPose& pose) const
  {
    const std::vector<Eigen::Matrix4d> world = jointWorldTransforms(joints_, pose);
    std::array<Vec3, kNumExtremities> roots;
    for (int label = 0; label < kNumExtremities; ++label)
      roots[label] = world[kExtremityRoots[label]].topRightCorner<3, 1>();
    return roots;
  }

  /// Posed points when beta_k moves by `step` (normals not needed by the Jacobian).
  Points poseWithShapeStep(const BodyPose& pose, int k, double step) const
  {
    Points rest = rest_;
    for (int i = 0; i < numPoints(); ++i)
      rest.row(i) += step * basis_.block(3 * i, k, 3, 1).transpose();
    Points joints = joints_;
    for (int j = 0; j < NumJoints; ++j)
      joints.row(j) += step * model_.jointBasis.block(3 * j, k, 3, 1).transpose();
    return skin(rest, joints, pose, nullptr);
  }

private:
  Points skin(const Points& rest, const Points& joints, const BodyPose& pose, Points* normals) const
  {
    const std::vector<Eigen::Matrix4d> world = jointWorldTransforms(joints, pose);
    std::array<Eigen::Matrix<double, 3, 4>, NumJoints> skinning;
    for (int j = 0; j < NumJoints; ++j)
    {
      skinning[j].leftCols<3>() = world[j].topLeftCorner<3, 3>();
      skinning[j].col(3) = world[j].topRightCorner<3, 1>() -
                           world[j].topLeftCorner<3, 3>() * joints.row(j).transpose();
    }
    Points out(numPoints(), 3);
    if (normals) normals->resize(numPoints(), 3);
    for (int i = 0; i < numPoints(); ++i)
    {
      Eigen::Matrix<double, 3, 4> m = Eigen::Matrix<double, 3, 4>::Zero();
      for (const auto& [j, w] : weights_[i]) m += w * skinning[j];
      out.row(i) = (m.leftCols<3>() * rest.row(i).transpose() + m.col(3)).transpose();
      if (normals)
        normals->row(i) =
            (m.leftCols<3>() * restNormals_.row(i).transpose()).normalized().transpose();
    }
    return out;
  }

  const BodyModel& model_;
  std::vector<int> vertices_;
  int numSamples_ = 0;
  std::vector<std::vector<std::pair<int, double>>> weights_;
  Eigen::MatrixXd basis_;
  Eigen::VectorXd beta_;
  Points rest_, restNormals_, joints_;
  std::array<double, kNumExtremities> reach_{};
  std::array<std::vector<int>, kNumExtremities> regions_;
};

/// A frame ready for closest-point queries, with its detected extremities.
struct FrameSurface
{
  const TriangleMesh* mesh = nullptr;
  std::unique_ptr<SurfaceLocator> locator;
  Points normals;
  Vec3 centroid = Vec3::Zero();
  std::vector<Vec3> extremities;
  mutable std::vector<int> hints; ///< last closest face of each body sample

  /// Detects the extremities unless `known` gives them.
  FrameSurface(const TriangleMesh& frame, double persistence, const std::vector<Vec3>* known)
      : mesh(&frame)
  {
    locator = std::make_unique<SurfaceLocator>(frame);
    normals = vertexNormals(frame);
    if (signedVolume(frame) < 0.0) normals = -normals; // inward-facing triangles
    const Eigen::VectorXd areas = faceAreas(frame);
    for (int f = 0; f < frame.numFaces(); ++f)
      centroid += areas[f] *
                  (frame.vertex(frame.F(f, 0)) + frame.vertex(frame.F(f, 1)) +
                   frame.vertex(frame.F(f, 2))) /
                  3.0;
    centroid /= std::max(areas.sum(), 1e-12);
    if (known)
    {
      extremities = *known;
      return;
    }
    for (const Extremity& e : geodesicExtremities(frame, persistence))
      extremities.push_back(frame.vertex(e.vertex));
    if (extremities.size() > 7) extremities.resize(7);
  }

  /// Closest point and the (outward) surface normal there.
  bool closest(int sample, const Vec3& p, double maxDistance, Vec3& point, Vec3& normal) const
  {
    // hints is sized by the caller before parallel queries (one slot per sample).
    const SurfacePoint s = locator->closestPoint(p, maxDistance, hints[sample]);
    if (!s.valid()) return false;
    hints[sample] = s.face;
    normal = Vec3::Zero();
    for (int k = 0; k < 3; ++k) normal += s.bary[k] * normals.row(mesh->F(s.face, k)).transpose();
    if (normal.squaredNorm() < 1e-20) return false;
    normal.normalize();
    point = s.position;
    return true;
  }
};

/// Residuals at fixed assignments: plane rows r = n.(p - target) (hinge rows count only
/// when positive) and point rows r = p - target.
struct Assignments
{
  struct PlaneRow
  {
    int point;
    Vec3 target, normal;
    double weight;
    bool hinge;
  };
  struct PointRow
  {
    int point;
    Vec3 target;
    double weight;
  };
  std::vector<PlaneRow> planes;
  std::vector<PointRow> points;
  int matchedExtremities = 0;

  double energy(const Points& p) const
  {
    double e = 0.0;
    for (const PlaneRow& r : planes)
    {
      double s = r.normal.dot(p.row(r.point).transpose() - r.target);
      if (r.hinge) s = std::max(0.0, s);
      e += r.weight * s * s;
    }
    for (const PointRow& r : points)
      e += r.weight * (p.row(r.point).transpose() - r.target).squaredNorm();
    return e;
  }

  /// Adds J^T W J and J^T W r, J's columns being the point displacements per unit parameter.
  void accumulate(const Points& p, const std::vector<Points>& columns, Eigen::MatrixXd& h,
                  Eigen::VectorXd& g) const
  {
    const int n = static_cast<int>(columns.size());
    Eigen::MatrixXd j(planes.size() + 3 * points.size(), n);
    Eigen::VectorXd r(j.rows());
    int row = 0;
    for (const PlaneRow& pr : planes)
    {
      const double s = pr.normal.dot(p.row(pr.point).transpose() - pr.target);
      if (pr.hinge && s <= 0.0) continue;
      const double w = std::sqrt(pr.weight);
      for (int c = 0; c < n; ++c)
        j(row, c) = w * pr.normal.dot(columns[c].row(pr.point).transpose());
      r[row++] = w * s;
    }
    for (const PointRow& pr : points)
    {
      const double w = std::sqrt(pr.weight);
      for (int c = 0; c < n; ++c) j.block(row, c, 3, 1) = w * columns[c].row(pr.point).transpose();
      r.segment<3>(row) = w * (p.row(pr.point).transpose() - pr.target);
      row += 3;
    }
    const auto used = j.topRows(row);
    h.noalias() += used.transpose() * used;
    g.noalias() += used.transpose() * r.head(row);
  }
};

/// Pairs detected extremities with the body's (head top, hands, toes) by proximity under the
/// current estimate, each used at most once. A detection is a candidate for a label only within
/// the gate and within reach of the joint the extremity hangs from (a hand cannot be further
/// from its shoulder than the arm is long): tips of cloth folds or of merged parts are left out.
void matchExtremities(const Points& p, const BodySamples& samples,
                      const std::array<Vec3, kNumExtremities>& roots,
                      const std::vector<Vec3>& detected, double gate, double handGate,
                      std::array<int, 5>& match)
{
  match.fill(-1);
  std::array<int, 5> current;
  current.fill(-1);
  std::vector<bool> used(detected.size(), false);
  double bestScore = -1.0;
  // Exhaustive over at most 5 labels x 8 choices: maximise matched count, then closeness.
  std::function<void(int, int, double)> search = [&](int label, int count, double cost)
  {
    if (label == kNumExtremities)
    {
      const double score = count * 100.0 - cost;
      if (score > bestScore) bestScore = score, match = current;
      return;
    }
    current[label] = -1;
    search(label + 1, count, cost);
    const Vec3 body = p.row(samples.extremityPoint(label)).transpose();
    for (size_t d = 0; d < detected.size(); ++d)
    {
      if (used[d]) continue;
      const double distance = (detected[d] - body).norm();
      const bool hand = label == 1 || label == 2;
      if (distance > (hand ? std::max(gate, handGate) : gate)) continue;
      if ((detected[d] - roots[label]).norm() > 1.1 * samples.reach()[label] + 0.03) continue;
      used[d] = true;
      current[label] = static_cast<int>(d);
      search(label + 1, count + 1, cost + distance);
      used[d] = false;
      current[label] = -1;
    }
  };
  search(0, 0, 0.0);
}

class SequenceFitter
{
public:
  SequenceFitter(const BodyModel& model, const BodyFitOptions& options)
      : options_(options), samples_(model, options.samples),
        priorWeights_(jointPriorWeights(options))
  {
  }

  BodySamples& samples() { return samples_; }

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
    if (stage.landmarkWeight > 0.0 && !frame.extremities.empty())
    {
      std::array<int, 5> match;
      matchExtremities(p, samples_, samples_.extremityRoots(pose), frame.extremities, gate,
                       options_.handGate, match);
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

  double regulariser(const Eigen::VectorXd& x, const Eigen::VectorXd* previous) const
  {
    double e = 0.0;
    for (int k = 3; k < NumJoints * 3; ++k) e += priorWeights_[k] * x[k] * x[k];
    for (int k : kHingeBends) e += limitWeight() * std::pow(std::min(0.0, x[k]), 2);
    if (previous)
      for (int k = 0; k < NumJoints * 3; ++k)
        e += options_.temporalWeight * std::pow(x[k] - (*previous)[k], 2);
    return e;
  }

  /// Damped Gauss-Newton on the pose with assignments refreshed every iteration.
  /// `rigid` moves the body as a whole only (root rotation and translation).
  double fitPose(const FrameSurface& frame, BodyPose& pose, const BodyPose* previous,
                 const std::vector<BodyFitStage>& stages, double gate, int* matched = nullptr,
                 bool rigid = false)
  {
    auto active = [rigid](int c) { return !rigid || c < 3 || c >= NumJoints * 3; };
    Eigen::VectorXd x = toVector(pose);
    Eigen::VectorXd prev = previous ? toVector(*previous) : Eigen::VectorXd();
    const Eigen::VectorXd* prevPtr = previous ? &prev : nullptr;
    double energy = 0.0;
    double lambda = 1e-3;
    std::vector<Points> columns(kPoseParameters);
    for (const BodyFitStage& stage : stages)
      for (int it = 0; it < stage.iterations; ++it)
      {
        Points normals;
        const Points p = samples_.pose(toPose(x), &normals);
        const Assignments a = assign(frame, toPose(x), p, normals, stage, gate);
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
              columns[c] = (samples_.pose(toPose(xs)) - p) / kStep;
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
            h(k, k) += options_.temporalWeight;
            g[k] += options_.temporalWeight * (x[k] - prev[k]);
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
              a.energy(samples_.pose(toPose(candidate))) + regulariser(candidate, prevPtr);
          if (std::isfinite(e) && e <= energy)
          {
            x = candidate;
            energy = e;
            lambda = std::max(1e-6, lambda / 3.0);
            break;
          }
          lambda *= 10.0;
        }
      }
    pose = toPose(x);
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
    last.nearestWeight = last.insideWeight = 0.0; // only the extremity rows below
    const Assignments extremities = assign(frame, pose, p, normals, last, options_.extremityGate);
    return total / ns + extremities.energy(p);
  }

  /// Tries every heading about the up axis, the body centred on the frame and moved rigidly;
  /// then fits fully from the best heading and from those a quarter, half and three quarters
  /// of a turn away (front and back are hard to tell apart under wide clothing: the limbs must
  /// settle before the feet and arms reveal the facing) and keeps the best.
  BodyFrameFit initialFit(const FrameSurface& frame)
  {
    const int headings = std::max(1, options_.headings);
    const std::vector<BodyFitStage> quick = {{1.0, 0.1, 0.0, 4, 0.4}, {0.3, 1.0, 1.0, 4, 0.15}};
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
    BodyFrameFit chosen;
    double chosenScore = std::numeric_limits<double>::infinity();
    for (int h : candidates)
    {
      BodyFrameFit fit;
      fit.pose = tried[h].second;
      fit.energy = fitPose(frame, fit.pose, nullptr, options_.stages, options_.extremityGate,
                           &fit.extremitiesMatched);
      measure(frame, fit);
      const double s = score(frame, fit.pose);
      if (s < chosenScore) chosenScore = s, chosen = fit;
    }
    return chosen;
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
    fit.insideFraction = static_cast<double>(inside) / samples_.numSamples();
    const bool poor = fit.medianDistance > options_.poorDistance ||
                      fit.insideFraction < options_.poorInside || !std::isfinite(fit.energy);
    fit.status = poor ? BodyFitStatus::Poor : BodyFitStatus::Ok;
    fit.message = poor ? "body far from or outside the frame (median distance " +
                             std::to_string(fit.medianDistance) + " m, inside " +
                             std::to_string(fit.insideFraction) + ")"
                       : std::string();
  }

  /// One frame: from `init`, full schedule; a poor result is retried from every heading.
  void fitFrame(const FrameSurface& frame, const BodyPose& init, const BodyPose* previous,
                const std::vector<BodyFitStage>& stages, BodyFrameFit& fit)
  {
    fit.pose = init;
    fit.energy =
        fitPose(frame, fit.pose, previous, stages, options_.extremityGate, &fit.extremitiesMatched);
    measure(frame, fit);
    if (fit.status == BodyFitStatus::Ok) return;
    const BodyFrameFit retry = initialFit(frame);
    // A fresh start must be clearly better and face roughly the same way: a body turned the
    // other way round can fit a wide garment almost as well, and a person cannot turn round
    // between two frames.
    if (retry.status == BodyFitStatus::Ok &&
        headingChange(retry.pose, init, options_.up) < 0.5 * M_PI &&
        score(frame, retry.pose) < 0.5 * score(frame, fit.pose))
    {
      fit.pose = retry.pose;
      fit.energy = retry.energy;
      fit.extremitiesMatched = retry.extremitiesMatched;
      measure(frame, fit);
    }
  }

  /// Gauss-Newton steps on beta with the key frames' poses fixed.
  void fitShape(const std::vector<const FrameSurface*>& frames, const std::vector<BodyPose>& poses,
                int iterations)
  {
    const int k = std::min(options_.shapeComponents, samples_.numComponents());
    if (k <= 0 || frames.empty()) return;
    const BodyFitStage& stage = options_.stages.back();
    double lambda = 1e-3;
    for (int it = 0; it < iterations; ++it)
    {
      Eigen::MatrixXd h = Eigen::MatrixXd::Zero(k, k);
      Eigen::VectorXd g = Eigen::VectorXd::Zero(k);
      std::vector<Assignments> assignments;
      const double perFrame = 1.0 / frames.size();
      for (size_t f = 0; f < frames.size(); ++f)
      {
        Points normals;
        const Points p = samples_.pose(poses[f], &normals);
        Assignments a = assign(*frames[f], poses[f], p, normals, stage, options_.extremityGate);
        for (auto& r : a.planes) r.weight *= perFrame;
        for (auto& r : a.points) r.weight *= perFrame;
        std::vector<Points> columns(k);
        parallelFor(
            0, k,
            [&](int c)
            { columns[c] = (samples_.poseWithShapeStep(poses[f], c, kStep) - p) / kStep; },
            4);
        a.accumulate(p, columns, h, g);
        assignments.push_back(std::move(a));
      }
      const Eigen::VectorXd beta = samples_.beta();
      auto energyOf = [&](const Eigen::VectorXd& b)
      {
        samples_.setShape(b);
        double e = options_.shapePriorWeight * b.head(k).squaredNorm();
        for (size_t f = 0; f < frames.size(); ++f)
          e += assignments[f].energy(samples_.pose(poses[f]));
        return e;
      };
      h.diagonal().array() += options_.shapePriorWeight;
      g += options_.shapePriorWeight * beta.head(k);
      const double energy = energyOf(beta);
      bool accepted = false;
      for (int attempt = 0; attempt < 8 && !accepted; ++attempt)
      {
        Eigen::MatrixXd damped = h;
        damped.diagonal().array() += lambda * (h.diagonal().array() + 1e-12);
        Eigen::VectorXd candidate = beta;
        candidate.head(k) += damped.ldlt().solve(-g);
        const double e = energyOf(candidate);
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
        samples_.setShape(beta);
        break;
      }
    }
  }

private:
  const BodyFitOptions& options_;
  BodySamples samples_;
  Eigen::VectorXd priorWeights_; ///< per rotation parameter
};

std::string frameProblem(const TriangleMesh* frame)
{
  if (!frame || frame->numFaces() == 0) return "empty frame";
  if (!frame->V.allFinite()) return "frame has non-finite coordinates";
  if (frame->F.minCoeff() < 0 || frame->F.maxCoeff() >= frame->numVertices())
    return "frame has out-of-range vertex indices";
  return {};
}
} // namespace

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
                              const BodyFitOptions& options, const BodyFitProgress& progress)
{
  if (model.numVertices() == 0) throw Error("body fit: the body model is empty");
  if (options.stages.empty()) throw Error("body fit: no stage in the weight schedule");
  const int n = static_cast<int>(frames.size());
  BodyFitResult result;
  result.frames.resize(n);
  SequenceFitter fitter(model, options);
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
