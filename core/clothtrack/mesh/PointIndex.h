#pragma once
// Exact nearest-neighbour search over a 3D point set (FLANN single KD-tree). FLANN stays in
// the .cpp so that its heavy headers are compiled once.
#include "TriangleMesh.h"

#include <memory>
#include <vector>

namespace clothtrack
{
struct Neighbour
{
  int index;
  double distance;
};

class PointIndex
{
public:
  explicit PointIndex(const Points& points);
  ~PointIndex();
  PointIndex(const PointIndex&) = delete;
  PointIndex& operator=(const PointIndex&) = delete;

  int size() const;
  /// Nearest point; index -1 on an empty set. Safe to call from several threads.
  Neighbour nearest(const Vec3& query) const;
  /// The k nearest points, nearest first.
  std::vector<Neighbour> nearest(const Vec3& query, int k) const;
  /// All points within `radius`, nearest first.
  std::vector<Neighbour> withinRadius(const Vec3& query, double radius) const;

private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};
} // namespace clothtrack
