#include "hair/style/feature_standardization.h"

#include <cmath>

#include "hair/core/error.h"

namespace hair {

void check_finite_features(const Eigen::MatrixXd& rows,
                           std::span<const std::string> feature_names) {
  if (rows.allFinite()) return;
  for (Eigen::Index row = 0; row < rows.rows(); ++row)
    for (Eigen::Index column = 0; column < rows.cols(); ++column) {
      double value = rows(row, column);
      if (std::isfinite(value)) continue;
      std::string where =
          "feature row " + std::to_string(row) + ", column " + std::to_string(column);
      if (static_cast<size_t>(column) < feature_names.size())
        where += " (" + feature_names[static_cast<size_t>(column)] + ")";
      throw Error::bad_input("", where + ": " +
                                     (std::isnan(value) ? "NaN"
                                      : value > 0       ? "+inf"
                                                        : "-inf") +
                                     " (features must be finite)");
    }
}

std::vector<double> feature_log_offsets(std::span<const std::string> names,
                                        double length_offset_h) {
  std::vector<double> offsets;
  for (const std::string& name : names)
    offsets.push_back(name.ends_with("_h")          ? length_offset_h
                      : name == "middle_node_count" ? kCountLogOffset
                                                    : 0.0);
  return offsets;
}

void check_log_offsets(std::span<const double> log_offsets, const std::string& who) {
  for (double offset : log_offsets)
    if (!(offset >= 0) || !std::isfinite(offset))
      throw Error::usage(who + ": a log offset of " + std::to_string(offset) +
                         " (must be 0 or positive, and finite)");
}

namespace {

/// `rows` with every column of positive log offset c taken to log(max(x, 0) + c): lengths,
/// distances and counts are never negative (a negative one, which none of ours is, counts
/// as 0).
Eigen::MatrixXd log_scaled(const Eigen::MatrixXd& rows, const Eigen::VectorXd& log_offset) {
  if (log_offset.size() == 0) return rows;
  Eigen::MatrixXd scaled = rows;
  for (Eigen::Index column = 0; column < rows.cols(); ++column)
    if (log_offset[column] > 0)
      scaled.col(column) = (rows.col(column).array().max(0.0) + log_offset[column]).log().matrix();
  return scaled;
}

}  // namespace

FeatureStandardization feature_standardization(const Eigen::MatrixXd& original_rows,
                                               std::span<const double> log_offsets) {
  FeatureStandardization result;
  if (!log_offsets.empty()) {
    if (log_offsets.size() != static_cast<size_t>(original_rows.cols()))
      throw Error::usage("feature standardisation: " + std::to_string(log_offsets.size()) +
                         " log offsets for " + std::to_string(original_rows.cols()) + " features");
    check_log_offsets(log_offsets, "feature standardisation");
    result.log_offset = Eigen::Map<const Eigen::VectorXd>(
        log_offsets.data(), static_cast<Eigen::Index>(log_offsets.size()));
  }
  const Eigen::MatrixXd rows = log_scaled(original_rows, result.log_offset);
  auto n = static_cast<double>(rows.rows());
  result.mean = rows.colwise().sum().transpose() / n;
  result.scale.resize(rows.cols());
  for (Eigen::Index column = 0; column < rows.cols(); ++column) {
    // Equal values give a mean that need not equal them (rounding): test equality instead
    // of a zero deviation, so that a constant column is never scaled by a rounding error.
    bool constant = rows.col(column).minCoeff() == rows.col(column).maxCoeff();
    double deviation =
        std::sqrt((rows.col(column).array() - result.mean[column]).square().sum() / n);
    result.scale[column] = constant || !(deviation > 0) ? 1.0 : deviation;
  }
  return result;
}

FloatRows standardized_rows(const FeatureStandardization& standardization,
                            const Eigen::MatrixXd& original_rows) {
  const Eigen::MatrixXd rows = log_scaled(original_rows, standardization.log_offset);
  return ((rows.rowwise() - standardization.mean.transpose()).array().rowwise() /
          standardization.scale.transpose().array())
      .cast<float>();
}

}  // namespace hair
