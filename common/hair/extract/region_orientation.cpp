// The direction of each quad region's rails: the evidence, the mesh's conventions, the
// overrule passes and the order they run in (decide_directions()).
#include "hair/extract/region_orientation.h"

#include <spdlog/spdlog.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include "hair/extract/continuation.h"

namespace hair {
namespace {

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

}  // namespace

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

}  // namespace hair
