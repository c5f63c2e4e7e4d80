#include "PointIndex.h"

#include <flann/flann.hpp>

#include <cmath>

namespace clothtrack
{
struct PointIndex::Impl
{
  Points points;
  std::unique_ptr<flann::Index<flann::L2_Simple<double>>> index;
};

PointIndex::PointIndex(const Points& points) : impl_(std::make_unique<Impl>())
{
  impl_->points = points;
  if (points.rows() == 0) return;
  flann::Matrix<double> data(impl_->points.data(), static_cast<size_t>(points.rows()), 3);
  impl_->index = std::make_unique<flann::Index<flann::L2_Simple<double>>>(
      data, flann::KDTreeSingleIndexParams(10));
  impl_->index->buildIndex();
}

PointIndex::~PointIndex() = default;

int PointIndex::size() const
{
  return static_cast<int>(impl_->points.rows());
}

Neighbour PointIndex::nearest(const Vec3& query) const
{
  const auto result = nearest(query, 1);
  return result.empty() ? Neighbour{-1, 0.0} : result.front();
}

std::vector<Neighbour> PointIndex::nearest(const Vec3& query, int k) const
{
  k = std::min(k, size());
  if (k <= 0) return {};
  double q[3] = {query[0], query[1], query[2]};
  std::vector<size_t> ids(k);
  std::vector<double> d2(k);
  flann::Matrix<double> queryMat(q, 1, 3);
  flann::Matrix<size_t> idMat(ids.data(), 1, k);
  flann::Matrix<double> distMat(d2.data(), 1, k);
  impl_->index->knnSearch(queryMat, idMat, distMat, k,
                          flann::SearchParams(flann::FLANN_CHECKS_UNLIMITED, 0, true));
  std::vector<Neighbour> out(k);
  for (int i = 0; i < k; ++i) out[i] = {static_cast<int>(ids[i]), std::sqrt(d2[i])};
  return out;
}

std::vector<Neighbour> PointIndex::withinRadius(const Vec3& query, double radius) const
{
  if (size() == 0 || !(radius >= 0)) return {};
  double q[3] = {query[0], query[1], query[2]};
  flann::Matrix<double> queryMat(q, 1, 3);
  std::vector<std::vector<size_t>> ids;
  std::vector<std::vector<double>> d2;
  flann::SearchParams params(flann::FLANN_CHECKS_UNLIMITED, 0, true);
  impl_->index->radiusSearch(queryMat, ids, d2, static_cast<float>(radius * radius), params);
  std::vector<Neighbour> out(ids[0].size());
  for (size_t i = 0; i < out.size(); ++i)
    out[i] = {static_cast<int>(ids[0][i]), std::sqrt(d2[0][i])};
  return out;
}
} // namespace clothtrack
