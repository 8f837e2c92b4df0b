#include "hair/grow/strand_growing.h"

#include <spdlog/spdlog.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <map>
#include <memory>
#include <numbers>
#include <numeric>
#include <optional>

#include "hair/core/error.h"
#include "hair/geom/body_sdf.h"
#include "hair/geom/point_index.h"
#include "hair/geom/triangle_mesh_distance.h"
#include "hair/grow/card_surfaces.h"
#include "hair/grow/grow_params.h"
#include "hair/grow/orientation_field.h"
#include "hair/grow/painted_field_seeds.h"
#include "hair/grow/shell_field_seeds.h"
#include "hair/grow/surface_sampling.h"

namespace hair {

const char* grow_rule_name(GrowRule rule) {
  switch (rule) {
    case GrowRule::root:
      return "root";
    case GrowRule::field:
      return "field";
    case GrowRule::input_strand:
      return "input_strand";
    case GrowRule::bridge:
      return "bridge";
  }
  return "?";
}

namespace {

using Vec3 = Eigen::Vector3d;

bool is_root_type(GroupType type) {
  return type == GroupType::root_free || type == GroupType::root_connected;
}

/// A place where a strand can be entered at the end of another: the first point of an
/// input strand (followed root to tip) or its last (followed backwards, for pieces that
/// extract read tip to root).
struct StrandEntry {
  int32_t strand = -1;
  bool backward = false;
};

/// Everything the growing of one strand looks up, built once.
class GrowingContext {
 public:
  /// With `any_type_roots`, roots take any input strand whatever the types say.
  GrowingContext(const GrowInput& input, const GrowParams& params, bool any_type_roots)
      : input_(input), params_(params), h_(input.head_height_m) {
    const StrandSet& strands = input.input_strands;
    const auto& group = std::get<std::vector<int32_t>>(strands.strand_attributes.at("group"));
    strand_group_ = group;
    int64_t strand_count = strands.strand_count();
    group_strands_.resize(input.group_type.size());
    for (int64_t s = 0; s < strand_count; ++s)
      group_strands_[static_cast<size_t>(group[static_cast<size_t>(s)])].push_back(
          static_cast<int32_t>(s));

    // Points of the strands that carry roots, for the roots' clusters and reference
    // lengths: root-type strands of clusters that start at the root; else any root-type
    // strand; else any strand.
    std::vector<int64_t> rows;
    for (int64_t s = 0; s < strand_count && !any_type_roots; ++s)
      if (carries_roots(s))
        for (int64_t row = strands.offsets[s]; row < strands.offsets[s + 1]; ++row)
          rows.push_back(row);
    if (rows.empty() && !any_type_roots) {
      for (int64_t s = 0; s < strand_count; ++s)
        if (is_root_type(type_of_strand(s)))
          for (int64_t row = strands.offsets[s]; row < strands.offsets[s + 1]; ++row)
            rows.push_back(row);
    }
    if (rows.empty()) {
      any_type_roots_ = true;
      for (int64_t row = 0; row < strands.point_count(); ++row) rows.push_back(row);
    }
    root_point_rows_ = rows;
    Points3f root_points(static_cast<Eigen::Index>(rows.size()), 3);
    for (size_t i = 0; i < rows.size(); ++i)
      root_points.row(static_cast<Eigen::Index>(i)) = strands.points.row(rows[i]);
    root_index_ = std::make_unique<PointIndex>(root_points);
    point_strand_.resize(static_cast<size_t>(strands.point_count()));
    for (int64_t s = 0; s < strand_count; ++s)
      for (int64_t row = strands.offsets[s]; row < strands.offsets[s + 1]; ++row)
        point_strand_[static_cast<size_t>(row)] = static_cast<int32_t>(s);

    // Per group, an index of its points for follow().
    group_index_.resize(group_strands_.size());
    group_rows_.resize(group_strands_.size());
    group_reach_m_.assign(group_strands_.size(), 0.0);
    for (size_t g = 0; g < group_strands_.size(); ++g) {
      double longest_m = 0;
      for (int32_t s : group_strands_[g])
        for (int64_t row = strands.offsets[s]; row < strands.offsets[s + 1]; ++row) {
          group_rows_[g].push_back(row);
          if (row + 1 < strands.offsets[s + 1])
            longest_m = std::max(
                longest_m,
                (point_of(strands.points, row + 1) - point_of(strands.points, row)).norm());
        }
      Points3f points(static_cast<Eigen::Index>(group_rows_[g].size()), 3);
      for (size_t i = 0; i < group_rows_[g].size(); ++i)
        points.row(static_cast<Eigen::Index>(i)) = strands.points.row(group_rows_[g][i]);
      group_index_[g] = std::make_unique<PointIndex>(points);
      // A little beyond follow_radius_h + half the longest segment, for float rounding.
      group_reach_m_[g] = 1.01 * (params.follow_radius_h * h_ + 0.5 * longest_m) + 1e-6;
    }

    // Entries: both ends of every input strand.
    Points3f entry_points(2 * strand_count, 3);
    for (int64_t s = 0; s < strand_count; ++s) {
      entry_points.row(2 * s) = strands.points.row(strands.offsets[s]);
      entry_points.row(2 * s + 1) = strands.points.row(strands.offsets[s + 1] - 1);
      entries_.push_back({static_cast<int32_t>(s), false});
      entries_.push_back({static_cast<int32_t>(s), true});
    }
    entry_index_ = std::make_unique<PointIndex>(entry_points);
    all_index_ = std::make_unique<PointIndex>(strands.points);

    // Groups that feed a continuation (a cap's cards whose tips meet the start of a tail
    // after its band): a strand of theirs ends within continued_root_radius_h of the
    // start of a strand of a cluster that does not start at the root.
    group_feeds_continuation_.assign(group_strands_.size(), 0);
    const double feed_m = params.continued_root_radius_h * h_;
    for (int64_t s = 0; s < strand_count; ++s) {
      const Vec3 tip = point_of(strands.points, strands.offsets[s + 1] - 1);
      for (int32_t e : entry_index_->within(tip.cast<float>(), static_cast<float>(feed_m))) {
        const StrandEntry& entry = entries_[static_cast<size_t>(e)];
        if (entry.backward || cluster_starts_at_root(cluster_of_strand(entry.strand)) ||
            group_of_strand(entry.strand) == group_of_strand(s))
          continue;
        group_feeds_continuation_[static_cast<size_t>(group_of_strand(s))] = 1;
        break;
      }
    }
    for (size_t g = 0; g < group_feeds_continuation_.size(); ++g) {
      if (!group_feeds_continuation_[g]) continue;
      const auto c = static_cast<size_t>(input_.group_cluster[g]);
      if (cluster_feeds_continuation_.size() <= c) cluster_feeds_continuation_.resize(c + 1, 0);
      cluster_feeds_continuation_[c] = 1;
    }

    // Strands whose tip hangs off the scalp: farther than continued_tip_off_scalp_h from
    // the centre of every scalp triangle (next_entry()).
    hangs_off_scalp_.assign(static_cast<size_t>(strand_count), 0);
    std::vector<Eigen::Index> scalp_rows;
    for (Eigen::Index t = 0; t < input.body_triangles.rows(); ++t)
      if (input.scalp_triangle[static_cast<size_t>(t)]) scalp_rows.push_back(t);
    if (!scalp_rows.empty()) {
      Points3f centres(static_cast<Eigen::Index>(scalp_rows.size()), 3);
      for (size_t i = 0; i < scalp_rows.size(); ++i) {
        Eigen::RowVector3f centre = Eigen::RowVector3f::Zero();
        for (int k = 0; k < 3; ++k)
          centre += input.body_vertices.row(input.body_triangles(scalp_rows[i], k));
        centres.row(static_cast<Eigen::Index>(i)) = centre / 3;
      }
      const PointIndex scalp_index(centres);
      const auto off_m = static_cast<float>(params.continued_tip_off_scalp_h * h_);
      for (int64_t s = 0; s < strand_count; ++s)
        hangs_off_scalp_[static_cast<size_t>(s)] =
            scalp_index.within(strands.points.row(strands.offsets[s + 1] - 1).transpose(), off_m)
                .empty();
    }

    // Heights above the body, for layers.
    if (params.layer_radius_h > 0) {
      body_distance_ =
          std::make_unique<TriangleMeshDistance>(input.body_vertices, input.body_triangles);
      height_m_.resize(static_cast<size_t>(strands.point_count()));
      for (int64_t row = 0; row < strands.point_count(); ++row)
        height_m_[static_cast<size_t>(row)] =
            body_distance_->distance(point_of(strands.points, row));
    }

    // The whole hair mesh with its paint: the strokes a bridge must not cut across, and
    // the way a stub lies.
    if (input.hair_triangles.rows() > 0 &&
        input.hair_triangle_flow.rows() == input.hair_triangles.rows())
      painted_hair_ =
          std::make_unique<TriangleMeshDistance>(input.hair_vertices, input.hair_triangles);

    // Each group's own faces, for the hold on its card's surface.
    if (params.follow_card_keep_h > 0 && input.hair_triangles.rows() > 0)
      card_surfaces_ =
          CardSurfaces(input.hair_vertices, input.hair_triangles, input.hair_triangle_group,
                       static_cast<int64_t>(group_strands_.size()));

    // Arc length from each point to its strand's tip.
    length_to_tip_m_.assign(static_cast<size_t>(strands.point_count()), 0.0);
    for (int64_t s = 0; s < strand_count; ++s)
      for (int64_t row = strands.offsets[s + 1] - 2; row >= strands.offsets[s]; --row)
        length_to_tip_m_[static_cast<size_t>(row)] =
            length_to_tip_m_[static_cast<size_t>(row + 1)] +
            (point_of(strands.points, row + 1) - point_of(strands.points, row)).norm();
  }

