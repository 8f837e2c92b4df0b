#include "hair/sim/guide_selection.h"

#include <algorithm>
#include <limits>
#include <numeric>
#include <stdexcept>
#include <string>

namespace hair {
namespace {

using Vec3 = Eigen::Vector3d;

/// Guides per cluster: proportional to the candidates, by largest remainders, at least
/// one for every cluster with candidates while guides last.
std::vector<int32_t> allocate_guides(const std::vector<int64_t>& candidates, int guide_count) {
  size_t clusters = candidates.size();
  std::vector<int32_t> guides(clusters, 0);
  int64_t total = std::accumulate(candidates.begin(), candidates.end(), int64_t{0});
  if (total == 0 || guide_count <= 0) return guides;
  int64_t budget = std::min<int64_t>(guide_count, total);
  // One each first, the largest clusters first, while there are guides to give.
  std::vector<size_t> order(clusters);
  std::iota(order.begin(), order.end(), size_t{0});
  std::stable_sort(order.begin(), order.end(),
                   [&](size_t a, size_t b) { return candidates[a] > candidates[b]; });
  int64_t given = 0;
  for (size_t c : order) {
    if (candidates[c] > 0 && given < budget) {
      guides[c] = 1;
      ++given;
    }
  }
  // The rest in proportion, by largest remainders of the ideal shares.
  std::vector<double> remainder(clusters, -1);
  for (size_t c = 0; c < clusters; ++c) {
    if (candidates[c] == 0) continue;
    double ideal = static_cast<double>(budget) * static_cast<double>(candidates[c]) /
                   static_cast<double>(total);
    auto whole = static_cast<int32_t>(std::min<double>(ideal, static_cast<double>(candidates[c])));
    if (whole > guides[c]) {
      given += whole - guides[c];
      guides[c] = whole;
    }
    remainder[c] = ideal - whole;
  }
  while (given > budget) {  // the minimum of one overshot: take back from the largest
    size_t largest =
        static_cast<size_t>(std::max_element(guides.begin(), guides.end()) - guides.begin());
    --guides[largest];
    --given;
  }
  std::stable_sort(order.begin(), order.end(),
                   [&](size_t a, size_t b) { return remainder[a] > remainder[b]; });
  while (given < budget) {
    bool any = false;
    for (size_t c : order) {
      if (given == budget) break;
      if (guides[c] < candidates[c]) {
        ++guides[c];
        ++given;
        any = true;
      }
    }
    if (!any) break;
  }
  return guides;
}

}  // namespace

std::vector<int64_t> farthest_point_sample(const std::vector<Vec3>& points, int64_t count) {
  auto n = static_cast<int64_t>(points.size());
  count = std::min(count, n);
  std::vector<int64_t> taken;
  if (count <= 0) return taken;
  Vec3 centroid = Vec3::Zero();
  for (const Vec3& p : points) centroid += p;
  centroid /= static_cast<double>(n);
  std::vector<double> distance(static_cast<size_t>(n));
  for (int64_t i = 0; i < n; ++i)
    distance[static_cast<size_t>(i)] = (points[static_cast<size_t>(i)] - centroid).squaredNorm();
  int64_t next = std::min_element(distance.begin(), distance.end()) - distance.begin();
  std::fill(distance.begin(), distance.end(), std::numeric_limits<double>::infinity());
  while (static_cast<int64_t>(taken.size()) < count) {
    taken.push_back(next);
    const Vec3& chosen = points[static_cast<size_t>(next)];
    int64_t farthest = -1;
    double farthest_distance = -1;
    for (int64_t i = 0; i < n; ++i) {
      auto k = static_cast<size_t>(i);
      distance[k] = std::min(distance[k], (points[k] - chosen).squaredNorm());
      if (distance[k] > farthest_distance) {
        farthest_distance = distance[k];
        farthest = i;
      }
    }
    next = farthest;
  }
  return taken;
}

GuidePlan plan_guides(const StrandSet& strands, const std::vector<int8_t>& cluster_style,
                      int guide_count) {
  const auto& point_cluster =
      std::get<std::vector<int32_t>>(strands.point_attributes.at("cluster"));
  const size_t cluster_count = cluster_style.size();
  auto style_of = [&](int32_t cluster) {
    if (cluster < 0 || static_cast<size_t>(cluster) >= cluster_count)
      throw std::out_of_range("a grown point names cluster " + std::to_string(cluster) + " of " +
                              std::to_string(cluster_count));
    return cluster_style[static_cast<size_t>(cluster)];
  };
  auto held_by_head = [&](int64_t row) {
    return style_of(point_cluster[static_cast<size_t>(row)]) ==
           static_cast<int8_t>(HairStyle::fixed);
  };

  GuidePlan plan;
  plan.cluster_candidates.assign(cluster_count, 0);
  plan.cluster_guides.assign(cluster_count, 0);
  std::vector<std::vector<GuideStrand>> candidates(cluster_count);
  std::vector<int32_t> wisp_of_cluster(cluster_count, -1);
  for (size_t c = 0; c < cluster_count; ++c) {
    if (cluster_style[c] == static_cast<int8_t>(HairStyle::braided)) {
      wisp_of_cluster[c] = static_cast<int32_t>(plan.wisps.size());
      plan.wisps.emplace_back().cluster = static_cast<int32_t>(c);
    }
  }

  for (int64_t s = 0; s < strands.strand_count(); ++s) {
    int64_t begin = strands.offsets[static_cast<size_t>(s)],
            end = strands.offsets[static_cast<size_t>(s) + 1];
    if (end - begin < 2) continue;
    bool simulated_before = false;  // a guide of an earlier run simulates the rest
    std::vector<uint8_t> seen(cluster_count, 0);
    for (int64_t row = begin; row < end;) {
      int32_t cluster = point_cluster[static_cast<size_t>(row)];
      int64_t run_end = row;
      while (run_end < end && point_cluster[static_cast<size_t>(run_end)] == cluster) ++run_end;
      auto c = static_cast<size_t>(cluster);
      int8_t style = style_of(cluster);
      bool first_run = !seen[c];
      seen[c] = 1;
      bool held = row == begin || held_by_head(row - 1);
      if (first_run && style == static_cast<int8_t>(HairStyle::braided)) {
        WispPlan& wisp = plan.wisps[static_cast<size_t>(wisp_of_cluster[c])];
        if (run_end - row >= 2) {
          wisp.member_strand.push_back(s);
          wisp.member_first_point.push_back(row - begin);
          wisp.member_end_point.push_back(run_end - begin);
          wisp.anchor_m.push_back(point_of(strands.points, row == begin ? row : row - 1));
          if (!held) ++wisp.loose_anchor_count;
        }
        simulated_before = true;
      } else if (first_run && !simulated_before &&
                 (style == static_cast<int8_t>(HairStyle::normal) ||
                  style == static_cast<int8_t>(HairStyle::short_hair)) &&
                 held) {
        GuideStrand guide;
        guide.strand = s;
        guide.anchor_point = row == begin ? 0 : row - 1 - begin;
        guide.cluster = cluster;
        guide.style = static_cast<HairStyle>(style);
        candidates[c].push_back(guide);
        simulated_before = true;
      } else if (style != static_cast<int8_t>(HairStyle::fixed)) {
        simulated_before = true;
      }
      row = run_end;
    }
  }

  for (size_t c = 0; c < cluster_count; ++c)
    plan.cluster_candidates[c] = static_cast<int64_t>(candidates[c].size());
  for (const WispPlan& wisp : plan.wisps)
    plan.cluster_candidates[static_cast<size_t>(wisp.cluster)] =
        static_cast<int64_t>(wisp.member_strand.size());
  std::vector<int64_t> strand_candidates(cluster_count);
  for (size_t c = 0; c < cluster_count; ++c)
    strand_candidates[c] = static_cast<int64_t>(candidates[c].size());
  plan.cluster_guides = allocate_guides(strand_candidates, guide_count);
  for (size_t c = 0; c < cluster_count; ++c) {
    if (plan.cluster_guides[c] == 0) continue;
    std::vector<Vec3> anchors;
    for (const GuideStrand& guide : candidates[c])
      anchors.push_back(point_of(
          strands.points, strands.offsets[static_cast<size_t>(guide.strand)] + guide.anchor_point));
    for (int64_t k : farthest_point_sample(anchors, plan.cluster_guides[c]))
      plan.guides.push_back(candidates[c][static_cast<size_t>(k)]);
  }
  for (const WispPlan& wisp : plan.wisps)
    if (!wisp.member_strand.empty()) plan.cluster_guides[static_cast<size_t>(wisp.cluster)] = 1;
  // Drop wisps without members (a braided cluster no strand ran through).
  std::erase_if(plan.wisps, [](const WispPlan& wisp) { return wisp.member_strand.empty(); });
  return plan;
}

}  // namespace hair
