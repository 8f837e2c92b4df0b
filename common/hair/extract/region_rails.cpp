// The rails of each quad region: the family that runs along the hair, its chains, and the
// parting of closed, draped and folded ones.
#include "hair/extract/region_rails.h"

#include <algorithm>
#include <cmath>
#include <cstddef>

#include "hair/extract/region_orientation.h"

namespace hair {
namespace {

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

}  // namespace

std::optional<double> share_true(const std::vector<bool>& observations) {
  if (observations.size() < 3) return std::nullopt;
  return static_cast<double>(std::count(observations.begin(), observations.end(), true)) /
         static_cast<double>(observations.size());
}

std::vector<std::vector<int>> along_families(
    const Points3f& vertices, const std::vector<PatchTopology>& topologies,
    const std::vector<std::vector<std::array<FamilyPaint, 2>>>& paint,
    const Eigen::Vector3d& head_centre, double head_height_m, const ExtractParams& params,
    ExtractStats& stats) {
  constexpr double min_alignment_difference = 0.2;
  auto paint_decides = [&](size_t p, size_t r) {
    return family_along_paint(paint[p][r], params.along_paint_min_judged_share,
                              params.along_paint_min_gap);
  };
  CirclingLimits circling;
  circling.min_circling_share = params.along_circling_min_share;
  circling.min_sweep_deg = params.along_circling_min_sweep_deg;
  circling.max_other_circling_share = 1 - params.along_circling_min_share;
  circling.other_min_length_m = params.along_circling_other_min_length_h * head_height_m;
  // The family across rings round the head, per region (-1: none), once. Where the paint
  // is clear, it says where the hair runs, whatever the mesh's shape.
  std::vector<std::vector<int>> across(topologies.size());
  for (size_t p = 0; p < topologies.size(); ++p)
    for (size_t r = 0; r < topologies[p].regions.size(); ++r) {
      const auto& f = topologies[p].regions[r].families;
      int family = -1;
      if (std::min(paint[p][r][0].judged_share, paint[p][r][1].judged_share) <
          params.along_paint_min_judged_share) {
        const Eigen::Vector3d axis = region_axis_direction(vertices, f[0], head_centre);
        family = family_across_rings({family_circling(vertices, f[0], head_centre, axis),
                                      family_circling(vertices, f[1], head_centre, axis)},
                                     circling);
      }
      across[p].push_back(family);
    }
  auto across_rings = [&](size_t p, size_t r) { return across[p][r]; };
  std::vector<bool> along_is_v;  // clear regions: does the along family follow v?
  for (size_t p = 0; p < topologies.size(); ++p)
    for (size_t r = 0; r < topologies[p].regions.size(); ++r) {
      const auto& f = topologies[p].regions[r].families;
      double longer = std::max(f[0].mean_chain_length, f[1].mean_chain_length);
      double shorter = std::min(f[0].mean_chain_length, f[1].mean_chain_length);
      if (f[0].v_alignment < 0 || std::abs(f[0].v_alignment - f[1].v_alignment) < min_alignment_difference)
        continue;
      int along = paint_decides(p, r);
      if (along < 0) along = across_rings(p, r);
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
      } else if (int family = across_rings(p, r); family >= 0) {
        rule = AlongRule::across_rings;
        chosen = family;
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

double rail_length(const Points3f& vertices, const std::vector<int32_t>& rail) {
  double length = 0;
  for (size_t i = 1; i < rail.size(); ++i)
    length += (vertices.row(rail[i]) - vertices.row(rail[i - 1])).cast<double>().norm();
  return length;
}

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

}  // namespace hair
