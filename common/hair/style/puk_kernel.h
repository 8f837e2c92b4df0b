#pragma once

#include <opencv2/ml.hpp>

namespace hair {

/// The Pearson VII function-based universal kernel (PUK) of Üstün, Melssen and Buydens,
/// "Facilitating the application of Support Vector Regression by using a universal Pearson
/// VII function based kernel", Chemometrics and Intelligent Laboratory Systems 81 (2006),
/// eq. (13), which the paper's SVM uses (section 5.1):
///
///   K(x, y) = 1 / (1 + (2 ||x - y|| sqrt(2^(1/omega) - 1) / sigma)^2)^omega
///
/// evaluated as Weka's weka.classifiers.functions.supportVector.Puk does:
///   factor = 2 sqrt(2^(1/omega) - 1) / sigma          (Puk.computeFactor)
///   t = factor ||x - y||,  K = 1 / (1 + t t)^omega      (Puk.evaluate)
/// with ||x - y||^2 summed over the coordinate differences (Weka expands it into dot
/// products, which rounds differently and can go slightly negative; the kernel is the same).
///
/// sigma is the width of the peak at half its height (K = 1/2 at ||x - y|| = sigma / 2),
/// in the units of the features; omega the tailing factor: omega = 1 is the Cauchy
/// (Lorentzian) form 1 / (1 + 4 ||x - y||^2 / sigma^2), and as omega grows K approaches the
/// Gaussian exp(-4 ln 2 ||x - y||^2 / sigma^2). K(x, x) = 1; K is in (0, 1].
///
///   @param[in] a, b  n values each
///   @param[in] sigma, omega  > 0 (not checked here: see PukKernel)
double puk_kernel(const double* a, const double* b, int n, double sigma, double omega);

/// puk_kernel() of two rows of floats (widened to double), rounded to float: the value
/// OpenCV's SVM gets from PukKernel::calc, so that a prediction made with this function
/// repeats OpenCV's exactly.
float puk_kernel_float(const float* a, const float* b, int n, double sigma, double omega);

/// puk_kernel() as an OpenCV custom SVM kernel (cv::ml::SVM::setCustomKernel). OpenCV
/// trains on CV_32F rows and keeps kernel values as float: calc() gives puk_kernel_float().
class PukKernel final : public cv::ml::SVM::Kernel {
 public:
  /// Throws hair::Error (usage) unless sigma and omega are finite and positive.
  PukKernel(double sigma, double omega);

  /// cv::ml::SVM::CUSTOM.
  int getType() const override;
  /// results[j] = K(vecs row j, another) for the `vcount` rows of `var_count` floats in
  /// `vecs` (row-major).
  void calc(int vcount, int var_count, const float* vecs, const float* another,
            float* results) override;

  double sigma() const { return sigma_; }
  double omega() const { return omega_; }

 private:
  double sigma_;
  double omega_;
};

}  // namespace hair
