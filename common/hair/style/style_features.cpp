#include "hair/style/style_features.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <numeric>

#include "hair/core/error.h"
#include "hair/geom/strand_geometry.h"

namespace hair {
namespace {

using Vec3 = Eigen::Vector3d;

const std::vector<int32_t>& point_ids(const StyleFeatureInput& input, const std::string& name) {
  const auto& columns = input.strands.point_attributes;
  auto found = columns.find(name);
  if (found == columns.end() || !std::holds_alternative<std::vector<int32_t>>(found->second))
    throw Error::bad_input(input.source, "the grown strands have no int32 point attribute '" +
                                             name + "' (strands.h5 from grow before schema v2?)");
  return std::get<std::vector<int32_t>>(found->second);
}

/// Angle between two directions in radians, 0 when either is zero.
double angle_between(const Vec3& a, const Vec3& b) {
  if (a.squaredNorm() == 0 || b.squaredNorm() == 0) return 0;
  return std::atan2(a.cross(b).norm(), a.dot(b));
}

double strand_length_m(const StrandSet& strands, int64_t s) {
  double length_m = 0;
  for (int64_t row = strands.offsets[s] + 1; row < strands.offsets[s + 1]; ++row)
    length_m += (point_of(strands.points, row) - point_of(strands.points, row - 1)).norm();
  return length_m;
}

/// Mean of the strands' j-th points for every j: the centre strand (#points_per x 3).
/// `strands` all have `points_per` points; `members` picks the strands averaged.
Eigen::MatrixXd centre_strand(const StrandSet& strands, int points_per,
                              const std::vector<int64_t>& members) {
  Eigen::MatrixXd centre = Eigen::MatrixXd::Zero(points_per, 3);
  for (int64_t s : members) centre += strands.strand(s).cast<double>();
  if (!members.empty()) centre /= static_cast<double>(members.size());
  return centre;
}

/// d_j of equation (6) for every j: the mean distance of the strands' j-th points to the
/// centre strand's (#points_per).
Eigen::VectorXd spread_profile(const StrandSet& profiles, int points_per) {
  std::vector<int64_t> all(static_cast<size_t>(profiles.strand_count()));
  for (size_t s = 0; s < all.size(); ++s) all[s] = static_cast<int64_t>(s);
  Eigen::MatrixXd centre = centre_strand(profiles, points_per, all);
  Eigen::VectorXd spread = Eigen::VectorXd::Zero(points_per);
  for (int64_t s = 0; s < profiles.strand_count(); ++s)
    spread += (profiles.strand(s).cast<double>() - centre).rowwise().norm();
  return spread / static_cast<double>(std::max<int64_t>(1, profiles.strand_count()));
}

/// Equation (7), in metres: max over nodes i and positions j of |c_j^i - c_j^total|.
///
/// Nodes are middle clusters; a grown strand follows one node's groups for a while, then
/// maybe another's, so the nodes' centre strands are not whole strands to resample and
/// average point by point. c^total is the mean of the runs that follow middle nodes,
/// taken at equal arc lengths (`step_m`) from each run's start while at least half of
/// those runs are that long; c_j^i is the mean of the points following node i whose
/// nearest point of c^total is c_j^total (at least 5 of them). With fewer than two nodes
/// so measured, 0.
double twist_m(const ClusterRuns& cluster, double step_m) {
  const StrandSet& runs = cluster.runs;
  std::vector<int64_t> members;
  for (int64_t s = 0; s < runs.strand_count(); ++s)
    for (int64_t row = runs.offsets[s]; row < runs.offsets[s + 1]; ++row)
      if (cluster.point_middle_node[static_cast<size_t>(row)] >= 0) {
        members.push_back(s);
        break;
      }
  if (members.empty()) return 0;
  // c^total: the members' points at arc lengths 0, step, 2 step, ... from their starts.
  std::vector<Vec3> sum;
  std::vector<int64_t> count;
  for (int64_t s : members) {
    size_t k = 0;
    double along_m = 0, next_m = 0;
    for (int64_t row = runs.offsets[s]; row + 1 < runs.offsets[s + 1]; ++row) {
      Vec3 a = point_of(runs.points, row), b = point_of(runs.points, row + 1);
      double length_m = (b - a).norm();
      while (next_m <= along_m + length_m) {
        double t = length_m > 0 ? (next_m - along_m) / length_m : 0;
        if (k == sum.size()) sum.push_back(Vec3::Zero()), count.push_back(0);
        sum[k] += a + t * (b - a);
        ++count[k];
        ++k;
        next_m += step_m;
      }
      along_m += length_m;
    }
  }
  std::vector<Vec3> total;
  for (size_t k = 0; k < sum.size() && 2 * count[k] >= static_cast<int64_t>(members.size()); ++k)
    total.push_back(sum[k] / static_cast<double>(count[k]));
  if (total.size() < 2) return 0;
  // c^i_j: node i's points by their nearest point of c^total.
  std::map<std::pair<int32_t, size_t>, std::pair<Vec3, int64_t>> node_sums;
  for (int64_t s : members)
    for (int64_t row = runs.offsets[s]; row < runs.offsets[s + 1]; ++row) {
      int32_t node = cluster.point_middle_node[static_cast<size_t>(row)];
      if (node < 0) continue;
      Vec3 point = point_of(runs.points, row);
      size_t nearest = 0;
      for (size_t k = 1; k < total.size(); ++k)
        if ((total[k] - point).squaredNorm() < (total[nearest] - point).squaredNorm()) nearest = k;
      auto& [node_sum, node_count] = node_sums[{node, nearest}];
      if (node_count == 0) node_sum = Vec3::Zero();
      node_sum += point;
      ++node_count;
    }
  std::map<int32_t, bool> measured;
  double largest_m = 0;
  for (const auto& [key, value] : node_sums) {
    if (value.second < 5) continue;
    measured[key.first] = true;
    largest_m = std::max(
        largest_m, (value.first / static_cast<double>(value.second) - total[key.second]).norm());
  }
  return measured.size() >= 2 ? largest_m : 0;
}

/// The raw features of section 6.1 (the layout of raw_feature_names()).
Eigen::RowVectorXd raw_feature_row(const ClusterRuns& cluster, const StrandSet& particles,
                                   int points_per, const TriangleMeshDistance& skin) {
  const int p = points_per;
  const int64_t n = particles.strand_count();
  Eigen::RowVectorXd row = Eigen::RowVectorXd::Zero(raw_feature_count(p));
  if (n == 0) return row;
  std::vector<int64_t> all(static_cast<size_t>(n));
  for (int64_t s = 0; s < n; ++s) all[static_cast<size_t>(s)] = s;
  Eigen::MatrixXd average = centre_strand(particles, p, all);

  // Per strand, computed in parallel and summed in strand order (deterministic).
  Eigen::MatrixXd skin_distance(n, p), average_distance(n, p), turn(n, p - 1);
#pragma omp parallel for schedule(dynamic, 64)
  for (int64_t s = 0; s < n; ++s) {
    Eigen::MatrixXd strand = particles.strand(s).cast<double>();
    for (int j = 0; j < p; ++j) {
      skin_distance(s, j) = skin.distance(strand.row(j).transpose());
      average_distance(s, j) = (strand.row(j) - average.row(j)).norm();
    }
    Vec3 before = cluster.arrival[static_cast<size_t>(s)];
    for (int j = 0; j + 1 < p; ++j) {
      Vec3 edge = (strand.row(j + 1) - strand.row(j)).transpose();
      turn(s, j) = angle_between(before, edge);
      before = edge;
    }
  }

  Eigen::MatrixXd all_points = particles.points.cast<double>();
  Eigen::RowVector3d mean = all_points.colwise().mean();
  Eigen::RowVector3d variance = (all_points.rowwise() - mean).array().square().colwise().mean();
  auto column_variance = [](const Eigen::MatrixXd& values) {
    Eigen::RowVectorXd mean_row = values.colwise().mean();
    return Eigen::RowVectorXd((values.rowwise() - mean_row).array().square().colwise().mean());
  };
  Eigen::MatrixXd edge_sum = Eigen::MatrixXd::Zero(p - 1, 3);
  for (int64_t s = 0; s < n; ++s) {
    Eigen::MatrixXd strand = particles.strand(s).cast<double>();
    edge_sum += strand.bottomRows(p - 1) - strand.topRows(p - 1);
  }
  Eigen::MatrixXd mean_edge = edge_sum / static_cast<double>(n);

  int at = 0;
  auto put = [&](const Eigen::RowVectorXd& values) {
    row.segment(at, values.size()) = values;
    at += static_cast<int>(values.size());
  };
  put(mean);
  put(variance);
  put(Eigen::RowVectorXd::Constant(1, static_cast<double>(n)));
  put(skin_distance.colwise().mean());
  put(column_variance(skin_distance));
  put(average_distance.colwise().mean());
  put(column_variance(average_distance));
  put(Eigen::Map<const Eigen::RowVectorXd>(Eigen::MatrixXd(mean_edge.transpose()).data(),
                                           3 * (p - 1)));
  put(turn.colwise().mean());
  put(Eigen::Map<const Eigen::RowVectorXd>(Eigen::MatrixXd(average.transpose()).data(), 3 * p));
  return row;
}

/// Every k-th run of `cluster`, k = ceil(#runs / max_count) (all runs for max_count 0).
ClusterRuns sampled_runs(const ClusterRuns& cluster, int max_count) {
  int64_t count = cluster.runs.strand_count();
  if (max_count <= 0 || count <= max_count) return cluster;
  int64_t stride = (count + max_count - 1) / max_count;
  ClusterRuns sample;
  for (int64_t s = 0; s < count; s += stride) {
    auto i = static_cast<size_t>(s);
    sample.runs.append_strand(cluster.runs.strand(s));
    sample.starts_at_root.push_back(cluster.starts_at_root[i]);
    sample.ends_at_tip.push_back(cluster.ends_at_tip[i]);
    sample.arrival.push_back(cluster.arrival[i]);
    sample.middle_node.push_back(cluster.middle_node[i]);
    sample.point_middle_node.insert(
        sample.point_middle_node.end(), cluster.point_middle_node.begin() + cluster.runs.offsets[s],
        cluster.point_middle_node.begin() + cluster.runs.offsets[s + 1]);
  }
  return sample;
}

/// Mean skin distance of the runs' points at 0, 25, 50, 75 and 100% of their length, in H.
std::array<double, 5> skin_distance_profile_h(const StrandSet& runs,
                                              const TriangleMeshDistance& skin, double h) {
  constexpr int kPoints = 5;
  StrandSet quarters = resample_by_count(runs, kPoints);
  std::vector<double> distance_m(static_cast<size_t>(quarters.point_count()));
#pragma omp parallel for schedule(dynamic, 256)
  for (int64_t row = 0; row < quarters.point_count(); ++row)
    distance_m[static_cast<size_t>(row)] = skin.distance(point_of(quarters.points, row));
  std::array<double, kPoints> mean_h{};
  for (int64_t s = 0; s < quarters.strand_count(); ++s)
    for (int j = 0; j < kPoints; ++j)
      mean_h[static_cast<size_t>(j)] += distance_m[static_cast<size_t>(quarters.offsets[s] + j)];
  for (double& value : mean_h)
    value /= static_cast<double>(std::max<int64_t>(1, quarters.strand_count())) * h;
  return mean_h;
}

/// -y of the unit mean edge vector of `profiles` (every strand `points_per` points) at
/// the first edge, a third, two thirds and the last; 0 where the mean is zero.
std::array<double, 4> downward_profile(const StrandSet& profiles, int points_per) {
  std::array<double, 4> downward{};
  for (int k = 0; k < 4; ++k) {
    auto edge = static_cast<int64_t>(std::lround(k * (points_per - 2) / 3.0));
    Vec3 mean = Vec3::Zero();
    for (int64_t s = 0; s < profiles.strand_count(); ++s)
      mean += point_of(profiles.points, profiles.offsets[s] + edge + 1) -
              point_of(profiles.points, profiles.offsets[s] + edge);
    double norm = mean.norm();
    downward[static_cast<size_t>(k)] = norm > 0 ? -mean.y() / norm : 0.0;
  }
  return downward;
}

/// The q-quantile of `values` (not empty; reordered): the value at rank ceil(q n) - 1,
/// so 1 gives the maximum.
double quantile_of(std::vector<double>& values, double q) {
  auto n = values.size();
  auto rank = static_cast<size_t>(std::max(1.0, std::ceil(q * static_cast<double>(n)))) - 1;
  rank = std::min(rank, n - 1);
  std::nth_element(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(rank),
                   values.end());
  return values[rank];
}

}  // namespace

const std::vector<std::string>& paper_feature_names() {
  static const std::vector<std::string> names = {
      "mean_length_h", "long_length_h",     "gathering_ratio", "far_scalp_distance_h",
      "root_share",    "middle_node_count", "twist_h"};
  return names;
}

Eigen::RowVectorXd paper_feature_row(const PaperFeatures& features) {
  Eigen::RowVectorXd row(7);
  row << features.mean_length_h, features.long_length_h, features.gathering_ratio,
      features.far_scalp_distance_h, features.root_share,
      static_cast<double>(features.middle_node_count), features.twist_h;
  return row;
}

const std::vector<std::string>& extended_feature_names() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> all = paper_feature_names();
    all.insert(all.end(), {"tip_share", "end_spread_h", "skin_distance_0_h", "skin_distance_25_h",
                           "skin_distance_50_h", "skin_distance_75_h", "skin_distance_100_h",
                           "downward_0", "downward_33", "downward_67", "downward_100"});
    return all;
  }();
  return names;
}

