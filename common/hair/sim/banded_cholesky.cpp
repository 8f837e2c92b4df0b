#include "hair/sim/banded_cholesky.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

namespace hair {

namespace {

/// The factorisation, right-looking: once row j of U is known, its outer product is taken
/// off the trailing kd x kd triangle. Every update of that triangle is independent of the
/// others and runs along a column of the storage (column l holds A(k, l) for k = l - kd ..
/// l contiguously), so the loops vectorise; the left-looking order (a dot product per
/// entry) waits on each multiply-add in turn. The bandwidth is a compile-time constant
/// where it is the strand solver's, so the loops unroll, and a run-time one otherwise.
/// The forward substitution U^T y = b rides along: y_j is known once row j is, and is
/// taken off the right-hand sides below it the same way.
template <int kFixed>
int factor_and_forward(double* band, double* rhs, int n, int runtime_kd) {
  const int kd = kFixed > 0 ? kFixed : runtime_kd, ldab = kd + 1;
  auto column = [&](int l) { return band + static_cast<ptrdiff_t>(l) * ldab + kd - l; };
  std::array<double, 64> row_storage{};
  std::vector<double> row_heap;
  double* row = row_storage.data();
  if (kd > static_cast<int>(row_storage.size())) {
    row_heap.resize(static_cast<size_t>(kd));
    row = row_heap.data();
  }
  for (int j = 0; j < n; ++j) {
    double* column_j = column(j);  // column_j[k] = A(k, j), then U(k, j)
    double diagonal = column_j[j];
    if (!(diagonal > 0)) return j + 1;
    diagonal = std::sqrt(diagonal);
    column_j[j] = diagonal;
    const double inverse = 1 / diagonal;
    const int reach = std::min(n - 1 - j, kd);
    for (int t = 0; t < reach; ++t) row[t] = column(j + 1 + t)[j] *= inverse;  // U(j, j+1+t)
    const double y = rhs[j] * inverse;
    rhs[j] = y;
    for (int t = 0; t < reach; ++t) rhs[j + 1 + t] -= row[t] * y;
    for (int t = 0; t < reach; ++t) {
      double* column_l = column(j + 1 + t) + j + 1;  // A(j+1 .. j+1+t, l)
      const double scale = row[t];
      for (int i = 0; i <= t; ++i) column_l[i] -= row[i] * scale;
    }
  }
  return 0;
}

}  // namespace

int solve_banded_spd(std::span<double> band, std::span<double> rhs, int n, int bandwidth) {
  const int kd = bandwidth, ldab = bandwidth + 1;
  int info = bandwidth == 11 ? factor_and_forward<11>(band.data(), rhs.data(), n, kd)
                             : factor_and_forward<0>(band.data(), rhs.data(), n, kd);
  if (info != 0) return info;
  // U(k, j), k <= j <= k + kd.
  auto u = [&](int k, int j) -> double& {
    return band[static_cast<size_t>(kd + k - j + j * ldab)];
  };
  // U x = y by columns: once x_j is known, it is taken off the entries above it, along
  // column j.
  for (int j = n - 1; j >= 0; --j) {
    double value = rhs[static_cast<size_t>(j)] / u(j, j);
    rhs[static_cast<size_t>(j)] = value;
    for (int k = std::max(0, j - kd); k < j; ++k) rhs[static_cast<size_t>(k)] -= u(k, j) * value;
  }
  return 0;
}

}  // namespace hair
