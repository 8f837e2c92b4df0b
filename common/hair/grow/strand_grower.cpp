// The grower of one strand from its root (StrandGrower): the field phase, the input strands
// followed group after group, and the bridges between them.
#include "hair/grow/strand_grower.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>

namespace hair {
namespace {

using Vec3 = Eigen::Vector3d;

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
    // The stretch through air the strand is on: its length, the points before it and the
    // direction there.
    const AirAroundHair* air = context_.air();
    const double air_stop_m = params_.field_air_stop_h * context_.input().head_height_m;
    double air_m = 0;
    size_t before_air = 0;
    Vec3 direction_before_air = direction_;
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
      // Grown hair lies where the mesh has hair: a stretch through air longer than
      // field_air_stop_h is taken back, and the input strands take over.
      if (air != nullptr) {
        if (air->is_air(strand_.points.back())) {
          if (air_m == 0) {
            before_air = strand_.points.size() - 1;
            direction_before_air = direction_;
          }
          air_m += (strand_.points.back() - point).norm();
          if (air_m > air_stop_m) {
            take_back_to(before_air);
            direction_ = direction_before_air;
            ++strand_.field_air_stops;
            break;
          }
        } else {
          air_m = 0;
        }
      }
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

}  // namespace

GrowingStrand grow_strand(const GrowingContext& context, const OrientationField* field,
                          const BodySdf& body, int32_t root_cluster, const Vec3& root,
                          int64_t reference_row) {
  return StrandGrower(context, field, body, root_cluster).grow(root, reference_row);
}

}  // namespace hair
