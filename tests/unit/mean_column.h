#pragma once

// A column of a printed measurement table: the mean of the values that were measured.

#include <cmath>
#include <limits>

namespace hair::testing {

/// What a measure reads when it does not apply (no middle groups, no braid, ...).
inline constexpr double kNotMeasured = std::numeric_limits<double>::quiet_NaN();

/// Mean of the measured values added to it, NaN ones left out; NaN when none was.
struct MeanColumn {
  double sum = 0;
  int count = 0;
  void add(double value) {
    if (!std::isnan(value)) sum += value, ++count;
  }
  double mean() const { return count ? sum / count : kNotMeasured; }
};

}  // namespace hair::testing
