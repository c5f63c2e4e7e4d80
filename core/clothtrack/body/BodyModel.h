#pragma once
// A statistical body model M(beta, theta): a mean mesh in rest pose, a linear shape space
// (vertex and joint displacements per standard deviation, so beta ~ N(0, I) gives plausible
// bodies), a skeleton posed by linear blend skinning, and oriented anatomical landmarks.
#include "Skeleton.h"

#include <string>
#include <vector>

namespace clothtrack
{
/// An oriented point on the body: a vertex and a nearby vertex giving a tangent direction.
struct OrientedLandmark
{
  std::string name;
  int vertex = -1;
  int directionVertex = -1;
};

/// Joint rotations: one axis-angle vector (radians) per joint, relative to the rest pose and
/// expressed in world axes at rest; plus a global translation.
struct BodyPose
{
  Eigen::Matrix<double, NumJoints, 3> rotations = Eigen::Matrix<double, NumJoints, 3>::Zero();
  Vec3 translation = Vec3::Zero();
};

struct BodyModel
{
  TriangleMesh mesh;                 ///< mean body, rest pose
  Points joints;                     ///< mean joint positions, NumJoints x 3
  Eigen::MatrixXd vertexBasis;       ///< 3n x K: displacement of (x0,y0,z0,x1,...) per unit beta_k
  Eigen::MatrixXd jointBasis;        ///< 3J x K
  Eigen::VectorXd explainedVariance; ///< fraction of the population variance per component
  Eigen::MatrixXd weights;           ///< n x NumJoints skinning weights (rows sum to 1)
  std::vector<OrientedLandmark> landmarks;

  int numVertices() const { return mesh.numVertices(); }
  int numShapeComponents() const { return static_cast<int>(vertexBasis.cols()); }

  /// Rest-pose vertices and joints of shape beta (missing entries are 0, extra ones ignored).
  void shape(const Eigen::VectorXd& beta, Points& vertices, Points& jointPositions) const;

  /// Linear blend skinning of rest-pose vertices with their joints. `jointTransforms`
  /// (optional) receives each joint's world transform (rotation and position after posing).
  Points pose(const Points& vertices, const Points& jointPositions, const BodyPose& pose,
              std::vector<Eigen::Matrix4d>* jointTransforms = nullptr) const;

  /// The posed mesh of shape beta.
  TriangleMesh posed(const Eigen::VectorXd& beta, const BodyPose& pose,
                     Points* posedJoints = nullptr) const;

  /// Joint positions of shape beta in `pose` (cheap: no skinning).
  Points posedJoints(const Eigen::VectorXd& beta, const BodyPose& pose) const;

  /// `pose` with its vertical translation adjusted so that the lowest vertex of the posed body
  /// touches the floor (y = 0).
  BodyPose grounded(const Eigen::VectorXd& beta, const BodyPose& pose) const;

  /// Index of a landmark by name, -1 if absent.
  int landmarkIndex(const std::string& name) const;
};

/// World transform of every joint for `pose` (joints given in rest pose).
std::vector<Eigen::Matrix4d> jointWorldTransforms(const Points& jointPositions,
                                                  const BodyPose& pose);

/// Linear blend skinning of rest-pose points with per-point weights (rows x NumJoints).
Points skinPoints(const Points& points, const Eigen::MatrixXd& weights,
                  const Points& jointPositions,
                  const std::vector<Eigen::Matrix4d>& worldTransforms);

/// How far a pose is from the model's rest pose: the sum of the rotation angles (radians) of the
/// joints below the root. The root rotation and the translation move the body without bending
/// it, so they do not count.
double restPoseDistance(const BodyPose& pose);

/// Rodrigues: rotation matrix of an axis-angle vector.
Eigen::Matrix3d axisAngleToMatrix(const Vec3& axisAngle);
} // namespace clothtrack
