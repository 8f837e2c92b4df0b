#include "hair/core/params.h"

#include <fmt/format.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <stdexcept>
#include <string_view>
#include <utility>

#include "hair/core/error.h"

namespace hair {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

/// The number in `text` (TOML or command-line spelling, optional leading '+'), or nothing.
std::optional<double> parsed_double(std::string_view text) {
  if (!text.empty() && text.front() == '+') text.remove_prefix(1);
  double value = 0.0;
  const auto [end, status] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (text.empty() || status != std::errc() || end != text.data() + text.size()) {
    return std::nullopt;
  }
  return value;
}

std::optional<long long> parsed_integer(std::string_view text) {
  if (!text.empty() && text.front() == '+') text.remove_prefix(1);
  long long value = 0;
  const auto [end, status] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (text.empty() || status != std::errc() || end != text.data() + text.size()) {
    return std::nullopt;
  }
  return value;
}

Error bad_value(const std::string& name, const std::string& shown_value,
                const std::string& problem) {
  return Error::usage(fmt::format("parameter {} = {} {}", name, shown_value, problem));
}

std::string quoted_text(const std::string& text) {
  std::string out = "\"";
  for (char c : text) {
    if (c == '"' || c == '\\') out += '\\';
    out += c;
  }
  return out + "\"";
}

/// Shortest text that reads back to the same floating-point value, always with a
/// decimal point or exponent so that TOML reads it as a float.
template <typename Real>
std::string toml_float(Real value) {
  std::string text = fmt::format("{}", value);
  if (text.find_first_of(".e") == std::string::npos) text += ".0";
  return text;
}

std::string joined(const std::vector<std::string>& words) {
  std::string out;
  for (const auto& word : words) out += (out.empty() ? "" : ", ") + word;
  return out;
}

std::string bound_text(double bound) { return fmt::format("{}", bound); }

}  // namespace

ParamRange ParamRange::closed(double min, double max) { return {min, max, true, true}; }
ParamRange ParamRange::at_least(double min) { return {min, kInfinity, true, false}; }
ParamRange ParamRange::above(double min) { return {min, kInfinity, false, false}; }
ParamRange ParamRange::at_most(double max) { return {-kInfinity, max, false, true}; }

bool ParamRange::contains(double value) const {
  if (!std::isfinite(value)) return false;
  const bool above_min = min_included ? value >= min : value > min;
  const bool below_max = max_included ? value <= max : value < max;
  return above_min && below_max;
}

bool ParamRange::is_bounded() const { return min != -kInfinity || max != kInfinity; }

std::string ParamRange::to_string() const {
  return fmt::format("{}{}, {}{}", min_included ? '[' : '(', bound_text(min), bound_text(max),
                     max_included ? ']' : ')');
}

ParamSet::ParamSet(CLI::App& app)
    : group_(app.add_option_group("Parameters",
                                  "Stage parameters; also read from the --params TOML file, "
                                  "the command line wins")) {
  app.allow_config_extras(CLI::config_extras_mode::error);
}

ParamSet::ParamSet(CLI::App& app, ValuesUnchecked) : ParamSet(app) { defaults_checked_ = false; }

void ParamSet::add(const std::string& name, double& value, const std::string& description,
                   ParamRange range) {
  check_default_in_range(name, value, range);
  add_option(register_param({name, description, &value, range, {}, nullptr}), "FLOAT",
             toml_float(value));
}

void ParamSet::add(const std::string& name, float& value, const std::string& description,
                   ParamRange range) {
  check_default_in_range(name, value, range);
  add_option(register_param({name, description, &value, range, {}, nullptr}), "FLOAT",
             toml_float(value));
}

void ParamSet::add(const std::string& name, int& value, const std::string& description,
                   ParamRange range) {
  check_default_in_range(name, value, range);
  add_option(register_param({name, description, &value, range, {}, nullptr}), "INT",
             std::to_string(value));
}

