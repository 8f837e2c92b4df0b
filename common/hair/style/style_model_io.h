#pragma once

#include <filesystem>
#include <span>
#include <string>

#include "hair/style/style_classifier.h"

namespace hair {

/// The `format` entry of a style model file.
inline constexpr const char* kStyleModelFormat = "hairstyle.style_model";
/// The version this build writes and reads. History: 1, the first; 2 (2026-11-27), the
/// standardisation's log offsets (lengths in H and the node count on a log scale).
inline constexpr int kStyleModelVersion = 2;

/// A style model as the text of a YAML file (cv::FileStorage), one file per feature set,
/// meant to be kept in the repository and diffed:
///
///   format: "hairstyle.style_model"    version: 2
///   feature_set, feature_names         the d features, in the order of a row
///   training_rows, class_labels, class_names, class_counts
///   default_classifier                 "svm" or "random_forest"
///   standardization: {log_offset, mean, scale}   d values each (log_offset: 0 for a
///                                      feature as it is, feature_standardization.h)
///   svm: {sigma, omega, c, grid_correct, grid_rows, feature_count, class_labels,
///         support_vectors (one row of d values each),
///         decision_functions: [{first, second, rho, alpha, sv_index}, ...]}
///   random_forest_settings: {trees, max_depth, min_sample_count, active_var_count, seed}
///   random_forest: OpenCV's RTrees::write
///
/// Numbers are written with enough digits to read back the same doubles and floats, so a
/// model read back predicts exactly as the one written.
std::string style_model_text(const StyleModel& model);

/// Writes style_model_text() to `path`, atomically (temporary name, then rename).
/// Throws hair::Error: usage for a missing directory, runtime when writing fails.
void write_style_model(const std::filesystem::path& path, const StyleModel& model);

/// Reads a model written by write_style_model(). The file must have the format and
/// version above, every entry, consistent sizes, and (unless `expected_feature_names` is
/// empty, for tools that only show a model) exactly the caller's feature names in order.
/// Throws hair::Error (bad input) with one line naming the file, the entry and the
/// problem, e.g.
///   "m.yml:/version: model version 1, this build reads version 2: retrain the model ..."
///   "m.yml:/svm/sigma: missing"
///   "m.yml:/feature_names: the model's features [a, b] differ from the caller's [a, c] ..."
StyleModel read_style_model(const std::filesystem::path& path,
                            std::span<const std::string> expected_feature_names);

/// read_style_model() of a text already in memory; `name` stands for the file in errors.
StyleModel style_model_from_text(const std::string& text, const std::string& name,
                                 std::span<const std::string> expected_feature_names);

}  // namespace hair
