#include "hair/banded_cholesky.h"

#include <algorithm>
#include <cmath>

namespace hair {

int solve_banded_spd(std::span<double> band, std::span<double> rhs, int n, int bandwidth) {
  const int kd = bandwidth, ldab = bandwidth + 1;
  // U(k, j), k <= j <= k + kd.
  auto u = [&](int k, int j) -> double& {
    return band[static_cast<size_t>(kd + k - j + j * ldab)];
  };
  for (int j = 0; j < n; ++j) {
    int first = std::max(0, j - kd);
    double diagonal = u(j, j);
    for (int k = first; k < j; ++k) diagonal -= u(k, j) * u(k, j);
    if (!(diagonal > 0)) return j + 1;
    diagonal = std::sqrt(diagonal);
    u(j, j) = diagonal;
    int last = std::min(n - 1, j + kd);
    for (int i = j + 1; i <= last; ++i) {
      double value = u(j, i);
      for (int k = std::max(0, i - kd); k < j; ++k) value -= u(k, j) * u(k, i);
      u(j, i) = value / diagonal;
    }
  }
  // U^T y = b, then U x = y.
  for (int j = 0; j < n; ++j) {
    double value = rhs[static_cast<size_t>(j)];
    for (int k = std::max(0, j - kd); k < j; ++k) value -= u(k, j) * rhs[static_cast<size_t>(k)];
    rhs[static_cast<size_t>(j)] = value / u(j, j);
  }
  for (int j = n - 1; j >= 0; --j) {
    double value = rhs[static_cast<size_t>(j)];
    for (int i = j + 1; i <= std::min(n - 1, j + kd); ++i)
      value -= u(j, i) * rhs[static_cast<size_t>(i)];
    rhs[static_cast<size_t>(j)] = value / u(j, j);
  }
  return 0;
}

}  // namespace hair
