#include "hair/h5/schema.h"

#include <algorithm>
#include <limits>
#include <nlohmann/json.hpp>
#include <regex>
#include <set>

#include "hair/core/error.h"
#include "hair/h5/embedded_schemas.h"

namespace hair::h5 {

namespace {

using Json = nlohmann::ordered_json;

/// Reads one schema's JSON, throwing runtime errors that name the schema file and the
/// element ("datasets[2] (/strands/offsets): unknown key 'constrains'").
class SchemaParser {
 public:
  explicit SchemaParser(std::string source_name) : source_name_(std::move(source_name)) {}

  Schema parse(std::string_view json_text) const {
    Json root;
    try {
      root = Json::parse(json_text);
    } catch (const Json::exception& error) {
      fail("", std::string("not valid JSON: ") + error.what());
    }
    if (!root.is_object()) fail("", "expected a JSON object");
    check_keys(
        root, {"name", "version", "description", "history", "dimensions", "attributes", "datasets"},
        "");
    Schema schema;
    schema.name = string_field(root, "name", "", true);
    schema.version = integer_field(root, "version", "");
    if (schema.version < 1) fail("version", "must be at least 1");
    schema.description = string_field(root, "description", "", true);
    schema.history = history(array_field(root, "history", ""), schema.version);
    schema.dimensions = dimensions(object_field(root, "dimensions", ""));
    for (const Json& item : array_field(root, "attributes", "")) {
      schema.attributes.push_back(attribute(item, schema.attributes.size()));
    }
    std::set<std::string> paths;
    for (const Json& item : array_field(root, "datasets", "")) {
      schema.datasets.push_back(dataset(item, schema.datasets.size(), schema.dimensions));
      if (!paths.insert(schema.datasets.back().path).second) {
        fail("datasets", "path " + schema.datasets.back().path + " appears twice");
      }
    }
    return schema;
  }

 private:
  [[noreturn]] void fail(const std::string& where, const std::string& reason) const {
    throw Error::runtime(source_name_, (where.empty() ? "" : where + ": ") + reason);
  }

  void check_keys(const Json& object, std::initializer_list<std::string_view> allowed,
                  const std::string& where) const {
    for (const auto& [key, value] : object.items()) {
      if (std::find(allowed.begin(), allowed.end(), key) == allowed.end()) {
        fail(where, "unknown key '" + key + "'");
      }
    }
  }

  const Json* optional_field(const Json& object, const std::string& key) const {
    const auto found = object.find(key);
    return found == object.end() ? nullptr : &*found;
  }

  const Json& field(const Json& object, const std::string& key, const std::string& where) const {
    const Json* value = optional_field(object, key);
    if (value == nullptr) fail(where, "missing key '" + key + "'");
    return *value;
  }

  std::string string_field(const Json& object, const std::string& key, const std::string& where,
                           bool required) const {
    const Json* value = required ? &field(object, key, where) : optional_field(object, key);
    if (value == nullptr) return {};
    if (!value->is_string()) fail(where, "'" + key + "' must be a string");
    return value->get<std::string>();
  }

  int64_t integer_field(const Json& object, const std::string& key,
                        const std::string& where) const {
    const Json& value = field(object, key, where);
    if (!value.is_number_integer()) fail(where, "'" + key + "' must be an integer");
    return value.get<int64_t>();
  }

  bool bool_field(const Json& object, const std::string& key, const std::string& where,
                  bool default_value) const {
    const Json* value = optional_field(object, key);
    if (value == nullptr) return default_value;
    if (!value->is_boolean()) fail(where, "'" + key + "' must be true or false");
    return value->get<bool>();
  }

  std::optional<double> number_field(const Json& object, const std::string& key,
                                     const std::string& where) const {
    const Json* value = optional_field(object, key);
    if (value == nullptr) return std::nullopt;
    if (!value->is_number()) fail(where, "'" + key + "' must be a number");
    return value->get<double>();
  }

