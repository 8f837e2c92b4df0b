#include "hair/cluster/adjusted_rand_index.h"

#include <algorithm>
#include <string>
#include <utility>

#include "hair/core/error.h"

namespace hair {
namespace {

/// Labels renumbered 0, 1, ... in increasing order of value; sets `count` to how many.
std::vector<int64_t> dense_labels(const std::vector<int32_t>& labels, int64_t& count) {
  std::vector<int32_t> values = labels;
  std::sort(values.begin(), values.end());
  values.erase(std::unique(values.begin(), values.end()), values.end());
  count = static_cast<int64_t>(values.size());
  std::vector<int64_t> dense;
  dense.reserve(labels.size());
  for (int32_t label : labels)
    dense.push_back(std::lower_bound(values.begin(), values.end(), label) - values.begin());
  return dense;
}

/// The number of pairs among `count` items, count choose 2.
double pairs(int64_t count) { return 0.5 * static_cast<double>(count) * (count - 1); }

/// Sum over runs of equal values in a sorted vector of pairs(run length).
double sum_of_pairs(std::vector<int64_t> values) {
  std::sort(values.begin(), values.end());
  double sum = 0;
  for (size_t begin = 0, end = 0; begin < values.size(); begin = end) {
    while (end < values.size() && values[end] == values[begin]) ++end;
    sum += pairs(static_cast<int64_t>(end - begin));
  }
  return sum;
}

}  // namespace

double adjusted_rand_index(const std::vector<int32_t>& a, const std::vector<int32_t>& b) {
  if (a.size() != b.size())
    throw Error::usage("adjusted Rand index: labelings of " + std::to_string(a.size()) + " and " +
                       std::to_string(b.size()) + " items");
  auto n = static_cast<int64_t>(a.size());
  if (n < 2) return 1.0;
  int64_t count_a = 0, count_b = 0;
  std::vector<int64_t> dense_a = dense_labels(a, count_a);
  std::vector<int64_t> dense_b = dense_labels(b, count_b);
  std::vector<int64_t> joint(dense_a.size());
  for (size_t i = 0; i < joint.size(); ++i) joint[i] = dense_a[i] * count_b + dense_b[i];

  double together_both = sum_of_pairs(std::move(joint));  // sum over the contingency table
  double together_a = sum_of_pairs(std::move(dense_a));   // sum over its row sums
  double together_b = sum_of_pairs(std::move(dense_b));   // sum over its column sums
  double expected = together_a * (together_b / pairs(n));
  double maximum = 0.5 * (together_a + together_b);
  // The denominator is 0 only when both labelings are one cluster or both all singletons.
  if (maximum - expected == 0) return 1.0;
  return (together_both - expected) / (maximum - expected);
}

}  // namespace hair
