// What a growing strand looks up of the input, built once (GrowingContext).
#include "hair/grow/growing_context.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "hair/grow/triangle_centre.h"

namespace hair {
namespace {

using Vec3 = Eigen::Vector3d;

}  // namespace

GrowingContext::GrowingContext(const GrowInput& input, const GrowParams& params,
                               bool any_type_roots)
    : input_(input), params_(params), h_(input.head_height_m) {
  index_groups();
  index_root_points(any_type_roots);
  index_group_rails();
  index_entries();
  find_continuation_feeders();
  find_tips_off_scalp();
  measure_heights_above_body();
  index_hair_mesh();
  measure_lengths_to_tip();
}

void GrowingContext::index_groups() {
  const StrandSet& strands = input_.input_strands;
  const auto& group = std::get<std::vector<int32_t>>(strands.strand_attributes.at("group"));
  strand_group_ = group;
  int64_t strand_count = strands.strand_count();
  group_strands_.resize(input_.group_type.size());
  for (int64_t s = 0; s < strand_count; ++s)
    group_strands_[static_cast<size_t>(group[static_cast<size_t>(s)])].push_back(
        static_cast<int32_t>(s));
}

void GrowingContext::index_root_points(bool any_type_roots) {
  const StrandSet& strands = input_.input_strands;
  const int64_t strand_count = strands.strand_count();
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
}

void GrowingContext::index_group_rails() {
  const StrandSet& strands = input_.input_strands;
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
    group_reach_m_[g] = 1.01 * (params_.follow_radius_h * h_ + 0.5 * longest_m) + 1e-6;
  }
}

void GrowingContext::index_entries() {
  const StrandSet& strands = input_.input_strands;
  const int64_t strand_count = strands.strand_count();
  Points3f entry_points(2 * strand_count, 3);
  for (int64_t s = 0; s < strand_count; ++s) {
    entry_points.row(2 * s) = strands.points.row(strands.offsets[s]);
    entry_points.row(2 * s + 1) = strands.points.row(strands.offsets[s + 1] - 1);
    entries_.push_back({static_cast<int32_t>(s), false});
    entries_.push_back({static_cast<int32_t>(s), true});
  }
  entry_index_ = std::make_unique<PointIndex>(entry_points);
  all_index_ = std::make_unique<PointIndex>(strands.points);
}

void GrowingContext::find_continuation_feeders() {
  const StrandSet& strands = input_.input_strands;
  const int64_t strand_count = strands.strand_count();
  group_feeds_continuation_.assign(group_strands_.size(), 0);
  const double feed_m = params_.continued_root_radius_h * h_;
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
}

void GrowingContext::find_tips_off_scalp() {
  const StrandSet& strands = input_.input_strands;
  const int64_t strand_count = strands.strand_count();
  hangs_off_scalp_.assign(static_cast<size_t>(strand_count), 0);
  std::vector<Eigen::Index> scalp_rows;
  for (Eigen::Index t = 0; t < input_.body_triangles.rows(); ++t)
    if (input_.scalp_triangle[static_cast<size_t>(t)]) scalp_rows.push_back(t);
  if (scalp_rows.empty()) return;
  Points3f centres(static_cast<Eigen::Index>(scalp_rows.size()), 3);
  for (size_t i = 0; i < scalp_rows.size(); ++i)
    centres.row(static_cast<Eigen::Index>(i)) =
        triangle_centre<float>(input_.body_vertices, input_.body_triangles, scalp_rows[i])
            .transpose();
  const PointIndex scalp_index(centres);
  const auto off_m = static_cast<float>(params_.continued_tip_off_scalp_h * h_);
  for (int64_t s = 0; s < strand_count; ++s)
    hangs_off_scalp_[static_cast<size_t>(s)] =
        scalp_index.within(strands.points.row(strands.offsets[s + 1] - 1).transpose(), off_m)
            .empty();
}

void GrowingContext::measure_heights_above_body() {
  if (!(params_.layer_radius_h > 0)) return;
  const StrandSet& strands = input_.input_strands;
  body_distance_ =
      std::make_unique<TriangleMeshDistance>(input_.body_vertices, input_.body_triangles);
  height_m_.resize(static_cast<size_t>(strands.point_count()));
  for (int64_t row = 0; row < strands.point_count(); ++row)
    height_m_[static_cast<size_t>(row)] = body_distance_->distance(point_of(strands.points, row));
}

