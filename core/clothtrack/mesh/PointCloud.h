#pragma once
// A point set without faces, as depth cameras, multi-view stereo and LiDAR deliver a frame:
// positions, and per point an optional normal and colour.
#include <clothtrack/mesh/TriangleMesh.h>

#include <cstdint>

namespace clothtrack
{
using Colours = Eigen::Matrix<std::uint8_t, Eigen::Dynamic, 3, Eigen::RowMajor>;

struct PointCloud
{
  Points P;  ///< positions
  Points N;  ///< unit normals, one per point, or none (0 rows)
  Colours C; ///< RGB colours, one per point, or none (0 rows)

  int size() const { return static_cast<int>(P.rows()); }
  bool hasNormals() const { return N.rows() == P.rows() && P.rows() > 0; }
  bool hasColours() const { return C.rows() == P.rows() && P.rows() > 0; }
};

/// The cloud keeping only the points whose `keep` entry is true (normals and colours follow).
PointCloud selectPoints(const PointCloud& cloud, const std::vector<bool>& keep);
} // namespace clothtrack
