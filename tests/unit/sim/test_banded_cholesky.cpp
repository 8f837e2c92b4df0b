// The band solver of the strand dynamics against LAPACK's dpbsv on random SPD band
// matrices, and its refusal of a matrix that is not positive definite.
#include <gtest/gtest.h>

#include <random>
#include <vector>

#include "hair/sim/banded_cholesky.h"

extern "C" void dpbsv_(const char* uplo, const int* n, const int* kd, const int* nrhs, double* ab,
                       const int* ldab, double* b, const int* ldb, int* info);

namespace hair {
namespace {

TEST(BandedCholesky, MatchesLapackDpbsv) {
  std::mt19937 random(7);
  std::uniform_real_distribution<double> uniform(-1, 1);
  for (int n : {1, 5, 12, 60, 171}) {
    for (int kd : {0, 3, 11}) {
      int ldab = kd + 1;
      // A = B^T B + n I restricted to the band stays SPD when the diagonal dominates.
      std::vector<double> band(static_cast<size_t>(ldab * n), 0.0), rhs(static_cast<size_t>(n));
      for (int j = 0; j < n; ++j) {
        for (int i = std::max(0, j - kd); i < j; ++i)
          band[static_cast<size_t>(kd + i - j + j * ldab)] = uniform(random);
        band[static_cast<size_t>(kd + j * ldab)] = 2.0 * (kd + 1) + uniform(random);
        rhs[static_cast<size_t>(j)] = uniform(random);
      }
      std::vector<double> lapack_band = band, lapack_rhs = rhs;
      int nrhs = 1, info = -1;
      dpbsv_("U", &n, &kd, &nrhs, lapack_band.data(), &ldab, lapack_rhs.data(), &n, &info);
      ASSERT_EQ(info, 0);
      ASSERT_EQ(solve_banded_spd(band, rhs, n, kd), 0);
      for (int i = 0; i < n; ++i)
        EXPECT_NEAR(rhs[static_cast<size_t>(i)], lapack_rhs[static_cast<size_t>(i)], 1e-12)
            << n << " " << kd;
    }
  }
}

TEST(BandedCholesky, RefusesAnIndefiniteMatrix) {
  // [[1, 2], [2, 1]] has eigenvalues 3 and -1.
  std::vector<double> band{0, 1, 2, 1}, rhs{1, 1};
  EXPECT_EQ(solve_banded_spd(band, rhs, 2, 1), 2);
}

}  // namespace
}  // namespace hair
