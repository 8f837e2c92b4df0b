// Continuation: the index of the ends of oriented strands, and the directions it gives
// undecided regions and takes from regions decided by one cue.
#include "hair/extract/continuation.h"

#include <algorithm>
#include <cmath>
#include <cstddef>

#include "hair/extract/region_orientation.h"

namespace hair {
namespace {

/// Unit direction of the rail's first (or last) segment, from its first to its last point.
Eigen::Vector3f end_direction(const Points3f& vertices, const std::vector<int32_t>& rail,
                              bool at_last) {
  Eigen::Vector3f d = at_last ? Eigen::Vector3f(vertices.row(rail[rail.size() - 1]) -
                                                vertices.row(rail[rail.size() - 2]))
                              : Eigen::Vector3f(vertices.row(rail[1]) - vertices.row(rail[0]));
  float norm = d.norm();
  return norm > 0 ? Eigen::Vector3f(d / norm) : Eigen::Vector3f::Zero();
}

}  // namespace

StrandEndIndex::StrandEndIndex(const Points3f& vertices, const std::vector<RegionRails>& regions,
                               const std::vector<bool>& leave_out) {
  std::vector<Eigen::Vector3f> positions;
  auto add_ends = [&](std::vector<int32_t> rail, bool reverse, int32_t patch) {
    if (reverse) std::reverse(rail.begin(), rail.end());
    positions.push_back(vertices.row(rail.front()).transpose());
    ends_.push_back({true, end_direction(vertices, rail, false), patch});
    positions.push_back(vertices.row(rail.back()).transpose());
    ends_.push_back({false, end_direction(vertices, rail, true), patch});
  };
  for (const RegionRails& region : regions) {
    if (!leave_out.empty() && leave_out[static_cast<size_t>(region.patch)]) continue;
    for (const auto& rail : region.parted_rails) add_ends(rail, false, region.patch);
    if (region.decision)
      for (const auto& rail : region.open_rails)
        add_ends(rail, region.decision->reverse, region.patch);
  }
  if (ends_.empty()) return;
  Points3f end_points(static_cast<Eigen::Index>(positions.size()), 3);
  for (size_t i = 0; i < positions.size(); ++i)
    end_points.row(static_cast<Eigen::Index>(i)) = positions[i].transpose();
  index_.emplace(end_points);
}

template <typename Judge>
int StrandEndIndex::first_vote(const Eigen::Vector3f& point, int32_t patch, float radius,
                               const Judge& judge) const {
  if (!index_) return 0;
  for (int32_t id : index_->within(point, radius)) {  // nearest first
    const StrandEnd& other = ends_[static_cast<size_t>(id)];
    if (other.patch == patch) continue;
    if (int vote = judge(other); vote != 0) return vote;
  }
  return 0;
}

int StrandEndIndex::vote(const Eigen::Vector3f& point, const Eigen::Vector3f& outward,
                         int32_t patch, float radius) const {
  return first_vote(point, patch, radius, [&](const StrandEnd& other) {
    if (other.is_root) return -1;
    return -outward.dot(other.flow) > aligned ? 1 : -1;
  });
}

int StrandEndIndex::through_vote(const Eigen::Vector3f& point, const Eigen::Vector3f& outward,
                                 int32_t patch, float radius) const {
  return first_vote(point, patch, radius, [&](const StrandEnd& other) {
    if (other.is_root && outward.dot(other.flow) > aligned) return -1;
    if (!other.is_root && -outward.dot(other.flow) > aligned) return 1;
    return 0;
  });
}

namespace {

/// What the two ends of `rail` (as it runs) say of it, by `vote(point, outward)` at each:
/// whether its first point is a root, minus whether its last point is (each +1, -1 or 0).
/// +2: both ends say it runs as it is; -2: both say it runs backwards.
template <typename EndVote>
int rail_end_score(const Points3f& vertices, const std::vector<int32_t>& rail,
                   const EndVote& vote) {
  int first_is_root =
      vote(vertices.row(rail.front()).transpose(), -end_direction(vertices, rail, false));
  int last_is_root =
      vote(vertices.row(rail.back()).transpose(), end_direction(vertices, rail, true));
  return first_is_root - last_is_root;
}

/// One round of continuation: decides regions left open from the oriented strands of
/// other patches (decided regions, parted rails) whose ends lie within `radius` of a
/// rail's ends. The nearest such end E' at a rail end E, with the rail's outward
/// direction u at E (pointing out of the rail) and the hair's flow f at E', says:
///  - E' a root: other hair starts where the rail ends, E is the rail's tip, at any
///    angle (a tail leaves a ponytail's band downwards while cap strands arrive there
///    from all sides);
///  - E' a tip: if the rail carries that flow on (-u . f > cos 60 deg), E is the rail's
///    root (continuation); otherwise both arrive at one place and E is a tip too
///    (convergence, as cap strands meet at the band).
/// A region is decided when at least half of its rails have a neighbour and three
/// quarters of their votes agree. Returns how many regions it decided.
int decide_by_continuation_once(const Points3f& vertices, std::vector<RegionRails>& regions,
                                float radius) {
  const StrandEndIndex ends(vertices, regions);

  std::vector<std::optional<OrientationDecision>> decided(regions.size());
  for (size_t r = 0; r < regions.size(); ++r) {
    const RegionRails& region = regions[r];
    if (region.decision || region.open_rails.empty()) continue;
    bool spoke = false;  // whether an end of the rail being scored had a neighbour
    auto end_vote = [&](const Eigen::Vector3f& point, const Eigen::Vector3f& outward) {
      int vote = ends.vote(point, outward, region.patch, radius);
      spoke = spoke || vote != 0;
      return vote;
    };
    double forward = 0, backward = 0, rails_with_neighbour = 0;
    for (const auto& rail : region.open_rails) {
      spoke = false;
      int score = rail_end_score(vertices, rail, end_vote);  // > 0: the rail runs as it is
      forward += score > 0 ? 1 : 0;
      backward += score < 0 ? 1 : 0;
      rails_with_neighbour += spoke ? 1 : 0;
    }
    double votes = forward + backward;
    if (rails_with_neighbour < 0.5 * static_cast<double>(region.open_rails.size()) || votes == 0 ||
        std::abs(forward - backward) < 0.5 * votes)
      continue;
    decided[r] = OrientationDecision{backward > forward, OrientationRule::continuation,
                                     static_cast<float>(std::abs(forward - backward) / votes)};
  }
  int count = 0;
  for (size_t r = 0; r < regions.size(); ++r)  // applied together: order does not matter
    if (decided[r]) {
      regions[r].decision = decided[r];
      ++count;
    }
  return count;
}

}  // namespace

int continuation_overrules_ids(const Points3f& vertices, std::vector<RegionRails>& regions,
                               const OrientationThresholds& thresholds, float radius,
                               int max_rounds) {
  int turned = 0;
  for (int round = 0; round < max_rounds; ++round) {
    const StrandEndIndex ends(vertices, regions);
    std::vector<size_t> to_turn;
    for (size_t r = 0; r < regions.size(); ++r) {
      const RegionRails& region = regions[r];
      if (!region.decision || region.open_rails.empty() ||
          region.evidence.head_distance_min_m < thresholds.height_min_head_distance_m ||
          !decided_by_one_cue(region, thresholds))
        continue;
      auto through_vote = [&](const Eigen::Vector3f& point, const Eigen::Vector3f& outward) {
        return ends.through_vote(point, outward, region.patch, radius);
      };
      double forward = 0, backward = 0;
      for (std::vector<int32_t> rail : region.open_rails) {
        if (region.decision->reverse) std::reverse(rail.begin(), rail.end());
        int score = rail_end_score(vertices, rail, through_vote);  // > 0: runs as decided
        forward += score > 0 ? 1 : 0;
        backward += score == -2 ? 1 : 0;  // both ends say it runs backwards
      }
      double votes = forward + backward;
      if (backward >= 0.5 * static_cast<double>(region.open_rails.size()) &&
          backward - forward >= 0.5 * votes)
        to_turn.push_back(r);
    }
    if (to_turn.empty()) break;
    for (size_t r : to_turn) {  // applied together: order does not matter
      OrientationDecision& decision = *regions[r].decision;
      decision = OrientationDecision{!decision.reverse, OrientationRule::continuation, 0.75f};
    }
    turned += static_cast<int>(to_turn.size());
  }
  return turned;
}

void decide_by_continuation(const Points3f& vertices, std::vector<RegionRails>& regions,
                            float radius, int max_rounds) {
  for (int round = 0; round < max_rounds; ++round)
    if (decide_by_continuation_once(vertices, regions, radius) == 0) return;
}

}  // namespace hair