Eigen::RowVectorXd extended_feature_row(const PaperFeatures& features) {
  Eigen::RowVectorXd row(static_cast<Eigen::Index>(extended_feature_names().size()));
  row << paper_feature_row(features), features.tip_share, features.end_spread_h,
      Eigen::Map<const Eigen::RowVectorXd>(
          features.skin_distance_h.data(),
          static_cast<Eigen::Index>(features.skin_distance_h.size())),
      Eigen::Map<const Eigen::RowVectorXd>(features.downward.data(),
                                           static_cast<Eigen::Index>(features.downward.size()));
  return row;
}

const Eigen::MatrixXd& feature_set_rows(const StyleFeatures& features,
                                        const std::string& feature_set) {
  if (feature_set == "paper") return features.paper_rows;
  if (feature_set == "extended") return features.extended_rows;
  if (feature_set == "raw") return features.raw_rows;
  throw Error::usage("unknown feature set '" + feature_set + "': paper, extended or raw");
}

std::vector<std::string> feature_set_names(const std::string& feature_set, int raw_points) {
  if (feature_set == "paper") return paper_feature_names();
  if (feature_set == "extended") return extended_feature_names();
  if (feature_set == "raw") return raw_feature_names(raw_points);
  throw Error::usage("unknown feature set '" + feature_set + "': paper, extended or raw");
}

