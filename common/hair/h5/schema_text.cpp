#include "hair/h5/schema_text.h"

#include <fmt/format.h>

#include <algorithm>

namespace hair::h5 {

namespace {

/// "min 0, max 1, finite" for the rules that are set.
std::string constraints_text(const DatasetConstraints& rules, bool is_float) {
  std::vector<std::string> parts;
  if (is_float) parts.push_back(rules.finite ? "finite" : "may be non-finite");
  if (rules.min) parts.push_back(fmt::format(">= {}", *rules.min));
  if (rules.max) parts.push_back(fmt::format("<= {}", *rules.max));
  if (rules.exclusive_min) parts.push_back(fmt::format("> {}", *rules.exclusive_min));
  if (rules.exclusive_max) parts.push_back(fmt::format("< {}", *rules.exclusive_max));
  if (!rules.csr_offsets_of.empty()) parts.push_back("CSR offsets of " + rules.csr_offsets_of);
  if (!rules.index_into.empty()) {
    parts.push_back("indices into " + rules.index_into + (rules.allow_none ? " or -1" : ""));
  }
  return fmt::format("{}", fmt::join(parts, ", "));
}

std::string equals_text(const std::variant<std::string, int64_t, double>& value) {
  if (const auto* text = std::get_if<std::string>(&value)) return "= \"" + *text + "\"";
  if (const auto* integer = std::get_if<int64_t>(&value)) return fmt::format("= {}", *integer);
  return fmt::format("= {}", std::get<double>(value));
}

}  // namespace

std::string format_schema(const Schema& schema) {
  std::string text =
      fmt::format("{} v{}\n  {}\n\nhistory\n", schema.name, schema.version, schema.description);
  for (const SchemaChange& change : schema.history) {
    text += fmt::format("  v{}  {}\n", change.version, change.changes);
  }
  size_t width = 0;
  for (const auto& [name, description] : schema.dimensions) width = std::max(width, name.size());
  text += "\ndimensions\n";
  for (const auto& [name, description] : schema.dimensions) {
    text += fmt::format("  {:<{}}  {}\n", name, width, description);
  }
  text += "\nroot attributes\n";
  text += fmt::format("  schema (string) = \"{}\"\n  schema_version (int64) = {}\n", schema.name,
                      schema.version);
  for (const AttributeSpec& spec : schema.attributes) {
    std::vector<std::string> rules;
    if (spec.equals) rules.push_back(equals_text(*spec.equals));
    if (spec.type != AttributeType::string) {
      const std::string range =
          constraints_text(spec.constraints, spec.type == AttributeType::float64);
      if (!range.empty()) rules.push_back(range);
    }
    if (spec.is_json) rules.push_back("JSON text");
    if (!spec.unit.empty()) rules.push_back("unit " + spec.unit);
    if (!spec.required) rules.push_back("optional");
    text += fmt::format("  {} ({}){}{}\n      {}\n", spec.name, attribute_type_name(spec.type),
                        rules.empty() ? "" : "  ", fmt::join(rules, ", "), spec.description);
  }
  text += "\ndatasets\n";
  for (const DatasetSpec& spec : schema.datasets) {
    std::vector<std::string> rules;
    const std::string constraints =
        spec.is_enum() ? "" : constraints_text(spec.constraints, is_floating(*spec.dtype));
    if (!constraints.empty()) rules.push_back(constraints);
    if (!spec.unit.empty()) rules.push_back("unit " + spec.unit);
    if (!spec.required) rules.push_back("optional");
    text +=
        fmt::format("  {}  {} {}{}{}\n      {}\n", spec.path, spec.dtype_text(), spec.shape_text(),
                    rules.empty() ? "" : "  ", fmt::join(rules, ", "), spec.description);
  }
  return text;
}

}  // namespace hair::h5
