#pragma once
// The random numbers of synthetic hair: std::mt19937 with its distributions written out,
// so that a seed gives the same model on every platform.

#include <cstddef>
#include <cstdint>
#include <random>
#include <utility>
#include <vector>

namespace hair::synth {

/// Random numbers from std::mt19937, whose output the standard fixes, with the
/// distributions written out here (the standard library's are implementation-defined),
/// so that a seed gives the same model everywhere.
class Rng {
 public:
  explicit Rng(uint32_t seed) : engine_(seed) {}
  /// Uniform in [lo, hi).
  double uniform(double lo, double hi) {
    return lo + (hi - lo) * (static_cast<double>(engine_()) / 4294967296.0);
  }
  /// Uniform integer in [lo, hi].
  int integer(int lo, int hi) {
    if (hi <= lo) return lo;
    return lo + static_cast<int>(engine_() % static_cast<uint32_t>(hi - lo + 1));
  }
  bool chance(double probability) { return uniform(0, 1) < probability; }
  /// Fisher-Yates shuffle.
  template <class T>
  void shuffle(std::vector<T>& values) {
    for (size_t i = values.size(); i > 1; --i)
      std::swap(values[i - 1], values[static_cast<size_t>(integer(0, static_cast<int>(i) - 1))]);
  }

 private:
  std::mt19937 engine_;
};

}  // namespace hair::synth