int raw_feature_count(int raw_points) { return 11 * raw_points + 3; }

std::vector<std::string> raw_feature_names(int raw_points) {
  std::vector<std::string> names = {
      "position_mean_x",     "position_mean_y",     "position_mean_z", "position_variance_x",
      "position_variance_y", "position_variance_z", "strand_count"};
  auto indexed = [&](const std::string& stem, int count) {
    for (int j = 0; j < count; ++j) {
      char index[16];
      std::snprintf(index, sizeof index, "%02d", j);
      names.push_back(stem + "_" + index);
    }
  };
  indexed("skin_distance_mean", raw_points);
  indexed("skin_distance_variance", raw_points);
  indexed("average_strand_distance_mean", raw_points);
  indexed("average_strand_distance_variance", raw_points);
  for (int j = 0; j + 1 < raw_points; ++j)
    for (const char* axis : {"x", "y", "z"}) {
      char name[40];
      std::snprintf(name, sizeof name, "edge_mean_%s_%02d", axis, j);
      names.push_back(name);
    }
  indexed("direction_difference_mean", raw_points - 1);
  for (int j = 0; j < raw_points; ++j)
    for (const char* axis : {"x", "y", "z"}) {
      char name[40];
      std::snprintf(name, sizeof name, "average_strand_%s_%02d", axis, j);
      names.push_back(name);
    }
  return names;
}

