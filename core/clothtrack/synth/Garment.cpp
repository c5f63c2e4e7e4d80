#include "Garment.h"

#include <clothtrack/base/Error.h>

#include <algorithm>
#include <cmath>

namespace clothtrack
{
GarmentType garmentFromName(const std::string& name)
{
  if (name == "dress") return GarmentType::Dress;
  if (name == "skirt") return GarmentType::Skirt;
  if (name == "trousers") return GarmentType::Trousers;
  if (name == "shirt") return GarmentType::Shirt;
  throw Error("unknown garment '" + name + "' (one of: dress, skirt, trousers, shirt)");
}

namespace
{
// Largest distance of body vertices from a vertical axis through `centre`, among vertices at
// height y (within a band) whose dominant joint is in `joints`.
double bodyRadius(const Points& v, const Eigen::MatrixXd& w, const Vec3& centre, double y,
                  const std::vector<int>& joints)
{
  double r = 0;
  for (Eigen::Index i = 0; i < v.rows(); ++i)
  {
    if (std::abs(v(i, 1) - y) > 0.02) continue;
    int dominant;
    w.row(i).maxCoeff(&dominant);
    if (std::find(joints.begin(), joints.end(), dominant) == joints.end()) continue;
    r = std::max(r, std::hypot(v(i, 0) - centre.x(), v(i, 2) - centre.z()));
  }
  return r;
}

// A tube of rings around an axis: ring r at centre(r) with radius(r); segments around.
struct Tube
{
  std::vector<Vec3> centres;
  std::vector<double> radii;
  std::vector<Vec3> axes; // ring normal (the tube direction)
};

void appendTube(const Tube& tube, int segments, Garment& g,
                const std::vector<Eigen::RowVectorXd>& ringWeights,
                const std::vector<char>& ringPinned, const std::vector<double>& ringFollow)
{
  const int base = g.rest.numVertices();
  const int rings = static_cast<int>(tube.centres.size());
  Points V(base + rings * segments, 3);
  V.topRows(base) = g.rest.V;
  Eigen::MatrixXd W(base + rings * segments, NumJoints);
  W.topRows(base) = g.weights;
  for (int r = 0; r < rings; ++r)
  {
    const Vec3 axis = tube.axes[r].normalized();
    const Vec3 u = axis.unitOrthogonal();
    const Vec3 v = axis.cross(u);
    for (int s = 0; s < segments; ++s)
    {
      const double a = 2 * M_PI * s / segments;
      V.row(base + r * segments + s) =
          (tube.centres[r] + tube.radii[r] * (std::cos(a) * u + std::sin(a) * v)).transpose();
      W.row(base + r * segments + s) = ringWeights[r];
      g.pinned.push_back(ringPinned[r]);
      g.follow.push_back(ringFollow[r]);
    }
  }
  Triangles F(g.rest.numFaces() + 2 * (rings - 1) * segments, 3);
  F.topRows(g.rest.numFaces()) = g.rest.F;
  int f = g.rest.numFaces();
  for (int r = 0; r + 1 < rings; ++r)
    for (int s = 0; s < segments; ++s)
    {
      const int a = base + r * segments + s, b = base + r * segments + (s + 1) % segments;
      const int c = a + segments, d = b + segments;
      F.row(f++) << a, c, b;
      F.row(f++) << b, c, d;
    }
  g.rest.V = V;
  g.rest.F = F;
  g.weights = W;
}

Eigen::RowVectorXd oneHot(int joint)
{
  Eigen::RowVectorXd w = Eigen::RowVectorXd::Zero(NumJoints);
  w[joint] = 1.0;
  return w;
}

Eigen::RowVectorXd blend(int a, int b, double t)
{
  return (1 - t) * oneHot(a) + t * oneHot(b);
}
} // namespace

Garment makeGarment(const BodyModel& model, const Eigen::VectorXd& beta, const GarmentOptions& o)
{
  Points v, j;
  model.shape(beta, v, j);
  const double stature = v.col(1).maxCoeff() - v.col(1).minCoeff();
  Garment g;
  g.weights.resize(0, NumJoints);
  const Vec3 pelvis = j.row(Pelvis).transpose();
  const std::vector<int> torso = {Pelvis, Spine1, Spine2, Spine3, LeftHip, RightHip};

  auto skirtTube = [&](double topY, double bottomY, bool pinTop)
  {
    const int rings = 26, segments = 72;
    const Vec3 centre(pelvis.x(), 0, pelvis.z());
    const double topR = bodyRadius(v, model.weights, centre, topY, torso) + o.ease;
    const double waistY = j(Spine1, 1);
    const double waistR =
        bodyRadius(v, model.weights, centre, std::min(topY, waistY), torso) + o.ease;
    const double hipR = bodyRadius(v, model.weights, centre, j(Pelvis, 1) - 0.05, torso) + o.ease;
    Tube tube;
    std::vector<Eigen::RowVectorXd> weights;
    std::vector<char> pinned;
    std::vector<double> follow;
    const double hipY = j(Pelvis, 1) - 0.06;
    for (int r = 0; r < rings; ++r)
    {
      const double t = static_cast<double>(r) / (rings - 1);
      const double y = topY + t * (bottomY - topY);
      double radius;
      if (y > waistY)
        radius = topR + (waistR - topR) * (topY - y) / std::max(topY - waistY, 1e-6);
      else if (y > hipY)
        radius = waistR + (hipR - waistR) * (waistY - y) / std::max(waistY - hipY, 1e-6);
      else
        radius = hipR * (1 + (o.flare - 1) * (hipY - y) / std::max(hipY - bottomY, 1e-6));
      tube.centres.push_back(Vec3(centre.x(), y, centre.z()));
      tube.radii.push_back(radius);
      tube.axes.push_back(Vec3::UnitY());
      // Above the hips the cloth fits the torso; below, it hangs from the pelvis.
      weights.push_back(y > j(Spine2, 1)
                            ? blend(Spine2, Spine3, std::min(1.0, (y - j(Spine2, 1)) / 0.08))
                        : y > waistY ? blend(Spine1, Spine2, (y - waistY) / (j(Spine2, 1) - waistY))
                        : y > hipY   ? blend(Pelvis, Spine1, (y - hipY) / (waistY - hipY))
                                     : oneHot(Pelvis));
      pinned.push_back(pinTop && r == 0);
      follow.push_back(y > hipY ? 0.5 : 0.02 * (1 - t));
    }
    appendTube(tube, segments, g, weights, pinned, follow);
  };

  switch (o.type)
  {
  case GarmentType::Dress:
    skirtTube(j(Spine3, 1) - 0.02, o.hemHeight * stature, true);
    break;
  case GarmentType::Skirt:
    skirtTube(j(Spine1, 1) - 0.01, o.hemHeight * stature, true);
    break;
  case GarmentType::Trousers:
  {
    for (int side : {LeftHip, RightHip})
    {
      const int knee = side == LeftHip ? LeftKnee : RightKnee,
                ankle = side == LeftHip ? LeftAnkle : RightAnkle;
      const std::vector<int> leg = {side, knee};
      Tube tube;
      std::vector<Eigen::RowVectorXd> weights;
      std::vector<char> pinned;
      std::vector<double> follow;
      const int rings = 24, segments = 40;
      const Vec3 top = j.row(side).transpose(),
                 bottom = j.row(ankle).transpose() + Vec3(0, 0.03, 0);
      for (int r = 0; r < rings; ++r)
      {
        const double t = static_cast<double>(r) / (rings - 1);
        const Vec3 c = top + t * (bottom - top);
        const double radius =
            bodyRadius(v, model.weights, c, c.y(), t < 0.5 ? leg : std::vector<int>{knee, ankle}) +
            o.ease + 0.015;
        tube.centres.push_back(c);
        tube.radii.push_back(std::max(radius, 0.06));
        tube.axes.push_back((bottom - top).normalized());
        const double kneeT = (j(side, 1) - j(knee, 1)) / (j(side, 1) - j(ankle, 1));
        weights.push_back(t < kneeT ? blend(side, knee, std::max(0.0, (t - kneeT + 0.1) / 0.2))
                                    : oneHot(knee));
        pinned.push_back(r == 0);
        follow.push_back(0.3);
      }
      appendTube(tube, segments, g, weights, pinned, follow);
    }
    break;
  }
  case GarmentType::Shirt:
  {
    skirtTube(j(Spine3, 1) + 0.04, j(Pelvis, 1) - 0.08, true);
    for (int side : {LeftShoulder, RightShoulder})
    {
      const int elbow = side == LeftShoulder ? LeftElbow : RightElbow;
      Tube tube;
      std::vector<Eigen::RowVectorXd> weights;
      std::vector<char> pinned;
      std::vector<double> follow;
      const Vec3 a = j.row(side).transpose(), b = j.row(elbow).transpose();
      const int rings = 10;
      for (int r = 0; r < rings; ++r)
      {
        const double t = 0.15 + 0.7 * r / (rings - 1);
        tube.centres.push_back(a + t * (b - a));
        tube.radii.push_back(0.085);
        tube.axes.push_back((b - a).normalized());
        weights.push_back(oneHot(side));
        pinned.push_back(r == 0);
        follow.push_back(0.4);
      }
      appendTube(tube, 36, g, weights, pinned, follow);
    }
    break;
  }
  }
  return g;
}
} // namespace clothtrack
