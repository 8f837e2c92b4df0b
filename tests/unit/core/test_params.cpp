#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include "unit/file_test.h"
#include "hair/core/error.h"
#include "hair/core/params.h"

namespace {

namespace fs = std::filesystem;

/// A temporary directory of its own per test, removed afterwards.
class ParamsTest : public hair::test::FileTest {};

/// Parameters of a made-up stage, with one of each kind.
struct ExampleParams {
  double k1 = 0.5;
  float spacing_m = 0.01f;
  int iterations = 10;
  bool settle = true;
  std::string eigensolver = "spectra";

  void bind(hair::ParamSet& params) {
    params.add("k1", k1, "Weight of the first term", hair::ParamRange::closed(0, 1));
    params.add("spacing_m", spacing_m, "Point spacing along a strand, metres",
               hair::ParamRange::above(0));
    params.add("iterations", iterations, "Solver iterations", hair::ParamRange::at_least(1));
    params.add("settle", settle, "Let the hair settle before the animation");
    params.add("eigensolver", eigensolver, "Sparse eigensolver", {"spectra", "dense"});
  }
};

/// Parses `arguments` (after the program name) into a fresh app, as a stage would.
void parse(CLI::App& app, std::vector<std::string> arguments) {
  std::vector<const char*> argv{"stage"};
  for (const auto& argument : arguments) argv.push_back(argument.c_str());
  app.parse(static_cast<int>(argv.size()), argv.data());
}

std::string usage_message(const std::function<void()>& action) {
  try {
    action();
  } catch (const hair::Error& error) {
    EXPECT_EQ(error.kind(), hair::ErrorKind::usage);
    EXPECT_EQ(error.exit_code(), 2);
    return error.what();
  }
  ADD_FAILURE() << "no hair::Error thrown";
  return "";
}

/// The usage error of reading ExampleParams from the parameter file `path`.
std::string usage_message_for_file(const std::string& path) {
  CLI::App app;
  app.set_config("--params");
  hair::ParamSet params(app);
  ExampleParams values;
  values.bind(params);
  return usage_message([&] { parse(app, {"--params", path}); });
}

TEST_F(ParamsTest, DefaultsStayWithoutFileOrOptions) {
  CLI::App app;
  hair::ParamSet params(app);
  ExampleParams values;
  values.bind(params);
  parse(app, {});
  EXPECT_EQ(values.k1, 0.5);
  EXPECT_EQ(values.iterations, 10);
  EXPECT_TRUE(values.settle);
  EXPECT_EQ(values.eigensolver, "spectra");
}

TEST_F(ParamsTest, CommandLineSetsEveryKind) {
  CLI::App app;
  hair::ParamSet params(app);
  ExampleParams values;
  values.bind(params);
  parse(app, {"--k1", "0.25", "--spacing_m=0.002", "--iterations", "3", "--settle=false",
              "--eigensolver", "dense"});
  EXPECT_EQ(values.k1, 0.25);
  EXPECT_EQ(values.spacing_m, 0.002f);
  EXPECT_EQ(values.iterations, 3);
  EXPECT_FALSE(values.settle);
  EXPECT_EQ(values.eigensolver, "dense");
}

TEST_F(ParamsTest, BareFlagMeansTrue) {
  CLI::App app;
  hair::ParamSet params(app);
  ExampleParams values;
  values.settle = false;
  values.bind(params);
  parse(app, {"--settle"});
  EXPECT_TRUE(values.settle);
}

TEST_F(ParamsTest, FileWithCommentsSetsValuesAndCommandLineWins) {
  const std::string path = write_file("params.toml", R"(# a stage's parameters
k1 = 0.75   # inline comment
spacing_m = 1e-3

iterations = 4
settle = false
eigensolver = "dense"
)");
  CLI::App app;
  app.set_config("--params");
  hair::ParamSet params(app);
  ExampleParams values;
  values.bind(params);
  parse(app, {"--params", path, "--iterations", "7"});
  EXPECT_EQ(values.k1, 0.75);
  EXPECT_EQ(values.spacing_m, 1e-3f);
  EXPECT_EQ(values.iterations, 7);
  EXPECT_FALSE(values.settle);
  EXPECT_EQ(values.eigensolver, "dense");
}

TEST_F(ParamsTest, OutOfRangeNamesParameterValueAndRange) {
  CLI::App app;
  hair::ParamSet params(app);
  ExampleParams values;
  values.bind(params);
  EXPECT_EQ(usage_message([&] {
              parse(app, {"--k1", "1.5"});
            }),
            "parameter k1 = 1.5 is out of range [0, 1]");
}

TEST_F(ParamsTest, OutOfRangeInFileIsRejected) {
  EXPECT_EQ(usage_message_for_file(write_file("params.toml", "spacing_m = 0.0\n")),
            "parameter spacing_m = 0.0 is out of range (0, inf)");
}

TEST_F(ParamsTest, WrongTypesNameTheParameter) {
  const auto message_for = [](const std::vector<std::string>& arguments) {
    CLI::App app;
    hair::ParamSet params(app);
    ExampleParams values;
    values.bind(params);
    return usage_message([&] { parse(app, arguments); });
  };
  EXPECT_EQ(message_for({"--k1", "abc"}), "parameter k1 = \"abc\" is not a number");
  EXPECT_EQ(message_for({"--k1", "nan"}), "parameter k1 = nan is not a finite number");
  EXPECT_EQ(message_for({"--iterations", "2.5"}), "parameter iterations = 2.5 is not an integer");
  EXPECT_EQ(message_for({"--iterations", "0"}),
            "parameter iterations = 0 is out of range [1, inf)");
  EXPECT_EQ(message_for({"--settle=yes"}), "parameter settle = \"yes\" is not true or false");
  EXPECT_EQ(message_for({"--eigensolver", "lapack"}),
            "parameter eigensolver = \"lapack\" is not one of: spectra, dense");
}

TEST_F(ParamsTest, WrongTypeInFileNamesTheParameter) {
  EXPECT_EQ(usage_message_for_file(write_file("params.toml", "k1 = \"abc\"\n")),
            "parameter k1 = \"abc\" is not a number");
}

TEST_F(ParamsTest, UnknownKeyInFileIsNamed) {
  const std::string path = write_file("params.toml", "k1 = 0.5\nfoo = 3\n");
  CLI::App app;
  app.set_config("--params");
  hair::ParamSet params(app);
  ExampleParams values;
  values.bind(params);
  try {
    parse(app, {"--params", path});
    FAIL() << "unknown key accepted";
  } catch (const CLI::ParseError& error) {
    EXPECT_EQ(hair::parameter_file_error_line(error, "params.toml"),
              "unknown parameter 'foo' in params.toml");
  }
}

TEST_F(ParamsTest, CrossCheckReportsItsMessage) {
  CLI::App app;
  hair::ParamSet params(app);
  double weight_s1 = 0.5;
  double weight_s2 = 0.5;
  params.add("weight_s1", weight_s1, "Weight of S1", hair::ParamRange::closed(0, 1));
  params.add("weight_s2", weight_s2, "Weight of S2", hair::ParamRange::closed(0, 1));
  params.add_check([&]() -> std::optional<std::string> {
    if (std::abs(weight_s1 + weight_s2 - 1.0) > 1e-9) {
      return "weight_s1 + weight_s2 must be 1, not " + std::to_string(weight_s1 + weight_s2);
    }
    return std::nullopt;
  });
  parse(app, {});
  EXPECT_NO_THROW(params.check());
  parse(app, {"--weight_s1", "0.7"});
  EXPECT_EQ(usage_message([&] { params.check(); }),
            "weight_s1 + weight_s2 must be 1, not 1.200000");
}

TEST_F(ParamsTest, EffectiveJsonKeepsRegistrationOrder) {
  CLI::App app;
  hair::ParamSet params(app);
  ExampleParams values;
  values.bind(params);
  parse(app, {"--k1", "0.1"});
  const nlohmann::ordered_json json = params.effective_json();
  std::vector<std::string> keys;
  for (const auto& item : json.items()) keys.push_back(item.key());
  EXPECT_EQ(keys,
            (std::vector<std::string>{"k1", "spacing_m", "iterations", "settle", "eigensolver"}));
  EXPECT_EQ(json.dump(),
            R"({"k1":0.1,"spacing_m":0.01,"iterations":10,"settle":true,"eigensolver":"spectra"})");
}

TEST_F(ParamsTest, EffectiveTomlReadsBackToTheSameValues) {
  ExampleParams written;
  written.k1 = 0.1 + 0.2;  // not a short decimal: must survive the round trip exactly
  written.spacing_m = 1.0f / 3.0f;
  written.iterations = 42;
  written.settle = false;
  written.eigensolver = "dense";
  std::string toml;
  {
    CLI::App app;
    hair::ParamSet params(app);
    written.bind(params);
    parse(app, {});
    toml = params.effective_toml();
  }
  EXPECT_NE(toml.find("# Weight of the first term (range [0, 1])\nk1 = "), std::string::npos)
      << toml;
  EXPECT_NE(toml.find("eigensolver = \"dense\""), std::string::npos) << toml;

  const std::string path = write_file("effective.toml", toml);
  CLI::App app;
  app.set_config("--params");
  hair::ParamSet params(app);
  ExampleParams read;
  read.bind(params);
  parse(app, {"--params", path});
  EXPECT_EQ(read.k1, written.k1);
  EXPECT_EQ(read.spacing_m, written.spacing_m);
  EXPECT_EQ(read.iterations, written.iterations);
  EXPECT_EQ(read.settle, written.settle);
  EXPECT_EQ(read.eigensolver, written.eigensolver);
  EXPECT_EQ(params.effective_toml(), toml);
}

TEST_F(ParamsTest, WholeNumberFloatsAreWrittenAsTomlFloats) {
  CLI::App app;
  hair::ParamSet params(app);
  double scale = 1.0;
  params.add("scale", scale, "Scale");
  EXPECT_EQ(params.effective_toml(), "# Scale\nscale = 1.0\n");
}

TEST_F(ParamsTest, BadRegistrationsAreProgrammingErrors) {
  CLI::App app;
  hair::ParamSet params(app);
  double k1 = 2.0;
  EXPECT_THROW(params.add("k1", k1, "Weight", hair::ParamRange::closed(0, 1)),
               std::invalid_argument);
  std::string mode = "other";
  EXPECT_THROW(params.add("mode", mode, "Mode", {"a", "b"}), std::invalid_argument);
  double once = 0.0;
  params.add("once", once, "Once");
  EXPECT_THROW(params.add("once", once, "Once"), std::invalid_argument);
}

TEST(ParamRange, TextAndMembership) {
  EXPECT_EQ(hair::ParamRange::closed(0, 1).to_string(), "[0, 1]");
  EXPECT_EQ(hair::ParamRange::above(0).to_string(), "(0, inf)");
  EXPECT_EQ(hair::ParamRange::at_most(2.5).to_string(), "(-inf, 2.5]");
  EXPECT_TRUE(hair::ParamRange::closed(0, 1).contains(1.0));
  EXPECT_FALSE(hair::ParamRange::above(0).contains(0.0));
  EXPECT_FALSE(hair::ParamRange{}.contains(std::numeric_limits<double>::infinity()));
  EXPECT_TRUE(hair::ParamRange{}.contains(-1e300));
}

}  // namespace

