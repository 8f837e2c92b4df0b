#pragma once
// Continuation: the ends of the oriented strands of decided regions, indexed, and the
// directions they give the regions whose rails meet them.

#include <Eigen/Core>
#include <cstdint>
#include <optional>
#include <vector>

#include "hair/extract/region_rails.h"
#include "hair/extract/strand_orientation.h"
#include "hair/geom/point_index.h"
#include "hair/mesh/poly_mesh.h"

namespace hair {

/// The end of an oriented strand of a decided patch, and the hair's flow there.
struct StrandEnd {
  bool is_root = false;
  Eigen::Vector3f flow;  ///< unit direction root to tip at this end
  int32_t patch = 0;
};

/// The ends of the oriented strands of decided regions and parted rails, to find what
/// lies at a strand's end (see decide_by_continuation_once()).
class StrandEndIndex {
 public:
  /// Every region's ends, but those of patches with `leave_out` set (may be empty).
  StrandEndIndex(const Points3f& vertices, const std::vector<RegionRails>& regions,
                 const std::vector<bool>& leave_out = {});

  /// What the nearest end of another patch's strand within `radius` of `point` says of a
  /// strand end there whose outward direction is `outward`: +1 it is a root, -1 a tip,
  /// 0 no neighbour.
  int vote(const Eigen::Vector3f& point, const Eigen::Vector3f& outward, int32_t patch,
           float radius) const;

  /// What a strand end at `point` with outward direction `outward` is, judged only by
  /// hair that runs on through it: the nearest end of another patch's strand within
  /// `radius` that is either a root leaving along `outward` (the hair goes on: a tip
  /// here, -1) or a tip arriving against it (the hair comes in: a root here, +1), both
  /// within 60 degrees; 0 if none. Ends beside it (roots side by side in dense hair, cap
  /// strands converging at a band) do not count.
  int through_vote(const Eigen::Vector3f& point, const Eigen::Vector3f& outward, int32_t patch,
                   float radius) const;

 private:
  static constexpr float aligned = 0.5f;  // cos 60 degrees

  /// The first non-zero `judge(end)` over the ends of other patches' strands within
  /// `radius` of `point`, nearest first; 0 if none.
  template <typename Judge>
  int first_vote(const Eigen::Vector3f& point, int32_t patch, float radius,
                 const Judge& judge) const;

  std::vector<StrandEnd> ends_;
  std::optional<PointIndex> index_;
};

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
                               int max_rounds = 8);

/// Continuation in rounds, so that a decision travels along chains of patches (a cap
/// made of several patches meeting the tail at one of them), at most `max_rounds`.
void decide_by_continuation(const Points3f& vertices, std::vector<RegionRails>& regions,
                            float radius, int max_rounds = 16);

}  // namespace hair