void GrowingContext::index_hair_mesh() {
  hair_painted_ = input_.hair_triangles.rows() > 0 &&
                 input_.hair_triangle_flow.rows() == input_.hair_triangles.rows();
  // The whole hair mesh, indexed where the paint or the air test needs it.
  if (hair_painted_ || (input_.hair_triangles.rows() > 0 && params_.field_air_stop_h > 0)) {
    hair_distance_ =
        std::make_unique<TriangleMeshDistance>(input_.hair_vertices, input_.hair_triangles);
    if (params_.field_air_stop_h > 0) {
      const TriangleMeshDistance* body = body_distance_.get();
      if (body == nullptr && input_.body_triangles.rows() > 0) {
        air_body_distance_ =
            std::make_unique<TriangleMeshDistance>(input_.body_vertices, input_.body_triangles);
        body = air_body_distance_.get();
      }
      air_ = std::make_unique<AirAroundHair>(*hair_distance_, body, params_.air_distance_h * h_,
                                             params_.air_covered_reach_h * h_);
    }
  }
  if (params_.follow_card_keep_h > 0 && input_.hair_triangles.rows() > 0)
    card_surfaces_ =
        CardSurfaces(input_.hair_vertices, input_.hair_triangles, input_.hair_triangle_group,
                     static_cast<int64_t>(group_strands_.size()));
}

void GrowingContext::measure_lengths_to_tip() {
  const StrandSet& strands = input_.input_strands;
  const int64_t strand_count = strands.strand_count();
  length_to_tip_m_.assign(static_cast<size_t>(strands.point_count()), 0.0);
  for (int64_t s = 0; s < strand_count; ++s)
    for (int64_t row = strands.offsets[s + 1] - 2; row >= strands.offsets[s]; --row)
      length_to_tip_m_[static_cast<size_t>(row)] =
          length_to_tip_m_[static_cast<size_t>(row + 1)] +
          (point_of(strands.points, row + 1) - point_of(strands.points, row)).norm();
}

double GrowingContext::height_along(int64_t row, double length_m, int64_t& cursor) const {
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

int64_t GrowingContext::reference_row(const Vec3& root, int64_t root_id) const {
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

GrowingContext::Following GrowingContext::follow(int32_t group, bool backward,
                                                 const Vec3& point) const {
  const StrandSet& strands = input_.input_strands;
  double best = std::numeric_limits<double>::infinity();
  Following result{Vec3::UnitY() * -1.0, true, best};
  const auto g = static_cast<size_t>(group);
  // A segment with a point within follow_radius_h has an end within that plus half its
  // length: the segments at the group's points within reach_m are all there can be.
  std::vector<int64_t> segments;  // first rows
  // In any order: the segments are sorted below.
  for (int32_t id : group_index_[g]->within_unordered(point.cast<float>(),
                                                      static_cast<float>(group_reach_m_[g]))) {
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

std::optional<Vec3> GrowingContext::bridge_target(const StrandEntry& entry, const Vec3& here,
                                                  const Vec3& direction,
                                                  std::optional<double> max_angle_deg) const {
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

bool GrowingContext::crosses_paint(const Vec3& from, const Vec3& to) const {
  if (!(params_.bridge_paint_max_angle_deg > 0)) return false;
  const Vec3 gap = to - from;
  const double gap_m = gap.norm();
  if (gap_m <= params_.step_h * h_) return false;
  const std::optional<Vec3> flow = painted_flow_near(from + 0.5 * gap);
  if (!flow) return false;
  const double max_angle_rad = params_.bridge_paint_max_angle_deg * std::numbers::pi / 180;
  return std::abs(gap.dot(*flow)) < std::cos(max_angle_rad) * gap_m;
}

std::optional<Vec3> GrowingContext::painted_flow_near(const Vec3& point) const {
  if (!hair_painted_) return std::nullopt;
  const TriangleMeshDistance::Nearest face = hair_distance_->nearest(point);
  if (face.triangle < 0 || face.distance > params_.follow_radius_h * h_) return std::nullopt;
  const Vec3 flow = point_of(input_.hair_triangle_flow, face.triangle);
  if (!(flow.norm() > 0)) return std::nullopt;
  return flow.normalized();
}

std::optional<StrandEntry> GrowingContext::next_entry(const Vec3& point, const Vec3& direction,
                                                      const std::vector<int32_t>& visited_groups,
                                                      int32_t preferred_cluster,
                                                      int32_t excluded_cluster, bool from_card,
                                                      bool hanging_continuations_only) const {
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

std::optional<int32_t> GrowingContext::joined_feeder(
    const Vec3& point, const Vec3& direction, const std::vector<int32_t>& visited_groups) const {
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

}  // namespace hair
