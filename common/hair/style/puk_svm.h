#pragma once

#include <cstdint>
#include <opencv2/ml.hpp>
#include <span>
#include <vector>

#include "hair/style/feature_standardization.h"

namespace hair {

/// Settings of a C-support-vector classifier with the PUK kernel (puk_kernel.h).
struct PukSvmParams {
  double sigma = 1;  ///< kernel peak width, in standardised feature units (> 0)
  double omega = 1;  ///< kernel tailing factor (> 0)
  double c = 1;      ///< soft-margin penalty C (> 0)
  bool operator==(const PukSvmParams&) const = default;
};

/// OpenCV's SMO stops when the largest violation of the optimality conditions is below
/// this (the tolerance of libsvm and of Weka's SMO; OpenCV's own default is FLT_EPSILON
/// with at most 1000 iterations)...
inline constexpr double kSvmTolerance = 1e-3;
/// ... or after this many iterations.
inline constexpr int kSvmMaxIterations = 100000;

/// One one-vs-one decision function, as OpenCV's SVM::getDecisionFunction gives it:
///   f(x) = -rho + sum_k alpha[k] K(support_vectors row sv_index[k], x),
/// a vote for class `first` when f(x) > 0, else for class `second`.
struct SvmDecisionFunction {
  int32_t first = 0;   ///< index into PukSvm::class_labels
  int32_t second = 0;  ///< index into PukSvm::class_labels, > first
  double rho = 0;
  std::vector<double> alpha;      ///< #support vectors of this pair, signed (y alpha)
  std::vector<int32_t> sv_index;  ///< as many rows of PukSvm::support_vectors
};

/// A trained PUK SVM held in our own fields, so that it can be saved and read back (OpenCV
/// cannot read back an SVM with a custom kernel: SVM::write writes an unknown kernel
/// type, which SVM::read rejects) and used for prediction without OpenCV.
struct PukSvm {
  PukSvmParams params;
  std::vector<int32_t> class_labels;  ///< k >= 1, ascending (OpenCV's class order)
  FloatRows support_vectors;          ///< #sv x d, standardised feature rows
  /// k (k - 1) / 2 functions, pairs in OpenCV's order (0,1), (0,2), ..., (0,k-1), (1,2), ...
  /// (none when k = 1: the only class is always predicted).
  std::vector<SvmDecisionFunction> decision_functions;
  int feature_count = 0;  ///< d
};

/// OpenCV's C_SVC with a PukKernel, trained on `rows` (n x d, standardised) with
/// `labels` (n, at least two distinct values), stopping as kSvmTolerance says.
/// Throws hair::Error: usage for fewer than two classes or a bad parameter, runtime when
/// OpenCV fails.
cv::Ptr<cv::ml::SVM> trained_opencv_puk_svm(const FloatRows& rows, std::span<const int32_t> labels,
                                            const PukSvmParams& params);

/// Our copy of an SVM trained by trained_opencv_puk_svm() with `class_labels` (ascending,
/// the distinct training labels).
PukSvm puk_svm_from_opencv(const cv::ml::SVM& svm, std::vector<int32_t> class_labels,
                           const PukSvmParams& params);

/// trained_opencv_puk_svm() copied by puk_svm_from_opencv(); with a single class in
/// `labels`, a model without decision functions that predicts that class.
PukSvm trained_puk_svm(const FloatRows& rows, std::span<const int32_t> labels,
                       const PukSvmParams& params);

/// What an SVM says about one row.
struct SvmPrediction {
  int32_t label = 0;                    ///< the class of most votes (the lower index of equals)
  std::vector<double> decision_values;  ///< f(x) of every decision function, in their order
  std::vector<int32_t> votes;           ///< k, per PukSvm::class_labels
};

/// The prediction of `svm` for `row` (d standardised values), computed as OpenCV 4.6's
/// SVM::predict does (svm.cpp, PredictBody): kernel values with every support vector as
/// float (puk_kernel_float), each pair's sum -rho + sum alpha K in double, a vote for the
/// pair's first class when the sum is > 0 and for its second otherwise, and the class of
/// most votes, the first (lowest label) of equals. So it equals OpenCV's, bit for bit.
SvmPrediction svm_prediction(const PukSvm& svm, const float* row);

/// The class the one-vs-one vote gives when `excluded_label` may not win: only the
/// contests between two other classes vote (a decision value > 0 for the pair's first
/// class), the class of most votes wins, the first of equals. The SVM's own label where
/// the excluded class is not one of its classes or it has no other.
///   @param[in] decision_values  as SvmPrediction::decision_values
int32_t svm_label_without(const PukSvm& svm, std::span<const double> decision_values,
                          int32_t excluded_label);

}  // namespace hair
