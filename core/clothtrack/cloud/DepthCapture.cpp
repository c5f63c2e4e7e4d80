#include "DepthCapture.h"

#include <clothtrack/base/Error.h>

#include <cmath>
#include <limits>
#include <random>

namespace clothtrack
{
namespace
{
/// A pinhole camera looking at a point, Y up.
struct Camera
{
  Vec3 origin;
  Eigen::Matrix3d toCamera; // rows: right, up, forward
  double focal, cx, cy;
  int width, height;

  Eigen::Vector3d project(const Vec3& p) const // (column, row, depth)
  {
    const Vec3 q = toCamera * (p - origin);
    return {cx + focal * q.x() / q.z(), cy - focal * q.y() / q.z(), q.z()};
  }
  Vec3 ray(double column, double row) const
  {
    const Vec3 d((column - cx) / focal, -(row - cy) / focal, 1.0);
    return toCamera.transpose() * d.normalized();
  }
};

Camera makeCamera(const DepthRig& rig, int k)
{
  Camera camera;
  camera.origin = cameraPosition(rig, k);
  const Vec3 forward = (rig.centre - camera.origin).normalized();
  const Vec3 right = forward.cross(Vec3::UnitY()).normalized();
  const Vec3 up = right.cross(forward);
  camera.toCamera.row(0) = right.transpose();
  camera.toCamera.row(1) = up.transpose();
  camera.toCamera.row(2) = forward.transpose();
  camera.focal = rig.focalPixels;
  camera.width = rig.width;
  camera.height = rig.height;
  camera.cx = 0.5 * rig.width;
  camera.cy = 0.5 * rig.height;
  return camera;
}

/// Distance along each pixel's ray to the nearest triangle (infinity where nothing is hit).
std::vector<double> renderDepth(const TriangleMesh& mesh, const Camera& camera)
{
  std::vector<double> depth(static_cast<size_t>(camera.width) * camera.height,
                            std::numeric_limits<double>::infinity());
  for (int f = 0; f < mesh.numFaces(); ++f)
  {
    const Vec3 a = mesh.vertex(mesh.F(f, 0)), b = mesh.vertex(mesh.F(f, 1)),
               c = mesh.vertex(mesh.F(f, 2));
    const Eigen::Vector3d pa = camera.project(a), pb = camera.project(b), pc = camera.project(c);
    if (pa.z() <= 0.05 || pb.z() <= 0.05 || pc.z() <= 0.05) continue;
    const int c0 = std::max(0, static_cast<int>(std::floor(std::min({pa.x(), pb.x(), pc.x()}))));
    const int c1 =
        std::min(camera.width - 1, static_cast<int>(std::ceil(std::max({pa.x(), pb.x(), pc.x()}))));
    const int r0 = std::max(0, static_cast<int>(std::floor(std::min({pa.y(), pb.y(), pc.y()}))));
    const int r1 = std::min(camera.height - 1,
                            static_cast<int>(std::ceil(std::max({pa.y(), pb.y(), pc.y()}))));
    const Vec3 e1 = b - a, e2 = c - a;
    for (int row = r0; row <= r1; ++row)
      for (int column = c0; column <= c1; ++column)
      {
        // Moller-Trumbore through the pixel's centre.
        const Vec3 d = camera.ray(column + 0.5, row + 0.5);
        const Vec3 pv = d.cross(e2);
        const double det = e1.dot(pv);
        if (std::abs(det) < 1e-14) continue;
        const Vec3 tv = camera.origin - a;
        const double u = tv.dot(pv) / det;
        if (u < 0 || u > 1) continue;
        const Vec3 qv = tv.cross(e1);
        const double v = d.dot(qv) / det;
        if (v < 0 || u + v > 1) continue;
        const double t = e2.dot(qv) / det;
        double& z = depth[static_cast<size_t>(row) * camera.width + column];
        if (t > 0 && t < z) z = t;
      }
  }
  return depth;
}
} // namespace

Vec3 cameraPosition(const DepthRig& rig, int k)
{
  // Offset by half a step: four cameras stand at the diagonals and see front, back and sides.
  const double angle = 2 * M_PI * (k + 0.5) / rig.cameras;
  return rig.centre +
         Vec3(rig.distance * std::sin(angle), rig.elevation, rig.distance * std::cos(angle));
}

PointCloud captureDepth(const TriangleMesh& truth, const DepthRig& rig)
{
  if (rig.cameras < 1) throw Error("a depth rig needs at least one camera");
  std::mt19937 rng(rig.seed);
  std::normal_distribution<double> gauss(0.0, 1.0);
  std::vector<Vec3> seen;
  for (int k = 0; k < rig.cameras; ++k)
  {
    const Camera camera = makeCamera(rig, k);
    const std::vector<double> depth = renderDepth(truth, camera);
    for (int row = 0; row < camera.height; ++row)
      for (int column = 0; column < camera.width; ++column)
      {
        const double t = depth[static_cast<size_t>(row) * camera.width + column];
        if (!std::isfinite(t)) continue;
        const double noisy = t + rig.noise * gauss(rng);
        seen.push_back(camera.origin + noisy * camera.ray(column + 0.5, row + 0.5));
      }
  }
  const Vec3 low = truth.V.colwise().minCoeff().transpose() - Vec3::Constant(0.25);
  const Vec3 high = truth.V.colwise().maxCoeff().transpose() + Vec3::Constant(0.25);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  const size_t strays = static_cast<size_t>(std::lround(rig.outliers * seen.size()));
  for (size_t i = 0; i < strays; ++i)
  {
    const Vec3 u(uniform(rng), uniform(rng), uniform(rng));
    seen.push_back(low + u.cwiseProduct(high - low));
  }
  PointCloud cloud;
  cloud.P.resize(static_cast<long>(seen.size()), 3);
  for (size_t i = 0; i < seen.size(); ++i) cloud.P.row(static_cast<long>(i)) = seen[i].transpose();
  return cloud;
}
} // namespace clothtrack
