#pragma once

#include <Eigen/Core>
#include <span>
#include <string>

namespace hair {

/// Feature rows as the OpenCV classifiers take them: one sample a row, CV_32F, row-major
/// (n x d).
using FloatRows = Eigen::Matrix<float, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

/// Per-feature centring and scaling, z = (x - mean) / scale, computed on training rows
/// only and applied to every row given to the classifiers (both the SVM, whose kernel
/// compares distances across features, and the random forest, which does not need it
/// but gets the same rows).
struct FeatureStandardization {
  Eigen::VectorXd mean;   ///< d, column means of the training rows
  Eigen::VectorXd scale;  ///< d, column standard deviations (divided by n); 1 for a
                          ///< column whose training values are all equal
};

/// Throws hair::Error (bad input) for the first NaN or infinite value of `rows` (n x d),
/// naming its row and feature: "feature row 12, column 3 (long_length_h): NaN".
/// `feature_names`: d names, or empty (the column number alone).
void check_finite_features(const Eigen::MatrixXd& rows,
                           std::span<const std::string> feature_names = {});

/// The standardisation of the rows of `rows` (n x d, n >= 1, finite).
FeatureStandardization feature_standardization(const Eigen::MatrixXd& rows);

/// (rows - mean) / scale, row by row, rounded to float (n x d).
FloatRows standardized_rows(const FeatureStandardization& standardization,
                            const Eigen::MatrixXd& rows);

}  // namespace hair