  GroupType type_of_strand(int64_t s) const {
    return input_.group_type[static_cast<size_t>(strand_group_[static_cast<size_t>(s)])];
  }
  int32_t cluster_of_strand(int64_t s) const {
    return input_.group_cluster[static_cast<size_t>(strand_group_[static_cast<size_t>(s)])];
  }
  int32_t group_of_strand(int64_t s) const { return strand_group_[static_cast<size_t>(s)]; }
  int32_t cluster_of_group(int32_t group) const {
    return input_.group_cluster[static_cast<size_t>(group)];
  }
  /// Whether a group of `cluster` feeds a continuation (a cap gathered into a band).
  bool cluster_feeds_continuation(int32_t cluster) const {
    return cluster >= 0 && static_cast<size_t>(cluster) < cluster_feeds_continuation_.size() &&
           cluster_feeds_continuation_[static_cast<size_t>(cluster)] != 0;
  }
  bool cluster_starts_at_root(int32_t cluster) const {
    const auto& starts = input_.cluster_starts_at_root;
    return starts.empty() || starts.at(static_cast<size_t>(cluster)) != 0;
  }
  /// A root-type strand of a cluster that starts at the root: roots grow near it.
  bool carries_roots(int64_t s) const {
    return is_root_type(type_of_strand(s)) && cluster_starts_at_root(cluster_of_strand(s));
  }
  /// A root-type strand of a cluster that does not start at the root: it continues
  /// another group (cluster-all's split_continued_roots).
  bool continues_another(int64_t s) const {
    return is_root_type(type_of_strand(s)) && !cluster_starts_at_root(cluster_of_strand(s));
  }
  bool any_type_roots() const { return any_type_roots_; }

  /// The input-strand point nearest `point` among the root-type strands (all strands
  /// when there are none): its row in input_strands.points.
  int64_t nearest_root_point(const Vec3& point) const {
    return root_point_rows_[static_cast<size_t>(
        root_index_->nearest(point.cast<float>(), 1).front())];
  }
  int32_t strand_of_point(int64_t row) const { return point_strand_[static_cast<size_t>(row)]; }

  bool layered() const { return body_distance_ != nullptr; }
  const CardSurfaces& card_surfaces() const { return card_surfaces_; }
  const TriangleMeshDistance& body_distance() const { return *body_distance_; }
  /// Height above the body of the input strand through `row`, `length_m` further along it
  /// towards its tip (its tip's height beyond it); `cursor` (a row of the same strand, at
  /// or after `row`) makes a walk along the strand linear.
  double height_along(int64_t row, double length_m, int64_t& cursor) const {
    const StrandSet& strands = input_.input_strands;
    int64_t last = strands.offsets[strand_of_point(row) + 1] - 1;
    double remaining_m = length_to_tip_m(row) - length_m;
    cursor = std::max(cursor, row);
    while (cursor < last && length_to_tip_m(cursor + 1) >= remaining_m) ++cursor;
    if (cursor == last) return height_m_[static_cast<size_t>(last)];
    double a = length_to_tip_m(cursor), b = length_to_tip_m(cursor + 1);
    double t = a > b ? std::clamp((a - remaining_m) / (a - b), 0.0, 1.0) : 0.0;
    return (1 - t) * height_m_[static_cast<size_t>(cursor)] +
           t * height_m_[static_cast<size_t>(cursor + 1)];
  }

  /// The reference point of the root `root_id` at `root`: the nearest point of a
  /// root-carrying strand, or with layers, that strand's point nearest the root on a strand
  /// drawn by hash among those of the nearest one's cluster within layer_radius_h.
  int64_t reference_row(const Vec3& root, int64_t root_id) const {
    int64_t nearest = nearest_root_point(root);
    if (!layered() || any_type_roots_) return nearest;
    int32_t cluster = cluster_of_strand(strand_of_point(nearest));
    // Per candidate strand, its nearest point: the ids come nearest first, so after a
    // stable sort by strand the first of each strand.
    std::vector<std::pair<int32_t, int64_t>> candidates;
    for (int32_t id :
         root_index_->within(root.cast<float>(), static_cast<float>(params_.layer_radius_h * h_))) {
      int64_t row = root_point_rows_[static_cast<size_t>(id)];
      int32_t s = strand_of_point(row);
      if (cluster_of_strand(s) == cluster) candidates.emplace_back(s, row);
    }
    if (candidates.empty()) return nearest;
    std::stable_sort(candidates.begin(), candidates.end(),
                     [](const auto& a, const auto& b) { return a.first < b.first; });
    candidates.erase(std::unique(candidates.begin(), candidates.end(),
                                 [](const auto& a, const auto& b) { return a.first == b.first; }),
                     candidates.end());
    // SplitMix64 of the root's id and the seed: the same draw whatever the thread count.
    uint64_t z = static_cast<uint64_t>(root_id) * 0x9E3779B97F4A7C15ull +
                 static_cast<uint64_t>(params_.seed) + 0x632BE59BD9B4E019ull;
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    z ^= z >> 31;
    return candidates[static_cast<size_t>(z % candidates.size())].second;
  }
  double length_to_tip_m(int64_t row) const { return length_to_tip_m_[static_cast<size_t>(row)]; }

  /// Closest point of the rails of `group` to `point`: the tangent there (along the
  /// reading direction) and whether the point lies past the end being read towards.
  struct Following {
    Vec3 direction;
    bool past_end = false;
    double distance_m = 0;        ///< from the rail
    Vec3 closest = Vec3::Zero();  ///< the rail's point nearest
  };
  /// Only rails within follow_radius_h are looked at: farther, the point is lost anyway
  /// (distance_m is then infinite).
  Following follow(int32_t group, bool backward, const Vec3& point) const {
    const StrandSet& strands = input_.input_strands;
    double best = std::numeric_limits<double>::infinity();
    Following result{Vec3::UnitY() * -1.0, true, best};
    const auto g = static_cast<size_t>(group);
    // A segment with a point within follow_radius_h has an end within that plus half its
    // length: the segments at the group's points within reach_m are all there can be.
    std::vector<int64_t> segments;  // first rows
    for (int32_t id :
         group_index_[g]->within(point.cast<float>(), static_cast<float>(group_reach_m_[g]))) {
      int64_t row = group_rows_[g][static_cast<size_t>(id)];
      int32_t s = strand_of_point(row);
      if (row > strands.offsets[s]) segments.push_back(row - 1);
      if (row + 1 < strands.offsets[s + 1]) segments.push_back(row);
    }
    std::sort(segments.begin(), segments.end());
    segments.erase(std::unique(segments.begin(), segments.end()), segments.end());
    for (int64_t row : segments) {
      int32_t s = strand_of_point(row);
      int64_t first = strands.offsets[s], last = strands.offsets[s + 1] - 1;
      Vec3 a = point_of(strands.points, row), b = point_of(strands.points, row + 1);
      Vec3 ab = b - a;
      double length2 = ab.squaredNorm();
      if (length2 <= 0) continue;
      double t = std::clamp((point - a).dot(ab) / length2, 0.0, 1.0);
      double distance2 = (a + t * ab - point).squaredNorm();
      if (distance2 >= best) continue;
      best = distance2;
      Vec3 direction = ab.normalized() * (backward ? -1.0 : 1.0);
      // Past the end: beyond the last segment's far end in the reading direction.
      bool at_end = backward ? (row == first && t <= 0.0) : (row == last - 1 && t >= 1.0);
      result = {direction, at_end && (point - (backward ? a : b)).dot(direction) >= 0,
                std::sqrt(distance2), a + t * ab};
    }
    return result;
  }

  /// The first point of `entry`'s strand where it is entered.
  Vec3 entry_start(const StrandEntry& entry) const {
    const StrandSet& strands = input_.input_strands;
    return point_of(strands.points, entry.backward ? strands.offsets[entry.strand + 1] - 1
                                                   : strands.offsets[entry.strand]);
  }

