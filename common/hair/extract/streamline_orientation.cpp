// The orientation of the strands traced along a patch's paint: which patches are traced,
// and the sense their streamlines take (oriented_streamlines()).
#include "hair/extract/streamline_orientation.h"

#include <spdlog/spdlog.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <utility>

namespace hair {
namespace {

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

/// The least mean cosine between a streamline's segments and the oriented segments near
/// them for these to say which way it runs.
constexpr double kMinMeanCosine = 0.3;

/// 1. Continuation at the ends: each undecided streamline (`sense` 0) takes the sense the
/// strands of other patches at its ends give it (StrandEndIndex::vote(), within `radius`).
/// Returns how many it decided.
int continue_other_strands(const std::vector<PaintedStreamline>& lines, int32_t patch,
                           const StrandEndIndex& other_ends, float radius,
                           std::vector<int>& sense) {
  int continued = 0;
  for (size_t i = 0; i < lines.size(); ++i) {
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
  return continued;
}

/// 1b. Votes at the ends must agree with each other where they are neighbours (a layered
/// cut puts other layers' roots beside this one's roots, which reads as a tip there): if
/// fewer than three quarters of the voting streamlines (decided, not `by_rails`) that have
/// a voting neighbour within `2 * radius` run its way, the votes are dropped (their `sense`
/// set back to 0). Returns whether they were.
bool drop_disagreeing_end_votes(const std::vector<PaintedStreamline>& lines,
                                const std::vector<bool>& by_rails, float radius,
                                std::vector<int>& sense) {
  std::vector<size_t> voters;
  for (size_t i = 0; i < lines.size(); ++i)
    if (sense[i] != 0 && !by_rails[i]) voters.push_back(i);
  SegmentIndex votes;
  for (size_t i : voters) votes.add(lines[i].points, sense[i], i);
  votes.build();
  int with_neighbour = 0, agreeing = 0;
  for (size_t i : voters) {
    int judged = 0;
    const double cosine_sum =
        sense[i] * votes.agreement(lines[i].points, 2 * radius, judged, i);
    if (judged < 2 || std::abs(cosine_sum) < kMinMeanCosine * judged) continue;
    ++with_neighbour;
    agreeing += cosine_sum > 0 ? 1 : 0;
  }
  if (with_neighbour > 0 && agreeing < 0.75 * with_neighbour) {
    for (size_t i : voters) sense[i] = 0;
    return true;
  }
  return false;
}

/// 2. ...carried through the patch: a streamline runs the way its decided neighbours do
/// (the paint's flow is smooth), in rounds, so that it spreads across a cap. Returns how
/// many streamlines it decided.
int spread_to_neighbours(const std::vector<PaintedStreamline>& lines, float radius,
                         std::vector<int>& sense) {
  const size_t count = lines.size();
  int spread = 0;
  for (int round = 0; round < 32; ++round) {
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
      if (judged >= 2 && std::abs(cosine_sum) >= kMinMeanCosine * judged) {
        next[i] = cosine_sum > 0 ? 1 : -1;
        ++decided;
      }
    }
    sense = std::move(next);
    spread += decided;
    if (decided == 0) break;
  }
  return spread;
}

}  // namespace

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

void SegmentIndex::add(const Points3f& points, int sense, size_t owner) {
  for (Eigen::Index k = 1; k < points.rows(); ++k) {
    Eigen::Vector3f segment = points.row(k) - points.row(k - 1);
    if (!(segment.norm() > 0)) continue;
    direction_.push_back(static_cast<float>(sense) * segment.normalized());
    midpoints_.push_back(0.5f * (points.row(k) + points.row(k - 1)).transpose());
    owner_.push_back(owner);
  }
}

void SegmentIndex::build() {
  Points3f rows(static_cast<Eigen::Index>(midpoints_.size()), 3);
  for (size_t k = 0; k < midpoints_.size(); ++k)
    rows.row(static_cast<Eigen::Index>(k)) = midpoints_[k].transpose();
  if (rows.rows() > 0) index_.emplace(rows);
}

double SegmentIndex::agreement(const Points3f& points, float radius, int& judged,
                               std::optional<size_t> skip_owner) const {
  double cosine_sum = 0;
  judged = 0;
  if (!index_) return 0;
  for (Eigen::Index k = 1; k < points.rows(); ++k) {
    Eigen::Vector3f segment = points.row(k) - points.row(k - 1);
    if (!(segment.norm() > 0)) continue;
    Eigen::Vector3f midpoint = 0.5f * (points.row(k) + points.row(k - 1)).transpose();
    index_->visit_within(midpoint, radius, [&](int32_t id) {
      if (skip_owner && owner_[static_cast<size_t>(id)] == *skip_owner) return true;
      cosine_sum += segment.normalized().dot(direction_[static_cast<size_t>(id)]);
      ++judged;
      return false;  // the nearest
    });
  }
  return cosine_sum;
}

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

PatchStreamlines oriented_streamlines(std::vector<PaintedStreamline> lines, int32_t patch,
                                      const StrandEndIndex& other_ends, const SegmentIndex& rails,
                                      const OrientationDecision& rails_decision,
                                      bool rails_run_along_the_hair, double near_m,
                                      const TriangleMeshDistance& head_distance,
                                      const OrientationThresholds& thresholds) {
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
      if (judged >= 2 && std::abs(cosine_sum) >= kMinMeanCosine * judged) {
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

  // 1. Continuation at the ends: the strands of other patches there, dropped where the
  // votes of neighbours disagree (1b); 2. carried through the patch to their neighbours.
  continued = continue_other_strands(lines, patch, other_ends, radius, sense);
  if (continued > 0 && drop_disagreeing_end_votes(lines, by_rails, radius, sense)) continued = 0;
  if (continued + followed_rails > 0) continued += spread_to_neighbours(lines, radius, sense);
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

}  // namespace hair
