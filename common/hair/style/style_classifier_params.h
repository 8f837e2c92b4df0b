#pragma once

#include <cstdint>
#include <optional>
#include <string_view>
#include <vector>

#include "hair/style/puk_svm_grid_search.h"
#include "hair/style/random_forest.h"

namespace hair {

/// The two classifiers of the paper (section 5.1).
enum class StyleClassifierKind : int8_t {
  svm = 0,            ///< support vector machine with the PUK kernel
  random_forest = 1,  ///< random forest
};

/// "svm" or "random_forest" ("unknown" outside the enumeration).
const char* style_classifier_name(StyleClassifierKind kind);
/// The kind named by one of style_classifier_name()'s words; nullopt for any other text.
std::optional<StyleClassifierKind> style_classifier_from_name(std::string_view name);

/// Settings of the style classifiers' cross-validation and training.
struct StyleClassifierParams {
  /// Folds of the cross-validation that measures the classifiers (the paper: ten).
  int folds = 10;
  /// Folds of the grid search for the SVM's sigma, omega and C, run on each training set
  /// of the cross-validation, and on all rows for the final model (>= 2).
  int inner_folds = 5;
  /// Seed of the fold assignments (stratified_folds): the outer folds use it, the grid
  /// search inside outer fold f uses seed + 1 + f, that of the final model seed + 1 + folds.
  uint64_t seed = 1;
  PukSvmGrid svm_grid;
  RandomForestParams forest;
  /// The classifier whose class a trained model reports as the style. The SVM: on real
  /// meshes held out one at a time it gives more strands their style than the random
  /// forest (docs/measured/classify_real_holdout.md), though the paper found the forest
  /// the more accurate in its cross-validation (86.7% against 84.8%).
  StyleClassifierKind default_classifier = StyleClassifierKind::svm;
  /// Per feature, the offset c of its log scale, log(max(x, 0) + c), before the
  /// standardisation (feature_log_offsets(): lengths in H and the node count); 0 for a
  /// feature taken as it is; empty: every feature as it is. hair-train-style sets it from
  /// the feature names; a trained model keeps it (StyleModel::standardization).
  std::vector<double> feature_log_offsets;

  /// Throws hair::Error (usage) naming the first bad setting and its value.
  void check() const;
};

}  // namespace hair