void ParamSet::add(const std::string& name, bool& value, const std::string& description) {
  Param& param = register_param({name, description, &value, {}, {}, nullptr});
  const size_t index = params_.size() - 1;
  // A flag: `--name` or `--name=false`; the file's `name = false` arrives as the text
  // "false". The value is parsed (and stored) by the same code as every other kind.
  // CLI11 shows no default for flags: the help text carries it.
  const std::string help =
      fmt::format("{} (true or false, default {})", description, value ? "true" : "false");
  param.option =
      group_->add_flag("--" + name, help)
          ->multi_option_policy(CLI::MultiOptionPolicy::TakeLast)
          ->each([this, index](const std::string& text) { parse_into(params_[index], text); });
}

void ParamSet::add(const std::string& name, std::string& value, const std::string& description,
                   std::vector<std::string> allowed_words) {
  if (allowed_words.empty()) {
    throw std::invalid_argument("parameter '" + name + "' has no allowed words");
  }
  if (defaults_checked_ &&
      std::find(allowed_words.begin(), allowed_words.end(), value) == allowed_words.end()) {
    throw std::invalid_argument(fmt::format("default of parameter {} = {} is not one of: {}", name,
                                            quoted_text(value), joined(allowed_words)));
  }
  add_option(register_param({name, description, &value, {}, std::move(allowed_words), nullptr}),
             "WORD", value);
}

ParamSet::Param& ParamSet::register_param(Param param) {
  for (const auto& existing : params_) {
    if (existing.name == param.name) {
      throw std::invalid_argument("parameter '" + param.name + "' registered twice");
    }
  }
  params_.push_back(std::move(param));
  return params_.back();
}

void ParamSet::check_default_in_range(const std::string& name, double value,
                                      const ParamRange& range) const {
  if (defaults_checked_ && !range.contains(value)) {
    throw std::invalid_argument(fmt::format("default of parameter {} = {} is out of range {}", name,
                                            value, range.to_string()));
  }
}

void ParamSet::add_option(Param& param, const std::string& type_name,
                          const std::string& default_text) {
  const size_t index = params_.size() - 1;
  param.option =
      group_
          ->add_option_function<std::string>(
              "--" + param.name,
              [this, index](const std::string& text) { parse_into(params_[index], text); },
              help_text(param))
          ->type_name(type_name)
          ->default_str(default_text);
}

void ParamSet::parse_into(const Param& param, const std::string& text) const {
  const auto parse_number = [&](auto* target) {
    const std::optional<double> number = parsed_double(text);
    if (!number) throw bad_value(param.name, quoted_text(text), "is not a number");
    using Real = std::remove_pointer_t<decltype(target)>;
    const auto stored = static_cast<Real>(*number);
    if (!param.range.contains(stored)) {
      throw bad_value(param.name, text,
                      std::isfinite(stored) ? "is out of range " + param.range.to_string()
                                            : std::string("is not a finite number"));
    }
    *target = stored;
  };
  std::visit(
      [&](auto* target) {
        using Target = std::remove_pointer_t<decltype(target)>;
        if constexpr (std::is_same_v<Target, double> || std::is_same_v<Target, float>) {
          parse_number(target);
        } else if constexpr (std::is_same_v<Target, int>) {
          const std::optional<long long> integer = parsed_integer(text);
          if (!integer) {
            throw bad_value(param.name, parsed_double(text) ? text : quoted_text(text),
                            "is not an integer");
          }
          if (!param.range.contains(static_cast<double>(*integer)) ||
              *integer < std::numeric_limits<int>::min() ||
              *integer > std::numeric_limits<int>::max()) {
            throw bad_value(param.name, text, "is out of range " + param.range.to_string());
          }
          *target = static_cast<int>(*integer);
        } else if constexpr (std::is_same_v<Target, bool>) {
          if (text != "true" && text != "false") {
            throw bad_value(param.name, quoted_text(text), "is not true or false");
          }
          *target = text == "true";
        } else {
          const auto& words = param.allowed_words;
          if (std::find(words.begin(), words.end(), text) == words.end()) {
            throw bad_value(param.name, quoted_text(text), "is not one of: " + joined(words));
          }
          *target = text;
        }
      },
      param.value);
}

std::string ParamSet::constraint_text(const Param& param) const {
  return std::visit(
      [&](auto* target) -> std::string {
        using Target = std::remove_pointer_t<decltype(target)>;
        if constexpr (std::is_same_v<Target, bool>) {
          return "(true or false)";
        } else if constexpr (std::is_same_v<Target, std::string>) {
          return "(one of: " + joined(param.allowed_words) + ")";
        } else {
          return param.range.is_bounded() ? "(range " + param.range.to_string() + ")" : "";
        }
      },
      param.value);
}