namespace {

void declare_example(hair::ParamSet& params, ExampleParams& values) { values.bind(params); }

std::string check_message(const ExampleParams& values) {
  try {
    hair::check_params(values, declare_example);
  } catch (const hair::Error& error) {
    EXPECT_EQ(error.kind(), hair::ErrorKind::usage);
    return error.what();
  }
  return "";
}

TEST(CheckParams, ValuesSetInCodeMeetTheCommandLinesBounds) {
  // What a library caller sets is refused as a user's command line would be, by name.
  EXPECT_EQ(check_message(ExampleParams{}), "");
  ExampleParams values;
  values.k1 = 1.5;
  EXPECT_EQ(check_message(values), "parameter k1 = 1.5 is out of range [0, 1]");
  values = {};
  values.iterations = 0;
  EXPECT_EQ(check_message(values), "parameter iterations = 0 is out of range [1, inf)");
  values = {};
  values.spacing_m = std::nanf("");
  EXPECT_NE(check_message(values).find("spacing_m"), std::string::npos);
  values = {};
  values.eigensolver = "lapack";
  EXPECT_EQ(check_message(values), "parameter eigensolver = \"lapack\" is not one of: spectra, dense");
  // The values checked are left as they are (a copy is declared).
  values = {};
  values.k1 = 0.1;
  EXPECT_EQ(check_message(values), "");
  EXPECT_EQ(values.k1, 0.1);
}

}  // namespace
