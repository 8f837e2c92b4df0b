#pragma once

#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "hair/h5/dataset.h"
#include "hair/h5/file.h"

namespace hair::h5 {

/// One attribute as a listing shows it.
struct AttributeEntry {
  std::string name;
  std::string type_name;  ///< "string", "int64", "float64[3]", ...
  std::string text;       ///< the value as text (attribute_text())
};

/// Range of numeric values.
struct NumericSummary {
  double min = std::numeric_limits<double>::infinity();   ///< smallest finite value
  double max = -std::numeric_limits<double>::infinity();  ///< largest finite value
  int64_t finite = 0;                                     ///< number of finite values
  int64_t non_finite = 0;                                 ///< number of NaN and infinite values

  /// Counts `value` and widens the range if it is finite.
  void add(double value);
};

/// Widest 2-D numeric dataset whose columns get their own range (x, y, z of points).
inline constexpr int64_t kMaxSummaryColumns = 4;

/// One group or dataset of a file.
struct TreeEntry {
  std::string path;                        ///< absolute, "/" for the root
  ObjectKind kind = ObjectKind::group;     ///< group, dataset or other
  DatasetInfo dataset;                     ///< datasets only
  std::vector<AttributeEntry> attributes;  ///< in name order
  std::optional<NumericSummary> summary;   ///< numeric datasets, when summaries are asked for
  /// With `summary`, for 2-D datasets of at most kMaxSummaryColumns columns: one per column.
  std::vector<NumericSummary> column_summaries;
  /// Enum datasets, when summaries are asked for: each member name with its count of
  /// values, in value order.
  std::vector<std::pair<std::string, int64_t>> enum_counts;
};

/// Every group and dataset of `file`, depth first with members in name order, the root
/// first. With `with_summaries`, numeric datasets are read (in bounded blocks) for their
/// range and enum datasets for their counts.
std::vector<TreeEntry> list_tree(const File& file, bool with_summaries);

}  // namespace hair::h5
