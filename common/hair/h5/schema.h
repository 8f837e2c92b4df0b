#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <variant>
#include <vector>

#include "hair/h5/dtype.h"
#include "hair/h5/enum_dataset.h"

namespace hair::h5 {

// The machine-readable form of a schema of schemas/ (the format is specified in
// schemas/README.md). Every schema of schemas/ is compiled into the library.

/// One extent of a dataset's shape: a fixed size, or a named dimension plus an offset
/// ("n_strands+1").
struct DimensionExpression {
  std::string dimension;  ///< empty for a fixed size
  int64_t offset = 0;     ///< the fixed size, or what is added to the dimension
  /// "3", "n_points", "n_strands+1".
  std::string text() const;
};

/// Value rules of a dataset (schemas/README.md, "Constraints").
struct DatasetConstraints {
  bool finite = true;                   ///< float dtypes: no NaN or Inf
  std::optional<double> min;            ///< every value >= min
  std::optional<double> max;            ///< every value <= max
  std::optional<double> exclusive_min;  ///< every value > exclusive_min
  std::optional<double> exclusive_max;  ///< every value < exclusive_max
  std::string csr_offsets_of;  ///< dimension: starts at 0, never decreases, ends at its size
  std::string index_into;      ///< dimension: every value in [0, size)
  bool allow_none = false;     ///< with index_into: -1 is allowed too
};

/// One dataset a file of the schema carries.
struct DatasetSpec {
  std::string path;            ///< absolute, e.g. "/strands/points"
  std::optional<Dtype> dtype;  ///< unset for enum datasets
  EnumMembers enum_members;    ///< enum datasets: members in declared order
  std::vector<DimensionExpression> shape;
  std::string description;
  std::string unit;  ///< informational, e.g. "m"; may be empty
  bool required = true;
  DatasetConstraints constraints;

  bool is_enum() const { return !dtype.has_value(); }
  /// "float32" or "enum {strip=0, grid=1}".
  std::string dtype_text() const;
  /// "[n_points, 3]".
  std::string shape_text() const;
};

/// Stored types of root attributes.
enum class AttributeType { string, int64, float64 };

/// "string", "int64" or "float64".
std::string_view attribute_type_name(AttributeType type);

/// One root attribute a file of the schema carries (besides `schema` and
/// `schema_version`, which every file carries).
struct AttributeSpec {
  std::string name;
  AttributeType type = AttributeType::string;
  std::string description;
  std::string unit;  ///< informational; may be empty
  bool required = true;
  std::optional<std::variant<std::string, int64_t, double>> equals;  ///< the only allowed value
  DatasetConstraints constraints;  ///< numbers: finite, min, max, exclusive_min, exclusive_max
  bool is_json = false;            ///< strings: must parse as JSON ("format": "json")
};

/// One entry of a schema's version history.
struct SchemaChange {
  int64_t version = 0;
  std::string changes;
};

/// A parsed schema.
struct Schema {
  std::string name;  ///< e.g. "hairstyle.extract"
  int64_t version = 0;
  std::string description;
  std::vector<SchemaChange> history;
  std::vector<std::pair<std::string, std::string>> dimensions;  ///< name, description
  std::vector<AttributeSpec> attributes;
  std::vector<DatasetSpec> datasets;

  /// The dataset spec of `path`; a runtime error if the schema has none (a bug in the
  /// stage that asks).
  const DatasetSpec& dataset(std::string_view path) const;

  /// Parses a schema's JSON text; `source_name` names it in errors. A malformed schema
  /// (unknown key, unknown dtype or dimension, ...) is a runtime error.
  static Schema parse(std::string_view json_text, const std::string& source_name);

  /// Every schema compiled into the library, sorted by name.
  static const std::vector<Schema>& all();

  /// The compiled-in schema called `name`; a usage error listing the known names if there
  /// is none.
  static const Schema& find(std::string_view name);
};

}  // namespace hair::h5