std::vector<ClusterRuns> cluster_runs(const StyleFeatureInput& input) {
  const StrandSet& strands = input.strands;
  const std::vector<int32_t>& point_cluster = point_ids(input, "cluster");
  const std::vector<int32_t>& point_group = point_ids(input, "group");
  auto normal_column = strands.strand_attributes.find("root_normal");
  if (normal_column == strands.strand_attributes.end() ||
      !std::holds_alternative<Points3f>(normal_column->second))
    throw Error::bad_input(input.source, "the grown strands have no root_normal attribute");
  const Points3f& root_normal = std::get<Points3f>(normal_column->second);

  std::vector<ClusterRuns> clusters(static_cast<size_t>(input.cluster_count));
  std::vector<Points3f> pending;
  for (int64_t s = 0; s < strands.strand_count(); ++s) {
    int64_t first = strands.offsets[s], end = strands.offsets[s + 1];
    for (int64_t start = first; start < end;) {
      int32_t cluster = point_cluster[static_cast<size_t>(start)];
      if (cluster < 0 || cluster >= input.cluster_count)
        throw Error::bad_input(input.source, "point " + std::to_string(start) + " has cluster " +
                                                 std::to_string(cluster) + ", outside 0.." +
                                                 std::to_string(input.cluster_count - 1));
      int64_t stop = start + 1;
      while (stop < end && point_cluster[static_cast<size_t>(stop)] == cluster) ++stop;
      if (stop - start >= 2) {
        ClusterRuns& runs = clusters[static_cast<size_t>(cluster)];
        runs.runs.append_strand(strands.points.middleRows(start, stop - start));
        runs.starts_at_root.push_back(start == first ? 1 : 0);
        runs.ends_at_tip.push_back(stop == end ? 1 : 0);
        runs.arrival.push_back(start == first ? Vec3(root_normal.row(s).cast<double>().transpose())
                                              : Vec3(point_of(strands.points, start) -
                                                     point_of(strands.points, start - 1)));
        std::map<int32_t, int64_t> votes;
        for (int64_t row = start; row < stop; ++row) {
          int32_t group = point_group[static_cast<size_t>(row)];
          int32_t node = group >= 0 && group < static_cast<int32_t>(input.group_middle_node.size())
                             ? input.group_middle_node[static_cast<size_t>(group)]
                             : -1;
          runs.point_middle_node.push_back(node);
          if (node >= 0) ++votes[node];
        }
        int32_t best = -1;
        int64_t best_votes = 0;
        for (const auto& [node, count] : votes)
          if (count > best_votes) best = node, best_votes = count;
        runs.middle_node.push_back(best);
      }
      start = stop;
    }
  }
  return clusters;
}

