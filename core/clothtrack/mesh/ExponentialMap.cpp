#include "ExponentialMap.h"

#include "Geodesic.h"
#include "MeshTopology.h"
#include <clothtrack/base/Error.h>

#include <cmath>
#include <limits>
#include <string>

namespace clothtrack
{
namespace
{
// Rotation taking unit vector a to unit vector b about their common perpendicular.
Eigen::Matrix3d minimalRotation(const Vec3& a, const Vec3& b)
{
  const Vec3 axis = a.cross(b);
  const double s = axis.norm(), c = a.dot(b);
  if (s < 1e-12)
    return c > 0 ? Eigen::Matrix3d::Identity()
                 : Eigen::Matrix3d(Eigen::AngleAxisd(M_PI, a.unitOrthogonal()));
  return Eigen::AngleAxisd(std::atan2(s, c), axis / s).toRotationMatrix();
}
} // namespace

ExponentialMapper::ExponentialMapper(const TriangleMesh& mesh)
    : mesh_(mesh), normals_(vertexNormals(mesh)), topology_(buildTopology(mesh)), geodesic_(mesh)
{
}

PolarPatch exponentialMap(const TriangleMesh& mesh, int face, const Vec3& bary,
                          const Vec3& direction, double radius)
{
  return ExponentialMapper(mesh).map(face, bary, direction, radius);
}

PolarPatch ExponentialMapper::map(int face, const Vec3& bary, const Vec3& direction,
                                  double radius) const
{
  const TriangleMesh& mesh = mesh_;
  if (face < 0 || face >= mesh.numFaces())
    throw Error("exponential map: seed face " + std::to_string(face) + " out of range");
  const Points& normals = normals_;
  const MeshTopology& topo = topology_;
  // Seed frame: the triangle's normal, x along the projected direction.
  const Vec3 a = mesh.vertex(mesh.F(face, 0)), b = mesh.vertex(mesh.F(face, 1)),
             c = mesh.vertex(mesh.F(face, 2));
  const Vec3 seed = bary[0] * a + bary[1] * b + bary[2] * c;
  Vec3 n0 = (b - a).cross(c - a);
  if (n0.norm() <= 0) throw Error("exponential map: the seed triangle is degenerate");
  n0.normalize();
  Vec3 x0 = direction - direction.dot(n0) * n0;
  if (x0.norm() < 1e-12)
    throw Error("exponential map: the seed direction is normal to the surface");
  x0.normalize();

  std::vector<int> order;
  const Eigen::VectorXd distance =
      geodesic_.distancesFromSeeds(seedsAtSurfacePoint(mesh, face, bary), radius, order);

  const int n = mesh.numVertices();
  std::vector<Eigen::Vector2d> uv(n, Eigen::Vector2d::Zero());
  std::vector<Eigen::Matrix3d> frame(n); // columns: x axis, y axis, normal
  std::vector<char> placed(n, 0);
  const Eigen::Matrix3d seedFrame = (Eigen::Matrix3d() << x0, n0.cross(x0), n0).finished();

  PolarPatch patch;
  for (int v : order)
  {
    const Vec3 p = mesh.vertex(v), nv = normals.row(v).transpose();
    Eigen::Vector2d sum = Eigen::Vector2d::Zero();
    double weights = 0;
    const Eigen::Matrix3d* bestFrame = nullptr;
    double bestLength = std::numeric_limits<double>::infinity();
    for (const int* w = topo.vertexVertices.begin(v); w != topo.vertexVertices.end(v); ++w)
    {
      if (!placed[*w]) continue;
      const Vec3 edge = p - mesh.vertex(*w);
      const double length = edge.norm();
      if (length <= 0) continue;
      // The edge as a tangent vector at the neighbour, with its length kept.
      const Eigen::Matrix3d& f = frame[*w];
      Vec3 t = edge - edge.dot(f.col(2)) * f.col(2);
      t = t.norm() > 1e-12 ? Vec3(t.normalized() * length) : Vec3::Zero();
      sum += (uv[*w] + Eigen::Vector2d(t.dot(f.col(0)), t.dot(f.col(1)))) / length;
      weights += 1 / length;
      if (length < bestLength)
      {
        bestLength = length;
        bestFrame = &f;
      }
    }
    if (weights == 0) // a vertex of the seed triangle: log map of the seed point directly
    {
      const Vec3 d = p - seed;
      const Vec3 t = d - d.dot(n0) * n0;
      const Vec3 scaled = t.norm() > 1e-12 ? Vec3(t.normalized() * d.norm()) : Vec3::Zero();
      uv[v] = Eigen::Vector2d(scaled.dot(x0), scaled.dot(n0.cross(x0)));
      frame[v] = minimalRotation(n0, nv) * seedFrame;
    }
    else
    {
      uv[v] = sum / weights;
      frame[v] = minimalRotation(bestFrame->col(2), nv) * *bestFrame;
    }
    placed[v] = 1;
    patch.vertices.push_back(v);
    patch.coordinates.push_back(uv[v]);
    patch.distances.push_back(distance[v]);
  }
  return patch;
}
} // namespace clothtrack