  /// Where a bridge from `here`, going `direction`, into the input strand of `entry` goes:
  /// its first point, read its way and short of its end, no farther than its start, that
  /// lies within a step of `here` or ahead within `max_angle_deg` (default
  /// bridge_max_angle_deg) of `direction`; std::nullopt where none does (or the angle is 0).
  std::optional<Vec3> bridge_target(const StrandEntry& entry, const Vec3& here,
                                    const Vec3& direction,
                                    std::optional<double> max_angle_deg = std::nullopt) const {
    const double angle_deg = max_angle_deg.value_or(params_.bridge_max_angle_deg);
    if (!(angle_deg > 0) || direction.squaredNorm() == 0) return std::nullopt;
    const StrandSet& strands = input_.input_strands;
    const int64_t first = strands.offsets[entry.strand],
                  last = strands.offsets[entry.strand + 1] - 1;
    const double step_m = params_.step_h * h_;
    const double start_gap_m = (entry_start(entry) - here).norm();
    const double min_cos = std::cos(angle_deg * std::numbers::pi / 180);
    for (int64_t k = 0; k < last - first; ++k) {
      const Vec3 p = point_of(strands.points, entry.backward ? last - k : first + k);
      const Vec3 gap = p - here;
      const double gap_m = gap.norm();
      if (gap_m > start_gap_m + step_m) continue;
      if (gap_m <= step_m || gap.dot(direction) >= min_cos * gap_m) return p;
    }
    return std::nullopt;
  }

  /// Whether a bridge from `from` to `to` runs more than bridge_paint_max_angle_deg off
  /// the clear paint of the hair face nearest its middle (within follow_radius_h); false
  /// where the gap is within a step, or no face near it has clear paint.
  bool crosses_paint(const Vec3& from, const Vec3& to) const {
    if (!(params_.bridge_paint_max_angle_deg > 0)) return false;
    const Vec3 gap = to - from;
    const double gap_m = gap.norm();
    if (gap_m <= params_.step_h * h_) return false;
    const std::optional<Vec3> flow = painted_flow_near(from + 0.5 * gap);
    if (!flow) return false;
    const double max_angle_rad = params_.bridge_paint_max_angle_deg * std::numbers::pi / 180;
    return std::abs(gap.dot(*flow)) < std::cos(max_angle_rad) * gap_m;
  }

  /// The clear painted flow axis (unit, either sense) of the hair face nearest `point`,
  /// where that face lies within follow_radius_h; std::nullopt where it does not, or its
  /// paint is not clear, or no paint was given.
  std::optional<Vec3> painted_flow_near(const Vec3& point) const {
    if (!painted_hair_) return std::nullopt;
    const TriangleMeshDistance::Nearest face = painted_hair_->nearest(point);
    if (face.triangle < 0 || face.distance > params_.follow_radius_h * h_) return std::nullopt;
    const Vec3 flow = point_of(input_.hair_triangle_flow, face.triangle);
    if (!(flow.norm() > 0)) return std::nullopt;
    return flow.normalized();
  }

  /// The best input strand to continue into from `point` going `direction`, among
  /// strands of groups not yet visited and not of `excluded_cluster`: the nearest entry
  /// (weighted by how much it turns), from `preferred_cluster` if any qualifies; with
  /// `hanging_continuations_only`, only the start of a tail or braid after its band.
  /// `from_card`: the strand is at the end of a card it followed, not of its field.
  std::optional<StrandEntry> next_entry(const Vec3& point, const Vec3& direction,
                                        const std::vector<int32_t>& visited_groups,
                                        int32_t preferred_cluster, int32_t excluded_cluster,
                                        bool from_card,
                                        bool hanging_continuations_only = false) const {
    const StrandSet& strands = input_.input_strands;
    double radius_m = params_.continue_radius_h * h_;
    double search_m = std::max(radius_m, params_.continued_root_radius_h * h_);
    double min_cos = std::cos(params_.continue_max_angle_deg * std::numbers::pi / 180);
    double min_cos_continued =
        std::cos(params_.continued_root_max_angle_deg * std::numbers::pi / 180);
    const bool leaving_roots = cluster_starts_at_root(preferred_cluster);
    std::optional<StrandEntry> best_same, best_other;
    double score_same = std::numeric_limits<double>::infinity(), score_other = score_same;
    for (int32_t e : entry_index_->within(point.cast<float>(), static_cast<float>(search_m))) {
      const StrandEntry& entry = entries_[static_cast<size_t>(e)];
      // Beyond continue_radius_h, and turning by more than continue_max_angle_deg, only
      // into the start of a group that continues another (root-type, in a cluster that
      // does not start at the root: a tail after its band); or, leaving a cluster that
      // starts at the root (once: not from piece to piece of what follows), into the start
      // of any strand of a cluster that does not and that hangs off the scalp
      // (continued_tip_off_scalp_h): a tail or braid after its band. One that ends over the
      // scalp lies on the hair there (a cap card read from its band end and typed as
      // continuing the cards beside it, spikes stacked on a cap), and a strand sent into it
      // would run back over the head or across the cap.
      const bool into_continuation =
          !entry.backward && !cluster_starts_at_root(cluster_of_strand(entry.strand)) &&
          (continues_another(entry.strand) ||
           (leaving_roots && hangs_off_scalp_[static_cast<size_t>(entry.strand)]));
      if (hanging_continuations_only &&
          !(into_continuation && hangs_off_scalp_[static_cast<size_t>(entry.strand)]))
        continue;
      double reach_m = into_continuation ? search_m : radius_m;
      if ((point_of(strands.points, entry.backward ? strands.offsets[entry.strand + 1] - 1
                                                   : strands.offsets[entry.strand]) -
           point)
              .norm() > reach_m)
        continue;
      int32_t group = group_of_strand(entry.strand);
      int32_t cluster = cluster_of_strand(entry.strand);
      if (cluster == excluded_cluster) continue;
      if (std::find(visited_groups.begin(), visited_groups.end(), group) != visited_groups.end())
        continue;
      int64_t first = strands.offsets[entry.strand], last = strands.offsets[entry.strand + 1] - 1;
      if (last - first < 1) continue;
      Vec3 start =
          entry.backward ? point_of(strands.points, last) : point_of(strands.points, first);
      Vec3 next =
          entry.backward ? point_of(strands.points, last - 1) : point_of(strands.points, first + 1);
      Vec3 leaving = (next - start).normalized();
      double turn_cos = leaving.dot(direction);
      if (turn_cos < (into_continuation ? min_cos_continued : min_cos)) continue;
      // Across a gap the hair goes on ahead: not back to a start behind it, nor sideways
      // to a card beside it (short01's spikes, stacked at every angle, chained round the
      // crown so). A tail after its band is entered as it turns, above, and a strand
      // hanging off the scalp (a braid's locks, crossing one another) as it lies.
      const bool checked_bridge =
          !into_continuation && !hangs_off_scalp_[static_cast<size_t>(entry.strand)];
      const std::optional<Vec3> target =
          checked_bridge ? bridge_target(entry, point, direction) : std::nullopt;
      if (checked_bridge && params_.bridge_max_angle_deg > 0 && !target) continue;
      // Nor from card to card across the paint between them (bridge_paint_max_angle_deg).
      // Out of the field a strand may rise across the hair it leaves into a card stacked
      // on it (a tuft standing on short01's cap, which no other hair reaches), as hair
      // rooted under such a tuft does.
      if (checked_bridge && from_card && crosses_paint(point, target.value_or(start))) continue;
      // Not behind us by more than the radius allows, and not across the gap sideways.
      Vec3 gap = start - point;
      double score = gap.norm() / reach_m + (1 - turn_cos);
      bool same = cluster == preferred_cluster;
      double& best_score = same ? score_same : score_other;
      auto& best_entry = same ? best_same : best_other;
      if (score < best_score) {
        best_score = score;
        best_entry = entry;
      }
    }
    return best_same ? best_same : best_other;
  }

  /// Where a strand that ends with no strand to continue into (its card ends on the cap)
  /// joins the cards feeding a continued cluster: the nearest point, within
  /// continue_radius_h, of an input strand of a group that feeds a continuation (not yet
  /// visited), running within continue_max_angle_deg of `direction`. Only hair that
  /// continues into a cluster not starting at the root has such groups (a tail after its
  /// band); elsewhere a strand ends where its card does.
  std::optional<int32_t> joined_feeder(const Vec3& point, const Vec3& direction,
                                       const std::vector<int32_t>& visited_groups) const {
    const StrandSet& strands = input_.input_strands;
    const double radius_m = params_.continue_radius_h * h_;
    const double min_cos = std::cos(params_.continue_max_angle_deg * std::numbers::pi / 180);
    std::optional<int32_t> best;
    double best_score = std::numeric_limits<double>::infinity();
    for (int32_t id : all_index_->within(point.cast<float>(), static_cast<float>(radius_m))) {
      const auto row = static_cast<int64_t>(id);
      const int32_t s = strand_of_point(row);
      const int32_t group = group_of_strand(s);
      if (!group_feeds_continuation_[static_cast<size_t>(group)] ||
          std::find(visited_groups.begin(), visited_groups.end(), group) != visited_groups.end())
        continue;
      if (row + 1 >= strands.offsets[s + 1]) continue;  // a tip: next_entry's business
      const Vec3 tangent =
          (point_of(strands.points, row + 1) - point_of(strands.points, row)).normalized();
      const double turn_cos = tangent.dot(direction);
      if (turn_cos < min_cos) continue;
      const double score =
          (point_of(strands.points, row) - point).norm() / radius_m + (1 - turn_cos);
      if (score < best_score) {
        best_score = score;
        best = group;
      }
    }
    return best;
  }

  const GrowInput& input() const { return input_; }
  const GrowParams& params() const { return params_; }

