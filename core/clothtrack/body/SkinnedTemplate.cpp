#include "SkinnedTemplate.h"

#include <clothtrack/base/Error.h>
#include <clothtrack/base/Parallel.h>
#include <clothtrack/mesh/MeshTopology.h>
#include <clothtrack/mesh/PointIndex.h>

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

  // The nearest body vertex's weights, then averaged over the template's edges.
  const PointIndex index(bodyVertices);
  weights_.resize(n, NumJoints);
  parallelFor(0, n,
              [&](int i)
              {
                const Neighbour nearest = index.nearest(templateMesh.V.row(i).transpose());
                weights_.row(i) = bodyWeights.row(nearest.index);
              });
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
