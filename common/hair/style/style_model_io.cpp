#include "hair/style/style_model_io.h"

#include <fmt/format.h>

#include <cmath>
#include <fstream>
#include <opencv2/core.hpp>
#include <sstream>
#include <utility>
#include <vector>

#include "hair/core/atomic_file.h"
#include "hair/core/error.h"
#include "hair/style/hair_style.h"

namespace hair {
namespace {

std::vector<double> values_of(const Eigen::VectorXd& vector) {
  return {vector.data(), vector.data() + vector.size()};
}

Eigen::VectorXd vector_of(const std::vector<double>& values) {
  return Eigen::Map<const Eigen::VectorXd>(values.data(), static_cast<Eigen::Index>(values.size()));
}

/// Reads the entries of a model file, each failure a bad-input error naming the file and
/// the entry ("/svm/sigma").
class ModelReader {
 public:
  explicit ModelReader(std::string name) : name_(std::move(name)) {}

  [[noreturn]] void fail(const std::string& path, const std::string& reason) const {
    throw Error::bad_dataset(name_, path, reason);
  }

  cv::FileNode child(const cv::FileNode& parent, const std::string& parent_path,
                     const std::string& key) const {
    if (!parent.isMap()) fail(parent_path.empty() ? "/" : parent_path, "is not a map");
    cv::FileNode node = parent[key];
    if (node.empty() || node.isNone()) fail(parent_path + "/" + key, "missing");
    return node;
  }

  double real(const cv::FileNode& parent, const std::string& parent_path,
              const std::string& key) const {
    cv::FileNode node = child(parent, parent_path, key);
    if (!node.isReal() && !node.isInt()) fail(parent_path + "/" + key, "is not a number");
    auto value = static_cast<double>(node);
    if (!std::isfinite(value)) fail(parent_path + "/" + key, "is not finite");
    return value;
  }

  int integer(const cv::FileNode& parent, const std::string& parent_path,
              const std::string& key) const {
    cv::FileNode node = child(parent, parent_path, key);
    if (!node.isInt()) fail(parent_path + "/" + key, "is not an integer");
    return static_cast<int>(node);
  }

  std::string text(const cv::FileNode& parent, const std::string& parent_path,
                   const std::string& key) const {
    cv::FileNode node = child(parent, parent_path, key);
    if (!node.isString()) fail(parent_path + "/" + key, "is not a string");
    return node.string();
  }

  cv::FileNode sequence(const cv::FileNode& parent, const std::string& parent_path,
                        const std::string& key) const {
    cv::FileNode node = child(parent, parent_path, key);
    if (!node.isSeq()) fail(parent_path + "/" + key, "is not a sequence");
    return node;
  }

  std::vector<double> reals(const cv::FileNode& parent, const std::string& parent_path,
                            const std::string& key) const {
    return reals_of(sequence(parent, parent_path, key), parent_path + "/" + key);
  }

  std::vector<double> reals_of(const cv::FileNode& node, const std::string& path) const {
    if (!node.isSeq()) fail(path, "is not a sequence");
    std::vector<double> values;
    for (const cv::FileNode& item : node) {
      if (!item.isReal() && !item.isInt()) fail(path, "holds a value that is not a number");
      values.push_back(static_cast<double>(item));
      if (!std::isfinite(values.back())) fail(path, "holds a value that is not finite");
    }
    return values;
  }

  std::vector<int32_t> integers(const cv::FileNode& parent, const std::string& parent_path,
                                const std::string& key) const {
    std::vector<int32_t> values;
    for (const cv::FileNode& item : sequence(parent, parent_path, key)) {
      if (!item.isInt()) fail(parent_path + "/" + key, "holds a value that is not an integer");
      values.push_back(static_cast<int32_t>(static_cast<int>(item)));
    }
    return values;
  }

  std::vector<std::string> texts(const cv::FileNode& parent, const std::string& parent_path,
                                 const std::string& key) const {
    std::vector<std::string> values;
    for (const cv::FileNode& item : sequence(parent, parent_path, key)) {
      if (!item.isString()) fail(parent_path + "/" + key, "holds a value that is not a string");
      values.push_back(item.string());
    }
    return values;
  }

  void expect_size(size_t size, size_t expected, const std::string& path,
                   const std::string& what) const {
    if (size != expected)
      fail(path, "has " + std::to_string(size) + " values, expected " + std::to_string(expected) +
                     " (" + what + ")");
  }

