#include "hair/banded_cholesky.h"

#include <algorithm>
#include <cmath>

namespace hair {

namespace {

/// The factorisation, with the bandwidth a compile-time constant where it is the strand
/// solver's (so the inner loops unroll) and a run-time one otherwise. Column j of the
/// storage holds U(k, j) for k = j - kd .. j contiguously, so both factors of the inner
/// products run along memory.
template <int kFixed>
int factor(double* band, int n, int runtime_kd) {
  const int kd = kFixed > 0 ? kFixed : runtime_kd, ldab = kd + 1;
  for (int j = 0; j < n; ++j) {
    double* column_j = band + static_cast<ptrdiff_t>(j) * ldab + kd - j;  // column_j[k] = U(k, j)
    int first = std::max(0, j - kd);
    double diagonal = column_j[j];
    for (int k = first; k < j; ++k) diagonal -= column_j[k] * column_j[k];
    if (!(diagonal > 0)) return j + 1;
    diagonal = std::sqrt(diagonal);
    column_j[j] = diagonal;
    const double inverse = 1 / diagonal;
    int last = std::min(n - 1, j + kd);
    for (int i = j + 1; i <= last; ++i) {
      double* column_i = band + static_cast<ptrdiff_t>(i) * ldab + kd - i;
      double value = column_i[j];
      for (int k = std::max(0, i - kd); k < j; ++k) value -= column_j[k] * column_i[k];
      column_i[j] = value * inverse;
    }
  }
  return 0;
}

}  // namespace

int solve_banded_spd(std::span<double> band, std::span<double> rhs, int n, int bandwidth) {
  const int kd = bandwidth, ldab = bandwidth + 1;
  int info = bandwidth == 11 ? factor<11>(band.data(), n, kd) : factor<0>(band.data(), n, kd);
  if (info != 0) return info;
  // U(k, j), k <= j <= k + kd.
  auto u = [&](int k, int j) -> double& {
    return band[static_cast<size_t>(kd + k - j + j * ldab)];
  };
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
