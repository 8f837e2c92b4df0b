#pragma once

#include <Eigen/Core>
#include <span>
#include <string>
#include <vector>

namespace hair {

/// Feature rows as the OpenCV classifiers take them: one sample a row, CV_32F, row-major
/// (n x d).
using FloatRows = Eigen::Matrix<float, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

/// Per-feature centring and scaling, z = (x' - mean) / scale, computed on training rows
/// only and applied to every row given to the classifiers (both the SVM, whose kernel
/// compares distances across features, and the random forest, which does not need it
/// but gets the same rows). x' is the feature itself, or for a feature with a log offset
/// c > 0, log(max(x, 0) + c) (feature_log_offsets()).
struct FeatureStandardization {
  /// d log offsets (0: the feature as it is), or empty: every feature as it is
  Eigen::VectorXd log_offset;
  Eigen::VectorXd mean;   ///< d, column means of the training rows (x')
  Eigen::VectorXd scale;  ///< d, column standard deviations (divided by n); 1 for a
                          ///< column whose training values are all equal
};

/// Log offset of a length or distance in head heights (a feature named *_h): lengths
/// compare by their ratio, so that a cluster 0.2 H long differs from one 0.4 H long as
/// one 1 H long does from one 2 H long, whatever the mesh's units and the hair's scale.
/// The offset keeps the lengths under it alike (a strand's distance to the skin at its
/// root, a missing twist: 0); 0.1 H (2.4 cm) was chosen on the corpus's cross-validation,
/// where 0.03-0.1 H tie and 0.3 H is worse (docs/classify.md, "Classifiers").
inline constexpr double kLengthLogOffsetH = 0.1;
/// Log offset of a count (middle_node_count): one node more counts for less the more
/// there are, so that a braid cut into 29 pieces lies near one cut into 10, not three
/// times as far from it as one cut into 3 (mesh density).
inline constexpr double kCountLogOffset = 1;

/// The log offsets of the features `names` (in this order): kLengthLogOffsetH for a
/// length or distance in H (a name ending in "_h"), kCountLogOffset for
/// middle_node_count, 0 (as it is) for the others: shares, ratios, cosines, and the raw
/// features (positions and their spreads, which the paper compares as they are).
/// `length_offset_h` replaces kLengthLogOffsetH (0: lengths as they are).
std::vector<double> feature_log_offsets(std::span<const std::string> names,
                                        double length_offset_h = kLengthLogOffsetH);

/// Throws hair::Error (usage), "`who`: a log offset of ... (must be 0 or positive, and
/// finite)", for the first offset of `log_offsets` that is negative or not finite.
void check_log_offsets(std::span<const double> log_offsets, const std::string& who);

/// Throws hair::Error (bad input) for the first NaN or infinite value of `rows` (n x d),
/// naming its row and feature: "feature row 12, column 3 (long_length_h): NaN".
/// `feature_names`: d names, or empty (the column number alone).
void check_finite_features(const Eigen::MatrixXd& rows,
                           std::span<const std::string> feature_names = {});

/// The standardisation of the rows of `rows` (n x d, n >= 1, finite), each feature taken
/// through its log offset first (`log_offsets`: d values >= 0, or empty: none). Throws
/// hair::Error (usage) for log offsets not d, negative or not finite.
FeatureStandardization feature_standardization(const Eigen::MatrixXd& rows,
                                               std::span<const double> log_offsets = {});

/// (x' - mean) / scale, row by row, rounded to float (n x d).
FloatRows standardized_rows(const FeatureStandardization& standardization,
                            const Eigen::MatrixXd& rows);

}  // namespace hair
