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

FeatureStandardization feature_standardization(const Eigen::MatrixXd& rows) {
  FeatureStandardization result;
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
                            const Eigen::MatrixXd& rows) {
  return ((rows.rowwise() - standardization.mean.transpose()).array().rowwise() /
          standardization.scale.transpose().array())
      .cast<float>();
}

}  // namespace hair
