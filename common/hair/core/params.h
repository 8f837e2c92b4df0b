#pragma once

#include <CLI/CLI.hpp>
#include <functional>
#include <limits>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <variant>
#include <vector>

namespace hair {

/// An interval of allowed numbers for a parameter, each end open or closed.
/// The default allows every finite number.
struct ParamRange {
  double min = -std::numeric_limits<double>::infinity();
  double max = std::numeric_limits<double>::infinity();
  bool min_included = false;  ///< [min vs (min
  bool max_included = false;  ///< max] vs max)

  /// [min, max]
  static ParamRange closed(double min, double max);
  /// [min, inf)
  static ParamRange at_least(double min);
  /// (min, inf): e.g. a strictly positive length
  static ParamRange above(double min);
  /// (-inf, max]
  static ParamRange at_most(double max);

  bool contains(double value) const;
  /// True unless this is the default range (every finite number).
  bool is_bounded() const;
  /// "[0, 1]", "(0, inf)".
  std::string to_string() const;
};

/// The parameters of one stage, bound to a CLI::App option group "Parameters".
///
/// Each parameter `name` is both a command-line option `--name VALUE` and a key
/// `name = VALUE` of the stage's TOML parameter file (read by CLI11's config support,
/// `--params FILE` in StageApp). The command line wins over the file. Values are checked
/// as they are read; a bad one throws hair::Error (usage) naming the parameter, e.g.
///   parameter k1 = 1.5 is out of range [0, 1]
///   parameter unit_scale = "abc" is not a number
///   parameter eigensolver = "lapack" is not one of: spectra, dense
/// Choices are words, never integers. Booleans are flags: `--name` or `--name=false` on
/// the command line, `name = true|false` in the file.
///
/// The bound variables must outlive the ParamSet and the parse; ParamSet is neither
/// copyable nor movable because the option callbacks refer to it.
class ParamSet {
 public:
  /// Adds the group "Parameters" to `app` and makes `app` reject unknown keys in its
  /// config file (see parameter_file_error_line for the message).
  explicit ParamSet(CLI::App& app);
  /// For check_params(): registering takes values outside their ranges, which
  /// check_values() then refuses by name.
  struct ValuesUnchecked {};
  ParamSet(CLI::App& app, ValuesUnchecked);
  ParamSet(const ParamSet&) = delete;
  ParamSet& operator=(const ParamSet&) = delete;

  /// Registers a parameter; `value` holds its default and receives the parsed value.
  /// Throws std::invalid_argument if the name is taken or the default breaks the range.
  void add(const std::string& name, double& value, const std::string& description,
           ParamRange range = {});
  void add(const std::string& name, float& value, const std::string& description,
           ParamRange range = {});
  void add(const std::string& name, int& value, const std::string& description,
           ParamRange range = {});
  void add(const std::string& name, bool& value, const std::string& description);
  /// A word from `allowed_words` (non-empty).
  void add(const std::string& name, std::string& value, const std::string& description,
           std::vector<std::string> allowed_words);

  /// Adds a cross check over several parameters (e.g. weights summing to 1); it returns
  /// a message describing the violation, or nothing when the values are consistent.
  void add_check(std::function<std::optional<std::string>()> check);

  /// Runs the cross checks after parsing; throws hair::Error (usage) with the first message.
  void check() const;

  /// Holds every bound value to its range or words, as if it had been read from the
  /// command line, then runs the cross checks; throws hair::Error (usage) with the same
  /// message a bad command-line value gets.
  void check_values() const;

  /// {"name": value, ...} in registration order (for the provenance attribute).
  nlohmann::ordered_json effective_json() const;

  /// The current values as a TOML parameter file, each preceded by its description and
  /// allowed values as comments; reading it back gives the same values.
  std::string effective_toml() const;

  /// True if `option` is one of this set's parameters.
  bool owns(const CLI::Option* option) const;

 private:
  using ValuePointer = std::variant<double*, float*, int*, bool*, std::string*>;

  struct Param {
    std::string name;
    std::string description;
    ValuePointer value;
    ParamRange range;                        ///< numbers only
    std::vector<std::string> allowed_words;  ///< words only
    CLI::Option* option = nullptr;
  };

  Param& register_param(Param param);
  void check_default_in_range(const std::string& name, double value,
                              const ParamRange& range) const;
  /// Adds the command-line option of `param`, the last one registered.
  void add_option(Param& param, const std::string& type_name, const std::string& default_text);
  void parse_into(const Param& param, const std::string& text) const;
  /// "(range [0, 1])", "(one of: a, b)", "(true or false)" or "".
  std::string constraint_text(const Param& param) const;
  /// The description followed by the constraint text.
  std::string help_text(const Param& param) const;

  CLI::App* group_;
  bool defaults_checked_ = true;
  std::vector<Param> params_;
  std::vector<std::function<std::optional<std::string>()>> checks_;
};

/// Checks `values` as a stage's command line checks them: `declare` (a stage's
/// declare_*_params) registers a copy of them with their ranges, words and cross checks,
/// and every value is held to them. A library entry point calls it, so that what a
/// caller sets in code meets the bounds a user's command line does. Throws hair::Error
/// (usage), e.g. "parameter step_h = 0.5 is out of range [0.001, 0.1]".
template <typename Values>
void check_params(const Values& values, void (*declare)(ParamSet&, Values&)) {
  Values copy = values;
  CLI::App app;
  ParamSet params(app, ParamSet::ValuesUnchecked{});
  declare(params, copy);
  params.check_values();
}

/// The one-line message for a CLI11 error raised while reading the parameter file at
/// `params_path`: an unknown key becomes "unknown parameter 'foo' in params.toml", a
/// command-line option set in the file is refused by name; other errors keep their text.
std::string parameter_file_error_line(const CLI::ParseError& error, const std::string& params_path);

}  // namespace hair
