#include "SkinnedTemplate.h"

#include <clothtrack/base/Error.h>
#include <clothtrack/base/Parallel.h>
#include <clothtrack/mesh/MeshTopology.h>
#include <clothtrack/mesh/PointIndex.h>

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <limits>
#include <memory>
#include <string>

namespace clothtrack
{
namespace
{
/// Each joint's world rotation (the rotation part of its world transform, which does not
/// depend on where the joints are).
std::vector<Eigen::Matrix3d> worldRotations(const BodyPose& pose)
{
  const std::vector<Eigen::Matrix4d> world = jointWorldTransforms(Points::Zero(NumJoints, 3), pose);
  std::vector<Eigen::Matrix3d> out(NumJoints);
  for (int j = 0; j < NumJoints; ++j) out[j] = world[j].topLeftCorner<3, 3>();
  return out;
}

/// A body part as a thick segment: the main axis of its vertices and their mean distance to it.
struct PartAxis
{
  Vec3 from = Vec3::Zero(), to = Vec3::Zero();
  double thickness = 1.0; ///< mean distance of the part's vertices to the axis
  double distance(const Vec3& p) const
  {
    const Vec3 axis = to - from;
    const double t =
        std::clamp((p - from).dot(axis) / std::max(axis.squaredNorm(), 1e-12), 0.0, 1.0);
    return (p - (from + t * axis)).norm();
  }
};

/// The body's parts, each the vertices its joint moves most, as thick segments; finds the part a
/// point hangs from (SkinnedTemplateOptions::partBindingDistance).
class BodyParts
{
public:
  BodyParts(const Points& bodyVertices, const Eigen::MatrixXd& bodyWeights)
      : members_(NumJoints), axes_(NumJoints), indices_(NumJoints)
  {
    for (int b = 0; b < static_cast<int>(bodyVertices.rows()); ++b)
    {
      Eigen::Index part;
      bodyWeights.row(b).maxCoeff(&part);
      members_[part].push_back(b);
    }
    for (int j = 0; j < NumJoints; ++j)
    {
      if (members_[j].size() < 4) continue; // too few to have an axis
      Points points(static_cast<Eigen::Index>(members_[j].size()), 3);
      for (size_t k = 0; k < members_[j].size(); ++k)
        points.row(k) = bodyVertices.row(members_[j][k]);
      axes_[j] = mainAxis(points);
      indices_[j] = std::make_unique<PointIndex>(points);
    }
  }

  /// The body vertex nearest to `p` within the part whose axis is nearest to `p` relative to the
  /// part's thickness; -1 when no part has an axis.
  int vertexFor(const Vec3& p) const
  {
    int best = -1;
    double bestScore = std::numeric_limits<double>::infinity();
    for (int j = 0; j < NumJoints; ++j)
      if (indices_[j])
      {
        const double score = axes_[j].distance(p) / axes_[j].thickness;
        if (score < bestScore) bestScore = score, best = j;
      }
    return best < 0 ? -1 : members_[best][indices_[best]->nearest(p).index];
  }

private:
  static PartAxis mainAxis(const Points& points)
  {
    const Vec3 centre = points.colwise().mean().transpose();
    const Points centred = points.rowwise() - centre.transpose();
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> pca(centred.transpose() * centred);
    const Vec3 direction = pca.eigenvectors().col(2);
    const Eigen::VectorXd along = centred * direction;
    PartAxis axis;
    axis.from = centre + along.minCoeff() * direction;
    axis.to = centre + along.maxCoeff() * direction;
    double sum = 0.0;
    for (Eigen::Index k = 0; k < points.rows(); ++k)
      sum += axis.distance(points.row(k).transpose());
    axis.thickness = std::max(sum / static_cast<double>(points.rows()), 1e-3);
    return axis;
  }