 private:
  const GrowInput& input_;
  const GrowParams& params_;
  double h_;
  std::vector<int32_t> strand_group_;
  std::vector<std::vector<int32_t>> group_strands_;
  std::vector<std::unique_ptr<PointIndex>> group_index_;  ///< per group, over group_rows_
  std::vector<std::vector<int64_t>> group_rows_;          ///< per group, its points' rows
  std::vector<double> group_reach_m_;                     ///< per group, for follow()
  std::vector<int64_t> root_point_rows_;
  std::unique_ptr<PointIndex> root_index_;
  std::vector<int32_t> point_strand_;
  std::vector<StrandEntry> entries_;
  /// Per input strand: whether its tip hangs off the scalp (next_entry()).
  std::vector<uint8_t> hangs_off_scalp_;
  std::unique_ptr<PointIndex> entry_index_;
  std::unique_ptr<PointIndex> all_index_;            ///< every input point, by row
  std::vector<uint8_t> group_feeds_continuation_;    ///< per group
  std::vector<uint8_t> cluster_feeds_continuation_;  ///< per cluster: one of its groups does
  std::vector<double> length_to_tip_m_;
  std::unique_ptr<TriangleMeshDistance> body_distance_;  ///< with layers only
  CardSurfaces card_surfaces_;  ///< empty without follow_card_keep_h or the hair mesh
  /// The whole hair mesh; null without its painted flow.
  std::unique_ptr<TriangleMeshDistance> painted_hair_;
  std::vector<double> height_m_;                         ///< per input point, with layers
  bool any_type_roots_ = false;
};

/// Near its root a strand heads the paint's way where the paint runs within this angle of
/// its field (GrowParams::root_heading_paint_h): as continue_max_angle_deg, a turn the
/// hair can take; paint farther off belongs to hair crossing over it.
const double kRootPaintMinCos = std::cos(60 * std::numbers::pi / 180);

/// Steps between two pulls of a strand towards its layer's height.
constexpr int kLayerEvery = 3;

/// A step that, once pushed out of the body, advanced less than this share of a step along
/// its direction ran into the body: where a card dives into the skin (bob01's front cards
/// into the forehead), the rail points into the body, every point is pushed back out, and
/// a strand that went on would tremble in place, 0.5 to 0.8 mm a step, until it reached
/// max_length_h in points (bob01: 51,226 of its 85,101 input-strand segments, in 174
/// strands). Hair stops where the body blocks it, so the strand ends there. A quarter:
/// sliding along the body's curve at the clearance advances far more (the step less what
/// the push-out removes, which is small unless the way runs into the surface), and
/// trembling far less. One such step alone is a corner the strand gets round (at the end
/// of ponytail01's cap field, before the band); kBlockedSteps in a row are the body.
constexpr double kBlockedAdvance = 0.25;
constexpr int kBlockedSteps = 2;

/// One strand being grown: its points and the rule of each.
struct GrowingStrand {
  std::vector<Vec3> points;
  std::vector<GrowRule> rules;
  std::vector<int32_t> clusters, groups;  ///< per point, as GrowResult::point_cluster, _group
  int64_t pushed_out = 0;
  int64_t continued_same = 0, continued_other = 0;
  int64_t joined = 0;  ///< times it joined the cards feeding a continuation (joined_feeder())
  bool ended_at_body = false;  ///< its last steps tried ran into the body (kBlockedAdvance)
  bool ended_at_fold = false;  ///< its next step, off the field, would have folded it back
  int blocked_steps = 0;       ///< steps in a row that hardly advanced
};

/// Grows one strand from its root (grow()): along its cluster's field, then along input
/// strands group after group, bridged from one to the next.
class StrandGrower {
 public:
  /// `field` is the root cluster's orientation field (null when the cluster has none).
  StrandGrower(const GrowingContext& context, const OrientationField* field, const BodySdf& body,
               int32_t root_cluster)
      : context_(context),
        params_(context.params()),
        field_(field),
        body_(body),
        root_cluster_(root_cluster),
        step_m_(params_.step_h * context.input().head_height_m),
        clearance_m_(params_.body_clearance_h * context.input().head_height_m),
        lost_m_(params_.follow_radius_h * context.input().head_height_m),
        keep_m_(params_.follow_keep_h * context.input().head_height_m),
        card_keep_m_(params_.follow_card_keep_h * context.input().head_height_m),
        root_heading_m_(params_.root_heading_paint_h * context.input().head_height_m),
        min_turn_cos_(std::cos(params_.max_turn_deg * std::numbers::pi / 180) - 1e-9),
        min_gathered_turn_cos_(
            std::min(min_turn_cos_,
                     std::cos(params_.continued_root_max_angle_deg * std::numbers::pi / 180))),
        cluster_(root_cluster) {}

  /// The strand from `root`; `reference_row` is the input-strand point nearest it.
  GrowingStrand grow(const Vec3& root, int64_t reference_row) {
    add_point(root, GrowRule::root, root_cluster_, -1);
    const bool left_field_early = along_field(root, reference_row);
    start_following(root, left_field_early);
    while (!full() && !too_long() && !strand_.ended_at_fold) {
      if (group_ >= 0) {
        const std::optional<bool> followed = follow_step();
        if (!followed) break;  // the rail dives into the body
        if (*followed) continue;
      }
      if (direction_.squaredNorm() == 0) break;
      if (!go_on()) break;
    }
    return std::move(strand_);
  }

 private:
  /// Appends `point` (pushed out of the body) unless the step to it turns the strand by more
  /// than max_turn_deg from its last step: false then, and nothing is added. Whichever rule
  /// takes the step (the field, a card's rail, a bridge to the next card), hair does not
  /// fold back on itself where nothing folds it; such a step is two pieces of hair read in
  /// opposite senses meeting (a braid's crossing pieces, cards read from either end). What
  /// folds it is a band or a weave: into a tail or braid after its band (a cluster that does
  /// not start at the root), from the cap or from piece to piece of a braid, the bridge and
  /// the first step along it may turn by up to continued_root_max_angle_deg, as
  /// next_entry() let the strand in, over two steps.
  bool add_point(Vec3 point, GrowRule rule, int32_t cluster, int32_t group) {
    if (rule != GrowRule::root && body_.push_out(point, clearance_m_)) ++strand_.pushed_out;
    const size_t n = strand_.points.size();
    if (n >= 2) {
      const Vec3 last = strand_.points[n - 1] - strand_.points[n - 2];
      const Vec3 step = point - strand_.points[n - 1];
      const double norms = last.norm() * step.norm();
      if (norms > 0 && last.dot(step) < min_turn_cos_ * norms) {
        if (!gathered_ || last.dot(step) < min_gathered_turn_cos_ * norms) return false;
        // Round the band's corner: a point 0.3 of the step along the bisector of the two
        // directions first, so that the strand turns by half the turn and then by the
        // rest less the corner cut (77 degrees of a 120-degree turn), never folding back
        // in one step.
        const Vec3 bisector = last / last.norm() + step / step.norm();
        if (bisector.squaredNorm() > 0) {
          Vec3 corner = strand_.points.back() + 0.3 * step.norm() * bisector.normalized();
          if (body_.push_out(corner, clearance_m_)) ++strand_.pushed_out;
          append(corner, rule, cluster, group);
        }
      }
    }
    append(point, rule, cluster, group);
    return true;
  }
  void append(const Vec3& point, GrowRule rule, int32_t cluster, int32_t group) {
    strand_.points.push_back(point);
    strand_.rules.push_back(rule);
    strand_.clusters.push_back(cluster);
    strand_.groups.push_back(group);
    strand_.ended_at_body = false;
  }
  /// Takes the strand back to its first `size` points.
  void take_back_to(size_t size) {
    strand_.points.resize(size);
    strand_.rules.resize(size);
    strand_.clusters.resize(size);
    strand_.groups.resize(size);
  }
  /// After add_point(): did the steps up to this one from `from` along `along` run into
  /// the body (kBlockedAdvance, kBlockedSteps)? Then those steps are taken back, and the
  /// strand ends at the body unless it goes on another way.
  bool ran_into_body(const Vec3& from, const Vec3& along) {
    if ((strand_.points.back() - from).dot(along) >= kBlockedAdvance * step_m_) {
      strand_.blocked_steps = 0;
      return false;
    }
    if (++strand_.blocked_steps < kBlockedSteps) return false;
    const size_t kept = strand_.points.size() > static_cast<size_t>(strand_.blocked_steps)
                            ? strand_.points.size() - static_cast<size_t>(strand_.blocked_steps)
                            : 1;
    take_back_to(kept);
    strand_.blocked_steps = 0;
    strand_.ended_at_body = true;
    return true;
  }
  bool full() const {
    return static_cast<int64_t>(strand_.points.size()) >= params_.max_points_per_strand;
  }
  bool too_long() const {
    return static_cast<double>(strand_.points.size() - 1) * step_m_ >
           params_.max_length_h * context_.input().head_height_m;
  }