  const Json& array_field(const Json& object, const std::string& key,
                          const std::string& where) const {
    const Json& value = field(object, key, where);
    if (!value.is_array()) fail(where, "'" + key + "' must be an array");
    return value;
  }

  const Json& object_field(const Json& object, const std::string& key,
                           const std::string& where) const {
    const Json& value = field(object, key, where);
    if (!value.is_object()) fail(where, "'" + key + "' must be an object");
    return value;
  }

  std::vector<SchemaChange> history(const Json& items, int64_t version) const {
    std::vector<SchemaChange> changes;
    for (const Json& item : items) {
      const std::string where = "history[" + std::to_string(changes.size()) + "]";
      if (!item.is_object()) fail(where, "expected an object");
      check_keys(item, {"version", "changes"}, where);
      changes.push_back(
          {integer_field(item, "version", where), string_field(item, "changes", where, true)});
    }
    const bool has_current =
        std::any_of(changes.begin(), changes.end(),
                    [&](const SchemaChange& c) { return c.version == version; });
    if (!has_current) fail("history", "no entry for version " + std::to_string(version));
    return changes;
  }

  std::vector<std::pair<std::string, std::string>> dimensions(const Json& object) const {
    static const std::regex identifier("[a-z_][a-z0-9_]*");
    std::vector<std::pair<std::string, std::string>> result;
    for (const auto& [name, description] : object.items()) {
      if (!std::regex_match(name, identifier))
        fail("dimensions", "bad dimension name '" + name + "'");
      if (!description.is_string()) fail("dimensions", "'" + name + "' needs a description string");
      result.emplace_back(name, description.get<std::string>());
    }
    return result;
  }

  DatasetConstraints constraints(const Json& object, const std::string& where) const {
    DatasetConstraints result;
    result.finite = bool_field(object, "finite", where, true);
    result.min = number_field(object, "min", where);
    result.max = number_field(object, "max", where);
    result.exclusive_min = number_field(object, "exclusive_min", where);
    result.exclusive_max = number_field(object, "exclusive_max", where);
    return result;
  }

  AttributeSpec attribute(const Json& item, size_t index) const {
    std::string where = "attributes[" + std::to_string(index) + "]";
    if (!item.is_object()) fail(where, "expected an object");
    AttributeSpec spec;
    spec.name = string_field(item, "name", where, true);
    where += " (" + spec.name + ")";
    check_keys(item,
               {"name", "dtype", "description", "unit", "required", "equals", "finite", "min",
                "max", "exclusive_min", "exclusive_max", "format"},
               where);
    if (spec.name == "schema" || spec.name == "schema_version") {
      fail(where, "every file carries this attribute; do not list it");
    }
    const std::string dtype = string_field(item, "dtype", where, true);
    if (dtype == "string")
      spec.type = AttributeType::string;
    else if (dtype == "int64")
      spec.type = AttributeType::int64;
    else if (dtype == "float64")
      spec.type = AttributeType::float64;
    else
      fail(where, "dtype must be string, int64 or float64, not '" + dtype + "'");
    spec.description = string_field(item, "description", where, true);
    spec.unit = string_field(item, "unit", where, false);
    spec.required = bool_field(item, "required", where, true);
    spec.constraints = constraints(item, where);
    if (const Json* equals = optional_field(item, "equals")) {
      if (spec.type == AttributeType::string && equals->is_string())
        spec.equals = equals->get<std::string>();
      else if (spec.type == AttributeType::int64 && equals->is_number_integer())
        spec.equals = equals->get<int64_t>();
      else if (spec.type == AttributeType::float64 && equals->is_number())
        spec.equals = equals->get<double>();
      else
        fail(where, "'equals' must be a value of the attribute's dtype");
    }
    const std::string format = string_field(item, "format", where, false);
    if (!format.empty() && (format != "json" || spec.type != AttributeType::string)) {
      fail(where, "'format' can only be \"json\", on a string attribute");
    }
    spec.is_json = format == "json";
    const bool has_range = spec.constraints.min || spec.constraints.max ||
                           spec.constraints.exclusive_min || spec.constraints.exclusive_max;
    if (spec.type == AttributeType::string && (has_range || item.contains("finite"))) {
      fail(where, "a string attribute takes no numeric constraints");
    }
    return spec;
  }

