#pragma once
// The body points the body fit's energy looks at. Internal to the body fit (BodyFit.cpp).
#include "BodyFitPose.h"

#include <clothtrack/base/Parallel.h>

#include <algorithm>
#include <vector>

namespace clothtrack::bodyfit
{
inline int dominantJoint(const BodyModel& model, int vertex)
{
  Eigen::Index j;
  model.weights.row(vertex).maxCoeff(&j);
  return static_cast<int>(j);
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
  /// The joint that moves point i most (its largest skinning weight).
  int dominantJointOf(int i) const { return dominantJoint(model_, vertices_[i]); }
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

  /// World transforms of the joints in `pose`.
  std::vector<Eigen::Matrix4d> jointTransforms(const BodyPose& pose) const
  {
    return jointWorldTransforms(joints_, pose);
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

} // namespace clothtrack::bodyfit
