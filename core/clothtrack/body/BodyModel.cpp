#include "BodyModel.h"

#include <cmath>

namespace clothtrack
{
Eigen::Matrix3d axisAngleToMatrix(const Vec3& axisAngle)
{
  const double angle = axisAngle.norm();
  if (angle < 1e-12) return Eigen::Matrix3d::Identity();
  return Eigen::AngleAxisd(angle, axisAngle / angle).toRotationMatrix();
}

void BodyModel::shape(const Eigen::VectorXd& beta, Points& vertices, Points& jointPositions) const
{
  const int k = std::min<int>(static_cast<int>(beta.size()), numShapeComponents());
  Eigen::VectorXd v = Eigen::Map<const Eigen::VectorXd>(mesh.V.data(), mesh.V.size());
  Eigen::VectorXd j = Eigen::Map<const Eigen::VectorXd>(joints.data(), joints.size());
  if (k > 0)
  {
    v += vertexBasis.leftCols(k) * beta.head(k);
    j += jointBasis.leftCols(k) * beta.head(k);
  }
  vertices = Eigen::Map<const Points>(v.data(), mesh.numVertices(), 3);
  jointPositions = Eigen::Map<const Points>(j.data(), NumJoints, 3);
}

std::vector<Eigen::Matrix4d> jointWorldTransforms(const Points& jointPositions,
                                                  const BodyPose& pose)
{
  // Each joint: its parent's transform times its local rotation about the joint.
  const auto& parents = jointParents();
  std::vector<Eigen::Matrix4d> world(NumJoints);
  for (int j = 0; j < NumJoints; ++j)
  {
    Eigen::Matrix4d local = Eigen::Matrix4d::Identity();
    local.topLeftCorner<3, 3>() = axisAngleToMatrix(pose.rotations.row(j).transpose());
    const Vec3 joint = jointPositions.row(j).transpose();
    const int p = parents[j];
    local.topRightCorner<3, 1>() =
        p < 0 ? Vec3(joint + pose.translation) : Vec3(joint - jointPositions.row(p).transpose());
    world[j] = p < 0 ? local : Eigen::Matrix4d(world[p] * local);
  }
  return world;
}

Points skinPoints(const Points& points, const Eigen::MatrixXd& weights,
                  const Points& jointPositions, const std::vector<Eigen::Matrix4d>& world)
{
  std::vector<Eigen::Matrix<double, 3, 4>> skinning(NumJoints);
  for (int j = 0; j < NumJoints; ++j)
  {
    Eigen::Matrix4d toJoint = Eigen::Matrix4d::Identity();
    toJoint.topRightCorner<3, 1>() = -jointPositions.row(j).transpose();
    skinning[j] = (world[j] * toJoint).topRows<3>();
  }
  Points out(points.rows(), 3);
  for (Eigen::Index i = 0; i < points.rows(); ++i)
  {
    Eigen::Matrix<double, 3, 4> blended = Eigen::Matrix<double, 3, 4>::Zero();
    for (int j = 0; j < NumJoints; ++j)
      if (weights(i, j) != 0.0) blended += weights(i, j) * skinning[j];
    out.row(i) = (blended.leftCols<3>() * points.row(i).transpose() + blended.col(3)).transpose();
  }
  return out;
}

Points BodyModel::pose(const Points& vertices, const Points& jointPositions,
                       const BodyPose& bodyPose,
                       std::vector<Eigen::Matrix4d>* jointTransforms) const
{
  const std::vector<Eigen::Matrix4d> world = jointWorldTransforms(jointPositions, bodyPose);
  Points out =
      vertices.rows() > 0 ? skinPoints(vertices, weights, jointPositions, world) : Points(0, 3);
  if (jointTransforms) *jointTransforms = world;
  return out;
}

TriangleMesh BodyModel::posed(const Eigen::VectorXd& beta, const BodyPose& bodyPose,
                              Points* posedJoints) const
{
  Points v, j;
  shape(beta, v, j);
  TriangleMesh out;
  std::vector<Eigen::Matrix4d> world;
  out.V = pose(v, j, bodyPose, &world);
  out.F = mesh.F;
  if (posedJoints)
  {
    posedJoints->resize(NumJoints, 3);
    for (int k = 0; k < NumJoints; ++k)
      posedJoints->row(k) = world[k].topRightCorner<3, 1>().transpose();
  }
  return out;
}

Points BodyModel::posedJoints(const Eigen::VectorXd& beta, const BodyPose& bodyPose) const
{
  Points v, j;
  shape(beta, v, j);
  std::vector<Eigen::Matrix4d> world;
  pose(Points(0, 3), j, bodyPose, &world);
  Points out(NumJoints, 3);
  for (int k = 0; k < NumJoints; ++k) out.row(k) = world[k].topRightCorner<3, 1>().transpose();
  return out;
}

BodyPose BodyModel::grounded(const Eigen::VectorXd& beta, const BodyPose& bodyPose) const
{
  BodyPose out = bodyPose;
  const TriangleMesh body = posed(beta, bodyPose);
  out.translation.y() -= body.V.col(1).minCoeff();
  return out;
}

double restPoseDistance(const BodyPose& pose)
{
  double sum = 0.0;
  for (int j = 0; j < NumJoints; ++j)
    if (j != Pelvis) sum += pose.rotations.row(j).norm();
  return sum;
}

int BodyModel::landmarkIndex(const std::string& name) const
{
  for (size_t i = 0; i < landmarks.size(); ++i)
    if (landmarks[i].name == name) return static_cast<int>(i);
  return -1;
}
} // namespace clothtrack
