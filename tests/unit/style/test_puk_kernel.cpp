// The Pearson VII universal kernel: known values and the OpenCV kernel's agreement.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "hair/core/error.h"
#include "hair/style/puk_kernel.h"

namespace hair {
namespace {

TEST(PukKernel, IsOneAtZeroDistance) {
  std::vector<double> x = {0.3, -1.2, 4.5};
  for (double sigma : {0.1, 1.0, 7.0})
    for (double omega : {0.5, 1.0, 3.0})
      EXPECT_EQ(puk_kernel(x.data(), x.data(), 3, sigma, omega), 1.0);
}

TEST(PukKernel, HandComputedValue) {
  // ||x - y|| = 5, sigma = 2, omega = 2: factor = 2 sqrt(sqrt(2) - 1) / 2, so
  // K = 1 / (1 + 25 (sqrt(2) - 1))^2.
  std::vector<double> x = {0, 0}, y = {3, 4};
  EXPECT_NEAR(puk_kernel(x.data(), y.data(), 2, 2.0, 2.0), 0.00775532115904805, 1e-15);
}

TEST(PukKernel, OmegaOneIsCauchy) {
  // omega = 1: factor = 2 / sigma, K = 1 / (1 + 4 ||x - y||^2 / sigma^2).
  std::vector<double> x = {1, 2, 3}, y = {2, 0, 5};  // squared distance 9
  for (double sigma : {0.5, 3.0, 10.0})
    EXPECT_NEAR(puk_kernel(x.data(), y.data(), 3, sigma, 1.0),
                1.0 / (1.0 + 4.0 * 9.0 / (sigma * sigma)), 1e-15);
}

TEST(PukKernel, HalfHeightAtHalfSigma) {
  // sigma is the full width at half maximum, for every omega.
  std::vector<double> x = {0}, y = {1.5};
  for (double omega : {0.5, 1.0, 2.0, 5.0, 50.0})
    EXPECT_NEAR(puk_kernel(x.data(), y.data(), 1, 3.0, omega), 0.5, 1e-14);
}

TEST(PukKernel, LargeOmegaApproachesGaussian) {
  // exp(-4 ln 2 ||x - y||^2 / sigma^2) = 1/16 at distance 2 for sigma = 2; the Cauchy form
  // (omega = 1) gives 1/5 there.
  std::vector<double> x = {0, 0}, y = {1.2, 1.6};
  double sigma = 2;
  double gaussian = std::exp(-4 * std::log(2.0) * 4 / (sigma * sigma));
  EXPECT_NEAR(gaussian, 1.0 / 16, 1e-15);
  EXPECT_NEAR(puk_kernel(x.data(), y.data(), 2, sigma, 1e5), gaussian, 1e-5);
  EXPECT_GT(std::abs(puk_kernel(x.data(), y.data(), 2, sigma, 1.0) - gaussian), 1e-2);
}

TEST(PukKernel, SymmetricAndDecreasing) {
  std::vector<double> x = {0.5, -0.5}, near = {0.7, -0.4}, far = {2.0, 1.0};
  EXPECT_EQ(puk_kernel(x.data(), far.data(), 2, 1.5, 2.0),
            puk_kernel(far.data(), x.data(), 2, 1.5, 2.0));
  EXPECT_GT(puk_kernel(x.data(), near.data(), 2, 1.5, 2.0),
            puk_kernel(x.data(), far.data(), 2, 1.5, 2.0));
  EXPECT_GT(puk_kernel(x.data(), far.data(), 2, 1.5, 2.0), 0.0);
}

TEST(PukKernel, OpenCvKernelGivesTheFloatValues) {
  std::vector<float> vectors = {0.1f, 0.2f, -1.0f, 3.0f, 0.5f, 0.5f};  // three rows of two
  std::vector<float> other = {0.4f, -0.3f};
  PukKernel kernel(1.7, 0.8);
  EXPECT_EQ(kernel.getType(), cv::ml::SVM::CUSTOM);
  std::vector<float> results(3);
  kernel.calc(3, 2, vectors.data(), other.data(), results.data());
  for (int j = 0; j < 3; ++j) {
    EXPECT_EQ(results[j], puk_kernel_float(vectors.data() + 2 * j, other.data(), 2, 1.7, 0.8));
    std::vector<double> a = {vectors[2 * j], vectors[2 * j + 1]}, b = {other[0], other[1]};
    EXPECT_EQ(results[j], static_cast<float>(puk_kernel(a.data(), b.data(), 2, 1.7, 0.8)));
  }
}

TEST(PukKernel, RejectsBadParameters) {
  EXPECT_THROW(PukKernel(0.0, 1.0), Error);
  EXPECT_THROW(PukKernel(1.0, -1.0), Error);
  EXPECT_THROW(PukKernel(std::nan(""), 1.0), Error);
  try {
    PukKernel(1.0, 0.0);
    FAIL();
  } catch (const Error& error) {
    EXPECT_EQ(error.exit_code(), 2);
    EXPECT_NE(std::string(error.what()).find("omega"), std::string::npos);
  }
}

}  // namespace
}  // namespace hair
