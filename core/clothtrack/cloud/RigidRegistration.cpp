#include "RigidRegistration.h"

#include "PclConversion.h"

#include <clothtrack/base/Error.h>

#include <pcl/filters/voxel_grid.h>
#include <pcl/kdtree/kdtree_flann.h>
#include <pcl/registration/gicp.h>

#include <string>

namespace clothtrack
{
namespace
{
using Cloud = pcl::PointCloud<pcl::PointXYZ>;

Cloud::Ptr thinned(const Points& points, double voxelSize, const char* which)
{
  Cloud::Ptr all = toPclXYZ(points);
  auto out = pcl::make_shared<Cloud>();
  if (voxelSize > 0)
  {
    pcl::VoxelGrid<pcl::PointXYZ> grid;
    grid.setInputCloud(all);
    const float leaf = static_cast<float>(voxelSize);
    grid.setLeafSize(leaf, leaf, leaf);
    grid.filter(*out);
  }
  else
    out = all;
  if (out->size() < 10)
    throw Error(std::string("rigid registration: the ") + which + " has " +
                std::to_string(out->size()) + " points after thinning (at least 10 needed)");
  return out;
}

/// Share of `moved` within `distance` of `target`.
double overlap(const Cloud& moved, const Cloud::Ptr& target, double distance)
{
  pcl::KdTreeFLANN<pcl::PointXYZ> tree;
  tree.setInputCloud(target);
  std::vector<int> index(1);
  std::vector<float> squared(1);
  size_t near = 0;
  for (const pcl::PointXYZ& p : moved)
    if (tree.nearestKSearch(p, 1, index, squared) == 1 && squared[0] <= distance * distance) ++near;
  return moved.empty() ? 0.0 : static_cast<double>(near) / moved.size();
}
} // namespace

RigidRegistration registerRigidly(const Points& source, const Points& target,
                                  const RigidRegistrationOptions& options)
{
  const Cloud::Ptr from = thinned(source, options.voxelSize, "source");
  const Cloud::Ptr to = thinned(target, options.voxelSize, "target");
  pcl::GeneralizedIterativeClosestPoint<pcl::PointXYZ, pcl::PointXYZ> gicp;
  gicp.setInputSource(from);
  gicp.setInputTarget(to);
  gicp.setMaxCorrespondenceDistance(options.maximumDistance);
  gicp.setMaximumIterations(options.maximumIterations);
  gicp.setTransformationEpsilon(1e-8);
  Cloud moved;
  gicp.align(moved);
  RigidRegistration out;
  out.converged = gicp.hasConverged();
  out.motion.matrix() = gicp.getFinalTransformation().cast<double>();
  out.overlap = overlap(moved, to, options.inlierDistance);
  return out;
}
} // namespace clothtrack
