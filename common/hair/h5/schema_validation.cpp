#include "hair/h5/schema_validation.h"

#include <charconv>
#include <cmath>
#include <map>
#include <nlohmann/json.hpp>

#include "hair/h5/attribute.h"
#include "hair/h5/dataset.h"
#include "hair/h5/dataset_blocks.h"

namespace hair::h5 {

namespace {

/// Shortest text that reads back as `value`.
std::string number_text(double value) {
  if (std::isnan(value)) return "nan";
  if (std::isinf(value)) return value > 0 ? "inf" : "-inf";
  char buffer[32];
  const auto result = std::to_chars(buffer, buffer + sizeof(buffer), value);
  return std::string(buffer, result.ptr);
}

/// "[4, 1]": the multi-index of the flat (row-major) index `flat` in `shape`.
std::string index_text(int64_t flat, const Shape& shape) {
  std::vector<int64_t> index(shape.size(), 0);
  for (size_t axis = shape.size(); axis-- > 0;) {
    if (shape[axis] == 0) break;
    index[axis] = flat % shape[axis];
    flat /= shape[axis];
  }
  return format_shape(index);
}

/// The first range rule of `rules` that `value` breaks ("values >= 0"), or empty.
std::string broken_range(double value, const DatasetConstraints& rules) {
  if (rules.min && !(value >= *rules.min)) return ">= " + number_text(*rules.min);
  if (rules.max && !(value <= *rules.max)) return "<= " + number_text(*rules.max);
  if (rules.exclusive_min && !(value > *rules.exclusive_min)) {
    return "> " + number_text(*rules.exclusive_min);
  }
  if (rules.exclusive_max && !(value < *rules.exclusive_max)) {
    return "< " + number_text(*rules.exclusive_max);
  }
  return {};
}

std::string equals_text(const std::variant<std::string, int64_t, double>& value) {
  if (const auto* text = std::get_if<std::string>(&value)) return "\"" + *text + "\"";
  if (const auto* integer = std::get_if<int64_t>(&value)) return std::to_string(*integer);
  return number_text(std::get<double>(value));
}

/// Size of a dimension and the dataset that fixed it.
struct BoundDimension {
  int64_t size = 0;
  std::string source;
};

/// Checks one file against one schema, stopping at the first violation.
class Validator {
 public:
  Validator(const File& file, const Schema& schema) : file_(file), schema_(schema) {}

  std::optional<Error> first_violation() {
    try {
      check_identity();
      for (const AttributeSpec& spec : schema_.attributes) check_attribute(spec);
      std::vector<const DatasetSpec*> present;
      for (const DatasetSpec& spec : schema_.datasets) {
        if (check_layout(spec)) present.push_back(&spec);
      }
      for (const DatasetSpec* spec : present) check_values(*spec);
    } catch (const Error& error) {
      if (error.kind() == ErrorKind::bad_input) return error;
      throw;
    }
    return std::nullopt;
  }

 private:
  [[noreturn]] void fail(const std::string& where, const std::string& reason) const {
    throw Error::bad_dataset(file_.name(), where, reason);
  }

  void check_identity() const {
    if (!has_attribute(file_, "/", "schema")) {
      fail("/@schema", "missing root attribute: not a hairstyle intermediate file");
    }
    const std::string name = read_string_attribute(file_, "/", "schema");
    if (name != schema_.name) fail("/@schema", "expected " + schema_.name + ", found " + name);
    if (!has_attribute(file_, "/", "schema_version"))
      fail("/@schema_version", "missing root attribute");
    const int64_t version = read_int64_attribute(file_, "/", "schema_version");
    if (version < schema_.version) {
      fail("/@schema_version", "schema version " + std::to_string(version) +
                                   " is older than supported " + std::to_string(schema_.version) +
                                   "; no upgrade path");
    }
    if (version > schema_.version) {
      fail("/@schema_version", "schema version " + std::to_string(version) +
                                   " is newer than supported " + std::to_string(schema_.version) +
                                   "; use a newer hairstyle");
    }
  }

  void check_attribute(const AttributeSpec& spec) const {
    const std::string where = "/@" + spec.name;
    if (!has_attribute(file_, "/", spec.name)) {
      if (spec.required) fail(where, "missing root attribute");
      return;
    }
    std::variant<std::string, int64_t, double> value;
    switch (spec.type) {
      case AttributeType::string:
        value = read_string_attribute(file_, "/", spec.name);
        break;
      case AttributeType::int64:
        value = read_int64_attribute(file_, "/", spec.name);
        break;
      case AttributeType::float64:
        value = read_double_attribute(file_, "/", spec.name);
        break;
    }
    if (spec.equals && value != *spec.equals) {
      fail(where, "expected " + equals_text(*spec.equals) + ", found " + equals_text(value));
    }
    if (spec.is_json) {
      const std::string& text = std::get<std::string>(value);
      if (!nlohmann::json::accept(text)) fail(where, "expected JSON text, found \"" + text + "\"");
    }
    if (spec.type == AttributeType::string) return;
    const double number = spec.type == AttributeType::int64
                              ? static_cast<double>(std::get<int64_t>(value))
                              : std::get<double>(value);
    if (spec.constraints.finite && !std::isfinite(number)) {
      fail(where, "expected a finite value, found " + number_text(number));
    }
    const std::string broken = broken_range(number, spec.constraints);
    if (!broken.empty())
      fail(where, "expected a value " + broken + ", found " + number_text(number));
  }

