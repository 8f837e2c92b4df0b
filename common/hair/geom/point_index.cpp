#include "hair/geom/point_index.h"

#include <algorithm>
#include <nanoflann.hpp>

namespace hair {

struct PointIndex::Tree {
  struct Cloud {
    Points3f points;
    size_t kdtree_get_point_count() const { return static_cast<size_t>(points.rows()); }
    float kdtree_get_pt(size_t i, size_t dim) const {
      return points(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(dim));
    }
    template <class Box>
    bool kdtree_get_bbox(Box&) const {
      return false;
    }
  };
  using Index = nanoflann::KDTreeSingleIndexAdaptor<nanoflann::L2_Simple_Adaptor<float, Cloud>,
                                                    Cloud, 3, uint32_t>;
  Cloud cloud;
  std::unique_ptr<Index> index;
};

PointIndex::PointIndex(const Points3f& points) : tree_(std::make_unique<Tree>()) {
  tree_->cloud.points = points;
  tree_->index =
      std::make_unique<Tree::Index>(3, tree_->cloud, nanoflann::KDTreeSingleIndexAdaptorParams(10));
  tree_->index->buildIndex();
}

PointIndex::~PointIndex() = default;
PointIndex::PointIndex(PointIndex&&) noexcept = default;
PointIndex& PointIndex::operator=(PointIndex&&) noexcept = default;

int64_t PointIndex::size() const { return tree_->cloud.points.rows(); }

namespace {

/// Nearest first, ties by id: one total order, so a prefix is the same whether the rest
/// are ordered or not.
bool nearer(const std::pair<uint32_t, float>& a, const std::pair<uint32_t, float>& b) {
  return a.second < b.second || (a.second == b.second && a.first < b.first);
}

}  // namespace

std::vector<int32_t> PointIndex::within(const Eigen::Vector3f& query, float radius) const {
  std::vector<std::pair<uint32_t, float>> matches;
  nanoflann::SearchParams params;
  params.sorted = false;
  tree_->index->radiusSearch(query.data(), radius * radius, matches, params);
  std::sort(matches.begin(), matches.end(), nearer);
  std::vector<int32_t> ids;
  ids.reserve(matches.size());
  for (const auto& match : matches) ids.push_back(static_cast<int32_t>(match.first));
  return ids;
}

void PointIndex::visit_within(const Eigen::Vector3f& query, float radius,
                              const std::function<bool(int32_t)>& visit) const {
  std::vector<std::pair<uint32_t, float>> matches;
  nanoflann::SearchParams params;
  params.sorted = false;
  tree_->index->radiusSearch(query.data(), radius * radius, matches, params);
  // Batches [done, end): the nearest of those not yet visited, ordered.
  size_t done = 0;
  for (size_t batch = 16; done < matches.size(); batch *= 4) {
    const auto first = matches.begin() + static_cast<std::ptrdiff_t>(done);
    const size_t end = std::min(matches.size(), done + batch);
    const auto last = matches.begin() + static_cast<std::ptrdiff_t>(end);
    if (last != matches.end()) std::nth_element(first, last, matches.end(), nearer);
    std::sort(first, last, nearer);
    for (; done < end; ++done)
      if (!visit(static_cast<int32_t>(matches[done].first))) return;
  }
}

std::vector<int32_t> PointIndex::within_unordered(const Eigen::Vector3f& query,
                                                  float radius) const {
  std::vector<std::pair<uint32_t, float>> matches;
  nanoflann::SearchParams params;
  params.sorted = false;
  tree_->index->radiusSearch(query.data(), radius * radius, matches, params);
  std::vector<int32_t> ids;
  ids.reserve(matches.size());
  for (const auto& match : matches) ids.push_back(static_cast<int32_t>(match.first));
  return ids;
}

bool PointIndex::any_within(const Eigen::Vector3f& query, float radius) const {
  if (size() == 0) return false;
  // The nearest point's squared distance as the tree measures it, held to the radius as
  // a radius search holds it (strictly less).
  uint32_t found = 0;
  float squared = 0;
  if (tree_->index->knnSearch(query.data(), 1, &found, &squared) == 0) return false;
  return squared < radius * radius;
}

std::vector<int32_t> PointIndex::nearest(const Eigen::Vector3f& query, int count) const {
  size_t wanted =
      std::min<size_t>(static_cast<size_t>(std::max(count, 0)), static_cast<size_t>(size()));
  std::vector<uint32_t> found(wanted);
  std::vector<float> squared(wanted);
  wanted = tree_->index->knnSearch(query.data(), wanted, found.data(), squared.data());
  std::vector<std::pair<float, uint32_t>> order;
  for (size_t i = 0; i < wanted; ++i) order.push_back({squared[i], found[i]});
  std::sort(order.begin(), order.end());
  std::vector<int32_t> ids;
  for (const auto& [distance, id] : order) ids.push_back(static_cast<int32_t>(id));
  return ids;
}

}  // namespace hair
