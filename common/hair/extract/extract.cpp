#include "hair/extract/extract.h"

#include <spdlog/spdlog.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <span>
#include <string>
#include <utility>

#include "hair/core/error.h"
#include "hair/extract/extract_params.h"
#include "hair/extract/group_sense.h"
#include "hair/extract/painted_streamlines.h"
#include "hair/extract/rail_paint.h"
#include "hair/extract/scalp.h"
#include "hair/geom/point_index.h"
#include "hair/mesh/mesh_checks.h"
#include "hair/mesh/mesh_patches.h"
#include "hair/mesh/quad_recovery.h"

namespace hair {
namespace {

/// The rails of one quad region, before and after orientation.
struct RegionRails {
  int32_t patch = 0;
  size_t region_in_patch = 0;
  std::vector<std::vector<int32_t>> open_rails;    ///< consistently oriented chains
  std::vector<std::vector<int32_t>> parted_rails;  ///< halves of parted rails, root to tip
  OrientationEvidence evidence;
  std::optional<OrientationDecision> decision;
};

/// The share of observations that are true, or nullopt with fewer than 3.
std::optional<double> share_true(const std::vector<bool>& observations) {
  if (observations.size() < 3) return std::nullopt;
  return static_cast<double>(std::count(observations.begin(), observations.end(), true)) /
         static_cast<double>(observations.size());
}

/// Picks the family of each quad region that runs along the hair: where the painted
/// flow decides (family_along_paint()), the family along the paint; else the family with
/// clearly longer chains; where the two are alike (square cards, caps), the family that
/// follows the mesh's texture axis, learnt from the clear regions.
std::vector<std::vector<int>> along_families(
    const std::vector<PatchTopology>& topologies,
    const std::vector<std::vector<std::array<FamilyPaint, 2>>>& paint, const ExtractParams& params,
    ExtractStats& stats) {
  constexpr double min_alignment_difference = 0.2;
  auto paint_decides = [&](size_t p, size_t r) {
    return family_along_paint(paint[p][r], params.along_paint_min_judged_share,
                              params.along_paint_min_gap);
  };
  std::vector<bool> along_is_v;  // clear regions: does the along family follow v?
  for (size_t p = 0; p < topologies.size(); ++p)
    for (size_t r = 0; r < topologies[p].regions.size(); ++r) {
      const auto& f = topologies[p].regions[r].families;
      double longer = std::max(f[0].mean_chain_length, f[1].mean_chain_length);
      double shorter = std::min(f[0].mean_chain_length, f[1].mean_chain_length);
      if (f[0].v_alignment < 0 || std::abs(f[0].v_alignment - f[1].v_alignment) < min_alignment_difference)
        continue;
      int along = paint_decides(p, r);
      if (along < 0 && longer < params.along_length_ratio * shorter) continue;
      if (along < 0) along = f[0].mean_chain_length > f[1].mean_chain_length ? 0 : 1;
      along_is_v.push_back(f[along].v_alignment > f[1 - along].v_alignment);
    }
  std::optional<bool> texture_axis_is_v;
  if (auto share = share_true(along_is_v)) {
    if (*share >= params.convention_min_agreement) texture_axis_is_v = true;
    if (*share <= 1 - params.convention_min_agreement) texture_axis_is_v = false;
  }

  std::vector<std::vector<int>> along(topologies.size());
  for (size_t p = 0; p < topologies.size(); ++p)
    for (size_t r = 0; r < topologies[p].regions.size(); ++r) {
      const auto& f = topologies[p].regions[r].families;
      int longer = f[0].mean_chain_length >= f[1].mean_chain_length ? 0 : 1;
      bool clear = f[longer].mean_chain_length >=
                   params.along_length_ratio * f[1 - longer].mean_chain_length;
      bool texture_tells =
          texture_axis_is_v && f[0].v_alignment >= 0 &&
          std::abs(f[0].v_alignment - f[1].v_alignment) >= min_alignment_difference;
      AlongRule rule = AlongRule::chain_length;
      int chosen = longer;
      if (int painted = paint_decides(p, r); painted >= 0) {
        rule = AlongRule::painted_flow;
        chosen = painted;
        if (clear && painted != longer) ++stats.regions_turned_by_paint;
      } else if (!clear && texture_tells) {
        rule = AlongRule::texture_axis;
        int v_family = f[0].v_alignment > f[1].v_alignment ? 0 : 1;
        chosen = *texture_axis_is_v ? v_family : 1 - v_family;
      }
      along[p].push_back(chosen);
      ++stats.regions_by_along_rule[static_cast<size_t>(rule)];
    }
  return along;
}

/// Parts a closed rail (first id repeated last) at its highest and lowest points into
/// two halves that both run downwards.
std::array<std::vector<int32_t>, 2> part_closed_rail(const Points3f& vertices,
                                                     std::vector<int32_t> ring) {
  ring.pop_back();
  size_t n = ring.size();
  size_t top = 0, bottom = 0;
  for (size_t i = 1; i < n; ++i) {
    if (vertices(ring[i], 1) > vertices(ring[top], 1)) top = i;
    if (vertices(ring[i], 1) < vertices(ring[bottom], 1)) bottom = i;
  }
  if (bottom == top) bottom = (top + n / 2) % n;
  std::array<std::vector<int32_t>, 2> halves;
  for (size_t i = top;; i = (i + 1) % n) {  // forwards from the top
    halves[0].push_back(ring[i]);
    if (i == bottom) break;
  }
  for (size_t i = top;; i = (i + n - 1) % n) {  // backwards from the top
    halves[1].push_back(ring[i]);
    if (i == bottom) break;
  }
  return halves;
}

double rail_length(const Points3f& vertices, const std::vector<int32_t>& rail) {
  double length = 0;
  for (size_t i = 1; i < rail.size(); ++i)
    length += (vertices.row(rail[i]) - vertices.row(rail[i - 1])).cast<double>().norm();
  return length;
}

/// Which of a rail's inner extremes part_rail_at_inner_extreme() looks for.
enum class InnerExtreme { highest, lowest };

/// A card's rail runs from root to tip, so its height changes one way along it, give or
/// take waves and curls. A rail whose highest or lowest point lies well inside it, with
/// both sides falling away from that point, is two strands meeting there:
///  - highest (a card draped over the head, from one side over the parting to the
///    other): two strands with their roots at the top, their tips at the rail's ends;
///  - lowest (a shell tail or lock modelled as a closed pouch, whose along-lines run
///    down its front, round its tip and back up its back): two strands from the rail's
///    ends down to their tips at the fold.
/// Each side is at least `min_side_share` of the rail's length and drops from the
/// extreme (or rises to it) by at least `min_side_drop` of its own length, and the tips
/// hang off the head (farther than `min_tip_distance` from it: a cap's rail from the
/// hairline over the crown to a band has both ends on the head, and is one strand).
/// Returns the two halves, each from root to tip, or nothing.
std::optional<std::array<std::vector<int32_t>, 2>> part_rail_at_inner_extreme(
    const Points3f& vertices, const std::vector<int32_t>& rail, InnerExtreme extreme,
    double min_side_share, double min_side_drop, const TriangleMeshDistance& head_distance,
    double min_tip_distance) {
  float sign = extreme == InnerExtreme::highest ? 1.0f : -1.0f;
  size_t inner = 0;
  for (size_t i = 1; i < rail.size(); ++i)
    if (sign * vertices(rail[i], 1) > sign * vertices(rail[inner], 1)) inner = i;
  if (inner == 0 || inner + 1 == rail.size()) return std::nullopt;
  // Both sides from the inner extreme out to the rail's ends.
  std::vector<int32_t> before(rail.begin(), rail.begin() + static_cast<std::ptrdiff_t>(inner) + 1);
  std::vector<int32_t> after(rail.begin() + static_cast<std::ptrdiff_t>(inner), rail.end());
  std::reverse(before.begin(), before.end());
  double total = rail_length(vertices, rail);
  auto far_from_head = [&](int32_t vertex) {
    return head_distance.distance(vertices.row(vertex).cast<double>().transpose()) >=
           min_tip_distance;
  };
  for (const auto* side : {&before, &after}) {
    double length = rail_length(vertices, *side);
    double drop = sign * (vertices(side->front(), 1) - vertices(side->back(), 1));
    if (length < min_side_share * total || drop < min_side_drop * length) return std::nullopt;
    if (extreme == InnerExtreme::highest && !far_from_head(side->back())) return std::nullopt;
  }
  if (extreme == InnerExtreme::lowest) {
    if (!far_from_head(rail[inner])) return std::nullopt;
    std::reverse(before.begin(), before.end());  // from the rail's ends down to the fold
    std::reverse(after.begin(), after.end());
  }
  return std::array<std::vector<int32_t>, 2>{before, after};
}

/// What the rails of a region say about their direction (see OrientationEvidence).
OrientationEvidence orientation_evidence(const Points3f& vertices,
                                         const std::vector<std::vector<int32_t>>& rails,
                                         const EdgeFamily& along_family,
                                         const TriangleMeshDistance& head_distance,
                                         const ExtractParams& params) {
  OrientationEvidence evidence;
  evidence.head_distance_min_m = std::numeric_limits<double>::infinity();
  double growing = 0, falling = 0, total_length = 0, distance_change = 0, height_drop = 0;
  for (const auto& rail : rails) {
    double length = rail_length(vertices, rail);
    int64_t steps_up = 0;
    for (size_t i = 1; i < rail.size(); ++i) steps_up += rail[i] > rail[i - 1] ? 1 : 0;
    double share_up = static_cast<double>(steps_up) / static_cast<double>(rail.size() - 1);
    if (share_up >= params.ordered_rail_fraction) growing += length;
    if (share_up <= 1 - params.ordered_rail_fraction) falling += length;
    Eigen::Vector3d first = vertices.row(rail.front()).cast<double>().transpose();
    Eigen::Vector3d last = vertices.row(rail.back()).cast<double>().transpose();
    double first_distance = head_distance.distance(first),
           last_distance = head_distance.distance(last);
    distance_change += last_distance - first_distance;
    evidence.head_distance_min_m =
        std::min({evidence.head_distance_min_m, first_distance, last_distance});
    height_drop += first.y() - last.y();
    total_length += length;
  }
  evidence.has_ordered_rails = growing + falling > 0;
  if (evidence.has_ordered_rails)
    evidence.vertex_order_vote = (growing - falling) / (growing + falling);
  if (rails.empty()) evidence.head_distance_min_m = 0;
  if (total_length > 0) {
    evidence.scalp_distance_slope = distance_change / total_length;
    evidence.height_slope = height_drop / total_length;
  }
  if (along_family.v_alignment >= 0) evidence.uv_growth = along_family.v_growth;
  return evidence;
}

/// Learns what the mesh's confidently decided regions say: whether its vertex ids
/// are to be trusted against the head distance, and its texture's v direction.
MeshConventions mesh_conventions(std::vector<RegionRails>& regions,
                                 const OrientationThresholds& thresholds,
                                 const ExtractParams& params) {
  MeshConventions conventions;
  // The ids are ignored for the whole mesh when the head distance contradicts them on
  // most of the regions where both decide, and those regions are at least half of the
  // regions whose ids agree among themselves: where the head distance decides only a
  // few regions (hair lying on the head; wavy or braided pieces nearing it), a handful
  // of cards numbered tip to root must not cost every card its ids.
  int64_t ordered = 0, agree = 0, disagree = 0;
  for (const RegionRails& region : regions) {
    const OrientationEvidence& e = region.evidence;
    if (!e.has_ordered_rails || std::abs(e.vertex_order_vote) < thresholds.vertex_order_min_vote)
      continue;
    ++ordered;
    if (std::abs(e.scalp_distance_slope) < thresholds.scalp_distance_min_slope) continue;
    ((e.vertex_order_vote < 0) == (e.scalp_distance_slope < 0) ? agree : disagree) += 1;
  }
  if (disagree > agree && 2 * disagree >= ordered) conventions.trust_vertex_order = false;

  // The texture's convention is learnt from the regions decided, but not from those that
  // only their ids decided against a decisive height: a card numbered tip to root lying
  // on the head is one of those, and so is hair brushed up, so neither may teach it.
  std::vector<bool> v_grows_to_tip;
  for (RegionRails& region : regions) {
    if (!conventions.trust_vertex_order) region.evidence.has_ordered_rails = false;
    region.decision = decide_orientation(region.evidence, thresholds, std::nullopt);
    const OrientationEvidence& e = region.evidence;
    const bool ids_against_height = region.decision &&
                                    region.decision->rule == OrientationRule::vertex_order &&
                                    std::abs(e.height_slope) >= thresholds.height_min_slope &&
                                    (e.height_slope < 0) != region.decision->reverse;
    if (region.decision && !ids_against_height && e.uv_growth &&
        std::abs(*e.uv_growth) >= thresholds.uv_min_growth)
      v_grows_to_tip.push_back((*e.uv_growth > 0) != region.decision->reverse);
  }
  if (auto share = share_true(v_grows_to_tip)) {
    if (*share >= params.convention_min_agreement) conventions.uv_growth_sign = 1;
    if (*share <= 1 - params.convention_min_agreement) conventions.uv_growth_sign = -1;
  }
  return conventions;
}

/// The end of an oriented strand of a decided patch, and the hair's flow there.
struct StrandEnd {
  bool is_root = false;
  Eigen::Vector3f flow;  ///< unit direction root to tip at this end
  int32_t patch = 0;
};

/// Unit direction of the rail's first (or last) segment, from its first to its last point.
Eigen::Vector3f end_direction(const Points3f& vertices, const std::vector<int32_t>& rail,
                              bool at_last) {
  Eigen::Vector3f d = at_last ? Eigen::Vector3f(vertices.row(rail[rail.size() - 1]) -
                                                vertices.row(rail[rail.size() - 2]))
                              : Eigen::Vector3f(vertices.row(rail[1]) - vertices.row(rail[0]));
  float norm = d.norm();
  return norm > 0 ? Eigen::Vector3f(d / norm) : Eigen::Vector3f::Zero();
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
/// The ends of the oriented strands of decided regions and parted rails, to find what
/// lies at a strand's end (see decide_by_continuation_once()).
class StrandEndIndex {
 public:
  /// Every region's ends, but those of patches with `leave_out` set (may be empty).
  StrandEndIndex(const Points3f& vertices, const std::vector<RegionRails>& regions,
                 const std::vector<bool>& leave_out = {}) {
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

  /// What the nearest end of another patch's strand within `radius` of `point` says of a
  /// strand end there whose outward direction is `outward`: +1 it is a root, -1 a tip,
  /// 0 no neighbour.
  int vote(const Eigen::Vector3f& point, const Eigen::Vector3f& outward, int32_t patch,
           float radius) const {
    return first_vote(point, patch, radius, [&](const StrandEnd& other) {
      if (other.is_root) return -1;
      return -outward.dot(other.flow) > aligned ? 1 : -1;
    });
  }

  /// What a strand end at `point` with outward direction `outward` is, judged only by
  /// hair that runs on through it: the nearest end of another patch's strand within
  /// `radius` that is either a root leaving along `outward` (the hair goes on: a tip
  /// here, -1) or a tip arriving against it (the hair comes in: a root here, +1), both
  /// within 60 degrees; 0 if none. Ends beside it (roots side by side in dense hair, cap
  /// strands converging at a band) do not count.
  int through_vote(const Eigen::Vector3f& point, const Eigen::Vector3f& outward, int32_t patch,
                   float radius) const {
    return first_vote(point, patch, radius, [&](const StrandEnd& other) {
      if (other.is_root && outward.dot(other.flow) > aligned) return -1;
      if (!other.is_root && -outward.dot(other.flow) > aligned) return 1;
      return 0;
    });
  }

 private:
  static constexpr float aligned = 0.5f;  // cos 60 degrees

  /// The first non-zero `judge(end)` over the ends of other patches' strands within
  /// `radius` of `point`, nearest first; 0 if none.
  template <typename Judge>
  int first_vote(const Eigen::Vector3f& point, int32_t patch, float radius,
                 const Judge& judge) const {
    if (!index_) return 0;
    for (int32_t id : index_->within(point, radius)) {  // nearest first
      const StrandEnd& other = ends_[static_cast<size_t>(id)];
      if (other.patch == patch) continue;
      if (int vote = judge(other); vote != 0) return vote;
    }
    return 0;
  }

  std::vector<StrandEnd> ends_;
  std::optional<PointIndex> index_;
};

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

/// Whether a region's direction rests on geometry alone, which the hair running on
/// through its ends may overrule: its vertex ids with the head distance silent, or its
/// head distance (with the height, or without it) against ids that agree among
/// themselves. A braid's pieces weave towards and away from the head and tilt as they
/// cross, so off the head their distance and height mislead; turned, such a piece
/// follows its ids and the pieces before and after it.
bool decided_by_one_cue(const RegionRails& region, const OrientationThresholds& thresholds) {
  const OrientationEvidence& e = region.evidence;
  const bool distance_decides =
      std::abs(e.scalp_distance_slope) >= thresholds.scalp_distance_min_slope;
  if (region.decision->rule == OrientationRule::vertex_order) return !distance_decides;
  const bool ids_agree =
      e.has_ordered_rails && std::abs(e.vertex_order_vote) >= thresholds.vertex_order_min_vote;
  return region.decision->rule == OrientationRule::scalp_distance && distance_decides &&
         ids_agree && (e.vertex_order_vote < 0) != region.decision->reverse;
}

/// Where a region off the head (every rail end at least `height_min_head_distance_m`
/// from it) had its direction decided by one cue (decided_by_one_cue(): its vertex ids
/// with the head distance silent, as a braid's piece or a card in the middle of a
/// hanging lock, or its head distance against its ids), and the hair
/// that runs on through its rails' ends says the other way, the hair wins: on at least
/// half of its rails both ends say it runs backwards (StrandEndIndex::through_vote(),
/// which ignores ends lying beside the rail's), three quarters of the rails that vote.
/// Ids are an accident of modelling (a card extruded from its tip, or turned round);
/// pieces that meet end to end are the hair itself. Applied in rounds, each on the
/// decisions of the last, so a turned piece can settle its neighbour; a piece between
/// two turned the wrong way, whose ends disagree, is left as it is. Returns how many
/// regions it turned. On the head it would misread: cap strands converging head-on at a
/// band or a whorl meet end to end just as pieces of one lock do.
int continuation_overrules_ids(const Points3f& vertices, std::vector<RegionRails>& regions,
                               const OrientationThresholds& thresholds, float radius,
                               int max_rounds = 8) {
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

/// Continuation in rounds, so that a decision travels along chains of patches (a cap
/// made of several patches meeting the tail at one of them), at most `max_rounds`.
void decide_by_continuation(const Points3f& vertices, std::vector<RegionRails>& regions,
                            float radius, int max_rounds = 16) {
  for (int round = 0; round < max_rounds; ++round)
    if (decide_by_continuation_once(vertices, regions, radius) == 0) return;
}

void append_rail(std::vector<Points3f>& polylines, const Points3f& vertices,
                 const std::vector<int32_t>& rail, std::vector<int32_t>& source_vertex) {
  Points3f points(static_cast<Eigen::Index>(rail.size()), 3);
  for (size_t i = 0; i < rail.size(); ++i)
    points.row(static_cast<Eigen::Index>(i)) = vertices.row(rail[i]);
  polylines.push_back(std::move(points));
  source_vertex.insert(source_vertex.end(), rail.begin(), rail.end());
}

/// The body's triangles with a vertex at or above the neck.
Triangles3i head_triangles_of(const Points3f& body_vertices, const Triangles3i& body_triangles,
                              double neck_y, const std::string& body_file) {
  Triangles3i head_triangles(body_triangles.rows(), 3);
  Eigen::Index head_triangle_count = 0;
  for (Eigen::Index t = 0; t < body_triangles.rows(); ++t) {
    double top_y = -std::numeric_limits<double>::infinity();
    for (int k = 0; k < 3; ++k)
      top_y = std::max<double>(top_y, body_vertices(body_triangles(t, k), 1));
    if (top_y >= neck_y) head_triangles.row(head_triangle_count++) = body_triangles.row(t);
  }
  head_triangles.conservativeResize(head_triangle_count, 3);
  if (head_triangle_count == 0)
    throw Error::bad_input(body_file, "body mesh has no head above the neck");
  return head_triangles;
}

/// The rails of every region of every patch (the chains of its along family; short
/// fragments dropped, closed, draped and folded rails parted), and what they say about their
/// direction.
std::vector<RegionRails> region_rails(const PolyMesh& mesh, const PaintedFlow& flow,
                                      const EdgeFaces& edge_faces,
                                      const std::vector<PatchTopology>& topologies,
                                      const std::vector<std::vector<int>>& along,
                                      const TriangleMeshDistance& head_distance,
                                      const ExtractParams& params, double head_height_m,
                                      ExtractStats& stats) {
  const Points3f& vertices = mesh.vertices;
  auto part_at_inner_extreme = [&](const std::vector<int32_t>& chain) {
    for (InnerExtreme extreme : {InnerExtreme::highest, InnerExtreme::lowest})
      if (auto halves = part_rail_at_inner_extreme(
              vertices, chain, extreme, params.parting_min_side_share,
              params.parting_min_side_drop, head_distance,
              params.parting_min_end_distance_h * head_height_m))
        return halves;
    return std::optional<std::array<std::vector<int32_t>, 2>>{};
  };
  std::vector<RegionRails> regions;
  for (int32_t p = 0; p < static_cast<int32_t>(topologies.size()); ++p) {
    stats.family_conflicts += topologies[p].family_conflicts;
    for (size_t r = 0; r < topologies[p].regions.size(); ++r) {
      RegionRails region;
      region.patch = p;
      region.region_in_patch = r;
      const EdgeFamily& along_family = topologies[p].regions[r].families[along[p][r]];
      double longest = 0;
      for (const auto& chain : along_family.chains)
        longest = std::max(longest, rail_length(vertices, chain));
      for (const auto& chain : along_family.chains) {
        if (rail_length(vertices, chain) < params.min_rail_length_share * longest) {
          ++stats.fragments_dropped;
        } else if (chain.size() > 2 && chain.front() == chain.back()) {
          for (auto& half : part_closed_rail(vertices, chain)) region.parted_rails.push_back(half);
          ++stats.rails_parted;
        } else if (auto halves = part_at_inner_extreme(chain)) {
          for (auto& half : *halves) region.parted_rails.push_back(half);
          ++stats.rails_parted;
        } else {
          region.open_rails.push_back(chain);
        }
      }
      regions.push_back(std::move(region));
    }
  }
#pragma omp parallel for schedule(dynamic)
  for (size_t i = 0; i < regions.size(); ++i) {
    const RegionRails& region = regions[i];
    int32_t p = region.patch;
    size_t r = region.region_in_patch;
    OrientationEvidence evidence =
        orientation_evidence(vertices, region.open_rails,
                             topologies[p].regions[r].families[along[p][r]], head_distance, params);
    AlphaFade fade = rails_alpha_fade(mesh, flow, edge_faces, region.open_rails);
    if (fade.judged_edges > 0) {
      evidence.alpha_fade_vote = fade.vote;
      evidence.alpha_fade_mean_fall = fade.mean_fall;
      evidence.alpha_fade_rail_fall = fade.mean_rail_fall;
    }
    regions[i].evidence = evidence;
  }
  return regions;
}

/// Where a region's vertex ids decided its direction but its paint says the other way
/// twice over, the paint wins. Twice over: its painted alpha fades out decisively
/// towards the other end, and its texture's v runs towards that end as the mesh's texture
/// does on its other painted regions (on at least `min_agreement` of the regions whose
/// fade and v growth are both decisive, v grows towards the fade, or on as many against
/// it). Vertex ids are an accident of how a card was modelled (one extruded from its
/// tip, or turned round, numbers tip to root); the texture is laid and painted on purpose,
/// one image for many cards. A mesh whose cards fade at either end (some at the root, to
/// soften a hairline) has no such convention, and its ids stay. Returns how many regions
/// it turned.
int paint_overrules(std::vector<RegionRails>& regions, const OrientationThresholds& thresholds,
                    double min_agreement, OrientationRule overruled) {
  auto fade_decides = [&](const OrientationEvidence& e) {
    return alpha_fade_decides(e, thresholds, true) && e.uv_growth &&
           std::abs(*e.uv_growth) >= thresholds.uv_min_growth;
  };
  // v grows towards the fade (the tips) when the alpha falls along the rails (vote > 0)
  // and v grows along them, or both run the other way.
  auto v_grows_to_fade = [](const OrientationEvidence& e) {
    return (*e.uv_growth > 0) == (*e.alpha_fade_vote > 0);
  };
  std::vector<bool> towards;
  for (const RegionRails& region : regions)
    if (fade_decides(region.evidence)) towards.push_back(v_grows_to_fade(region.evidence));
  const std::optional<double> share = share_true(towards);
  if (!share || (*share < min_agreement && *share > 1 - min_agreement)) return 0;
  const bool convention = *share >= min_agreement;
  int turned = 0;
  for (RegionRails& region : regions) {
    if (!region.decision || region.decision->rule != overruled) continue;
    const OrientationEvidence& e = region.evidence;
    if (!fade_decides(e) || v_grows_to_fade(e) != convention) continue;
    const bool fade_reverse = *e.alpha_fade_vote < 0;
    if (fade_reverse == region.decision->reverse) continue;
    region.decision = OrientationDecision{
        fade_reverse, OrientationRule::alpha_fade,
        static_cast<float>(std::min(std::abs(*e.uv_growth), std::abs(*e.alpha_fade_vote)))};
    ++turned;
  }
  return turned;
}

/// Whether a region's texture's v, read with the mesh's convention (learnt from its
/// confidently decided regions), says the region runs backwards; nullopt where it does
/// not decide (no texture, v growing by less than `uv_min_growth`, or no convention).
std::optional<bool> texture_says_reverse(const OrientationEvidence& e,
                                         const OrientationThresholds& thresholds,
                                         const MeshConventions& conventions) {
  if (!conventions.uv_growth_sign || !e.uv_growth ||
      std::abs(*e.uv_growth) < thresholds.uv_min_growth)
    return std::nullopt;
  return (*e.uv_growth > 0 ? 1 : -1) != *conventions.uv_growth_sign;
}

/// Where a region's vertex ids decided its direction with the head distance silent, and
/// both its height (the higher end is the root, by at least `height_min_slope`) and its
/// texture's v (by at least `uv_min_growth`, read with the mesh's convention, learnt
/// from its confidently decided regions) say the other way, the two win: hair lying
/// down the side of the head, or a piece hanging straight down behind it, numbered tip
/// to root, keeps its distance to the head but falls from its root and is textured from
/// it. Hair brushed up from its root, whose texture runs up with it, is left to its ids
/// (height and v disagree there). Returns how many regions it turned.
int height_and_texture_overrule_ids(std::vector<RegionRails>& regions,
                                    const OrientationThresholds& thresholds,
                                    const MeshConventions& conventions) {
  int turned = 0;
  for (RegionRails& region : regions) {
    const OrientationEvidence& e = region.evidence;
    const std::optional<bool> uv_reverse = texture_says_reverse(e, thresholds, conventions);
    if (!region.decision || region.decision->rule != OrientationRule::vertex_order ||
        std::abs(e.scalp_distance_slope) >= thresholds.scalp_distance_min_slope || !uv_reverse ||
        std::abs(e.height_slope) < thresholds.height_min_slope)
      continue;
    const bool height_reverse = e.height_slope < 0;
    if (height_reverse != *uv_reverse || height_reverse == region.decision->reverse) continue;
    region.decision =
        OrientationDecision{height_reverse, OrientationRule::height,
                            static_cast<float>(std::min(std::abs(e.height_slope), 1.0))};
    ++turned;
  }
  return turned;
}

/// Where a region off the head had its direction decided by its head distance (with
/// the height, or without it) against vertex ids that agree among themselves, and its
/// texture's v (read with the mesh's convention, by at least `uv_min_growth`) says what
/// the ids say, the two win: a braid's pieces weave towards and away from the head and
/// tilt as they cross, so off the head its distance and height mislead, while the ids
/// and the texture are laid along each card together, and the texture on purpose (a
/// card whose painted tips point up would show). With the height silent only, 14 more
/// of the corpus's braid pieces stay backwards (docs/extract.md). Returns how many
/// regions it turned.
int ids_and_texture_overrule_head_distance(std::vector<RegionRails>& regions,
                                           const OrientationThresholds& thresholds,
                                           const MeshConventions& conventions) {
  int turned = 0;
  for (RegionRails& region : regions) {
    const OrientationEvidence& e = region.evidence;
    const std::optional<bool> uv_reverse = texture_says_reverse(e, thresholds, conventions);
    if (!region.decision || region.decision->rule != OrientationRule::scalp_distance ||
        e.head_distance_min_m < thresholds.height_min_head_distance_m ||
        !decided_by_one_cue(region, thresholds) || !uv_reverse)
      continue;
    const bool ids_reverse = e.vertex_order_vote < 0;
    if (*uv_reverse != ids_reverse) continue;
    region.decision = OrientationDecision{
        ids_reverse, OrientationRule::uv,
        static_cast<float>(std::min(std::abs(*e.uv_growth), std::abs(e.vertex_order_vote)))};
    ++turned;
  }
  return turned;
}

/// Decides every region's direction: confident regions first, then continuation from
/// decided neighbours, then the mesh's conventions for the rest.
void decide_directions(const Points3f& vertices, std::vector<RegionRails>& regions,
                       const OrientationThresholds& thresholds, const ExtractParams& params,
                       double head_height_m, ExtractStats& stats) {
  MeshConventions conventions = mesh_conventions(regions, thresholds, params);
  stats.vertex_order_trusted = conventions.trust_vertex_order;
  stats.uv_growth_sign = conventions.uv_growth_sign.value_or(0);
  stats.paint_overruled_ids = paint_overrules(regions, thresholds, params.convention_min_agreement,
                                              OrientationRule::vertex_order);
  stats.height_and_texture_overruled_ids =
      height_and_texture_overrule_ids(regions, thresholds, conventions);
  stats.ids_and_texture_overruled_head_distance =
      ids_and_texture_overrule_head_distance(regions, thresholds, conventions);
  decide_by_continuation(vertices, regions,
                         static_cast<float>(params.continuation_radius_h * head_height_m));
  stats.continuation_overruled_ids =
      continuation_overrules_ids(vertices, regions, thresholds,
                                 static_cast<float>(params.continuation_radius_h * head_height_m));
  stats.paint_overruled_continuation = paint_overrules(
      regions, thresholds, params.convention_min_agreement, OrientationRule::continuation);
  for (RegionRails& region : regions)
    if (!region.decision)
      region.decision = decide_orientation(region.evidence, thresholds, conventions);
  for (const RegionRails& region : regions) {
    const OrientationEvidence& e = region.evidence;
    spdlog::debug(
        "patch {} region {}: ids vote {:.2f}, head distance slope {:.2f}, v growth {}, height "
        "slope {:.2f}, alpha fade vote {} (fall {:.3f} a face, {:.3f} a rail), nearest end "
        "{:.4f} m from the head: {}{}",
        region.patch, region.region_in_patch, e.vertex_order_vote, e.scalp_distance_slope,
        e.uv_growth ? fmt::format("{:.2f}", *e.uv_growth) : "none", e.height_slope,
        e.alpha_fade_vote ? fmt::format("{:.2f}", *e.alpha_fade_vote) : "none",
        e.alpha_fade_mean_fall, e.alpha_fade_rail_fall, e.head_distance_min_m,
        orientation_rule_name(region.decision->rule), region.decision->reverse ? ", reversed" : "");
  }
}

/// A patch without usable quads: one strand along its principal axis, directed by the
/// scalp distance and height of its ends. Returns the polyline and its decision.
std::pair<Points3f, OrientationDecision> triangle_soup_strand(
    const PolyMesh& hair_mesh, std::span<const int64_t> faces,
    const TriangleMeshDistance& head_distance, const OrientationThresholds& thresholds) {
  Points3f polyline = principal_axis_polyline(hair_mesh, faces);
  Eigen::Vector3d first = polyline.row(0).cast<double>().transpose();
  Eigen::Vector3d last = polyline.row(polyline.rows() - 1).cast<double>().transpose();
  double length = std::max(1e-12, (last - first).norm());
  OrientationEvidence evidence;
  evidence.scalp_distance_slope =
      (head_distance.distance(last) - head_distance.distance(first)) / length;
  evidence.height_slope = (first.y() - last.y()) / length;
  OrientationDecision decision =
      *decide_orientation(evidence, thresholds, MeshConventions{false, std::nullopt});
  if (decision.reverse) polyline = polyline.colwise().reverse().eval();
  return {std::move(polyline), decision};
}

/// The strands of a patch traced along its paint, oriented, and the group's decision.
struct PatchStreamlines {
  std::vector<Points3f> polylines;
  OrientationDecision decision;
};

/// The share of patch `p`'s chosen rails' judged length that runs along its faces' paint
/// (weighted by each region's quads), or nothing where the paint is clear on less than
/// `params.along_paint_min_judged_share` of it.
std::optional<double> rails_along_paint_share(const PatchTopology& topology,
                                              const std::vector<std::array<FamilyPaint, 2>>& paint,
                                              const std::vector<int>& along,
                                              const ExtractParams& params) {
  double judged = 0, agreeing = 0, weight = 0;
  for (size_t r = 0; r < topology.regions.size(); ++r) {
    const FamilyPaint& chosen = paint[r][static_cast<size_t>(along[r])];
    const auto quads = static_cast<double>(topology.regions[r].quad_count);
    weight += quads;
    judged += quads * chosen.judged_share;
    agreeing += quads * chosen.judged_share * chosen.along_share;
  }
  if (!(weight > 0) || judged < params.along_paint_min_judged_share * weight || !(judged > 0))
    return std::nullopt;
  return agreeing / judged;
}

/// Whether the median distance of the vertices of `faces` from the head is at most
/// `max_distance_m`: a cap or wig lying on the scalp, not a card or braid hanging off it.
bool lies_on_the_head(const PolyMesh& mesh, std::span<const int64_t> faces,
                      const TriangleMeshDistance& head_distance, double max_distance_m) {
  std::vector<double> distances;
  for (int64_t face : faces)
    for (int32_t vertex : mesh.face(face))
      distances.push_back(head_distance.distance(mesh.vertices.row(vertex).cast<double>().transpose()));
  if (distances.empty()) return false;
  std::nth_element(distances.begin(), distances.begin() + static_cast<std::ptrdiff_t>(distances.size() / 2),
                   distances.end());
  return distances[distances.size() / 2] <= max_distance_m;
}

/// Median length of the edges of `faces`.
double median_edge_length(const PolyMesh& mesh, std::span<const int64_t> faces) {
  std::vector<double> lengths;
  for (int64_t face : faces) {
    const int64_t first = mesh.face_offsets[static_cast<size_t>(face)];
    const int corners = mesh.face_size(face);
    for (int c = 0; c < corners; ++c)
      lengths.push_back((mesh.vertices.row(mesh.face_vertices[static_cast<size_t>(first + c)]) -
                         mesh.vertices.row(mesh.face_vertices[static_cast<size_t>(first + (c + 1) % corners)]))
                            .norm());
  }
  if (lengths.empty()) return 0;
  std::nth_element(lengths.begin(), lengths.begin() + static_cast<std::ptrdiff_t>(lengths.size() / 2),
                   lengths.end());
  return lengths[lengths.size() / 2];
}

/// Oriented strand segments (unit directions, each with the strand it belongs to) and an
/// index of their midpoints, to ask which way the hair runs near a point.
class SegmentIndex {
 public:
  /// Adds the segments of `points`, turned round when `sense` is negative.
  void add(const Points3f& points, int sense, size_t owner) {
    for (Eigen::Index k = 1; k < points.rows(); ++k) {
      Eigen::Vector3f segment = points.row(k) - points.row(k - 1);
      if (!(segment.norm() > 0)) continue;
      direction_.push_back(static_cast<float>(sense) * segment.normalized());
      midpoints_.push_back(0.5f * (points.row(k) + points.row(k - 1)).transpose());
      owner_.push_back(owner);
    }
  }
  /// Indexes what was added; call once, after the last add().
  void build() {
    Points3f rows(static_cast<Eigen::Index>(midpoints_.size()), 3);
    for (size_t k = 0; k < midpoints_.size(); ++k)
      rows.row(static_cast<Eigen::Index>(k)) = midpoints_[k].transpose();
    if (rows.rows() > 0) index_.emplace(rows);
  }
  bool empty() const { return !index_.has_value(); }

  /// Sum over the segments of `points` of the cosine with the nearest indexed segment
  /// within `radius` that does not belong to `skip_owner`; `judged` receives how many
  /// segments had one.
  double agreement(const Points3f& points, float radius, int& judged,
                   std::optional<size_t> skip_owner = std::nullopt) const {
    double cosine_sum = 0;
    judged = 0;
    if (!index_) return 0;
    for (Eigen::Index k = 1; k < points.rows(); ++k) {
      Eigen::Vector3f segment = points.row(k) - points.row(k - 1);
      if (!(segment.norm() > 0)) continue;
      Eigen::Vector3f midpoint = 0.5f * (points.row(k) + points.row(k - 1)).transpose();
      for (int32_t id : index_->within(midpoint, radius)) {
        if (skip_owner && owner_[static_cast<size_t>(id)] == *skip_owner) continue;
        cosine_sum += segment.normalized().dot(direction_[static_cast<size_t>(id)]);
        ++judged;
        break;  // the nearest
      }
    }
    return cosine_sum;
  }

 private:
  std::vector<Eigen::Vector3f> direction_, midpoints_;
  std::vector<size_t> owner_;
  std::optional<PointIndex> index_;
};

/// The segments of a patch's decided rails, oriented root to tip, where they run along the
/// paint (within kFlowAgreementAngleDeg of the clear painted flow of a face they border):
/// rails that cross the paint (rings round a cap, a grid that pays no heed to its hair) are
/// not the hair, and the sense their vertex ids or parting give them says nothing of it.
SegmentIndex decided_rail_segments(const PolyMesh& mesh, const PaintedFlow& flow,
                                   const EdgeFaces& edge_faces,
                                   std::span<const RegionRails> patch_regions) {
  SegmentIndex segments;
  const double min_cosine = std::cos(kFlowAgreementAngleDeg * std::numbers::pi / 180);
  // Whether the rail edge (a, b) runs along the clear paint of a face it borders.
  auto along_paint = [&](int32_t a, int32_t b) {
    const Eigen::Vector3f edge = mesh.vertices.row(b) - mesh.vertices.row(a);
    if (!(edge.norm() > 0)) return false;
    for (int64_t face : edge_faces.faces(a, b)) {
      if (face < 0) continue;
      const auto f = static_cast<size_t>(face);
      if (flow.coherence.size() > f && flow.coherence[f] >= kClearFlowCoherence &&
          std::abs(edge.normalized().dot(flow.direction[f])) >= min_cosine)
        return true;
    }
    return false;
  };
  // Each run of a rail's edges that run along the paint, in the rail's decided sense.
  auto add = [&](const std::vector<int32_t>& rail, bool reverse) {
    size_t run_start = 0;
    for (size_t i = 1; i <= rail.size(); ++i) {
      if (i < rail.size() && along_paint(rail[i - 1], rail[i])) continue;
      if (i - run_start >= 2) {
        Points3f points(static_cast<Eigen::Index>(i - run_start), 3);
        for (size_t k = run_start; k < i; ++k)
          points.row(static_cast<Eigen::Index>(k - run_start)) = mesh.vertices.row(rail[k]);
        segments.add(points, reverse ? -1 : 1, 0);
      }
      run_start = i;
    }
  };
  for (const RegionRails& region : patch_regions) {
    for (const auto& rail : region.open_rails) add(rail, region.decision && region.decision->reverse);
    for (const auto& rail : region.parted_rails) add(rail, false);
  }
  segments.build();
  return segments;
}

/// The direction streamline `points` gets from its own ends and shape: head distance,
/// alpha fade, height (decide_orientation() without conventions).
OrientationDecision own_orientation(const PaintedStreamline& line,
                                    const TriangleMeshDistance& head_distance,
                                    const OrientationThresholds& thresholds) {
  const Points3f& points = line.points;
  Eigen::Vector3d first = points.row(0).cast<double>().transpose();
  Eigen::Vector3d last = points.row(points.rows() - 1).cast<double>().transpose();
  double length = 0;
  for (Eigen::Index i = 1; i < points.rows(); ++i)
    length += (points.row(i) - points.row(i - 1)).cast<double>().norm();
  OrientationEvidence evidence;
  const double first_distance = head_distance.distance(first);
  const double last_distance = head_distance.distance(last);
  evidence.scalp_distance_slope = (last_distance - first_distance) / std::max(1e-12, length);
  evidence.height_slope = (first.y() - last.y()) / std::max(1e-12, length);
  evidence.head_distance_min_m = std::min(first_distance, last_distance);
  if (line.fade_mean_fall > 0) {
    evidence.alpha_fade_vote = line.fade_vote;
    evidence.alpha_fade_mean_fall = line.fade_mean_fall;
  }
  return *decide_orientation(evidence, thresholds, MeshConventions{false, std::nullopt});
}

/// The streamlines of a patch whose rails cross its paint, oriented, in this order:
///  0. where the patch's rails were decided by a confident rule (vertex order, head
///     distance, continuation, parting), a streamline runs the way its nearest rail
///     segments do (mean cosine at least 0.3, within `near_m`);
///  1. continuation at its ends: other patches' strand ends there (`other_ends`, as for
///     rails, decide_by_continuation_once()), kept only where neighbouring votes agree;
///  2. spread through the patch: a streamline runs the way its decided neighbours do;
///  3. the patch's rails decided by weaker rules;
///  4. its own ends (head distance, alpha fade, height: own_orientation()).
/// The group's decision is continuation, the rails' decision or the most common own rule,
/// whichever oriented most streamlines.
PatchStreamlines oriented_streamlines(std::vector<PaintedStreamline> lines, int32_t patch,
                                      const StrandEndIndex& other_ends, const SegmentIndex& rails,
                                      const OrientationDecision& rails_decision,
                                      bool rails_run_along_the_hair, double near_m,
                                      const TriangleMeshDistance& head_distance,
                                      const OrientationThresholds& thresholds) {
  constexpr double min_mean_cosine = 0.3;
  const auto radius = static_cast<float>(near_m);
  const size_t count = lines.size();
  std::vector<int> sense(count, 0);  // +1 as traced, -1 reversed, 0 undecided
  std::vector<bool> by_rails(count, false);
  int continued = 0, followed_rails = 0;

  // The patch's own decided rails, where they say which way the hair runs near a
  // streamline.
  auto follow_rails = [&] {
    if (rails.empty() || !rails_run_along_the_hair) return;
    for (size_t i = 0; i < count; ++i) {
      if (sense[i] != 0) continue;
      int judged = 0;
      const double cosine_sum = rails.agreement(lines[i].points, radius, judged);
      if (judged >= 2 && std::abs(cosine_sum) >= min_mean_cosine * judged) {
        sense[i] = cosine_sum > 0 ? 1 : -1;
        by_rails[i] = true;
        ++followed_rails;
      }
    }
  };
  // 0. Rails decided by a confident rule (vertex order, head distance, continuation,
  // parting) come first: a braid's pieces weave past each other's ends, so what lies at a
  // streamline's ends says less there than the piece's rails.
  const bool rails_confident = rails_decision.rule == OrientationRule::vertex_order ||
                               rails_decision.rule == OrientationRule::scalp_distance ||
                               rails_decision.rule == OrientationRule::continuation ||
                               rails_decision.rule == OrientationRule::parting;
  if (rails_confident) follow_rails();

  // 1. Continuation at the ends: the strands of other patches there.
  for (size_t i = 0; i < count; ++i) {
    if (sense[i] != 0) continue;
    const Points3f& points = lines[i].points;
    const Eigen::Index n = points.rows();
    const Eigen::Vector3f first = points.row(0).transpose(), last = points.row(n - 1).transpose();
    const int score =
        other_ends.vote(first, (first - Eigen::Vector3f(points.row(1).transpose())).normalized(),
                        patch, radius) -
        other_ends.vote(last, (last - Eigen::Vector3f(points.row(n - 2).transpose())).normalized(),
                        patch, radius);
    if (score != 0) {
      sense[i] = score > 0 ? 1 : -1;
      ++continued;
    }
  }
  // 1b. Votes at the ends must agree with each other where they are neighbours (a layered
  // cut puts other layers' roots beside this one's roots, which reads as a tip there): if
  // fewer than three quarters of the voting streamlines that have a voting neighbour run
  // its way, the votes are dropped.
  if (continued > 0) {
    std::vector<size_t> voters;
    for (size_t i = 0; i < count; ++i)
      if (sense[i] != 0 && !by_rails[i]) voters.push_back(i);
    SegmentIndex votes;
    for (size_t i : voters) votes.add(lines[i].points, sense[i], i);
    votes.build();
    int with_neighbour = 0, agreeing = 0;
    for (size_t i : voters) {
      int judged = 0;
      const double cosine_sum =
          sense[i] * votes.agreement(lines[i].points, 2 * radius, judged, i);
      if (judged < 2 || std::abs(cosine_sum) < min_mean_cosine * judged) continue;
      ++with_neighbour;
      agreeing += cosine_sum > 0 ? 1 : 0;
    }
    if (with_neighbour > 0 && agreeing < 0.75 * with_neighbour) {
      for (size_t i : voters) sense[i] = 0;
      continued = 0;
    }
  }

  // 2. ...carried through the patch: a streamline runs the way its decided neighbours do
  // (the paint's flow is smooth), in rounds, so that it spreads across a cap.
  for (int round = 0; round < 32 && continued + followed_rails > 0; ++round) {
    SegmentIndex decided_segments;
    for (size_t i = 0; i < count; ++i)
      if (sense[i] != 0) decided_segments.add(lines[i].points, sense[i], i);
    decided_segments.build();
    int decided = 0;
    std::vector<int> next = sense;
    for (size_t i = 0; i < count; ++i) {
      if (sense[i] != 0) continue;
      int judged = 0;
      const double cosine_sum = decided_segments.agreement(lines[i].points, 2 * radius, judged);
      if (judged >= 2 && std::abs(cosine_sum) >= min_mean_cosine * judged) {
        next[i] = cosine_sum > 0 ? 1 : -1;
        ++decided;
      }
    }
    sense = std::move(next);
    continued += decided;
    if (decided == 0) break;
  }
  // 3. Else the patch's rails, decided by a weaker rule (uv, height, alpha fade).
  if (!rails_confident) follow_rails();
  // 4. Each remaining streamline on its own.
  PatchStreamlines result;
  std::array<int, 7> rule_count{};
  double confidence_sum = 0;
  int on_their_own = 0;
  for (size_t i = 0; i < count; ++i) {
    if (sense[i] == 0) {
      const OrientationDecision decision = own_orientation(lines[i], head_distance, thresholds);
      sense[i] = decision.reverse ? -1 : 1;
      ++rule_count[static_cast<size_t>(decision.rule)];
      confidence_sum += decision.confidence;
      ++on_their_own;
    }
    Points3f& points = lines[i].points;
    if (sense[i] < 0) points = points.colwise().reverse().eval();
    result.polylines.push_back(std::move(points));
  }
  spdlog::debug("patch {}: {} streamlines continue others or their neighbours, {} follow the "
                "rails, {} on their own",
                patch, continued, followed_rails, on_their_own);
  if (continued >= std::max(followed_rails, on_their_own)) {
    result.decision = OrientationDecision{false, OrientationRule::continuation,
                                          static_cast<float>(continued) / static_cast<float>(count)};
  } else if (followed_rails >= on_their_own) {
    result.decision = rails_decision;
  } else {
    result.decision.rule = static_cast<OrientationRule>(
        std::max_element(rule_count.begin(), rule_count.end()) - rule_count.begin());
    result.decision.confidence = static_cast<float>(confidence_sum / on_their_own);
  }
  return result;
}

/// The strands, group (patch) by group: each region's rails in their decided direction,
/// or one strand along a patch without usable quads; the group's kind, rule and
/// confidence (those of its region with the most rails) into `result`.
void group_strands(const MeshPatches& patches, const std::vector<PatchTopology>& topologies,
                   const std::vector<std::vector<int>>& along, std::vector<RegionRails>& regions,
                   std::vector<std::optional<std::vector<PaintedStreamline>>> traced,
                   const std::vector<std::optional<double>>& rails_along_share,
                   const ExtractParams& params, double near_m,
                   const TriangleMeshDistance& head_distance,
                   const OrientationThresholds& thresholds, const EdgeFaces& edge_faces,
                   ExtractResult& result) {
  const Points3f& vertices = result.hair_mesh.vertices;
  std::vector<Points3f> polylines;
  std::vector<int32_t> strand_group, strand_rail, source_vertex;
  std::vector<bool> is_traced(traced.size());
  for (size_t p = 0; p < traced.size(); ++p) is_traced[p] = traced[p].has_value();
  const StrandEndIndex untraced_ends(vertices, regions, is_traced);
  size_t next_region = 0;
  for (int32_t p = 0; p < patches.patch_count(); ++p) {
    int32_t rail_in_patch = 0;
    size_t largest_rail_count = 0;
    OrientationDecision group_decision{false, OrientationRule::height, 0.0f};
    auto add_rail = [&](const std::vector<int32_t>& rail) {
      append_rail(polylines, vertices, rail, source_vertex);
      strand_group.push_back(p);
      strand_rail.push_back(rail_in_patch++);
    };
    const size_t first_region = next_region;
    const bool traced_patch = traced[static_cast<size_t>(p)] && !traced[static_cast<size_t>(p)]->empty();
    for (; next_region < regions.size() && regions[next_region].patch == p; ++next_region) {
      RegionRails& region = regions[next_region];
      if (!traced_patch) {
        for (auto& rail : region.open_rails) {
          if (region.decision->reverse) std::reverse(rail.begin(), rail.end());
          add_rail(rail);
        }
        for (const auto& rail : region.parted_rails) add_rail(rail);
      }
      size_t rail_count = region.open_rails.size() + region.parted_rails.size();
      if (rail_count > largest_rail_count) {
        largest_rail_count = rail_count;
        group_decision = region.open_rails.size() >= region.parted_rails.size()
                             ? *region.decision
                             : OrientationDecision{false, OrientationRule::parting, 1.0f};
      }
    }
    if (traced_patch) {
      PatchStreamlines oriented = oriented_streamlines(
          std::move(*traced[static_cast<size_t>(p)]), p, untraced_ends,
          decided_rail_segments(result.hair_mesh, result.painted_flow, edge_faces,
                                std::span<const RegionRails>(regions).subspan(
                                    first_region, next_region - first_region)),
          group_decision,
          rails_along_share[static_cast<size_t>(p)].value_or(0) >=
              params.streamline_rails_min_along_share,
          near_m, head_distance, thresholds);
      for (Points3f& polyline : oriented.polylines) {
        source_vertex.insert(source_vertex.end(), static_cast<size_t>(polyline.rows()), -1);
        polylines.push_back(std::move(polyline));
        strand_group.push_back(p);
        strand_rail.push_back(rail_in_patch++);
      }
      group_decision = oriented.decision;
    }
    PatchKind kind = patch_kind(topologies[p], along[p]);
    if (rail_in_patch == 0 || kind == PatchKind::triangle_soup) {
      kind = PatchKind::triangle_soup;
      auto [polyline, decision] =
          triangle_soup_strand(result.hair_mesh, patches.patch_faces[p], head_distance, thresholds);
      group_decision = decision;
      source_vertex.insert(source_vertex.end(), static_cast<size_t>(polyline.rows()), -1);
      polylines.push_back(std::move(polyline));
      strand_group.push_back(p);
      strand_rail.push_back(rail_in_patch++);
    }
    result.group_first_strand.push_back(static_cast<int32_t>(polylines.size()));
    result.group_kind.push_back(kind);
    result.group_rule.push_back(group_decision.rule);
    result.group_confidence.push_back(group_decision.confidence);
    result.group_face_count.push_back(static_cast<int32_t>(patches.patch_faces[p].size()));
    ++result.stats.groups_by_rule[static_cast<size_t>(group_decision.rule)];
    ++result.stats.groups_by_kind[static_cast<size_t>(kind)];
  }
  result.strands = strand_set_from_polylines(polylines);
  result.strands.strand_attributes["group"] = std::move(strand_group);
  result.strands.strand_attributes["rail"] = std::move(strand_rail);
  result.strands.point_attributes["source_vertex"] = std::move(source_vertex);
  check_strand_set(result.strands);
}

}  // namespace

ExtractResult extract_strands(PolyMesh hair_mesh, PolyMesh body_mesh, const ExtractParams& params,
                              const std::string& hair_file, const std::string& body_file,
                              const PaintedTextures& textures) {
  check_extract_params(params);
  ExtractResult result;
  MeshCleanup cleanup = clean_mesh(hair_mesh, hair_file);
  clean_mesh(body_mesh, body_file);
  hair_mesh.vertices *= static_cast<float>(params.unit_scale);
  body_mesh.vertices *= static_cast<float>(params.unit_scale);
  result.stats.degenerate_faces_removed = cleanup.degenerate_faces_removed;

  // The body: head height H, head region, triangles.
  result.head = head_measures(body_mesh, body_file);
  if (params.head_height_m > 0) {
    result.head.head_height = params.head_height_m;
    result.head.neck_y = result.head.head_top_y - params.head_height_m;
  }
  const double head_height_m = result.head.head_height;
  result.body_vertices = body_mesh.vertices;
  result.body_triangles = fan_triangulation(body_mesh.face_offsets, body_mesh.face_vertices);
  TriangleMeshDistance head_distance(
      result.body_vertices, head_triangles_of(result.body_vertices, result.body_triangles,
                                              result.head.neck_y, body_file));

  // The hair: quads, patches, edge families.
  QuadRecovery recovered = quads_from_triangles(hair_mesh, params.max_quad_corner_deviation_deg);
  result.stats.triangles_paired = recovered.triangles_paired;
  result.stats.triangles_left = recovered.triangles_left;
  result.hair_mesh = std::move(recovered.mesh);
  const Points3f& vertices = result.hair_mesh.vertices;
  MeshPatches patches = mesh_patches(result.hair_mesh);
  result.face_group = patches.face_patch;
  std::vector<PatchTopology> topologies(static_cast<size_t>(patches.patch_count()));
#pragma omp parallel for schedule(dynamic)
  for (int32_t p = 0; p < patches.patch_count(); ++p)
    topologies[p] = patch_topology(result.hair_mesh, patches.patch_faces[p]);

  // The painted flow, and the family of each region that runs along the hair.
  result.painted_flow = painted_flow(result.hair_mesh, textures, params.painted_flow);
  const PaintedFlow no_flow;
  const PaintedFlow& guiding_flow = params.paint_guides_strands ? result.painted_flow : no_flow;
  const EdgeFaces edge_faces(result.hair_mesh);
  const auto paint = family_paint(result.hair_mesh, guiding_flow, edge_faces, topologies);
  std::vector<std::vector<int>> along = along_families(topologies, paint, params, result.stats);

  // Rails, their directions, and the strands group by group.
  std::vector<RegionRails> regions =
      region_rails(result.hair_mesh, guiding_flow, edge_faces, topologies, along,
                   head_distance, params, head_height_m, result.stats);
  OrientationThresholds thresholds;
  thresholds.vertex_order_min_vote = params.vertex_order_min_vote;
  thresholds.scalp_distance_min_slope = params.scalp_distance_min_slope;
  thresholds.scalp_distance_lean_slope = params.scalp_distance_lean_slope;
  thresholds.uv_min_growth = params.uv_min_growth;
  thresholds.height_min_slope = params.height_min_slope;
  thresholds.height_min_head_distance_m = params.height_min_head_distance_h * head_height_m;
  thresholds.alpha_fade_min_fall = params.alpha_fade_min_fall;
  thresholds.alpha_fade_min_rail_fall = params.alpha_fade_min_rail_fall;

  // Patches whose rails would cross the paint are cut into strands along it instead;
  // their rails still take part in deciding directions, and orient the strands. Only
  // patches lying on the head are traced (caps and wigs, whose texture is unwrapped in
  // fans while their quads run in rings); cards, tubes and braid pieces hanging off it
  // keep their rails: the strokes painted on a braid's pieces twist around them, while
  // the bundle runs along the piece.
  std::vector<std::optional<std::vector<PaintedStreamline>>> traced(topologies.size());
  std::vector<std::optional<double>> rails_along_share(topologies.size());
  for (int32_t p = 0; p < patches.patch_count(); ++p)
    rails_along_share[static_cast<size_t>(p)] =
        rails_along_paint_share(topologies[p], paint[p], along[p], params);
#pragma omp parallel for schedule(dynamic)
  for (int32_t p = 0; p < patches.patch_count(); ++p)
    if (patch_kind(topologies[p], along[p]) != PatchKind::tube &&
        rails_along_share[static_cast<size_t>(p)] &&
        *rails_along_share[static_cast<size_t>(p)] < params.streamline_max_along_share &&
        lies_on_the_head(result.hair_mesh, patches.patch_faces[p], head_distance,
                         params.streamline_max_head_distance_h * head_height_m)) {
      StreamlineParams streamline_params;
      streamline_params.spacing_m =
          std::max(1e-6, median_edge_length(result.hair_mesh, patches.patch_faces[p]));
      streamline_params.min_length_m = 2 * streamline_params.spacing_m;
      traced[p] = painted_streamlines(result.hair_mesh, result.painted_flow,
                                      patches.patch_faces[p], streamline_params);
    }
  for (int32_t p = 0; p < patches.patch_count(); ++p)
    if (traced[static_cast<size_t>(p)]) {
      ++result.stats.patches_traced_along_paint;
      spdlog::debug(
          "{}: patch {} ({} faces, rails along the paint on {:.2f} of their length) traced along "
          "its paint: {} strands",
          hair_file, p, patches.patch_faces[p].size(), *rails_along_share[static_cast<size_t>(p)],
          traced[static_cast<size_t>(p)]->size());
    }
  decide_directions(vertices, regions, thresholds, params, head_height_m, result.stats);
  group_strands(patches, topologies, along, regions, std::move(traced), rails_along_share, params,
                params.continuation_radius_h * head_height_m, head_distance, thresholds, edge_faces,
                result);
  // Last, a strand that runs against the rest of its group turns round (the hair a patch
  // shows flows smoothly across it), within twice the continuation radius.
  GroupSenseParams sense;
  sense.radius_m = 2 * params.continuation_radius_h * head_height_m;
  result.stats.strands_turned_to_their_group =
      turn_strands_against_their_group(result.strands, result.group_first_strand, sense);

  ScalpParams scalp;
  scalp.neck_y = result.head.neck_y;
  scalp.max_distance_m = params.scalp_distance_h * head_height_m;
  scalp.under_hair_m = params.scalp_under_hair_h * head_height_m;
  scalp.under_hair_min_height_m = params.scalp_under_hair_min_height_h * head_height_m;
  scalp.face_below_y = result.head.head_top_y - params.scalp_face_below_top_h * head_height_m;
  scalp.face_radius_m = kFaceRadiusH * head_height_m;
  scalp.face_depth_m = kFaceDepthH * head_height_m;
  scalp.face_half_width_m = kFaceHalfWidthH * head_height_m;
  scalp.ear_thickness_m = kEarThicknessH * head_height_m;
  result.scalp_triangle =
      scalp_triangles(result.body_vertices, result.body_triangles, result.hair_mesh, scalp);
  return result;
}

}  // namespace hair
