#pragma once
// Geodesic distances on triangle meshes.
//
// WavefrontGeodesic propagates a front in increasing distance order from the sources, so a
// distance limit makes it local and cheap (cost proportional to the neighbourhood reached):
//  - Dijkstra: shortest paths along edges (overestimates: zig-zag paths);
//  - FastMarching: triangle updates from a virtual point source unfolded into the plane,
//    exact on flat meshes, falling back to edge updates where the front leaves a triangle.
// HeatGeodesic (Crane et al. 2013) solves two prefactored sparse systems: every query costs
// two back-substitutions over the whole mesh, and it is the most accurate of the three.
#include "MeshTopology.h"
#include "TriangleMesh.h"

#include <limits>
#include <memory>
#include <vector>

namespace clothtrack
{
constexpr double kUnreached = std::numeric_limits<double>::infinity();

/// A source vertex with its initial distance (0 for a point source at the vertex).
struct GeodesicSeed
{
  int vertex;
  double distance = 0.0;
};

/// Seeds for a point on triangle `face` with barycentric coordinates `bary`: its three
/// vertices at their Euclidean distance from the point.
std::vector<GeodesicSeed> seedsAtSurfacePoint(const TriangleMesh& mesh, int face, const Vec3& bary);

class WavefrontGeodesic
{
public:
  enum class Method
  {
    Dijkstra,
    FastMarching
  };
  WavefrontGeodesic(const TriangleMesh& mesh, Method method = Method::FastMarching);

  /// Distance to the nearest seed; kUnreached beyond `limit` and on parts with no seed.
  Eigen::VectorXd distancesFromSeeds(const std::vector<GeodesicSeed>& seeds,
                                     double limit = kUnreached) const;
  /// The same, safe to call from several threads at once: the vertices reached, nearest
  /// first, go to `reached` instead of lastReached().
  Eigen::VectorXd distancesFromSeeds(const std::vector<GeodesicSeed>& seeds, double limit,
                                     std::vector<int>& reached) const;
  Eigen::VectorXd distances(const std::vector<int>& sources, double limit = kUnreached) const;

  /// Vertices reached by the last call, in the order they were finalised (nearest first).
  const std::vector<int>& lastReached() const { return reached_; }

private:
  double triangleUpdate(int known1, int known2, int target, const Eigen::VectorXd& d) const;

  const TriangleMesh& mesh_;
  MeshTopology topology_;
  Method method_;
  mutable std::vector<int> reached_;
};

class HeatGeodesic
{
public:
  /// Factorises the heat and Poisson systems once. timeFactor scales t = factor * h^2 with h
  /// the mean edge length (1 is the value recommended by Crane et al.).
  explicit HeatGeodesic(const TriangleMesh& mesh, double timeFactor = 1.0);
  ~HeatGeodesic();

  Eigen::VectorXd distances(const std::vector<int>& sources, double limit = kUnreached) const;

private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};
} // namespace clothtrack
