#pragma once
// What a growing strand looks up of the input, built once: the strands that carry roots,
// the rails of each group, the entries into the next strand, heights above the body and
// the painted hair.

#include <Eigen/Core>
#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

#include "hair/cluster/typeify.h"
#include "hair/core/strand_set.h"
#include "hair/geom/point_index.h"
#include "hair/geom/triangle_mesh_distance.h"
#include "hair/grow/card_surfaces.h"
#include "hair/grow/strand_growing.h"
#include "hair/grow/strand_sense.h"

namespace hair {

/// Whether `type` is one of the root types (root_free, root_connected).
inline bool is_root_type(GroupType type) {
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
  GrowingContext(const GrowInput& input, const GrowParams& params, bool any_type_roots);

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
  int64_t nearest_root_point(const Eigen::Vector3d& point) const {
    return root_point_rows_[static_cast<size_t>(
        root_index_->nearest(point.cast<float>(), 1).front())];
  }
  int32_t strand_of_point(int64_t row) const { return point_strand_[static_cast<size_t>(row)]; }

  bool layered() const { return body_distance_ != nullptr; }
  const CardSurfaces& card_surfaces() const { return card_surfaces_; }
  /// Where the air is around the hair mesh (GrowParams::field_air_stop_h); null when the
  /// field phase does not stop at air.
  const AirAroundHair* air() const { return air_.get(); }
  const TriangleMeshDistance& body_distance() const { return *body_distance_; }
  /// Height above the body of the input strand through `row`, `length_m` further along it
  /// towards its tip (its tip's height beyond it); `cursor` (a row of the same strand, at
  /// or after `row`) makes a walk along the strand linear.
  double height_along(int64_t row, double length_m, int64_t& cursor) const;

  /// The reference point of the root `root_id` at `root`: the nearest point of a
  /// root-carrying strand, or with layers, that strand's point nearest the root on a strand
  /// drawn by hash among those of the nearest one's cluster within layer_radius_h.
  int64_t reference_row(const Eigen::Vector3d& root, int64_t root_id) const;
  double length_to_tip_m(int64_t row) const { return length_to_tip_m_[static_cast<size_t>(row)]; }

  /// Closest point of the rails of `group` to `point`: the tangent there (along the
  /// reading direction) and whether the point lies past the end being read towards.
  struct Following {
    Eigen::Vector3d direction;
    bool past_end = false;
    double distance_m = 0;                              ///< from the rail
    Eigen::Vector3d closest = Eigen::Vector3d::Zero();  ///< the rail's point nearest
  };
  /// Only rails within follow_radius_h are looked at: farther, the point is lost anyway
  /// (distance_m is then infinite).
  Following follow(int32_t group, bool backward, const Eigen::Vector3d& point) const;

  /// The first point of `entry`'s strand where it is entered.
  Eigen::Vector3d entry_start(const StrandEntry& entry) const {
    const StrandSet& strands = input_.input_strands;
    return point_of(strands.points, entry.backward ? strands.offsets[entry.strand + 1] - 1
                                                   : strands.offsets[entry.strand]);
  }

  /// Where a bridge from `here`, going `direction`, into the input strand of `entry` goes:
  /// its first point, read its way and short of its end, no farther than its start, that
  /// lies within a step of `here` or ahead within `max_angle_deg` (default
  /// bridge_max_angle_deg) of `direction`; std::nullopt where none does (or the angle is 0).
  std::optional<Eigen::Vector3d> bridge_target(
      const StrandEntry& entry, const Eigen::Vector3d& here, const Eigen::Vector3d& direction,
      std::optional<double> max_angle_deg = std::nullopt) const;

  /// Whether a bridge from `from` to `to` runs more than bridge_paint_max_angle_deg off
  /// the clear paint of the hair face nearest its middle (within follow_radius_h); false
  /// where the gap is within a step, or no face near it has clear paint.
  bool crosses_paint(const Eigen::Vector3d& from, const Eigen::Vector3d& to) const;

  /// The clear painted flow axis (unit, either sense) of the hair face nearest `point`,
  /// where that face lies within follow_radius_h; std::nullopt where it does not, or its
  /// paint is not clear, or no paint was given.
  std::optional<Eigen::Vector3d> painted_flow_near(const Eigen::Vector3d& point) const;

  /// The best input strand to continue into from `point` going `direction`, among
  /// strands of groups not yet visited and not of `excluded_cluster`: the nearest entry
  /// (weighted by how much it turns), from `preferred_cluster` if any qualifies; with
  /// `hanging_continuations_only`, only the start of a tail or braid after its band.
  /// `from_card`: the strand is at the end of a card it followed, not of its field.
  std::optional<StrandEntry> next_entry(const Eigen::Vector3d& point,
                                        const Eigen::Vector3d& direction,
                                        const std::vector<int32_t>& visited_groups,
                                        int32_t preferred_cluster, int32_t excluded_cluster,
                                        bool from_card,
                                        bool hanging_continuations_only = false) const;

  /// Where a strand that ends with no strand to continue into (its card ends on the cap)
  /// joins the cards feeding a continued cluster: the nearest point, within
  /// continue_radius_h, of an input strand of a group that feeds a continuation (not yet
  /// visited), running within continue_max_angle_deg of `direction`. Only hair that
  /// continues into a cluster not starting at the root has such groups (a tail after its
  /// band); elsewhere a strand ends where its card does.
  std::optional<int32_t> joined_feeder(const Eigen::Vector3d& point,
                                       const Eigen::Vector3d& direction,
                                       const std::vector<int32_t>& visited_groups) const;

  const GrowInput& input() const { return input_; }
  const GrowParams& params() const { return params_; }

 private:
  // The constructor's steps, in its order.
  /// Each input strand's group, and each group's strands.
  void index_groups();
  /// Points of the strands that carry roots, for the roots' clusters and reference
  /// lengths: root-type strands of clusters that start at the root; else any root-type
  /// strand; else any strand. Then the strand of every input point.
  void index_root_points(bool any_type_roots);
  /// Per group, an index of its points for follow().
  void index_group_rails();
  /// Entries: both ends of every input strand; and every input point.
  void index_entries();
  /// Groups that feed a continuation (a cap's cards whose tips meet the start of a tail
  /// after its band): a strand of theirs ends within continued_root_radius_h of the
  /// start of a strand of a cluster that does not start at the root.
  void find_continuation_feeders();
  /// Strands whose tip hangs off the scalp: farther than continued_tip_off_scalp_h from
  /// the centre of every scalp triangle (next_entry()).
  void find_tips_off_scalp();
  /// Heights above the body, for layers.
  void measure_heights_above_body();
  /// The whole hair mesh with its paint: the strokes a bridge must not cut across, and
  /// the way a stub lies. Each group's own faces, for the hold on its card's surface.
  void index_hair_mesh();
  /// Arc length from each point to its strand's tip.
  void measure_lengths_to_tip();

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
  /// The whole hair mesh; null without its triangles, or when neither its paint nor the
  /// air test needs it.
  std::unique_ptr<TriangleMeshDistance> hair_distance_;
  bool hair_painted_ = false;  ///< the hair mesh has its painted flow
  /// The body for the air test, when the layers' body_distance_ is not built.
  std::unique_ptr<TriangleMeshDistance> air_body_distance_;
  std::unique_ptr<AirAroundHair> air_;  ///< null with field_air_stop_h = 0 or no hair mesh
  std::vector<double> height_m_;                         ///< per input point, with layers
  bool any_type_roots_ = false;
};

}  // namespace hair
