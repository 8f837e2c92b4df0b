#pragma once
// Features of a cluster of grown strands for hairstyle classification (paper sections
// 5.1 and 6.1): the paper's hand-made features, and the raw-feature baseline it compares
// them with.

#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "hair/core/strand_set.h"
#include "hair/geom/triangle_mesh_distance.h"

namespace hair {

/// What the style features read of strands.h5, clusters.h5 and extract.h5.
struct StyleFeatureInput {
  /// Grown strands, root first; point_attributes "cluster" and "group" (int32), and
  /// strand_attributes "root_normal" (#strands x 3).
  StrandSet strands;
  int32_t cluster_count = 0;
  std::vector<int32_t> group_cluster;      ///< per input group: its final cluster
  std::vector<int32_t> group_middle_node;  ///< per input group: its middle cluster, or -1
  Points3f body_vertices;
  Triangles3i body_triangles;
  std::vector<uint8_t> scalp_triangle;  ///< per body triangle
  double head_height_m = 0;
  std::string source;  ///< names the grown strands in errors
};

/// Settings of style_features().
struct StyleFeatureParams {
  /// Points per strand for the gathering ratio (equation 6).
  int profile_points = 20;
  /// The paper's two maxima (the longest strand, the farthest particle from the scalp)
  /// are taken as this quantile: on an artist's mesh a few strands grown astray (2-6 H
  /// on a short cut or a cap) would otherwise decide them (docs/classify.md).
  double robust_max_quantile = 0.95;
  /// Spacing of the points of the centre strand of all middle nodes, c^total, for the
  /// twist (equation 7), in H.
  double twist_step_h = 0.02;
  /// Particles per strand for the raw features (section 6.1); 17 gives the paper's 190
  /// dimensions (raw_feature_count()).
  int raw_points = 17;
  /// Features other than the lengths, the root share and the strand count are measured
  /// on every k-th strand of a cluster, k chosen so that at most this many are (they are
  /// means, or a maximum whose tip strands are many; the distance queries dominate the
  /// time otherwise). 0: every strand.
  int max_sampled_strands = 1000;
  /// Whether to measure the raw features (training and evaluation want them; classify
  /// does not, and their distances to the skin are a third of its time). Without them
  /// StyleFeatures::raw_rows is all 0.
  bool raw_features = true;
};

/// The paper's features of one cluster (section 5.1). Lengths are in head heights H.
struct PaperFeatures {
  double mean_length_h = 0;  ///< short: the average length of the cluster's strands
  /// short: their maximum length, robust: the robust_max_quantile of the lengths
  double long_length_h = 0;
  /// fixed: equation (6), d_M / max_j d_j with d_j the mean distance of the strands'
  /// j-th points to the centre strand's; small when the strands gather at the end.
  double gathering_ratio = 1;
  /// fixed: the farthest particle's distance to the scalp, robust: the
  /// robust_max_quantile of the (sampled strands') particles' distances
  double far_scalp_distance_h = 0;
  double root_share = 0;            ///< fixed: share of the cluster's strands that start at a root
  int middle_node_count = 0;        ///< braided: middle clusters (cluster-middle) in the cluster
  /// braided: equation (7), max_ij |c_j^i - c_j^total| over the centre strands c^i of
  /// the middle nodes and c^total of all of them, matched by position along c^total
  /// (twist_m in style_features.cpp); 0 with fewer than two nodes.
  double twist_h = 0;

  // Ours, beyond the paper (the "extended" feature set): what tells a cap gathered by a
  // band, the first piece of long hair lying on the scalp, and short hair lying on the
  // head apart, which the paper's features above do not once clusters are split where
  // the group type changes (section 4.3).
  /// Share of the cluster's strands that end at a strand's tip (short hair ends in its
  /// cluster; a cap or the first piece of long hair goes on into another).
  double tip_share = 0;
  /// d_M of equation (6) in H: how far apart the strands end (a band gathers them).
  double end_spread_h = 0;
  /// Mean distance to the body's surface (the skin) of the strands' points at 0, 25,
  /// 50, 75 and 100% of their length, in H: where along its length hair leaves the
  /// head (a cap and short hair lie on it to the end, a tail leaves it at the band,
  /// hanging hair comes back to the shoulders).
  std::array<double, 5> skin_distance_h{};
  /// How much the strands point down at the start, a third, two thirds and the end of
  /// their length: -y of the unit mean of their edge vectors there (+Y up), 1 hanging
  /// straight down, 0 level, -1 rising.
  std::array<double, 4> downward{};
};

/// Names of the paper features, in the order of paper_feature_row().
const std::vector<std::string>& paper_feature_names();
/// The paper features as a row (the order of paper_feature_names()).
Eigen::RowVectorXd paper_feature_row(const PaperFeatures& features);
/// Names of the extended features: the paper's, then tip_share, end_spread_h,
/// skin_distance_{0,25,50,75,100}_h and downward_{0,33,67,100}.
const std::vector<std::string>& extended_feature_names();
/// The extended features as a row (the order of extended_feature_names()).
Eigen::RowVectorXd extended_feature_row(const PaperFeatures& features);

/// 11 * raw_points + 3: 190 for the default 17 particles.
int raw_feature_count(int raw_points);
/// Names of the raw features, e.g. "avg_strand_x_03" (raw_feature_count() of them).
std::vector<std::string> raw_feature_names(int raw_points);

/// The parts of grown strands in one cluster: every maximal run of consecutive points
/// of a strand whose point cluster is the cluster (a run has at least two points).
struct ClusterRuns {
  StrandSet runs;                          ///< root side first
  std::vector<uint8_t> starts_at_root;     ///< per run: it starts at a strand's root
  std::vector<uint8_t> ends_at_tip;        ///< per run: it ends at a strand's tip
  std::vector<Eigen::Vector3d> arrival;    ///< per run: the direction the strand comes
                                           ///< in with (the root's normal at a root)
  std::vector<int32_t> middle_node;        ///< per run: the middle cluster most of its
                                           ///< points follow, or -1
  std::vector<int32_t> point_middle_node;  ///< per point of the runs: the middle cluster
                                           ///< of the group it follows, or -1
};

/// The runs of every cluster (#cluster_count entries).
std::vector<ClusterRuns> cluster_runs(const StyleFeatureInput& input);

/// Features of every cluster.
struct StyleFeatures {
  std::vector<PaperFeatures> paper;   ///< per cluster
  Eigen::MatrixXd paper_rows;         ///< #clusters x paper_feature_names().size()
  Eigen::MatrixXd extended_rows;      ///< #clusters x extended_feature_names().size()
  Eigen::MatrixXd raw_rows;           ///< #clusters x raw_feature_count(raw_points)
  std::vector<int64_t> strand_count;  ///< per cluster: runs (0: nothing grew in it; its
                                      ///< features are all 0 and it is not classified)
  std::vector<int64_t> point_count;   ///< per cluster: grown points in it
};

/// The rows of `features` of the named feature set ("paper", "extended" or "raw"), and
/// their names; throws hair::Error (usage) for another name.
const Eigen::MatrixXd& feature_set_rows(const StyleFeatures& features,
                                        const std::string& feature_set);
std::vector<std::string> feature_set_names(const std::string& feature_set, int raw_points = 17);

/// The paper's features (section 5.1) and the raw features (section 6.1) of every
/// cluster of the grown strands. Deterministic whatever the thread count; every value
/// finite. Throws hair::Error (bad input) if a point attribute is missing or a cluster
/// id is out of range.
StyleFeatures style_features(const StyleFeatureInput& input, const StyleFeatureParams& params);

}  // namespace hair
