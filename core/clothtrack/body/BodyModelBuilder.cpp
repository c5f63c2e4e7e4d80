#include "BodyModelBuilder.h"

#include <clothtrack/base/Error.h>
#include <clothtrack/mesh/MeshTopology.h>
#include <clothtrack/mesh/PointIndex.h>

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <numeric>

namespace clothtrack
{
namespace
{
double segmentDistance(const Vec3& p, const Vec3& a, const Vec3& b)
{
  const Vec3 ab = b - a;
  const double t = std::clamp((p - a).dot(ab) / std::max(ab.squaredNorm(), 1e-12), 0.0, 1.0);
  return (p - (a + t * ab)).norm();
}

// Typical radius of the body around each bone, as a fraction of stature: distances to bones are
// compared relative to it, so that a thick torso and a thin forearm compete fairly.
double boneRadius(int j)
{
  switch (j)
  {
  case Pelvis:
  case Spine1:
  case Spine2:
  case Spine3:
    return 0.085;
  case Neck:
    return 0.035;
  case Head:
    return 0.060;
  case LeftClavicle:
  case RightClavicle:
    return 0.040;
  case LeftShoulder:
  case RightShoulder:
    return 0.030;
  case LeftElbow:
  case RightElbow:
    return 0.021;
  case LeftWrist:
  case RightWrist:
    return 0.020;
  case LeftHip:
  case RightHip:
    return 0.048;
  case LeftKnee:
  case RightKnee:
    return 0.028;
  case LeftAnkle:
  case RightAnkle:
    return 0.024;
  default:
    return 0.018; // toes
  }
}

bool isLeft(int j)
{
  return (j >= LeftClavicle && j <= LeftWrist) || (j >= LeftHip && j <= LeftToe);
}
} // namespace

Eigen::MatrixXd computeSkinningWeights(const TriangleMesh& mesh, const SkeletonGeometry& s,
                                       double H, int steps)
{
  const int n = mesh.numVertices();
  Eigen::MatrixXd w = Eigen::MatrixXd::Zero(n, NumJoints);
  for (int i = 0; i < n; ++i)
  {
    const Vec3 p = mesh.vertex(i);
    int best = 0;
    double bestScore = 1e300;
    for (int j = 0; j < NumJoints; ++j)
    {
      // A vertex never belongs to a limb of the other side.
      if (j != Pelvis && j > Spine3 && j != Neck && j != Head && std::abs(p.x()) > 0.02 * H &&
          (p.x() > 0) != isLeft(j))
        continue;
      const double d =
          segmentDistance(p, s.joints.row(j).transpose(), s.boneEnds.row(j).transpose());
      const double score = d / (boneRadius(j) * H);
      if (score < bestScore)
      {
        bestScore = score;
        best = j;
      }
    }
    w(i, best) = 1.0;
  }
  // Diffuse along the surface: averaging over 1-ring neighbours.
  const MeshTopology topo = buildTopology(mesh);
  Eigen::MatrixXd next(n, NumJoints);
  for (int step = 0; step < steps; ++step)
  {
    for (int i = 0; i < n; ++i)
    {
      Eigen::RowVectorXd sum = w.row(i);
      for (const int* k = topo.vertexVertices.begin(i); k != topo.vertexVertices.end(i); ++k)
        sum += w.row(*k);
      next.row(i) = sum / (1 + topo.vertexVertices.degree(i));
    }
    w.swap(next);
  }
  // Keep the four largest influences per vertex.
  for (int i = 0; i < n; ++i)
  {
    std::array<int, NumJoints> order;
    std::iota(order.begin(), order.end(), 0);
    std::partial_sort(order.begin(), order.begin() + 4, order.end(),
                      [&](int a, int b) { return w(i, a) > w(i, b); });
    Eigen::RowVectorXd kept = Eigen::RowVectorXd::Zero(NumJoints);
    for (int k = 0; k < 4; ++k)
      if (w(i, order[k]) > 1e-3) kept[order[k]] = w(i, order[k]);
    w.row(i) = kept / kept.sum();
  }
  return w;
}

void deformTemplate(const TriangleMesh& mesh, const SkeletonGeometry& s,
                    const Eigen::MatrixXd& weights, const BodyParameters& b, Points& vertices,
                    Points& joints)
{
  // Joints: each offset from the parent is scaled by the length factors of that link.
  const auto& parents = jointParents();
  auto linkScale = [&](int child) -> Eigen::Vector3d
  {
    const int p = parents[child];
    if (p == Pelvis && child != Spine1) return {b.hipWidth, 1.0, 1.0};
    if ((p == Spine3 && child != Neck) || child == LeftShoulder || child == RightShoulder)
      return {b.shoulderWidth, 1.0, 1.0};
    if (child == Head) return {1.0, b.neckLength, 1.0};
    if (child >= Spine1 && child <= Neck) return {1.0, b.torsoLength, 1.0};
    if (child == LeftElbow || child == LeftWrist || child == RightElbow || child == RightWrist)
      return Vec3::Constant(b.armLength);
    if (child == LeftKnee || child == LeftAnkle || child == RightKnee || child == RightAnkle)
      return Vec3::Constant(b.legLength);
    return Vec3::Ones();
  };
  joints.resize(NumJoints, 3);
  joints.row(Pelvis) = s.joints.row(Pelvis);
  for (int j = 1; j < NumJoints; ++j)
    joints.row(j) =
        joints.row(parents[j]) +
        (s.joints.row(j) - s.joints.row(parents[j])).cwiseProduct(linkScale(j).transpose());

  // Per-bone linear map: along the bone its length factor, across it the girth factors
  // (lateral x and anterior z for the torso, radial for limbs).
  std::array<Eigen::Matrix3d, NumJoints> M;
  for (int j = 0; j < NumJoints; ++j)
  {
    const Vec3 axis = (s.boneEnds.row(j) - s.joints.row(j)).normalized().transpose();
    auto limb = [&](double along, double girth)
    {
      return Eigen::Matrix3d(along * axis * axis.transpose() +
                             girth * (Eigen::Matrix3d::Identity() - axis * axis.transpose()));
    };
    switch (j)
    {
    case Pelvis:
      M[j] = Vec3(b.hipGirth, b.torsoLength, b.hipGirth).asDiagonal();
      break;
    case Spine1:
      M[j] = Vec3(b.waistGirth, b.torsoLength, b.waistGirth * b.belly).asDiagonal();
      break;
    case Spine2:
      M[j] = Vec3(0.5 * (b.waistGirth + b.chestGirth), b.torsoLength,
                  0.5 * (b.waistGirth * b.belly + b.chestGirth))
                 .asDiagonal();
      break;
    case Spine3:
      M[j] = Vec3(b.chestGirth, b.torsoLength, b.chestGirth * b.bust).asDiagonal();
      break;
    case Neck:
      M[j] = limb(b.neckLength, b.neckGirth);
      break;
    case Head:
      M[j] = Eigen::Matrix3d::Identity() * b.headSize;
      break;
    case LeftShoulder:
    case RightShoulder:
      M[j] = limb(b.armLength, b.upperArmGirth);
      break;
    case LeftElbow:
    case RightElbow:
      M[j] = limb(b.armLength, b.forearmGirth);
      break;
    case LeftHip:
    case RightHip:
      M[j] = limb(b.legLength, b.thighGirth);
      break;
    case LeftKnee:
    case RightKnee:
      M[j] = limb(b.legLength, b.calfGirth);
      break;
    default:
      M[j] = Eigen::Matrix3d::Identity();
      break;
    }
  }
  vertices.resize(mesh.numVertices(), 3);
  for (int i = 0; i < mesh.numVertices(); ++i)
  {
    const Vec3 v = mesh.vertex(i);
    Vec3 out = Vec3::Zero();
    for (int j = 0; j < NumJoints; ++j)
      if (weights(i, j) != 0.0)
        out +=
            weights(i, j) * (joints.row(j).transpose() + M[j] * (v - s.joints.row(j).transpose()));
    vertices.row(i) = out.transpose();
  }
  // Stand on the floor, then scale to the stature.
  const double floor = vertices.col(1).minCoeff();
  vertices.col(1).array() -= floor;
  joints.col(1).array() -= floor;
  const double scale = b.stature / std::max(vertices.col(1).maxCoeff(), 1e-9);
  vertices *= scale;
  joints *= scale;
}

namespace
{
struct LandmarkRule
{
  std::string name;
  int joint;
  double t;     // position along the bone (0 = joint, 1 = bone end)
  Vec3 outward; // the landmark is the extreme vertex of the bone's slab in this direction
  Vec3 tangent; // orientation, projected on the tangent plane
};

std::vector<LandmarkRule> landmarkRules(const SkeletonGeometry& s)
{
  const Vec3 up = Vec3::UnitY(), front = Vec3::UnitZ(), back = -Vec3::UnitZ();
  std::vector<LandmarkRule> rules = {
      {"forehead", Head, 0.62, Vec3(0, 0.25, 1), up},
      {"chin", Head, -0.05, Vec3(0, -0.6, 1), up},
      {"head_top", Head, 1.0, up, front},
      {"head_back", Head, 0.5, back, up},
      {"neck_front", Neck, 0.4, front, up},
      {"neck_back", Neck, 0.4, back, up},
      {"sternum", Spine3, 0.2, front, up},
      {"belly", Spine1, 0.1, front, up},
      {"back_upper", Spine3, 0.2, back, up},
      {"back_lower", Spine1, 0.2, back, up},
  };
  for (int side : {+1, -1})
  {
    const bool left = side > 0;
    const std::string p = left ? "left_" : "right_";
    auto J = [&](int l, int r) { return left ? l : r; };
    const Vec3 arm =
        (s.joints.row(J(LeftWrist, RightWrist)) - s.joints.row(J(LeftShoulder, RightShoulder)))
            .normalized()
            .transpose();
    const Vec3 armOut =
        Vec3(side * std::abs(arm.y()), std::abs(arm.x()), 0).normalized(); // up-out, across the arm
    auto add = [&](const std::string& n, int joint, double t, const Vec3& out, const Vec3& tan) {
      rules.push_back({p + n, joint, t, out, tan});
    };
    add("shoulder", J(LeftShoulder, RightShoulder), 0.0, Vec3(side * 0.4, 1, 0), front);
    add("upper_arm", J(LeftShoulder, RightShoulder), 0.5, back, arm);
    add("elbow", J(LeftElbow, RightElbow), 0.0, back, arm);
    add("forearm", J(LeftElbow, RightElbow), 0.5, front, arm);
    add("wrist", J(LeftWrist, RightWrist), 0.0, back, arm);
    add("hand", J(LeftWrist, RightWrist), 0.5, armOut, arm);
    add("hip", J(LeftHip, RightHip), 0.05, Vec3(side, 0, 0), up);
    add("buttock", Pelvis, -0.45, Vec3(side * 0.4, 0, -1), up);
    add("thigh", J(LeftHip, RightHip), 0.5, front, up);
    add("knee", J(LeftKnee, RightKnee), 0.0, front, up);
    add("shin", J(LeftKnee, RightKnee), 0.5, front, up);
    add("calf", J(LeftKnee, RightKnee), 0.3, back, up);
    add("ankle", J(LeftAnkle, RightAnkle), 0.0, Vec3(side, 0, 0), front);
    add("heel", J(LeftAnkle, RightAnkle), -0.25, Vec3(0, -0.3, -1), up);
    add("toe", J(LeftToe, RightToe), 1.0, front, Vec3(side, 0, 0));
  }
  return rules;
}
} // namespace

std::vector<OrientedLandmark> findLandmarks(const TriangleMesh& mesh, const SkeletonGeometry& s,
                                            double stature)
{
  const Points normals = vertexNormals(mesh);
  const PointIndex index(mesh.V);
  std::vector<OrientedLandmark> out;
  for (const LandmarkRule& rule : landmarkRules(s))
  {
    const Vec3 a = s.joints.row(rule.joint).transpose(), b = s.boneEnds.row(rule.joint).transpose();
    const Vec3 axis = (b - a).normalized();
    const Vec3 c = a + rule.t * (b - a);
    const Vec3 outward = rule.outward.normalized();
    // Candidates: vertices close to the bone's axis (within about twice the body's radius there)
    // and, for points within the bone, in a thin slab across it at c; the landmark is the most
    // outward of them.
    const double radius = 2.2 * boneRadius(rule.joint) * stature;
    const bool withinBone = rule.t >= 0 && rule.t <= 1;
    int best = -1;
    double bestValue = -1e300;
    for (int i = 0; i < mesh.numVertices(); ++i)
    {
      const Vec3 d = mesh.vertex(i) - c;
      const double axial = d.dot(axis);
      if ((d - axial * axis).norm() > radius || (withinBone && std::abs(axial) > 0.012 * stature))
        continue;
      const double value = d.dot(outward) - 0.5 * std::abs(axial);
      if (value > bestValue)
      {
        bestValue = value;
        best = i;
      }
    }
    if (best < 0) throw Error("body model: no vertex found for landmark " + rule.name);
    const Vec3 n = normals.row(best).transpose();
    Vec3 tangent = rule.tangent - rule.tangent.dot(n) * n;
    tangent = tangent.norm() > 1e-9 ? tangent.normalized() : n.unitOrthogonal();
    // The direction vertex: the nearest vertex to a point 3 cm along the tangent.
    const Vec3 target = mesh.vertex(best) + 0.03 * tangent;
    int direction = index.nearest(target).index;
    if (direction == best) direction = index.nearest(target, 2)[1].index;
    out.push_back({rule.name, best, direction});
  }
  return out;
}

void learnShapeSpace(Eigen::MatrixXd X, const Triangles& faces, int numComponents, BodyModel& model)
{
  const int N = static_cast<int>(X.rows());
  const int n = static_cast<int>((X.cols() - 3 * NumJoints) / 3);
  if (N < 2 || n <= 0) throw Error("shape space: need at least two bodies with vertices");
  const Eigen::RowVectorXd mean = X.colwise().mean();
  X.rowwise() -= mean;
  // PCA through the N x N Gram matrix (N << dimensions).
  const Eigen::MatrixXd gram = X * X.transpose();
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(gram);
  const Eigen::VectorXd lambda = eig.eigenvalues().reverse();
  const Eigen::MatrixXd vecs = eig.eigenvectors().rowwise().reverse();
  const int K = std::min(numComponents, N - 1);
  Eigen::MatrixXd basis(X.cols(), K);
  for (int k = 0; k < K; ++k)
  {
    const double l = std::max(lambda[k], 0.0);
    const Eigen::VectorXd direction = X.transpose() * vecs.col(k) / std::sqrt(std::max(l, 1e-300));
    basis.col(k) = direction * std::sqrt(l / (N - 1)); // one standard deviation
  }
  model.explainedVariance = lambda.head(K) / std::max(lambda.sum(), 1e-300);
  model.mesh.F = faces;
  model.mesh.V = Eigen::Map<const Points>(mean.data(), n, 3);
  model.joints = Eigen::Map<const Points>(mean.data() + 3 * n, NumJoints, 3);
  model.vertexBasis = basis.topRows(3 * n);
  model.jointBasis = basis.bottomRows(3 * NumJoints);
}

BodyModel buildBodyModel(const TriangleMesh& templateMesh, const SkeletonGeometry& skeleton,
                         double stature, const BodyModelBuildOptions& options)
{
  BodyModel model;
  model.weights =
      computeSkinningWeights(templateMesh, skeleton, stature, options.weightSmoothingSteps);

  const int n = templateMesh.numVertices();
  const int dims = 3 * n + 3 * NumJoints;
  const int N = options.populationSize;
  Eigen::MatrixXd X(N, dims);
  std::mt19937 rng(options.seed);
  Points v, j;
  for (int k = 0; k < N; ++k)
  {
    deformTemplate(templateMesh, skeleton, model.weights, sampleBodyParameters(rng, options.spread),
                   v, j);
    X.row(k).head(3 * n) = Eigen::Map<const Eigen::RowVectorXd>(v.data(), 3 * n);
    X.row(k).tail(3 * NumJoints) = Eigen::Map<const Eigen::RowVectorXd>(j.data(), 3 * NumJoints);
  }
  learnShapeSpace(std::move(X), templateMesh.F, options.numComponents, model);

  // Landmarks are found on the template's own skeleton, then carried by vertex index.
  model.landmarks = findLandmarks(templateMesh, skeleton, stature);
  return model;
}
} // namespace clothtrack