std::string ParamSet::help_text(const Param& param) const {
  const std::string constraint = constraint_text(param);
  return constraint.empty() ? param.description : param.description + " " + constraint;
}

void ParamSet::add_check(std::function<std::optional<std::string>()> check) {
  checks_.push_back(std::move(check));
}

void ParamSet::check() const {
  for (const auto& check : checks_) {
    if (const std::optional<std::string> violation = check()) throw Error::usage(*violation);
  }
}

void ParamSet::check_values() const {
  for (const auto& param : params_) {
    // The value's shortest text reads back to the same value, so parse_into() leaves it
    // as it is and refuses it with the command line's message.
    const std::string text = std::visit(
        [](auto* target) -> std::string {
          using Target = std::remove_pointer_t<decltype(target)>;
          if constexpr (std::is_same_v<Target, bool>) {
            return *target ? "true" : "false";
          } else if constexpr (std::is_same_v<Target, std::string>) {
            return *target;
          } else {
            return fmt::format("{}", *target);
          }
        },
        param.value);
    parse_into(param, text);
  }
  check();
}

nlohmann::ordered_json ParamSet::effective_json() const {
  nlohmann::ordered_json values = nlohmann::ordered_json::object();
  for (const auto& param : params_) {
    std::visit(
        [&](auto* target) {
          using Target = std::remove_pointer_t<decltype(target)>;
          if constexpr (std::is_same_v<Target, float>) {
            // The float's shortest decimal, not its binary expansion as a double.
            values[param.name] = *parsed_double(fmt::format("{}", *target));
          } else {
            values[param.name] = *target;
          }
        },
        param.value);
  }
  return values;
}

std::string ParamSet::effective_toml() const {
  std::string toml;
  for (const auto& param : params_) {
    if (!toml.empty()) toml += "\n";
    const std::string comment = help_text(param);
    size_t line_start = 0;
    while (line_start <= comment.size()) {
      const size_t line_end = std::min(comment.find('\n', line_start), comment.size());
      toml += "# " + comment.substr(line_start, line_end - line_start) + "\n";
      line_start = line_end + 1;
    }
    const std::string value_text = std::visit(
        [](auto* target) -> std::string {
          using Target = std::remove_pointer_t<decltype(target)>;
          if constexpr (std::is_same_v<Target, double> || std::is_same_v<Target, float>) {
            return toml_float(*target);
          } else if constexpr (std::is_same_v<Target, int>) {
            return std::to_string(*target);
          } else if constexpr (std::is_same_v<Target, bool>) {
            return *target ? "true" : "false";
          } else {
            return quoted_text(*target);
          }
        },
        param.value);
    toml += param.name + " = " + value_text + "\n";
  }
  return toml;
}

bool ParamSet::owns(const CLI::Option* option) const {
  for (const auto& param : params_) {
    if (param.option == option) return true;
  }
  return false;
}

std::string parameter_file_error_line(const CLI::ParseError& error,
                                      const std::string& params_path) {
  const std::string message = error.what();
  const std::string file = params_path.empty() ? "the parameter file" : params_path;
  const std::string_view extras_prefix = "INI was not able to parse ";
  const std::string_view not_configurable_suffix =
      ": This option is not allowed in a configuration file";
  if (dynamic_cast<const CLI::ConfigError*>(&error) != nullptr) {
    if (message.starts_with(extras_prefix)) {
      return fmt::format("unknown parameter '{}' in {}", message.substr(extras_prefix.size()),
                         file);
    }
    if (message.ends_with(not_configurable_suffix)) {
      const std::string key = message.substr(0, message.size() - not_configurable_suffix.size());
      return fmt::format("'{}' in {} is a command-line option, not a parameter", key, file);
    }
    return file + ": " + message;
  }
  if (dynamic_cast<const CLI::FileError*>(&error) != nullptr) {
    return fmt::format("cannot read parameter file {}", file);
  }
  return message;
}

}  // namespace hair