  DimensionExpression dimension_expression(const Json& item, const std::string& where,
                                           const std::set<std::string>& declared) const {
    static const std::regex expression(R"(([a-z_][a-z0-9_]*)\s*(?:([+-])\s*([0-9]+))?)");
    if (item.is_number_integer() && item.get<int64_t>() >= 0) return {"", item.get<int64_t>()};
    std::smatch match;
    const std::string text = item.is_string() ? item.get<std::string>() : item.dump();
    if (!item.is_string() || !std::regex_match(text, match, expression)) {
      fail(where, "bad shape entry " + text + " (expected a size, a dimension or dimension+k)");
    }
    const std::string dimension = match[1];
    if (declared.count(dimension) == 0) fail(where, "undeclared dimension '" + dimension + "'");
    int64_t offset = 0;
    if (match[2].matched) offset = std::stoll(match[3]) * (match[2] == "-" ? -1 : 1);
    return {dimension, offset};
  }

  DatasetSpec dataset(const Json& item, size_t index,
                      const std::vector<std::pair<std::string, std::string>>& dims) const {
    std::string where = "datasets[" + std::to_string(index) + "]";
    if (!item.is_object()) fail(where, "expected an object");
    DatasetSpec spec;
    spec.path = string_field(item, "path", where, true);
    where += " (" + spec.path + ")";
    check_keys(item,
               {"path", "dtype", "enum", "shape", "description", "unit", "required", "constraints"},
               where);
    if (!spec.path.starts_with("/") || spec.path.size() < 2) fail(where, "path must be absolute");
    const std::string dtype = string_field(item, "dtype", where, true);
    if (dtype == "enum") {
      for (const auto& [name, value] : object_field(item, "enum", where).items()) {
        if (!value.is_number_integer() ||
            value.get<int64_t>() < std::numeric_limits<int8_t>::min() ||
            value.get<int64_t>() > std::numeric_limits<int8_t>::max()) {
          fail(where, "enum value of '" + name + "' must be an int8");
        }
        spec.enum_members.push_back({name, static_cast<int8_t>(value.get<int64_t>())});
      }
      if (spec.enum_members.empty()) fail(where, "an enum needs members");
    } else {
      spec.dtype = dtype_from_name(dtype);
      if (!spec.dtype) fail(where, "unknown dtype '" + dtype + "'");
      if (item.contains("enum")) fail(where, "'enum' needs dtype \"enum\"");
    }
    std::set<std::string> declared;
    for (const auto& [name, description] : dims) declared.insert(name);
    const Json& shape = array_field(item, "shape", where);
    if (shape.empty()) fail(where, "shape must have at least one entry");
    for (const Json& entry : shape)
      spec.shape.push_back(dimension_expression(entry, where, declared));
    spec.description = string_field(item, "description", where, true);
    spec.unit = string_field(item, "unit", where, false);
    spec.required = bool_field(item, "required", where, true);
    if (const Json* rules = optional_field(item, "constraints")) {
      const std::string rules_where = where + " constraints";
      if (!rules->is_object()) fail(rules_where, "expected an object");
      check_keys(*rules,
                 {"finite", "min", "max", "exclusive_min", "exclusive_max", "csr_offsets_of",
                  "index_into", "allow_none"},
                 rules_where);
      spec.constraints = constraints(*rules, rules_where);
      spec.constraints.csr_offsets_of = string_field(*rules, "csr_offsets_of", rules_where, false);
      spec.constraints.index_into = string_field(*rules, "index_into", rules_where, false);
      spec.constraints.allow_none = bool_field(*rules, "allow_none", rules_where, false);
      check_constraints(spec, *rules, rules_where, declared);
    }
    return spec;
  }

