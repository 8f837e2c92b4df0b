#pragma once
// A labelled table of cluster features for training and evaluating the hairstyle
// classifiers (issue 6), as tab-separated text and as Weka's ARFF.

#include <Eigen/Core>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace hair {

/// One row per labelled cluster.
struct StyleTable {
  std::vector<std::string> feature_names;  ///< #features
  Eigen::MatrixXd rows;                    ///< #rows x #features
  std::vector<int8_t> label;       ///< per row: style code (normal 0, fixed 1, short 2, braided 3)
  std::vector<std::string> model;  ///< per row: the model the cluster is from
  std::vector<int32_t> cluster;    ///< per row: the cluster's id in its model
  std::vector<uint8_t> real_mesh;  ///< per row: 1 for an artist's mesh, 0 for synthetic
  std::vector<double> label_purity;  ///< per row: share of the cluster's groups with the label
  std::vector<int64_t> strand_count;  ///< per row: the cluster's grown strands (runs), its weight

  int64_t row_count() const { return rows.rows(); }
  /// Appends a row; `features` must have #feature_names values.
  void append(const Eigen::RowVectorXd& features, int8_t style, const std::string& model_name,
              int32_t cluster_id, bool real, double purity, int64_t strands);
};

/// Writes the table as tab-separated text: a header line `model cluster real_mesh
/// label label_purity strands <feature names...>`, then one line per row, values with 17
/// significant digits (they read back exactly). Atomic (temporary file, then rename).
void write_style_table_tsv(const std::filesystem::path& path, const StyleTable& table);

/// Reads a table written by write_style_table_tsv() (or by the versions before the
/// `strands` column, whose rows then weigh 0 strands); throws hair::Error (bad input) with
/// the file and line of the first malformed line.
StyleTable read_style_table_tsv(const std::filesystem::path& path);

/// Writes the table as ARFF (Weka's format): the numeric features, then the class
/// attribute `style {normal,fixed,short,braided}`; the model and cluster as a comment
/// per row. Atomic.
void write_style_table_arff(const std::filesystem::path& path, const StyleTable& table,
                            const std::string& relation);

}  // namespace hair
