#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "hair/core/strand_set.h"

namespace hair {

/// Type of a strand group (paper, section 4.1 and Algorithm 1).
enum class GroupType : int8_t {
  root_free = 0,       ///< nothing before it, nothing connectable after it
  root_connected = 1,  ///< nothing before it; a group after it continues its flow
  middle = 2,          ///< groups before and after it
  tip = 3,             ///< groups before it, none after it
};

/// Settings of typeify (pipelines/default/typeify.toml documents each).
struct TypeifyParams {
  /// Points of each group's centre strand (the average of its strands, resampled).
  int centre_points = 16;
  /// Another group is close to the beginning (end) of a group when its distal
  /// (proximal) half comes within this distance of the group's first (last) centre
  /// point; a fraction of the head height H.
  double neighbour_distance_h = 0.08;
  /// A group whose centre strand starts within this distance of the scalp (a fraction
  /// of H) counts as before it only the groups whose centre strand ends near its start:
  /// a card rooted on the scalp under another card's lower half is a root, not that
  /// card's continuation. 0, the default, leaves the paper's Algorithm 1 as written:
  /// the rule types the training corpus's root cards far better (at 0.05 H, cluster-all's
  /// bound for starting on the scalp), but the style classifier trained on what it yields
  /// holds out worse on the real meshes, and a braid's strips after its band turn into
  /// roots (docs/typeify.md).
  double root_scalp_distance_h = 0.0;
  /// The angle, in degrees, under which a root group's distal direction and a nearby
  /// group's proximal direction count as one flow; 0 takes it from the distribution
  /// of those angles over the model (see connection_angle_threshold()).
  double connect_angle_deg = 0.0;
  /// Bounds of the threshold taken from the distribution, in degrees.
  double min_connect_angle_deg = 20.0;
  double max_connect_angle_deg = 90.0;
};

/// Groups of a model with their types and neighbours.
struct GroupTypes {
  /// Centre strand of every group, #groups strands of TypeifyParams::centre_points.
  StrandSet centre_strands;
  std::vector<GroupType> type;                      ///< #groups
  std::vector<std::vector<int32_t>> before;         ///< R(g): groups close to g's beginning
  std::vector<std::vector<int32_t>> after;          ///< T(g): groups close to g's end
  std::vector<std::vector<float>> after_angle_rad;  ///< angle of flow to each T(g) member
  double connect_angle_threshold_rad = 0;           ///< the threshold used
  bool threshold_from_distribution = false;         ///< true when taken from the angles
  /// Per group: distance from its centre strand's first point to the scalp, metres
  /// (start_scalp_distances()); empty when typed without the body.
  std::vector<double> start_scalp_distance_m;
};

/// The centre strand of each group: every strand resampled by arc length to
/// `points` points, then averaged point by point (section 4.2, "center strands").
///
/// @param strands       input strands, root first
/// @param first_strand  #groups + 1 CSR offsets of the groups' strands
StrandSet centre_strands(const StrandSet& strands, const std::vector<int32_t>& first_strand,
                         int points);

/// A threshold splitting `angles_rad` in two classes (Otsu's method over a 90-bin
/// histogram of [0, pi]; where splits tie across an empty gap, the middle of the gap),
/// clamped to [min_rad, max_rad]; nullopt for fewer than 4 angles or a single class.
/// This is the rule for the paper's "threshold of similarity ... determined by the
/// distribution of the angles" (section 4.1).
std::optional<double> connection_angle_threshold(const std::vector<double>& angles_rad,
                                                 double min_rad, double max_rad);

/// Algorithm 1: the type of every group from its neighbours.
///
/// @param strands        input strands, root first (extract.h5 /strands)
/// @param first_strand   #groups + 1 CSR offsets of the groups' strands
/// @param head_height_m  H
GroupTypes group_types(const StrandSet& strands, const std::vector<int32_t>& first_strand,
                       double head_height_m, const TypeifyParams& params);

/// Algorithm 1 from the groups' centre strands (centre_strands()) and the distance from
/// each one's first point to the scalp (start_scalp_distances()), which turns on
/// TypeifyParams::root_scalp_distance_h; an empty `start_scalp_distance_m` leaves it off,
/// as group_types() above does.
GroupTypes group_types_from_centres(StrandSet centres, std::vector<double> start_scalp_distance_m,
                                    double head_height_m, const TypeifyParams& params);

}  // namespace hair