  /// 1. Along the cluster's field from the root, as long as what remains of the reference
  /// strand (length_factor). Whether the field ended before that (left early).
  bool along_field(const Vec3& root, int64_t reference_row) {
    if (!field_ || !field_->direction(root)) return false;
    const double length_limit_m = params_.length_factor * context_.length_to_tip_m(reference_row);
    double length_m = 0;
    Vec3 point = root;
    int64_t cursor = reference_row;
    // The layer's correction is looked up every kLayerEvery steps, from the first, and
    // spread over the steps up to the next look-up: one step that jumped by all of it
    // would climb from the scalp to the layer above at 50 degrees or more, across the hair.
    int steps_since_layer = kLayerEvery - 1;
    Vec3 layer_step = Vec3::Zero();
    double climb_per_m = -1;  // the climb to the layer per metre along, from the first look-up
    while (!full()) {
      if (length_m + step_m_ > length_limit_m) return false;
      std::optional<Vec3> d1 = field_->direction(point);
      if (!d1) break;
      std::optional<Vec3> d2 = field_->direction(point + 0.5 * step_m_ * *d1);
      if (!d2) break;
      if (length_m + 0.5 * step_m_ < root_heading_m_) d2 = heading_along_paint(point, *d2);
      if (length_m > 0 && d2->dot(direction_) < min_turn_cos_) break;
      Vec3 next = point + step_m_ * *d2;
      if (context_.layered() && ++steps_since_layer == kLayerEvery) {
        layer_step = towards_layer(next, reference_row, length_m + step_m_, cursor, climb_per_m) /
                     kLayerEvery;
        steps_since_layer = 0;
      }
      next += layer_step;
      if (!field_->contains(next)) break;
      // A step that would fold the strand back ends the field phase: the input strands
      // take over, as where the field ends early.
      if (!add_point(next, GrowRule::field, root_cluster_, -1)) break;
      // The field runs into the body here: the input strands take over, as where the
      // field ends early.
      if (ran_into_body(point, *d2)) break;
      direction_ = *d2;
      length_m += step_m_;
      point = strand_.points.back();
    }
    return true;
  }

  /// Towards the reference strand's height above the body at `length_m` along it, every
  /// kLayerEvery steps by at most layer_pull of those steps: the height and its direction
  /// from the body's signed distance field inside its band, from the exact distance beyond
  /// it (the costlier query: a third of grow's time on long01 when made every step). Within
  /// layer_climb_h of the root (and a step), by at most the climb's even slope instead:
  /// `climb_per_m` (negative until then) is set at the first look-up, the height still to
  /// climb there over layer_climb_h.
  Vec3 towards_layer(const Vec3& next, int64_t reference_row, double length_m, int64_t& cursor,
                     double& climb_per_m) const {
    double height_m = body_.distance(next);
    Vec3 up = Vec3::Zero();
    if (height_m < body_.band_m() - 1.5 * body_.voxel_m()) {
      up = body_.gradient(next);
    } else {
      TriangleMeshDistance::Nearest body_point = context_.body_distance().nearest(next);
      height_m = body_point.distance;
      if (height_m > 0) up = (next - body_point.closest_point) / height_m;
    }
    if (!(up.squaredNorm() > 0)) return Vec3::Zero();
    const double target_m = context_.height_along(reference_row, length_m, cursor);
    const double climb_m = params_.layer_climb_h * context_.input().head_height_m;
    if (climb_per_m < 0) climb_per_m = climb_m > 0 ? std::abs(target_m - height_m) / climb_m : 0.0;
    const double pull_m =
        (climb_m > 0 && length_m <= climb_m + step_m_ ? climb_per_m * step_m_
                                                      : params_.layer_pull * step_m_) *
        kLayerEvery;
    return up.normalized() * std::clamp(target_m - height_m, -pull_m, pull_m);
  }

  /// The field's direction `field_direction` at `point`, turned over the scalp onto the
  /// clear paint of the hair face nearest `point` (GrowingContext::painted_flow_near())
  /// where that runs within 60 degrees of it (kRootPaintMinCos): the paint's part along
  /// the body's surface, in the field's sense and as long as the field's, plus the field's
  /// own part off the surface (root_heading_paint_h). Unchanged where no such paint is
  /// near, or the paint runs within about 65 degrees of straight off the body.
  Vec3 heading_along_paint(const Vec3& point, const Vec3& field_direction) const {
    const std::optional<Vec3> flow = context_.painted_flow_near(point);
    if (!flow || std::abs(flow->dot(field_direction)) < kRootPaintMinCos) return field_direction;
    Vec3 normal = body_.gradient(point);
    if (!(normal.norm() > 0)) return field_direction;
    normal.normalize();
    Vec3 paint_over = *flow - flow->dot(normal) * normal;
    const Vec3 field_over = field_direction - field_direction.dot(normal) * normal;
    if (!(paint_over.norm() > 0.4) || !(field_over.norm() > 0)) return field_direction;
    paint_over.normalize();
    if (paint_over.dot(field_over) < 0) paint_over = -paint_over;
    return (paint_over * field_over.norm() + normal * field_direction.dot(normal)).normalized();
  }

  /// 2. The input strand to follow first.
  void start_following(const Vec3& root, bool left_field_early) {
    if (strand_.points.size() == 1) {
      // No field here (a root cluster without one, or a root outside its band): start on
      // the input strand nearest the root.
      int32_t s = context_.strand_of_point(context_.nearest_root_point(root));
      group_ = context_.group_of_strand(s);
      cluster_ = context_.cluster_of_strand(s);
      visited_.push_back(group_);
    } else if (left_field_early) {
      // The field ended before the strand grew as long as its input strands (the edge of
      // the band, beside a card): go on along the closest input strand of the cluster.
      int64_t row = context_.nearest_root_point(strand_.points.back());
      int32_t s = context_.strand_of_point(row);
      double min_cos = std::cos(params_.continue_max_angle_deg * std::numbers::pi / 180);
      if (context_.cluster_of_strand(s) == root_cluster_ &&
          (point_of(context_.input().input_strands.points, row) - strand_.points.back()).norm() <=
              lost_m_ &&
          context_.follow(context_.group_of_strand(s), false, strand_.points.back())
                  .direction.dot(direction_) >= min_cos) {
        group_ = context_.group_of_strand(s);
        visited_.push_back(group_);
      }
    }
  }

  /// One step along the group followed: true if taken; false at the group's end (lost,
  /// drifted off its rails, or turned back); std::nullopt where its rail dives into the
  /// body and the strand ends.
  std::optional<bool> follow_step() {
    const Vec3 point = strand_.points.back();
    GrowingContext::Following following = context_.follow(group_, backward_, point);
    // Just entered, the strand turns as next_entry() allowed (a tail after its band by up
    // to continued_root_max_angle_deg): only later steps may not turn back.
    bool turned_back =
        !just_entered_ && direction_.squaredNorm() > 0 && following.direction.dot(direction_) < 0;
    just_entered_ = false;
    if (following.past_end || following.distance_m > lost_m_ || turned_back) return false;
    direction_ = following.direction;
    // The midpoint rule, as along the field: the rail's direction half a step on. A step
    // along the direction at its start leaves a curving rail on the outside of each bend
    // (a ringlet's 8 mm helix turns 23 degrees in one 5 mm step); where the half step
    // finds no rail going on the same way (its end, a fold), the start's direction stays.
    const GrowingContext::Following half =
        context_.follow(group_, backward_, point + 0.5 * step_m_ * direction_);
    if (!half.past_end && half.distance_m <= lost_m_ && half.direction.dot(direction_) > 0)
      direction_ = half.direction;
    Vec3 next = point + step_m_ * direction_;
    double excess_m = following.distance_m - keep_m_;
    if (excess_m > 0 && params_.follow_pull > 0) {
      Vec3 towards = following.closest - point;
      towards -= towards.dot(direction_) * direction_;
      if (towards.squaredNorm() > 0)
        next += towards.normalized() * std::min(excess_m, params_.follow_pull * step_m_);
    }
    next = onto_card(next);
    const bool added = add_point(next, GrowRule::input_strand, cluster_, group_);
    gathered_ = false;
    if (!added) return false;  // a step that would fold the strand: the group's end here
    if (ran_into_body(point, direction_)) return std::nullopt;
    return true;
  }

  /// `next` drawn back towards the surface of the card followed where it lies farther
  /// than follow_card_keep_h from it, across the strand's direction only, by at most
  /// follow_card_pull steps.
  Vec3 onto_card(const Vec3& next) const {
    if (!(card_keep_m_ > 0) || !(params_.follow_card_pull > 0)) return next;
    const std::optional<TriangleMeshDistance::Nearest> card =
        context_.card_surfaces().nearest(group_, next);
    if (!card || !(card->distance > card_keep_m_)) return next;
    Vec3 towards = card->closest_point - next;
    towards -= towards.dot(direction_) * direction_;
    const double norm_m = towards.norm();
    if (!(norm_m > 0)) return next;
    return next + towards / norm_m *
                      std::min({card->distance - card_keep_m_, norm_m,
                                params_.follow_card_pull * step_m_});
  }

