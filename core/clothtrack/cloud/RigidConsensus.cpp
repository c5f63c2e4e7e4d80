#include "RigidConsensus.h"

#include <clothtrack/base/Error.h>

#include <pcl/point_cloud.h>
#include <pcl/point_types.h>
#include <pcl/sample_consensus/ransac.h>
#include <pcl/sample_consensus/sac_model_registration.h>

namespace clothtrack
{
namespace
{
pcl::PointCloud<pcl::PointXYZ>::Ptr toCloud(const std::vector<Vec3>& points)
{
  auto cloud = pcl::make_shared<pcl::PointCloud<pcl::PointXYZ>>();
  for (const Vec3& p : points)
    cloud->push_back(pcl::PointXYZ(static_cast<float>(p.x()), static_cast<float>(p.y()),
                                   static_cast<float>(p.z())));
  return cloud;
}

void requireSameLength(const std::vector<Vec3>& before, const std::vector<Vec3>& after)
{
  if (before.size() != after.size())
    throw Error("rigid consensus: " + std::to_string(before.size()) + " points before but " +
                std::to_string(after.size()) + " after");
}
} // namespace

RigidConsensus rigidConsensus(const std::vector<Vec3>& before, const std::vector<Vec3>& after,
                              double tolerance, int maximumIterations)
{
  requireSameLength(before, after);
  RigidConsensus out;
  out.inlier.assign(before.size(), false);
  if (before.size() < 3) return out;
  const auto source = toCloud(before);
  const auto target = toCloud(after);
  // Not random: the model's generator starts from a fixed seed, so runs repeat.
  auto model = pcl::make_shared<pcl::SampleConsensusModelRegistration<pcl::PointXYZ>>(
      source, /*random=*/false);
  model->setInputTarget(target);
  pcl::RandomSampleConsensus<pcl::PointXYZ> ransac(model, tolerance);
  ransac.setMaxIterations(maximumIterations);
  if (!ransac.computeModel()) return out;
  Eigen::VectorXf coefficients;
  ransac.getModelCoefficients(coefficients);
  std::vector<int> inliers;
  ransac.getInliers(inliers);
  if (inliers.size() < 3) return out;
  // Refined on all the inliers, then the inliers taken again under the refined motion.
  Eigen::VectorXf refined;
  model->optimizeModelCoefficients(inliers, coefficients, refined);
  model->selectWithinDistance(refined, tolerance, inliers);
  out.found = true;
  out.motion.matrix() =
      Eigen::Map<const Eigen::Matrix4f>(refined.data()).transpose().cast<double>();
  for (int i : inliers) out.inlier[i] = true;
  out.inliers = static_cast<int>(inliers.size());
  return out;
}

std::vector<bool> locallyRigidPairs(const std::vector<Vec3>& before, const std::vector<Vec3>& after,
                                    double radius, double tolerance, int minimumPairs)
{
  requireSameLength(before, after);
  std::vector<bool> kept(before.size(), true);
  for (size_t i = 0; i < before.size(); ++i)
  {
    std::vector<Vec3> near, nearAfter;
    size_t self = 0;
    for (size_t j = 0; j < before.size(); ++j)
      if ((before[j] - before[i]).norm() <= radius)
      {
        if (j == i) self = near.size();
        near.push_back(before[j]);
        nearAfter.push_back(after[j]);
      }
    if (static_cast<int>(near.size()) < std::max(3, minimumPairs)) continue;
    const RigidConsensus c = rigidConsensus(near, nearAfter, tolerance);
    kept[i] = !c.found || c.inlier[self];
  }
  return kept;
}
} // namespace clothtrack