  /// "[n_strands+1] = [5] (n_strands = 4 from /groups/first_strand)", naming the bound
  /// dimensions of `spec`'s shape.
  std::string expected_shape_text(const DatasetSpec& spec) const {
    std::string sizes = "[";
    std::string sources;
    bool all_bound = true;
    for (size_t axis = 0; axis < spec.shape.size(); ++axis) {
      const DimensionExpression& extent = spec.shape[axis];
      sizes += axis > 0 ? ", " : "";
      if (extent.dimension.empty()) {
        sizes += std::to_string(extent.offset);
        continue;
      }
      const auto bound = bound_.find(extent.dimension);
      if (bound == bound_.end()) {
        all_bound = false;
        continue;
      }
      sizes += std::to_string(bound->second.size + extent.offset);
      const std::string source = extent.dimension + " = " + std::to_string(bound->second.size) +
                                 " from " + bound->second.source;
      if (sources.find(source) == std::string::npos)
        sources += (sources.empty() ? "" : ", ") + source;
    }
    std::string text = spec.shape_text();
    if (all_bound && !sources.empty()) text += " = " + sizes + "]";
    if (!sources.empty()) text += " (" + sources + ")";
    return text;
  }

  /// Checks presence, dtype and shape, binding dimensions; false if an optional dataset
  /// is absent.
  bool check_layout(const DatasetSpec& spec) {
    const ObjectKind kind = file_.kind_of(spec.path);
    if (kind == ObjectKind::missing) {
      if (spec.required) fail(spec.path, "missing required dataset");
      return false;
    }
    const DatasetInfo info = dataset_info(file_, spec.path);
    if (spec.is_enum()) {
      if (info.type_name != "enum int8") {
        fail(spec.path, "expected " + spec.dtype_text() + ", found " + info.type_name);
      }
      const std::string difference =
          enum_members_difference(read_enum_members(file_, spec.path), spec.enum_members);
      if (!difference.empty()) fail(spec.path, difference);
    } else if (info.dtype != spec.dtype) {
      fail(spec.path, "expected " + spec.dtype_text() + ", found " + info.type_name);
    }
    if (info.shape.size() != spec.shape.size()) {
      fail(spec.path,
           "expected shape " + expected_shape_text(spec) + ", found " + format_shape(info.shape));
    }
    for (size_t axis = 0; axis < spec.shape.size(); ++axis) {
      const DimensionExpression& extent = spec.shape[axis];
      const int64_t found = info.shape[axis];
      const auto bound = bound_.find(extent.dimension);
      int64_t expected = extent.offset;
      if (!extent.dimension.empty() && bound == bound_.end()) {
        if (found - extent.offset < 0) {
          fail(spec.path, "expected shape " + spec.shape_text() + ", found " +
                              format_shape(info.shape) + " (" + extent.dimension + " would be " +
                              std::to_string(found - extent.offset) + ")");
        }
        bound_[extent.dimension] = {found - extent.offset, spec.path};
        continue;
      }
      if (!extent.dimension.empty()) expected += bound->second.size;
      if (found != expected) {
        fail(spec.path,
             "expected shape " + expected_shape_text(spec) + ", found " + format_shape(info.shape));
      }
    }
    return true;
  }

  /// The size of a dimension a constraint refers to.
  int64_t dimension_size(const std::string& dimension, const std::string& path) const {
    const auto bound = bound_.find(dimension);
    if (bound == bound_.end()) {
      fail(path, "dimension " + dimension + " has no size: no dataset present binds it");
    }
    return bound->second.size;
  }

  void check_values(const DatasetSpec& spec) {
    const Shape shape = dataset_info(file_, spec.path).shape;
    if (spec.is_enum()) {
      check_enum_values(spec, shape);
    } else if (is_floating(*spec.dtype)) {
      check_float_values(spec, shape);
    } else {
      check_integer_values(spec, shape);
    }
  }

  void check_enum_values(const DatasetSpec& spec, const Shape& shape) const {
    const std::vector<int8_t> values = read_enum_values(file_, spec.path);
    for (size_t index = 0; index < values.size(); ++index) {
      const bool is_member =
          std::any_of(spec.enum_members.begin(), spec.enum_members.end(),
                      [&](const EnumMember& member) { return member.value == values[index]; });
      if (!is_member) {
        fail(spec.path, "expected a member of " + format_enum_members(spec.enum_members) +
                            ", found value " + std::to_string(values[index]) + " at " +
                            index_text(static_cast<int64_t>(index), shape));
      }
    }
  }

