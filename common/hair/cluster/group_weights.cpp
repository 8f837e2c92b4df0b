#include "hair/cluster/group_weights.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace hair {
namespace {

/// Angle in [0, pi] between two vectors; pi / 2 when one of them is zero.
double angle_between(const Eigen::Vector3d& u, const Eigen::Vector3d& v) {
  double norms = u.norm() * v.norm();
  if (norms <= 0) return std::numbers::pi / 2;
  return std::acos(std::clamp(u.dot(v) / norms, -1.0, 1.0));
}

Eigen::Vector3d point(const Eigen::Ref<const Points3f>& strand, Eigen::Index row) {
  return strand.row(row).transpose().cast<double>();
}

}  // namespace

double offset_from_line(const Eigen::Vector3d& point, const Eigen::Vector3d& origin,
                        const Eigen::Vector3d& direction) {
  Eigen::Vector3d offset = point - origin;
  double length2 = direction.squaredNorm();
  if (length2 <= 0) return offset.norm();
  return (offset - offset.dot(direction) / length2 * direction).norm();
}

int farthest_from_chord(const Eigen::Ref<const Points3f>& centre) {
  auto points = static_cast<int>(centre.rows());
  if (points < 3) return points - 1;
  Eigen::Vector3d first = point(centre, 0), last = point(centre, points - 1);
  Eigen::Vector3d chord = last - first;
  double chord_length2 = chord.squaredNorm();
  int farthest = points / 2;
  double farthest_distance2 = 1e-18;
  for (int m = 1; m + 1 < points; ++m) {
    Eigen::Vector3d offset = point(centre, m) - first;
    double along = chord_length2 > 0 ? offset.dot(chord) / chord_length2 : 0;
    double distance2 = (offset - along * chord).squaredNorm();
    if (distance2 > farthest_distance2) {
      farthest_distance2 = distance2;
      farthest = m;
    }
  }
  return farthest;
}

ConnectionFeatures connection_features(const Eigen::Ref<const Points3f>& a,
                                       const Eigen::Ref<const Points3f>& b, double head_height_m,
                                       FlowDirection flow_direction, Closeness closeness) {
  ConnectionFeatures features;
  double a_to_b = (point(a, a.rows() - 1) - point(b, 0)).norm();
  double b_to_a = (point(b, b.rows() - 1) - point(a, 0)).norm();
  features.first_is_root_side = a_to_b <= b_to_a;
  const auto& root = features.first_is_root_side ? a : b;
  const auto& tip = features.first_is_root_side ? b : a;
  Eigen::Index root_points = root.rows(), tip_points = tip.rows();

  // (1): m over the distal half of c^r, n over the proximal half of c^t; or the ends.
  double closest2 = (point(root, root_points - 1) - point(tip, 0)).squaredNorm();
  if (closeness == Closeness::halves)
    for (Eigen::Index m = root_points / 2; m < root_points; ++m)
      for (Eigen::Index n = 0; n < (tip_points + 1) / 2; ++n)
        closest2 = std::min(closest2, (point(root, m) - point(tip, n)).squaredNorm());
  features.f1 = std::sqrt(closest2) / head_height_m;

  // (2): v_rt = p(c^r_M) - p(c^t_1), v_tt = p(c^t_M) - p(c^t_1).
  Eigen::Vector3d v_rt = point(root, root_points - 1) - point(tip, 0);
  Eigen::Vector3d v_tt = point(tip, tip_points - 1) - point(tip, 0);
  double tip_length2 = v_tt.squaredNorm();
  features.f2 =
      tip_length2 > 0 ? std::abs(v_rt.dot(v_tt)) / tip_length2 : std::numeric_limits<double>::max();

  // (3): c^r from its farthest point to its end, c^t from its start to its farthest
  // point; or over the quarters at the connection.
  int root_flow_from = 0, tip_flow_to = 0;
  if (flow_direction == FlowDirection::farthest_point) {
    root_flow_from = farthest_from_chord(root);
    tip_flow_to = farthest_from_chord(tip);
  } else {
    root_flow_from = static_cast<int>(std::min<Eigen::Index>(root_points - 2, root_points * 3 / 4));
    tip_flow_to = static_cast<int>(std::max<Eigen::Index>(1, (tip_points - 1) / 4));
  }
  Eigen::Vector3d root_leaving = point(root, root_points - 1) - point(root, root_flow_from);
  Eigen::Vector3d tip_entering = point(tip, tip_flow_to) - point(tip, 0);
  features.f3 = angle_between(root_leaving, tip_entering) / std::numbers::pi;

  // f4: each end off the line of the other's flow at the connection.
  Eigen::Vector3d root_end = point(root, root_points - 1), tip_start = point(tip, 0);
  features.f4 = (offset_from_line(tip_start, root_end, root_leaving) +
                 offset_from_line(root_end, tip_start, tip_entering)) /
                (2 * head_height_m);
  return features;
}

std::optional<double> connectivity_weight(const ConnectionFeatures& features,
                                          const ConnectivityParams& params) {
  if (!(features.f1 < params.f1_max && features.f2 < params.f2_max && features.f3 < params.f3_max &&
        features.f4 < params.f4_max))
    return std::nullopt;
  return params.k1 * features.f1 + params.k2 * features.f2 + params.k3 * features.f3 +
         params.k4 * features.f4;
}

std::optional<double> similarity_weight(const Eigen::Ref<const Points3f>& a,
                                        const Eigen::Ref<const Points3f>& b, double head_height_m,
                                        const SimilarityParams& params) {
  double roots = (point(a, 0) - point(b, 0)).norm() / head_height_m;                       // (4)
  double tips = (point(a, a.rows() - 1) - point(b, b.rows() - 1)).norm() / head_height_m;  // (5)
  if (!(roots < params.distance_max_h && tips < params.distance_max_h)) return std::nullopt;
  return (roots + tips) / 2;
}

const char* flow_direction_name(FlowDirection direction) {
  return direction == FlowDirection::farthest_point ? "farthest_point" : "end_quarter";
}

const char* closeness_name(Closeness closeness) {
  return closeness == Closeness::halves ? "halves" : "ends";
}

std::optional<FlowDirection> flow_direction_from_name(const std::string& name) {
  for (FlowDirection direction : {FlowDirection::farthest_point, FlowDirection::end_quarter})
    if (name == flow_direction_name(direction)) return direction;
  return std::nullopt;
}

std::optional<Closeness> closeness_from_name(const std::string& name) {
  for (Closeness closeness : {Closeness::halves, Closeness::ends})
    if (name == closeness_name(closeness)) return closeness;
  return std::nullopt;
}

}  // namespace hair