 private:
  std::string name_;
};

void check_feature_names(const ModelReader& reader, const std::vector<std::string>& model_names,
                         std::span<const std::string> expected) {
  if (expected.empty() ||
      std::equal(model_names.begin(), model_names.end(), expected.begin(), expected.end()))
    return;
  size_t first = 0;
  while (first < model_names.size() && first < expected.size() &&
         model_names[first] == expected[first])
    ++first;
  auto name_at = [](const auto& names, size_t i) {
    return i < names.size() ? fmt::format("'{}'", names[i]) : std::string("none");
  };
  reader.fail("/feature_names",
              fmt::format("the model's {} features differ from the caller's {} at feature {}: {} "
                          "in the model, {} given: retrain the model for these features",
                          model_names.size(), expected.size(), first, name_at(model_names, first),
                          name_at(expected, first)));
}

PukSvm read_svm(const ModelReader& reader, const cv::FileNode& node,
                const std::vector<int32_t>& class_labels, int feature_count,
                PukSvmSelection& selection) {
  const std::string path = "/svm";
  PukSvm svm;
  svm.params.sigma = reader.real(node, path, "sigma");
  svm.params.omega = reader.real(node, path, "omega");
  svm.params.c = reader.real(node, path, "c");
  if (!(svm.params.sigma > 0 && svm.params.omega > 0 && svm.params.c > 0))
    reader.fail(path, "sigma, omega and c must be positive");
  selection.params = svm.params;
  selection.correct = reader.integer(node, path, "grid_correct");
  selection.rows = reader.integer(node, path, "grid_rows");
  svm.feature_count = reader.integer(node, path, "feature_count");
  if (svm.feature_count != feature_count)
    reader.fail(path + "/feature_count", "is " + std::to_string(svm.feature_count) +
                                             ", the model has " + std::to_string(feature_count) +
                                             " features");
  svm.class_labels = class_labels;

  cv::FileNode vectors = reader.sequence(node, path, "support_vectors");
  svm.support_vectors.resize(static_cast<Eigen::Index>(vectors.size()), feature_count);
  Eigen::Index row = 0;
  for (const cv::FileNode& vector : vectors) {
    std::string row_path = path + "/support_vectors/" + std::to_string(row);
    std::vector<double> values = reader.reals_of(vector, row_path);
    reader.expect_size(values.size(), static_cast<size_t>(feature_count), row_path, "features");
    for (int column = 0; column < feature_count; ++column)
      svm.support_vectors(row, column) = static_cast<float>(values[static_cast<size_t>(column)]);
    ++row;
  }

  cv::FileNode functions = reader.sequence(node, path, "decision_functions");
  auto k = static_cast<int32_t>(class_labels.size());
  reader.expect_size(functions.size(), static_cast<size_t>(k * (k - 1) / 2),
                     path + "/decision_functions", "one per pair of classes");
  auto function_node = functions.begin();
  for (int32_t first = 0; first < k; ++first)
    for (int32_t second = first + 1; second < k; ++second, ++function_node) {
      std::string function_path =
          path + "/decision_functions/" + std::to_string(svm.decision_functions.size());
      SvmDecisionFunction function;
      function.first = reader.integer(*function_node, function_path, "first");
      function.second = reader.integer(*function_node, function_path, "second");
      if (function.first != first || function.second != second)
        reader.fail(function_path, "is for classes (" + std::to_string(function.first) + ", " +
                                       std::to_string(function.second) + "), expected (" +
                                       std::to_string(first) + ", " + std::to_string(second) + ")");
      function.rho = reader.real(*function_node, function_path, "rho");
      function.alpha = reader.reals(*function_node, function_path, "alpha");
      function.sv_index = reader.integers(*function_node, function_path, "sv_index");
      reader.expect_size(function.sv_index.size(), function.alpha.size(),
                         function_path + "/sv_index", "one per alpha");
      for (int32_t index : function.sv_index)
        if (index < 0 || index >= svm.support_vectors.rows())
          reader.fail(function_path + "/sv_index",
                      "holds " + std::to_string(index) + ", outside the " +
                          std::to_string(svm.support_vectors.rows()) + " support vectors");
      svm.decision_functions.push_back(std::move(function));
    }
  return svm;
}

cv::Ptr<cv::ml::RTrees> read_forest(const ModelReader& reader, const cv::FileNode& root,
                                    int feature_count) {
  cv::FileNode node = reader.child(root, "", "random_forest");
  cv::Ptr<cv::ml::RTrees> forest = cv::ml::RTrees::create();
  try {
    forest->read(node);
  } catch (const cv::Exception& error) {
    reader.fail("/random_forest", "OpenCV cannot read it: " + error.err);
  }
  if (!forest->isTrained()) reader.fail("/random_forest", "holds no trees");
  if (forest->getVarCount() != feature_count)
    reader.fail("/random_forest", "is for " + std::to_string(forest->getVarCount()) +
                                      " features, the model has " + std::to_string(feature_count));
  return forest;
}

}  // namespace

std::string style_model_text(const StyleModel& model) {
  cv::FileStorage fs(".yml", cv::FileStorage::WRITE | cv::FileStorage::MEMORY);
  fs << "format" << kStyleModelFormat;
  fs << "version" << kStyleModelVersion;
  fs << "feature_set" << model.feature_set;
  fs << "feature_names"
     << "[";
  for (const std::string& name : model.feature_names) fs << name;
  fs << "]";
  fs << "training_rows" << model.training_rows;
  fs << "class_labels" << std::vector<int>(model.class_labels.begin(), model.class_labels.end());
  fs << "class_names"
     << "[:";
  for (int32_t label : model.class_labels)
    fs << hair_style_name(static_cast<HairStyle>(static_cast<int8_t>(label)));
  fs << "]";
  fs << "class_counts" << std::vector<int>(model.class_counts.begin(), model.class_counts.end());
  fs << "default_classifier" << style_classifier_name(model.default_classifier);

  fs << "standardization"
     << "{";
  const Eigen::VectorXd log_offset = model.standardization.log_offset.size() == 0
                                         ? Eigen::VectorXd::Zero(model.standardization.mean.size())
                                         : model.standardization.log_offset;
  fs << "log_offset" << values_of(log_offset);
  fs << "mean" << values_of(model.standardization.mean);
  fs << "scale" << values_of(model.standardization.scale);
  fs << "}";

  const PukSvm& svm = model.svm;
  fs << "svm"
     << "{";
  fs << "sigma" << svm.params.sigma << "omega" << svm.params.omega << "c" << svm.params.c;
  fs << "grid_correct" << model.svm_selection.correct << "grid_rows" << model.svm_selection.rows;
  fs << "feature_count" << svm.feature_count;
  fs << "support_vectors"
     << "[";
  for (Eigen::Index row = 0; row < svm.support_vectors.rows(); ++row) {
    fs << "[:";  // floats with 9 digits, enough to read back the same float
    fs.writeRaw("f", svm.support_vectors.row(row).data(),
                static_cast<size_t>(svm.support_vectors.cols()) * sizeof(float));
    fs << "]";
  }
  fs << "]";
  fs << "decision_functions"
     << "[";
  for (const SvmDecisionFunction& function : svm.decision_functions) {
    fs << "{"
       << "first" << function.first << "second" << function.second << "rho" << function.rho;
    fs << "alpha" << function.alpha;
    fs << "sv_index" << std::vector<int>(function.sv_index.begin(), function.sv_index.end());
    fs << "}";
  }
  fs << "]";
  fs << "}";

  const RandomForestParams& forest = model.forest_params;
  fs << "random_forest_settings"
     << "{";
  fs << "trees" << forest.trees << "max_depth" << forest.max_depth << "min_sample_count"
     << forest.min_sample_count << "active_var_count" << forest.active_var_count;
  fs << "seed" << std::to_string(forest.seed);  // as text: FileStorage integers are 32-bit
  fs << "}";
  fs << "random_forest"
     << "{";
  model.forest->write(fs);
  fs << "}";
  return fs.releaseAndGetString();
}

void write_style_model(const std::filesystem::path& path, const StyleModel& model) {
  std::string text = style_model_text(model);
  AtomicFile output(path);
  {
    std::ofstream stream(output.temporary_path(), std::ios::binary);
    stream << text;
    stream.close();
    if (!stream) throw Error::runtime(path.string(), "cannot write the style model");
  }
  output.commit();
}

StyleModel style_model_from_text(const std::string& text, const std::string& name,
                                 std::span<const std::string> expected_feature_names) {
  ModelReader reader(name);
  cv::FileStorage fs;
  try {
    fs.open(text, cv::FileStorage::READ | cv::FileStorage::MEMORY | cv::FileStorage::FORMAT_YAML);
  } catch (const cv::Exception& error) {
    throw Error::bad_input(name, "not a readable YAML style model (OpenCV: " + error.err + ")");
  }
  if (!fs.isOpened()) throw Error::bad_input(name, "not a readable YAML style model");
  cv::FileNode root = fs.root();
  if (!root.isMap() || root["format"].empty())
    reader.fail("/format",
                std::string("missing: not a style model (format ") + kStyleModelFormat + ")");
  std::string format = reader.text(root, "", "format");
  if (format != kStyleModelFormat)
    reader.fail("/format", "is '" + format + "', expected '" + kStyleModelFormat + "'");
  int version = reader.integer(root, "", "version");
  if (version != kStyleModelVersion)
    reader.fail("/version", "model version " + std::to_string(version) +
                                ", this build reads version " + std::to_string(kStyleModelVersion) +
                                ": retrain the model with this build");

  StyleModel model;
  model.feature_set = reader.text(root, "", "feature_set");
  model.feature_names = reader.texts(root, "", "feature_names");
  if (model.feature_names.empty()) reader.fail("/feature_names", "is empty");
  check_feature_names(reader, model.feature_names, expected_feature_names);
  auto d = static_cast<int>(model.feature_names.size());

  model.training_rows = reader.integer(root, "", "training_rows");
  model.class_labels = reader.integers(root, "", "class_labels");
  if (model.class_labels.empty()) reader.fail("/class_labels", "is empty");
  for (size_t i = 1; i < model.class_labels.size(); ++i)
    if (model.class_labels[i] <= model.class_labels[i - 1])
      reader.fail("/class_labels", "is not strictly ascending");
  std::vector<int32_t> counts = reader.integers(root, "", "class_counts");
  reader.expect_size(counts.size(), model.class_labels.size(), "/class_counts", "one per class");
  model.class_counts.assign(counts.begin(), counts.end());
  std::string default_name = reader.text(root, "", "default_classifier");
  std::optional<StyleClassifierKind> kind = style_classifier_from_name(default_name);
  if (!kind)
    reader.fail("/default_classifier", "is '" + default_name + "', expected svm or random_forest");
  model.default_classifier = *kind;

  cv::FileNode standardization = reader.child(root, "", "standardization");
  std::vector<double> log_offset = reader.reals(standardization, "/standardization", "log_offset");
  std::vector<double> mean = reader.reals(standardization, "/standardization", "mean");
  std::vector<double> scale = reader.reals(standardization, "/standardization", "scale");
  reader.expect_size(log_offset.size(), static_cast<size_t>(d), "/standardization/log_offset",
                     "features");
  for (double value : log_offset)
    if (!(value >= 0) || !std::isfinite(value))
      reader.fail("/standardization/log_offset", "holds a value that is negative or not finite");
  reader.expect_size(mean.size(), static_cast<size_t>(d), "/standardization/mean", "features");
  reader.expect_size(scale.size(), static_cast<size_t>(d), "/standardization/scale", "features");
  for (double value : scale)
    if (!(value > 0)) reader.fail("/standardization/scale", "holds a value that is not positive");
  model.standardization = {vector_of(log_offset), vector_of(mean), vector_of(scale)};

  model.svm =
      read_svm(reader, reader.child(root, "", "svm"), model.class_labels, d, model.svm_selection);

  cv::FileNode settings = reader.child(root, "", "random_forest_settings");
  const std::string settings_path = "/random_forest_settings";
  model.forest_params.trees = reader.integer(settings, settings_path, "trees");
  model.forest_params.max_depth = reader.integer(settings, settings_path, "max_depth");
  model.forest_params.min_sample_count =
      reader.integer(settings, settings_path, "min_sample_count");
  model.forest_params.active_var_count =
      reader.integer(settings, settings_path, "active_var_count");
  std::string seed = reader.text(settings, settings_path, "seed");
  try {
    size_t used = 0;
    model.forest_params.seed = std::stoull(seed, &used);
    if (used != seed.size()) throw std::invalid_argument(seed);
  } catch (const std::exception&) {
    reader.fail(settings_path + "/seed", "is '" + seed + "', not an unsigned integer");
  }
  model.forest = read_forest(reader, root, d);
  return model;
}

StyleModel read_style_model(const std::filesystem::path& path,
                            std::span<const std::string> expected_feature_names) {
  std::ifstream stream(path, std::ios::binary);
  if (!stream) throw Error::bad_input(path.string(), "cannot open the style model");
  std::ostringstream text;
  text << stream.rdbuf();
  return style_model_from_text(text.str(), path.string(), expected_feature_names);
}

}  // namespace hair