StyleFeatures style_features(const StyleFeatureInput& input, const StyleFeatureParams& params) {
  if (params.profile_points < 2 || params.raw_points < 3)
    throw Error::usage("profile_points must be >= 2 and raw_points >= 3");
  if (!(params.robust_max_quantile > 0 && params.robust_max_quantile <= 1))
    throw Error::usage("robust_max_quantile must be in (0, 1]");
  if (!(input.head_height_m > 0))
    throw Error::bad_input(input.source, "head height is not positive");
  const double h = input.head_height_m;
  std::vector<ClusterRuns> clusters = cluster_runs(input);

  // The scalp (the triangles extract marked; the whole body if none) and the skin.
  std::vector<Eigen::Index> scalp_rows;
  for (Eigen::Index t = 0; t < input.body_triangles.rows(); ++t)
    if (static_cast<size_t>(t) < input.scalp_triangle.size() &&
        input.scalp_triangle[static_cast<size_t>(t)])
      scalp_rows.push_back(t);
  Triangles3i scalp_triangles(static_cast<Eigen::Index>(scalp_rows.size()), 3);
  for (size_t i = 0; i < scalp_rows.size(); ++i)
    scalp_triangles.row(static_cast<Eigen::Index>(i)) = input.body_triangles.row(scalp_rows[i]);
  if (scalp_triangles.rows() == 0) scalp_triangles = input.body_triangles;
  TriangleMeshDistance skin(input.body_vertices, input.body_triangles);
  TriangleMeshDistance scalp(input.body_vertices, scalp_triangles);

  StyleFeatures result;
  const auto cluster_count = static_cast<size_t>(input.cluster_count);
  result.paper.resize(cluster_count);
  result.paper_rows = Eigen::MatrixXd::Zero(input.cluster_count, 7);
  result.extended_rows = Eigen::MatrixXd::Zero(
      input.cluster_count, static_cast<Eigen::Index>(extended_feature_names().size()));
  result.raw_rows =
      Eigen::MatrixXd::Zero(input.cluster_count, raw_feature_count(params.raw_points));
  result.strand_count.assign(cluster_count, 0);
  result.point_count.assign(cluster_count, 0);

  // Middle nodes of each cluster, by its groups.
  std::vector<std::vector<int32_t>> nodes_of_cluster(cluster_count);
  for (size_t g = 0; g < input.group_cluster.size() && g < input.group_middle_node.size(); ++g) {
    int32_t cluster = input.group_cluster[g], node = input.group_middle_node[g];
    if (cluster < 0 || cluster >= input.cluster_count || node < 0) continue;
    auto& nodes = nodes_of_cluster[static_cast<size_t>(cluster)];
    if (std::find(nodes.begin(), nodes.end(), node) == nodes.end()) nodes.push_back(node);
  }

  for (size_t c = 0; c < cluster_count; ++c) {
    const ClusterRuns& cluster = clusters[c];
    const StrandSet& runs = cluster.runs;
    PaperFeatures& paper = result.paper[c];
    paper.middle_node_count = static_cast<int>(nodes_of_cluster[c].size());
    result.strand_count[c] = runs.strand_count();
    result.point_count[c] = runs.point_count();
    if (runs.strand_count() == 0) {
      result.paper_rows.row(static_cast<Eigen::Index>(c)) = paper_feature_row(paper);
      result.extended_rows.row(static_cast<Eigen::Index>(c)) = extended_feature_row(paper);
      continue;
    }
    std::vector<double> length_m(static_cast<size_t>(runs.strand_count()));
    for (int64_t s = 0; s < runs.strand_count(); ++s)
      length_m[static_cast<size_t>(s)] = strand_length_m(runs, s);
    paper.mean_length_h = std::accumulate(length_m.begin(), length_m.end(), 0.0) /
                          static_cast<double>(length_m.size()) / h;
    paper.long_length_h = quantile_of(length_m, params.robust_max_quantile) / h;
    double roots = 0;
    for (uint8_t at_root : cluster.starts_at_root) roots += at_root;
    double tips = 0;
    for (uint8_t at_tip : cluster.ends_at_tip) tips += at_tip;
    paper.tip_share = tips / static_cast<double>(runs.strand_count());
    paper.root_share = roots / static_cast<double>(runs.strand_count());

    ClusterRuns sample = sampled_runs(cluster, params.max_sampled_strands);
    StrandSet profiles = resample_by_count(sample.runs, params.profile_points);
    Eigen::VectorXd spread = spread_profile(profiles, params.profile_points);
    paper.gathering_ratio =
        spread.maxCoeff() > 0 ? spread(params.profile_points - 1) / spread.maxCoeff() : 1.0;
    paper.end_spread_h = spread(params.profile_points - 1) / h;
    paper.twist_h = twist_m(sample, params.twist_step_h * h) / h;
    std::vector<double> scalp_distance_m(static_cast<size_t>(profiles.point_count()));
#pragma omp parallel for schedule(dynamic, 256)
    for (int64_t row = 0; row < profiles.point_count(); ++row)
      scalp_distance_m[static_cast<size_t>(row)] = scalp.distance(point_of(profiles.points, row));
    paper.far_scalp_distance_h = quantile_of(scalp_distance_m, params.robust_max_quantile) / h;
    paper.skin_distance_h = skin_distance_profile_h(sample.runs, skin, h);
    paper.downward = downward_profile(profiles, params.profile_points);
    result.paper_rows.row(static_cast<Eigen::Index>(c)) = paper_feature_row(paper);
    result.extended_rows.row(static_cast<Eigen::Index>(c)) = extended_feature_row(paper);

    if (params.raw_features) {
      StrandSet particles = resample_by_count(sample.runs, params.raw_points);
      Eigen::RowVectorXd raw = raw_feature_row(sample, particles, params.raw_points, skin);
      raw(6) = static_cast<double>(runs.strand_count());  // strand_count: all of them
      result.raw_rows.row(static_cast<Eigen::Index>(c)) = raw;
    }
  }
  if (!result.extended_rows.allFinite() || !result.raw_rows.allFinite())
    throw Error::runtime(input.source, "a style feature is not finite");
  return result;
}

}  // namespace hair