  void check_constraints(const DatasetSpec& spec, const Json& rules, const std::string& where,
                         const std::set<std::string>& declared) const {
    const DatasetConstraints& rule = spec.constraints;
    const bool is_integer = spec.dtype && !is_floating(*spec.dtype);
    if (rules.contains("finite") && !(spec.dtype && is_floating(*spec.dtype))) {
      fail(where, "'finite' applies to float datasets only");
    }
    for (const std::string& dimension : {rule.csr_offsets_of, rule.index_into}) {
      if (!dimension.empty() && declared.count(dimension) == 0) {
        fail(where, "undeclared dimension '" + dimension + "'");
      }
    }
    if ((!rule.csr_offsets_of.empty() || !rule.index_into.empty()) && !is_integer) {
      fail(where, "'csr_offsets_of' and 'index_into' apply to integer datasets only");
    }
    if (!rule.csr_offsets_of.empty() && spec.shape.size() != 1) {
      fail(where, "'csr_offsets_of' applies to 1-D datasets only");
    }
    if (rule.allow_none && rule.index_into.empty()) fail(where, "'allow_none' needs 'index_into'");
    const bool has_range = rule.min || rule.max || rule.exclusive_min || rule.exclusive_max;
    if (spec.is_enum() && has_range) fail(where, "enum datasets take no numeric range");
  }

  std::string source_name_;
};

}  // namespace

std::string DimensionExpression::text() const {
  if (dimension.empty()) return std::to_string(offset);
  if (offset == 0) return dimension;
  return dimension + (offset > 0 ? "+" : "") + std::to_string(offset);
}

std::string DatasetSpec::dtype_text() const {
  return dtype ? std::string(dtype_name(*dtype)) : "enum " + format_enum_members(enum_members);
}

std::string DatasetSpec::shape_text() const {
  std::string text = "[";
  for (size_t axis = 0; axis < shape.size(); ++axis) {
    text += (axis > 0 ? ", " : "") + shape[axis].text();
  }
  return text + "]";
}

std::string_view attribute_type_name(AttributeType type) {
  switch (type) {
    case AttributeType::string:
      return "string";
    case AttributeType::int64:
      return "int64";
    case AttributeType::float64:
      return "float64";
  }
  return "unknown";
}

const DatasetSpec& Schema::dataset(std::string_view path) const {
  for (const DatasetSpec& spec : datasets) {
    if (spec.path == path) return spec;
  }
  throw Error::runtime(name, "the schema has no dataset " + std::string(path));
}

Schema Schema::parse(std::string_view json_text, const std::string& source_name) {
  return SchemaParser(source_name).parse(json_text);
}

const std::vector<Schema>& Schema::all() {
  static const std::vector<Schema> schemas = [] {
    std::vector<Schema> parsed;
    for (const EmbeddedSchema& embedded : embedded_schemas()) {
      parsed.push_back(parse(embedded.json_text, "schemas/" + std::string(embedded.file_name)));
    }
    std::sort(parsed.begin(), parsed.end(),
              [](const Schema& a, const Schema& b) { return a.name < b.name; });
    for (size_t index = 1; index < parsed.size(); ++index) {
      if (parsed[index].name == parsed[index - 1].name) {
        throw Error::runtime("schemas/", "two schemas are called " + parsed[index].name);
      }
    }
    return parsed;
  }();
  return schemas;
}

const Schema& Schema::find(std::string_view name) {
  std::string known;
  for (const Schema& schema : all()) {
    if (schema.name == name) return schema;
    known += (known.empty() ? "" : ", ") + schema.name;
  }
  throw Error::usage("unknown schema '" + std::string(name) + "' (known: " + known + ")");
}

}  // namespace hair::h5