  std::vector<std::vector<int>> members_;
  std::vector<PartAxis> axes_;
  std::vector<std::unique_ptr<PointIndex>> indices_;
};
} // namespace

PosedSkeleton posedSkeleton(const BodyModel& model, const Eigen::VectorXd& beta,
                            const BodyPose& pose)
{
  return {pose, model.posedJoints(beta, pose)};
}

std::vector<Eigen::Matrix<double, 3, 4>> jointMotions(const PosedSkeleton& from,
                                                      const PosedSkeleton& to)
{
  const std::vector<Eigen::Matrix3d> a = worldRotations(from.pose), b = worldRotations(to.pose);
  std::vector<Eigen::Matrix<double, 3, 4>> out(NumJoints);
  for (int j = 0; j < NumJoints; ++j)
  {
    const Eigen::Matrix3d r = b[j] * a[j].transpose();
    out[j].leftCols<3>() = r;
    out[j].col(3) = to.joints.row(j).transpose() - r * from.joints.row(j).transpose();
  }
  return out;
}

SkinnedTemplate::SkinnedTemplate(const TriangleMesh& templateMesh, const Points& bodyVertices,
                                 const Eigen::MatrixXd& bodyWeights,
                                 const PosedSkeleton& atTemplate,
                                 const SkinnedTemplateOptions& options)
    : positions_(templateMesh.V), atTemplate_(atTemplate)
{
  const int n = templateMesh.numVertices();
  if (n == 0) throw Error("skinned template: the template is empty");
  if (bodyVertices.rows() == 0) throw Error("skinned template: the body is empty");
  if (bodyWeights.rows() != bodyVertices.rows() || bodyWeights.cols() != NumJoints)
    throw Error("skinned template: " + std::to_string(bodyWeights.rows()) + " x " +
                std::to_string(bodyWeights.cols()) + " skinning weights for a body of " +
                std::to_string(bodyVertices.rows()) + " vertices and " + std::to_string(NumJoints) +
                " joints");

  // The bound body vertex's weights, then averaged over the template's edges.
  weights_.resize(n, NumJoints);
  const PointIndex index(bodyVertices);
  std::vector<unsigned char> far(n, 0);
  parallelFor(0, n,
              [&](int i)
              {
                const Neighbour nearest = index.nearest(templateMesh.V.row(i).transpose());
                weights_.row(i) = bodyWeights.row(nearest.index);
                far[i] = nearest.distance > options.partBindingDistance;
              });
  if (std::find(far.begin(), far.end(), 1) != far.end())
  {
    const BodyParts parts(bodyVertices, bodyWeights);
    parallelFor(0, n,
                [&](int i)
                {
                  if (!far[i]) return;
                  const int b = parts.vertexFor(templateMesh.V.row(i).transpose());
                  if (b >= 0) weights_.row(i) = bodyWeights.row(b);
                });
  }
  const Adjacency ring = buildTopology(templateMesh).vertexVertices;
  for (int round = 0; round < options.smoothingRounds; ++round)
  {
    Eigen::MatrixXd next(n, NumJoints);
    parallelFor(0, n,
                [&](int i)
                {
                  Eigen::RowVectorXd sum = weights_.row(i);
                  for (const int* j = ring.begin(i); j != ring.end(i); ++j) sum += weights_.row(*j);
                  next.row(i) = sum / (1 + ring.degree(i));
                });
    weights_.swap(next);
  }
}

Points SkinnedTemplate::posed(const PosedSkeleton& frame) const
{
  const auto motions = jointMotions(atTemplate_, frame);
  Points out(positions_.rows(), 3);
  parallelFor(
      0, static_cast<int>(positions_.rows()),
      [&](int i)
      {
        Eigen::Matrix<double, 3, 4> blend = Eigen::Matrix<double, 3, 4>::Zero();
        for (int j = 0; j < NumJoints; ++j)
          if (weights_(i, j) != 0.0) blend += weights_(i, j) * motions[j];
        out.row(i) =
            (blend.leftCols<3>() * positions_.row(i).transpose() + blend.col(3)).transpose();
      });
  return out;
}
} // namespace clothtrack
