#pragma once

#include <Eigen/Core>
#include <optional>
#include <string>

#include "hair/core/strand_set.h"

namespace hair {

/// Which directions equation (3) compares at a connection.
enum class FlowDirection {
  /// The paper's: c^r from its point farthest from its chord to its end, c^t from its
  /// start to its farthest point (half a strand on a bent one).
  farthest_point,
  /// The last quarter of c^r and the first quarter of c^t: the flow at the connection
  /// itself, which short pieces of a weaving braid need (their halves point apart).
  end_quarter,
};

/// What equation (1) measures between the two strands.
enum class Closeness {
  /// The paper's: the closest approach of c^r's distal half to c^t's proximal half.
  halves,
  /// The gap between c^r's last point and c^t's first: in a braid, pieces of the other
  /// streams cross the distal half of a piece, closer than its own continuation.
  ends,
};

/// Settings of the connectivity weight (paper, section 4.2, equations 1-3, and our
/// continuation offset f4). The weight w = k1 f1 + k2 f2 + k3 f3 + k4 f4 is a cost: 0 is
/// the best connection. Outside the bounds the weight is infinite: no edge.
///
/// The defaults are the first level's (cluster-middle): mostly f4, which tells a
/// stream's own continuation from a piece of another stream that starts as close, and
/// f1, which among pieces that all continue the flow (the tails below a ponytail's band)
/// prefers the nearest (docs/clustering.md). HairClusteringParams sets the second level's.
struct ConnectivityParams {
  double k1 = 0.2;       ///< coefficient of f1 (closeness at the connection)
  double k2 = 0.05;      ///< coefficient of f2 (overlap)
  double k3 = 0.05;      ///< coefficient of f3 (flow angle)
  double k4 = 0.7;       ///< coefficient of f4 (continuation offset); k1 + k2 + k3 + k4 = 1
  double f1_max = 0.25;  ///< the paper's bound H/4, f1 being in units of H
  double f2_max = 0.5;   ///< the paper's bound
  /// The paper's bound is 0.3 (54 degrees); consecutive pieces of a tight braid turn by
  /// more (synthetic braids: median 56 degrees across a junction), so 0.6.
  double f3_max = 0.6;
  /// No edge when f4 reaches this (in H): 0.03 H is 7 mm on MakeHuman. With
  /// closeness = ends, f4 <= f1, so f1_max or more is no bound.
  double f4_max = 0.03;
  FlowDirection flow_direction = FlowDirection::end_quarter;
  Closeness closeness = Closeness::ends;
};

/// The words of the enumerations above, as parameter files write them.
const char* flow_direction_name(FlowDirection direction);
const char* closeness_name(Closeness closeness);
/// The value of a word; std::nullopt for an unknown word.
std::optional<FlowDirection> flow_direction_from_name(const std::string& name);
std::optional<Closeness> closeness_from_name(const std::string& name);

/// Settings of the similarity weight between free-root groups (section 4.3, equations
/// 4 and 5): w = (|p(c_1^i) - p(c_1^j)| + |p(c_M^i) - p(c_M^j)|) / (2 H), an edge only
/// when both distances are under `distance_max_h` H.
struct SimilarityParams {
  double distance_max_h = 0.25;
};

/// The criteria between two centre strands (each #points x 3, root first).
struct ConnectionFeatures {
  bool first_is_root_side = true;  ///< the first strand is c^r, the second c^t
  double f1 = 0;  ///< closest approach of c^r's distal half to c^t's proximal half, in H
  double f2 = 0;  ///< |v_rt . v_tt| / |v_tt|^2: how far c^r's end lies along c^t
  double f3 = 0;  ///< angle between c^r's flow into its end and c^t's flow out of its start, / pi
  /// Continuation offset (ours, not the paper's), in H: how far c^t's first point lies
  /// off the line along which c^r flows out of its last point, and c^r's last point off
  /// the line along which c^t flows into its first, the mean of the two. The flows are
  /// f3's. 0 when each piece points straight at the other across the gap, as the pieces
  /// of one stream do, whatever the gap's length; a piece of another stream that starts
  /// beside the end, or two pieces joined tip to tip, lie off those lines.
  double f4 = 0;
};

/// Distance from `point` to the line through `origin` along `direction`; the distance
/// to `origin` when `direction` is zero.
double offset_from_line(const Eigen::Vector3d& point, const Eigen::Vector3d& origin,
                        const Eigen::Vector3d& direction);

/// Index of the point of `centre` farthest from the chord between its first and last
/// points, among the inner points; the middle point when the strand is straight.
int farthest_from_chord(const Eigen::Ref<const Points3f>& centre);

/// Equations (1)-(3) and f4 for centre strands `a` and `b`. Their order (which is c^r) is
/// decided by the distances from the end of one to the start of the other: the pair
/// with the shorter gap runs a -> b (a is c^r) or b -> a.
ConnectionFeatures connection_features(const Eigen::Ref<const Points3f>& a,
                                       const Eigen::Ref<const Points3f>& b, double head_height_m,
                                       FlowDirection flow_direction = FlowDirection::farthest_point,
                                       Closeness closeness = Closeness::halves);

/// The connectivity weight of `features`, or nullopt (infinite: no edge) when a
/// criterion is at or beyond its bound.
std::optional<double> connectivity_weight(const ConnectionFeatures& features,
                                          const ConnectivityParams& params);

/// The similarity weight of two free-root centre strands, or nullopt (no edge).
std::optional<double> similarity_weight(const Eigen::Ref<const Points3f>& a,
                                        const Eigen::Ref<const Points3f>& b, double head_height_m,
                                        const SimilarityParams& params);

}  // namespace hair