  void check_float_values(const DatasetSpec& spec, const Shape& shape) const {
    const DatasetConstraints& rules = spec.constraints;
    for_each_block<double>(file_, spec.path, [&](int64_t first, std::span<const double> values) {
      for (size_t offset = 0; offset < values.size(); ++offset) {
        const double value = values[offset];
        const int64_t index = first + static_cast<int64_t>(offset);
        if (!std::isfinite(value)) {
          if (rules.finite) {
            fail(spec.path, "expected finite values, found " + number_text(value) + " at " +
                                index_text(index, shape));
          }
          continue;
        }
        const std::string broken = broken_range(value, rules);
        if (!broken.empty()) {
          fail(spec.path, "expected values " + broken + ", found " + number_text(value) + " at " +
                              index_text(index, shape));
        }
      }
      return true;
    });
  }

  void check_integer_values(const DatasetSpec& spec, const Shape& shape) {
    const DatasetConstraints& rules = spec.constraints;
    const bool is_offsets = !rules.csr_offsets_of.empty();
    const int64_t index_limit =
        rules.index_into.empty() ? 0 : dimension_size(rules.index_into, spec.path);
    int64_t previous = 0;
    int64_t count = 0;
    for_each_block<int64_t>(file_, spec.path, [&](int64_t first, std::span<const int64_t> values) {
      for (size_t offset = 0; offset < values.size(); ++offset) {
        const int64_t value = values[offset];
        const int64_t index = first + static_cast<int64_t>(offset);
        const std::string broken = broken_range(static_cast<double>(value), rules);
        if (!broken.empty()) {
          fail(spec.path, "expected values " + broken + ", found " + std::to_string(value) +
                              " at " + index_text(index, shape));
        }
        const bool is_none = rules.allow_none && value == -1;
        if (!rules.index_into.empty() && !is_none && (value < 0 || value >= index_limit)) {
          fail(spec.path, "expected indices into " + rules.index_into + " (0 <= i < " +
                              std::to_string(index_limit) + (rules.allow_none ? ", or -1" : "") +
                              "), found " + std::to_string(value) + " at " +
                              index_text(index, shape));
        }
        if (is_offsets && index == 0 && value != 0) {
          fail(spec.path, "expected CSR offsets starting at 0, found " + std::to_string(value));
        }
        if (is_offsets && value < previous) {
          fail(spec.path, "expected non-decreasing CSR offsets, found " + std::to_string(value) +
                              " after " + std::to_string(previous) + " at " +
                              index_text(index, shape));
        }
        previous = value;
      }
      count += static_cast<int64_t>(values.size());
      return true;
    });
    if (is_offsets) check_offsets_end(spec, count, previous);
  }

  /// The last offset must be the size of the dimension the offsets index (which it binds
  /// if no dataset has).
  void check_offsets_end(const DatasetSpec& spec, int64_t count, int64_t last) {
    const std::string& dimension = spec.constraints.csr_offsets_of;
    if (count == 0) fail(spec.path, "expected CSR offsets, found none");
    const auto bound = bound_.find(dimension);
    if (bound == bound_.end()) {
      bound_[dimension] = {last, spec.path};
      return;
    }
    if (last != bound->second.size) {
      fail(spec.path, "expected CSR offsets ending at " + dimension + " = " +
                          std::to_string(bound->second.size) + " (from " + bound->second.source +
                          "), found " + std::to_string(last));
    }
  }

  const File& file_;
  const Schema& schema_;
  std::map<std::string, BoundDimension> bound_;
};

}  // namespace

std::optional<Error> first_violation(const File& file, const Schema& schema) {
  return Validator(file, schema).first_violation();
}

std::optional<std::string> validate_file(const File& file, std::string_view expected_schema) {
  std::string name(expected_schema);
  if (name.empty()) {
    try {
      if (!has_attribute(file, "/", "schema")) {
        return error_line(file.name(), "/@schema",
                          "missing root attribute: not a hairstyle intermediate file");
      }
      name = read_string_attribute(file, "/", "schema");
      Schema::find(name);
    } catch (const Error& error) {
      return error_line(file.name(), "/@schema", error.reason());
    }
  }
  const std::optional<Error> violation = first_violation(file, Schema::find(name));
  if (violation) return violation->what();
  return std::nullopt;
}

void require_schema(const File& file, std::string_view expected_schema) {
  const std::optional<Error> violation = first_violation(file, Schema::find(expected_schema));
  if (violation) throw *violation;
}

void write_schema_attributes(File& file, const Schema& schema) {
  write_string_attribute(file, "/", "schema", schema.name);
  write_int64_attribute(file, "/", "schema_version", schema.version);
}

void require_valid_output(const File& file, std::string_view schema_name) {
  file.flush();  // judged as it is on disk; a full disk is said as such
  const std::optional<Error> violation = first_violation(file, Schema::find(schema_name));
  if (violation) {
    throw Error(ErrorKind::runtime, violation->file(), violation->dataset(),
                "output does not conform to its schema: " + violation->reason());
  }
}

}  // namespace hair::h5