  /// At the end of the field or of an input strand: the next strand, bridged to; else the
  /// cards feeding a continuation joined, or the cap's field walked to a tail or braid.
  /// false: the strand ends here.
  bool go_on() {
    const Vec3 point = strand_.points.back();
    std::optional<StrandEntry> entry = context_.next_entry(
        point, direction_, visited_, cluster_, group_ < 0 ? root_cluster_ : -1, group_ >= 0);
    if (entry) {
      enter(*entry);
      return true;
    }
    // No strand starts here: where the hair continues into another cluster (a tail after
    // its band), join the cards that feed it.
    const std::optional<int32_t> joined = params_.join_continued_flow
                                              ? context_.joined_feeder(point, direction_, visited_)
                                              : std::nullopt;
    if (!joined) return gather_along_field(point);
    const int32_t joined_cluster = context_.cluster_of_group(*joined);
    (joined_cluster == cluster_ ? strand_.continued_same : strand_.continued_other) += 1;
    group_ = *joined;
    cluster_ = joined_cluster;
    backward_ = false;
    visited_.push_back(group_);
    ++strand_.joined;
    return true;
  }

  /// Into the input strand of `entry`: straight to bridge_target(); a step that gets no nearer
  /// (the start lies in the body, and each step is pushed back out) ends the bridge there.
  void enter(const StrandEntry& entry) {
    int32_t next_cluster = context_.cluster_of_strand(entry.strand);
    (next_cluster == cluster_ ? strand_.continued_same : strand_.continued_other) += 1;
    gathered_ = !context_.cluster_starts_at_root(next_cluster);
    group_ = context_.group_of_strand(entry.strand);
    cluster_ = next_cluster;
    backward_ = entry.backward;
    visited_.push_back(group_);
    just_entered_ = true;
    // Into a tail after its band, the bridge turns as its band lets it, no more: to the
    // first point of the tail's strand ahead within continued_root_max_angle_deg.
    std::optional<Vec3> target = context_.bridge_target(entry, strand_.points.back(), direction_);
    if (!target && gathered_)
      target = context_.bridge_target(entry, strand_.points.back(), direction_,
                                      params_.continued_root_max_angle_deg);
    const Vec3 start = target.value_or(context_.entry_start(entry));
    for (double gap_m = (start - strand_.points.back()).norm(); gap_m > step_m_ && !full();) {
      Vec3 towards = (start - strand_.points.back()).normalized();
      if (!add_point(strand_.points.back() + step_m_ * towards, GrowRule::bridge, cluster_,
                     group_)) {
        strand_.ended_at_fold = true;
        return;
      }
      double next_gap_m = (start - strand_.points.back()).norm();
      if (next_gap_m > gap_m - 0.25 * step_m_) break;
      gap_m = next_gap_m;
    }
  }

  /// A cap strand whose card ended on a cap that gathers into a band: on from `point` along
  /// the root cluster's field (never turning back) until the start of a tail or braid
  /// after the band (a cluster not starting at the root, hanging off the scalp) lies within
  /// reach, and into it; false (the points walked taken back) when none does within
  /// gather_along_field_h.
  bool gather_along_field(Vec3 point) {
    if (!field_ || params_.gather_along_field_h <= 0 || cluster_ != root_cluster_ ||
        !context_.cluster_feeds_continuation(root_cluster_))
      return false;
    const size_t kept = strand_.points.size();
    const int walk_steps = static_cast<int>(params_.gather_along_field_h / params_.step_h);
    Vec3 heading = direction_;
    for (int i = 0; i < walk_steps && !full(); ++i) {
      std::optional<Vec3> d = field_->direction(point);
      if (!d || d->dot(heading) <= 0) break;
      Vec3 next = point + step_m_ * *d;
      if (!field_->contains(next)) break;
      if (!add_point(next, GrowRule::field, root_cluster_, -1)) break;
      if (ran_into_body(point, *d)) break;
      heading = *d;
      point = strand_.points.back();
      if (std::optional<StrandEntry> entry =
              context_.next_entry(point, heading, visited_, cluster_, -1, false, true)) {
        direction_ = heading;
        enter(*entry);
        return true;
      }
    }
    take_back_to(kept);
    return false;
  }

