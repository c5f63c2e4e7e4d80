#include "ClothSimulator.h"

#include <clothtrack/mesh/MeshTopology.h>

#include <algorithm>
#include <cmath>

namespace clothtrack
{
ClothSimulator::ClothSimulator(const BodyModel& model, const Eigen::VectorXd& beta, Garment garment,
                               ClothOptions options)
    : model_(model), beta_(beta), garment_(std::move(garment)), options_(options)
{
  Points restVertices;
  model_.shape(beta_, restVertices, restJoints_);

  // Constraints from the rest garment: edges, and opposite vertices of adjacent triangles.
  const TriangleMesh& rest = garment_.rest;
  const MeshTopology topo = buildTopology(rest);
  for (int e = 0; e < topo.numEdges(); ++e)
  {
    const auto& edge = topo.edges[e];
    stretch_.push_back(edge);
    stretchLength_.push_back((rest.vertex(edge[0]) - rest.vertex(edge[1])).norm());
    if (topo.edgeFaces.degree(e) != 2) continue;
    int opposite[2] = {-1, -1};
    for (int k = 0; k < 2; ++k)
    {
      const int f = topo.edgeFaces.begin(e)[k];
      for (int c = 0; c < 3; ++c)
        if (rest.F(f, c) != edge[0] && rest.F(f, c) != edge[1]) opposite[k] = rest.F(f, c);
    }
    if (opposite[0] < 0 || opposite[1] < 0) continue;
    bend_.push_back({opposite[0], opposite[1]});
    bendLength_.push_back((rest.vertex(opposite[0]) - rest.vertex(opposite[1])).norm());
  }

  // Collision capsules: every bone with a body part around it, radius from its vertices.
  SkeletonGeometry skeleton{restJoints_, restJoints_}; // leaf bones: zero length
  setInnerBoneEnds(skeleton);
  boneEnds_ = skeleton.boneEnds;
  for (int j = 0; j < NumJoints; ++j)
  {
    std::vector<double> distances;
    const Vec3 a = restJoints_.row(j).transpose(), b = boneEnds_.row(j).transpose();
    for (int i = 0; i < restVertices.rows(); ++i)
    {
      int dominant;
      model_.weights.row(i).maxCoeff(&dominant);
      if (dominant != j) continue;
      const Vec3 p = restVertices.row(i).transpose();
      const Vec3 ab = b - a;
      const double t =
          ab.squaredNorm() > 0 ? std::clamp((p - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0) : 0.0;
      distances.push_back((p - (a + t * ab)).norm());
    }
    if (distances.size() < 10) continue;
    std::nth_element(distances.begin(), distances.begin() + distances.size() / 2, distances.end());
    capsules_.push_back({j, distances[distances.size() / 2]});
  }
  x_ = garment_.rest.V;
  previous_ = x_;
}

void ClothSimulator::targets(const BodyPose& pose, Points& target, Points& jointsWorld) const
{
  const std::vector<Eigen::Matrix4d> world = jointWorldTransforms(restJoints_, pose);
  target = skinPoints(garment_.rest.V, garment_.weights, restJoints_, world);
  // Both ends of every bone, posed: rows 0..J-1 joints, J..2J-1 bone ends.
  jointsWorld.resize(2 * NumJoints, 3);
  for (int j = 0; j < NumJoints; ++j)
  {
    jointsWorld.row(j) = world[j].topRightCorner<3, 1>().transpose();
    const Vec3 end =
        world[j].topLeftCorner<3, 3>() * (boneEnds_.row(j) - restJoints_.row(j)).transpose() +
        world[j].topRightCorner<3, 1>();
    jointsWorld.row(NumJoints + j) = end.transpose();
  }
}

void ClothSimulator::reset(const BodyPose& pose, int settleSteps)
{
  Points target, joints;
  targets(pose, target, joints);
  x_ = target;
  previous_ = x_;
  const double h = 1.0 / (25.0 * options_.substeps);
  for (int s = 0; s < settleSteps; ++s) substep(target, joints, h);
  previous_ = x_; // start at rest
}

void ClothSimulator::step(const BodyPose& pose, double dt)
{
  Points target, joints;
  targets(pose, target, joints);
  const double h = dt / options_.substeps;
  for (int s = 0; s < options_.substeps; ++s) substep(target, joints, h);
}

void ClothSimulator::substep(const Points& target, const Points& joints, double h)
{
  const int n = static_cast<int>(x_.rows());
  const Vec3 gravity(0, -options_.gravity * h * h, 0);
  Points predicted(n, 3);
  for (int i = 0; i < n; ++i)
  {
    if (garment_.pinned[i])
    {
      predicted.row(i) = target.row(i);
      continue;
    }
    Vec3 p = x_.row(i).transpose() + options_.damping * (x_.row(i) - previous_.row(i)).transpose() +
             gravity;
    p += 0.1 * garment_.follow[i] * (target.row(i).transpose() - p);
    predicted.row(i) = p.transpose();
  }
  auto project = [&](const std::vector<std::array<int, 2>>& pairs,
                     const std::vector<double>& lengths, double stretchK, double compressK)
  {
    for (size_t c = 0; c < pairs.size(); ++c)
    {
      const int a = pairs[c][0], b = pairs[c][1];
      const double wa = garment_.pinned[a] ? 0.0 : 1.0, wb = garment_.pinned[b] ? 0.0 : 1.0;
      if (wa + wb == 0) continue;
      const Vec3 d = (predicted.row(b) - predicted.row(a)).transpose();
      const double len = d.norm();
      if (len < 1e-12) continue;
      const double error = len - lengths[c];
      const double k = error > 0 ? stretchK : compressK;
      const Vec3 correction = k * error / (len * (wa + wb)) * d;
      predicted.row(a) += wa * correction.transpose();
      predicted.row(b) -= wb * correction.transpose();
    }
  };
  for (int it = 0; it < options_.iterations; ++it)
  {
    project(stretch_, stretchLength_, 1.0, options_.compression);
    project(bend_, bendLength_, options_.bending, options_.bending);
    // Collisions: out of every capsule, above the floor.
    for (int i = 0; i < n; ++i)
    {
      if (garment_.pinned[i]) continue;
      Vec3 p = predicted.row(i).transpose();
      for (const Capsule& capsule : capsules_)
      {
        const Vec3 a = joints.row(capsule.joint).transpose(),
                   b = joints.row(NumJoints + capsule.joint).transpose();
        const Vec3 ab = b - a;
        const double t =
            ab.squaredNorm() > 0 ? std::clamp((p - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0) : 0.0;
        const Vec3 closest = a + t * ab;
        const Vec3 away = p - closest;
        const double dist = away.norm(), minimum = capsule.radius + options_.collisionMargin;
        if (dist < minimum && dist > 1e-9) p = closest + away * (minimum / dist);
      }
      p.y() = std::max(p.y(), 0.002);
      predicted.row(i) = p.transpose();
    }
  }
  previous_ = x_;
  x_ = predicted;
}
} // namespace clothtrack
