#include "hair/style/puk_kernel.h"

#include <cmath>
#include <string>

#include "hair/core/error.h"

namespace hair {
namespace {

/// Weka's Puk.computeFactor: 2 sqrt(2^(1/omega) - 1) / sigma.
double puk_factor(double sigma, double omega) {
  return 2.0 * std::sqrt(std::pow(2.0, 1.0 / omega) - 1.0) / sigma;
}

/// Weka's Puk.evaluate from the squared distance.
double puk_from_squared_distance(double squared_distance, double factor, double omega) {
  double t = factor * std::sqrt(squared_distance);
  return 1.0 / std::pow(1.0 + t * t, omega);
}

template <typename T>
double squared_distance(const T* a, const T* b, int n) {
  double sum = 0;
  for (int k = 0; k < n; ++k) {
    double difference = static_cast<double>(a[k]) - static_cast<double>(b[k]);
    sum += difference * difference;
  }
  return sum;
}

}  // namespace

double puk_kernel(const double* a, const double* b, int n, double sigma, double omega) {
  return puk_from_squared_distance(squared_distance(a, b, n), puk_factor(sigma, omega), omega);
}

float puk_kernel_float(const float* a, const float* b, int n, double sigma, double omega) {
  return static_cast<float>(
      puk_from_squared_distance(squared_distance(a, b, n), puk_factor(sigma, omega), omega));
}

PukKernel::PukKernel(double sigma, double omega) : sigma_(sigma), omega_(omega) {
  if (!(std::isfinite(sigma) && sigma > 0 && std::isfinite(omega) && omega > 0))
    throw Error::usage("PUK kernel: sigma (" + std::to_string(sigma) + ") and omega (" +
                       std::to_string(omega) + ") must be finite and positive");
}

int PukKernel::getType() const { return cv::ml::SVM::CUSTOM; }

void PukKernel::calc(int vcount, int var_count, const float* vecs, const float* another,
                     float* results) {
  for (int j = 0; j < vcount; ++j)
    results[j] = puk_kernel_float(vecs + static_cast<ptrdiff_t>(j) * var_count, another, var_count,
                                  sigma_, omega_);
}

}  // namespace hair