  const GrowingContext& context_;
  const GrowParams& params_;
  const OrientationField* field_;
  const BodySdf& body_;
  const int32_t root_cluster_;
  const double step_m_, clearance_m_, lost_m_, keep_m_, card_keep_m_, root_heading_m_;
  const double min_turn_cos_;  ///< a step turning more than max_turn_deg is not taken
  const double min_gathered_turn_cos_;  ///< ...nor into a tail after its band, more than this
  GrowingStrand strand_;
  Vec3 direction_ = Vec3::Zero();  ///< of the last step
  std::vector<int32_t> visited_;   ///< groups followed or entered
  int32_t group_ = -1;             ///< the group followed (-1: none)
  int32_t cluster_;                ///< the cluster the strand is in
  bool backward_ = false;          ///< the group is followed tip to root
  bool just_entered_ = false;      ///< enter()ed the group, not yet followed a step
  bool gathered_ = false;  ///< entered a tail or braid after its band, not yet followed a step
};

/// Unit normal of body triangle `t` (right-hand rule of its vertex order).
Vec3 triangle_normal(const GrowInput& input, Eigen::Index t) {
  const Vec3 a = point_of(input.body_vertices, input.body_triangles(t, 0));
  return (point_of(input.body_vertices, input.body_triangles(t, 1)) - a)
      .cross(point_of(input.body_vertices, input.body_triangles(t, 2)) - a)
      .normalized();
}

/// The length of `offset` along the scalp: its part across the unit `normal`.
double along_the_scalp_m(const Vec3& offset, const Vec3& normal) {
  return (offset - offset.dot(normal) * normal).norm();
}

/// Whether the input strand through `row` rises off a scalp triangle of unit normal
/// `normal` at more than 45 degrees there (its segment from `row`, or into `row` at its
/// tip): hair standing on the head, like a spike card, rather than lying on it.
bool stands_off_the_scalp(const StrandSet& strands, int64_t row, const Vec3& normal) {
  const auto next = std::upper_bound(strands.offsets.begin(), strands.offsets.end(), row);
  const int64_t first = *(next - 1), last = *next - 1;
  if (last <= first) return false;
  const int64_t from = row < last ? row : row - 1;
  const Vec3 segment = point_of(strands.points, from + 1) - point_of(strands.points, from);
  if (!(segment.squaredNorm() > 0) || !(normal.squaredNorm() > 0)) return false;
  return std::abs(segment.normalized().dot(normal)) > std::sqrt(0.5);
}

/// Scalp triangles (input.scalp_triangle) whose centre lies within scalp_cover_h of the
/// input-strand point `nearest_row` gives for it (a row of input_strands.points); where
/// that point's strand stands off the scalp, only within standing_cover_h of it along
/// the scalp.
std::vector<uint8_t> scalp_under_strands(const GrowInput& input, const GrowParams& params,
                                         const std::function<int64_t(const Vec3&)>& nearest_row) {
  const StrandSet& strands = input.input_strands;
  const double h = input.head_height_m;
  std::vector<uint8_t> covered(input.scalp_triangle.size(), 0);
  const double cover_m = params.scalp_cover_h * h;
  const double standing_cover_m = std::min(params.standing_cover_h, params.scalp_cover_h) * h;
  for (Eigen::Index t = 0; t < input.body_triangles.rows(); ++t) {
    if (!input.scalp_triangle[static_cast<size_t>(t)]) continue;
    std::array<Vec3, 3> corner;
    for (int k = 0; k < 3; ++k)
      corner[static_cast<size_t>(k)] = point_of(input.body_vertices, input.body_triangles(t, k));
    const Vec3 centre = (corner[0] + corner[1] + corner[2]) / 3;
    const int64_t row = nearest_row(centre);
    const Vec3 offset = point_of(strands.points, row) - centre;
    if (offset.norm() > cover_m) continue;
    const Vec3 normal = triangle_normal(input, t);
    if (stands_off_the_scalp(strands, row, normal)) {
      // Along the scalp from the triangle (0 where the point lies over it), so that the
      // triangle under a spike's base carries roots however coarse the scalp.
      const Vec3 point = point_of(strands.points, row);
      const Vec3 from_triangle =
          point - closest_point_on_triangle(point, corner[0], corner[1], corner[2]);
      if (along_the_scalp_m(from_triangle, normal) > standing_cover_m) continue;
    }
    covered[static_cast<size_t>(t)] = 1;
  }
  return covered;
}

/// Area in m^2 of the body triangles flagged in `flags`.
double flagged_area_m2(const GrowInput& input, const std::vector<uint8_t>& flags) {
  double area_m2 = 0;
  for (Eigen::Index t = 0; t < input.body_triangles.rows(); ++t) {
    if (!flags[static_cast<size_t>(t)]) continue;
    const Vec3 a = point_of(input.body_vertices, input.body_triangles(t, 0));
    const Vec3 b = point_of(input.body_vertices, input.body_triangles(t, 1));
    const Vec3 c = point_of(input.body_vertices, input.body_triangles(t, 2));
    area_m2 += 0.5 * (b - a).cross(c - a).norm();
  }
  return area_m2;
}

/// The seeds under the root-carrying strands where they lie off the head
/// (GrowParams::field_shell_seeds, shell_field_seeds.h), with strand attribute "cluster"
/// (int32), that of the strand each lies under.
StrandSet shell_seeds(const GrowInput& input, const GrowingContext& context,
                      const GrowParams& params, const TriangleMeshDistance& body,
                      const PointIndex& hair) {
  const StrandSet& strands = input.input_strands;
  std::vector<Points3f> over;
  std::vector<int32_t> over_cluster;
  for (int64_t s = 0; s < strands.strand_count(); ++s)
    if (context.carries_roots(s)) {
      over.emplace_back(strands.strand(s));
      over_cluster.push_back(context.cluster_of_strand(s));
    }
  ShellSeedParams shell_params;
  shell_params.spacing_m = params.field_band_h * input.head_height_m;
  shell_params.max_height_m = params.shell_max_height_h * input.head_height_m;
  // Over the scalp and the neck under it: no lower than the scalp's lowest triangle
  // centre by more than max_height_m.
  double lowest_scalp_y = std::numeric_limits<double>::infinity();
  for (Eigen::Index t = 0; t < input.body_triangles.rows(); ++t) {
    if (!input.scalp_triangle[static_cast<size_t>(t)]) continue;
    double centre_y = 0;
    for (int k = 0; k < 3; ++k) centre_y += input.body_vertices(input.body_triangles(t, k), 1);
    lowest_scalp_y = std::min(lowest_scalp_y, centre_y / 3);
  }
  shell_params.min_foot_y_m = lowest_scalp_y - shell_params.max_height_m;
  StrandSet seeds = seeds_under_strands(over, body, hair, shell_params);
  const auto& under = std::get<std::vector<int32_t>>(seeds.strand_attributes.at("strand"));
  std::vector<int32_t> cluster(under.size());
  for (size_t k = 0; k < under.size(); ++k)
    cluster[k] = over_cluster[static_cast<size_t>(under[k])];
  seeds.strand_attributes["cluster"] = std::move(cluster);
  return seeds;
}

/// Flags in `covered` the scalp triangles whose centre lies within scalp_cover_h of a seed
/// of the lowest level under the hair (shell_seeds()): the scalp under a shell of hair.
void cover_scalp_under_shells(const GrowInput& input, const GrowParams& params,
                              const StrandSet& seeds, std::vector<uint8_t>& covered) {
  const auto& level = std::get<std::vector<int32_t>>(seeds.strand_attributes.at("level"));
  std::vector<Eigen::RowVector3f> lowest;
  for (int64_t s = 0; s < seeds.strand_count(); ++s)
    if (level[static_cast<size_t>(s)] == 0)
      for (int64_t row = seeds.offsets[s]; row < seeds.offsets[s + 1]; ++row)
        lowest.push_back(seeds.points.row(row));
  if (lowest.empty()) return;
  Points3f points(static_cast<Eigen::Index>(lowest.size()), 3);
  for (size_t k = 0; k < lowest.size(); ++k) points.row(static_cast<Eigen::Index>(k)) = lowest[k];
  const PointIndex index(points);
  const auto cover_m = static_cast<float>(params.scalp_cover_h * input.head_height_m);
  for (Eigen::Index t = 0; t < input.body_triangles.rows(); ++t) {
    if (!input.scalp_triangle[static_cast<size_t>(t)] || covered[static_cast<size_t>(t)]) continue;
    Eigen::Vector3f centre = Eigen::Vector3f::Zero();
    for (int k = 0; k < 3; ++k)
      centre += input.body_vertices.row(input.body_triangles(t, k)).transpose();
    if (!index.within(centre / 3, cover_m).empty()) covered[static_cast<size_t>(t)] = 1;
  }
}

/// The seeds the painted faces give the fields (GrowParams::field_paint_seeds): of the
/// groups whose strands seed them, sampled at half a voxel's edge, so that a
/// face adds to each voxel it covers about what a strand through it does.
StrandSet field_paint_seeds(const GrowInput& input, const GrowingContext& context,
                            const GrowParams& params) {
  const StrandSet& strands = input.input_strands;
  std::vector<uint8_t> seeding_group(input.group_cluster.size(), 0);
  for (int64_t s = 0; s < strands.strand_count(); ++s)
    if (context.carries_roots(s))
      seeding_group[static_cast<size_t>(context.group_of_strand(s))] = 1;
  if (!params.field_paint_seeds || input.hair_triangle_flow.rows() != input.hair_triangles.rows()) {
    StrandSet none;
    none.strand_attributes["group"] = std::vector<int32_t>{};
    return none;
  }
  PaintedFieldSeedParams seed_params;
  seed_params.spacing_m = 0.5 * params.field_voxel_h * input.head_height_m;
  seed_params.sign_radius_m = params.field_band_h * input.head_height_m;
  return painted_field_seeds(input.hair_vertices, input.hair_triangles, input.hair_triangle_group,
                             input.hair_triangle_flow, seeding_group, strands, seed_params);
}

/// The way a strand that cannot leave its root takes its one step: along the input strand
/// `strand` at its point `row` (the root's reference; nearly always its tip, where the
/// hair the mesh shows ends on the scalp: a cap's streamlines at the hairline, 93-100% of
/// such roots on short01, short02, bob01, afro01), less any part into the scalp (`normal`,
/// unit, outward), so it lies along the hair as the hair's ends there do; along the normal
/// where the strand runs straight into the scalp.
Vec3 stub_direction(const StrandSet& strands, int32_t strand, int64_t row, const Vec3& normal) {
  const int64_t first = strands.offsets[static_cast<size_t>(strand)];
  const int64_t last = strands.offsets[static_cast<size_t>(strand) + 1] - 1;
  if (last <= first) return normal;
  const int64_t from = std::min(row, last - 1);
  Vec3 along = point_of(strands.points, from + 1) - point_of(strands.points, from);
  if (!(along.norm() > 0)) return normal;
  along.normalize();
  if (along.dot(normal) < 0) along -= along.dot(normal) * normal;
  // Within about 25 degrees of straight into the scalp, what is left says little.
  if (!(along.norm() > 0.4)) return normal;
  return along.normalized();
}

/// A stub's `direction` (stub_direction()) turned onto the painted flow there: `flow`
/// (unit axis, either sense) less its part along the scalp's `normal`, in the sense of
/// `direction`, where `direction` is not the normal itself (it then says nothing of the
/// sense) and the paint does not run within about 65 degrees of straight into the scalp;
/// else `direction` as it was.
Vec3 along_paint(const Vec3& direction, const Vec3& normal, const std::optional<Vec3>& flow) {
  if (!flow) return direction;
  Vec3 tangent = *flow - flow->dot(normal) * normal;
  const double tangent_norm = tangent.norm();
  const double sense = tangent.dot(direction);
  if (!(tangent_norm > 0.4) || direction.dot(normal) > 0.999 || sense == 0) return direction;
  return (sense > 0 ? tangent : -tangent) / tangent_norm;
}

}  // namespace

GrowResult grow_strands(const GrowInput& input, const GrowParams& params) {
  check_grow_params(params);
  const double h = input.head_height_m;
  if (!(h > 0)) throw Error::bad_input(input.source, "head height is not positive");
  if (input.input_strands.strand_count() == 0)
    throw Error::bad_input(input.source, "no input strands to grow from");
  if (input.scalp_triangle.size() != static_cast<size_t>(input.body_triangles.rows()))
    throw Error::bad_input(input.source, "scalp flags do not match the body's triangles");
  auto context_ptr = std::make_unique<GrowingContext>(input, params, false);
  GrowResult result;
  std::vector<uint8_t> covered = scalp_under_strands(
      input, params, [&](const Vec3& point) { return context_ptr->nearest_root_point(point); });
  result.typed_root_scalp_share = 1.0;
  if (!context_ptr->any_type_roots() && params.min_typed_root_scalp_share > 0) {
    // The scalp under the hair whatever its types: where root-type strands cover too
    // little of it, the types do not say where the roots are.
    PointIndex all_points(input.input_strands.points);
    std::vector<uint8_t> covered_by_any =
        scalp_under_strands(input, params, [&](const Vec3& point) {
          return static_cast<int64_t>(all_points.nearest(point.cast<float>(), 1).front());
        });
    const double any_area_m2 = flagged_area_m2(input, covered_by_any);
    if (any_area_m2 > 0)
      result.typed_root_scalp_share = flagged_area_m2(input, covered) / any_area_m2;
    if (result.typed_root_scalp_share < params.min_typed_root_scalp_share) {
      spdlog::warn(
          "{}: root-type strands cover {:.0f}% of the scalp under the hair (under {:.0f}%); "
          "roots take the cluster of the nearest strand of any type",
          input.source, 100 * result.typed_root_scalp_share,
          100 * params.min_typed_root_scalp_share);
      context_ptr = std::make_unique<GrowingContext>(input, params, true);
      covered = std::move(covered_by_any);
    }
  } else if (context_ptr->any_type_roots()) {
    result.typed_root_scalp_share = 0.0;
    spdlog::warn("{}: no root-type strand group; roots take the cluster of the nearest strand",
                 input.source);
  }
  const GrowingContext& context = *context_ptr;
  result.roots_from_any_type = context.any_type_roots();
  // The body's distance, for the seeds under hair that lies off the head.
  StrandSet under_shells;
  if (params.field_shell_seeds) {
    std::vector<Eigen::RowVector3f> rows;
    for (int64_t s = 0; s < input.input_strands.strand_count(); ++s)
      if (context.carries_roots(s))
        for (int64_t row = input.input_strands.offsets[s]; row < input.input_strands.offsets[s + 1];
             ++row)
          rows.push_back(input.input_strands.points.row(row));
    Points3f points(static_cast<Eigen::Index>(rows.size()), 3);
    for (size_t k = 0; k < rows.size(); ++k) points.row(static_cast<Eigen::Index>(k)) = rows[k];
    const PointIndex seeding_hair(points);  // the points of the root-carrying strands
    std::unique_ptr<TriangleMeshDistance> own_body;
    if (!context.layered())
      own_body = std::make_unique<TriangleMeshDistance>(input.body_vertices, input.body_triangles);
    under_shells =
        shell_seeds(input, context, params, context.layered() ? context.body_distance() : *own_body,
                    seeding_hair);
    cover_scalp_under_shells(input, params, under_shells, covered);
  }
  for (uint8_t flag : covered) result.scalp_triangles_used += flag;
  const StrandSet& strands = input.input_strands;
  const double standing_cover_m = std::min(params.standing_cover_h, params.scalp_cover_h) * h;
  // Within a covered triangle, a root beside a standing strand lies within
  // standing_cover_h of it along the scalp (the triangles are coarser than that).
  const SampleAcceptance standing_base_only = [&](const Vec3& root, int32_t t) {
    const int64_t row = context.nearest_root_point(root);
    const Vec3 normal = triangle_normal(input, t);
    return !stands_off_the_scalp(strands, row, normal) ||
           along_the_scalp_m(point_of(strands.points, row) - root, normal) <= standing_cover_m;
  };
  if (result.scalp_triangles_used == 0)
    throw Error::bad_input(input.source,
                           "no scalp triangle lies under a root-type input strand: nothing to "
                           "grow from (is scalp_cover_h too small?)");
  SurfaceSamples roots =
      poisson_disk_samples(input.body_vertices, input.body_triangles, covered, params.strand_count,
                           static_cast<uint64_t>(params.seed), 5, standing_base_only);
  result.scalp_area_m2 = roots.area_m2;
  result.root_spacing_m = roots.min_spacing_m;
  auto root_count = static_cast<int64_t>(roots.positions.rows());
  std::vector<int64_t> reference_row(static_cast<size_t>(root_count));
  std::vector<int32_t> root_cluster(static_cast<size_t>(root_count));
#pragma omp parallel for schedule(dynamic, 256)
  for (int64_t r = 0; r < root_count; ++r) {
    reference_row[static_cast<size_t>(r)] = context.reference_row(point_of(roots.positions, r), r);
    root_cluster[static_cast<size_t>(r)] =
        context.cluster_of_strand(context.strand_of_point(reference_row[static_cast<size_t>(r)]));
  }

  // One field per cluster with roots, from its root-type strands.
  int32_t cluster_count = 0;
  for (int32_t c : input.group_cluster) cluster_count = std::max(cluster_count, c + 1);
  result.clusters.resize(static_cast<size_t>(cluster_count));
  for (int32_t c : root_cluster) ++result.clusters[static_cast<size_t>(c)].strand_count;
  std::vector<std::optional<OrientationField>> fields(static_cast<size_t>(cluster_count));
  OrientationFieldParams field_params{params.field_voxel_h * h, params.field_band_h * h};
  const StrandSet paint_seeds = field_paint_seeds(input, context, params);
  const auto& seed_group =
      std::get<std::vector<int32_t>>(paint_seeds.strand_attributes.at("group"));
  for (int32_t c = 0; c < cluster_count; ++c) {
    if (result.clusters[static_cast<size_t>(c)].strand_count == 0) continue;
    std::vector<Points3f> seeding;  // the cluster's root-carrying strands, then its paint seeds
    for (int64_t s = 0; s < strands.strand_count(); ++s)
      if (context.cluster_of_strand(s) == c && context.carries_roots(s))
        seeding.emplace_back(strands.strand(s));
    if (seeding.empty()) continue;
    for (int64_t s = 0; s < paint_seeds.strand_count(); ++s)
      if (context.cluster_of_group(seed_group[static_cast<size_t>(s)]) == c)
        seeding.emplace_back(paint_seeds.strand(s));
    if (params.field_shell_seeds) {
      const auto& under_cluster =
          std::get<std::vector<int32_t>>(under_shells.strand_attributes.at("cluster"));
      for (int64_t s = 0; s < under_shells.strand_count(); ++s)
        if (under_cluster[static_cast<size_t>(s)] == c)
          seeding.emplace_back(under_shells.strand(s));
    }
    std::vector<int64_t> ids(seeding.size());
    std::iota(ids.begin(), ids.end(), int64_t{0});
    fields[static_cast<size_t>(c)] =
        OrientationField::build(strand_set_from_polylines(seeding), ids, field_params);
    result.clusters[static_cast<size_t>(c)].field_voxel_count =
        fields[static_cast<size_t>(c)]->band_voxel_count();
    result.clusters[static_cast<size_t>(c)].field_seeded_voxels =
        fields[static_cast<size_t>(c)]->seeded_voxel_count();
  }

  // The body, over the region the strands can reach.
  double margin_m = (params.continue_radius_h + params.field_band_h + params.step_h) * h;
  Vec3 low = strands.points.colwise().minCoeff().cast<double>().transpose().array() - margin_m;
  Vec3 high = strands.points.colwise().maxCoeff().cast<double>().transpose().array() + margin_m;
  Vec3 root_low = roots.positions.colwise().minCoeff().cast<double>().transpose();
  Vec3 root_high = roots.positions.colwise().maxCoeff().cast<double>().transpose();
  low = low.cwiseMin(root_low);
  high = high.cwiseMax(root_high);
  BodySdf body(input.body_vertices, input.body_triangles, low, high, params.body_voxel_h * h,
               4 * params.body_voxel_h * h, input.source);

  // Grow, each strand on its own.
  std::vector<GrowingStrand> grown(static_cast<size_t>(root_count));
#pragma omp parallel for schedule(dynamic, 64)
  for (int64_t r = 0; r < root_count; ++r) {
    auto i = static_cast<size_t>(r);
    const auto& field = fields[static_cast<size_t>(root_cluster[i])];
    grown[i] = StrandGrower(context, field ? &*field : nullptr, body, root_cluster[i])
                   .grow(point_of(roots.positions, r), reference_row[i]);
  }

  // Assemble; a strand that could not leave its root gets a second point one step out
  // along the hair there (stub_direction()), so every strand is a polyline.
  std::vector<Points3f> polylines;
  polylines.reserve(grown.size());
  std::vector<GrowRule>& rules = result.point_rule;
  std::vector<int32_t> point_cluster, point_group;
  for (size_t i = 0; i < grown.size(); ++i) {
    GrowingStrand& strand = grown[i];
    if (strand.points.size() < 2) {
      Vec3 normal = roots.normals.row(static_cast<Eigen::Index>(i)).cast<double>().transpose();
      Vec3 direction = stub_direction(strands, context.strand_of_point(reference_row[i]),
                                      reference_row[i], normal);
      direction = along_paint(direction, normal, context.painted_flow_near(strand.points.front()));
      Vec3 step_end = strand.points.front() + params.step_h * h * direction;
      if (body.push_out(step_end, params.body_clearance_h * h)) ++strand.pushed_out;
      strand.points.push_back(step_end);
      strand.rules.push_back(GrowRule::field);
      strand.clusters.push_back(strand.clusters.front());
      strand.groups.push_back(-1);
    }
    Points3f polyline(static_cast<Eigen::Index>(strand.points.size()), 3);
    for (size_t k = 0; k < strand.points.size(); ++k)
      polyline.row(static_cast<Eigen::Index>(k)) = strand.points[k].cast<float>().transpose();
    polylines.push_back(std::move(polyline));
    rules.insert(rules.end(), strand.rules.begin(), strand.rules.end());
    point_cluster.insert(point_cluster.end(), strand.clusters.begin(), strand.clusters.end());
    point_group.insert(point_group.end(), strand.groups.begin(), strand.groups.end());
    result.points_pushed_out += strand.pushed_out;
    result.continuations_same_cluster += strand.continued_same;
    result.continuations_other_cluster += strand.continued_other;
    result.strands_joining_continued_flow += strand.joined > 0 ? 1 : 0;
    result.strands_ended_at_body += strand.ended_at_body ? 1 : 0;
    result.strands_ended_at_fold += strand.ended_at_fold ? 1 : 0;
  }
  result.strands = strand_set_from_polylines(polylines);
  result.strands.strand_attributes["cluster"] = root_cluster;
  result.strands.strand_attributes["root_triangle"] = roots.triangle;
  result.strands.strand_attributes["root_normal"] = roots.normals;
  result.strands.point_attributes["cluster"] = std::move(point_cluster);
  result.strands.point_attributes["group"] = std::move(point_group);
  check_strand_set(result.strands);
  return result;
}

}  // namespace hair
